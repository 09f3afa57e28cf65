// The importer's modelDescription.xml parser (libstride) on arbitrary bytes.
#include <exception>

#include "fuzz_input.hpp"
#include "stride/cosim/model_description.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)stride::cosim::parse_model_description_text(stride::fuzz::as_text(data, size),
                                                      "fuzz/modelDescription.xml");
  } catch (const std::exception&) {
  }
  return 0;
}
