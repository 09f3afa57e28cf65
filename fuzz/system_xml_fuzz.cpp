// The system XML parser (libstride) on arbitrary bytes.
#include <exception>

#include "fuzz_input.hpp"
#include "stride/cosim/system_structure.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)stride::cosim::parse_system_text(stride::fuzz::as_text(data, size), "fuzz.xml");
  } catch (const std::exception&) {
  }
  return 0;
}
