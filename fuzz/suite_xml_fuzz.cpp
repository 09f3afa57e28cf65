// The regression suite XML parser on arbitrary bytes.
#include <exception>
#include <string>

#include "fuzz_input.hpp"
#include "stride/suite/suite.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)stride::suite::parse_suite_text(std::string(stride::fuzz::as_text(data, size)),
                                          "fuzz-suite.xml");
  } catch (const std::exception&) {
  }
  return 0;
}
