// The gait's config.ini reader: the INI parser, then the [Walking Config] section read into the
// walking parameters with every range check.
#include <exception>

#include "fuzz_input.hpp"
#include "stride/gait/config_ini.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto doc =
        stride::gait::ini_document::parse(stride::fuzz::as_text(data, size), "fuzz.ini");
    (void)stride::gait::read_walking_config(doc, stride::gait::walking_params{}, nullptr);
  } catch (const std::exception&) {
  }
  return 0;
}
