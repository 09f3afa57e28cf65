// The calibration tool's target files: joint-mode posture CSV and plant-mode target.
#include <exception>
#include <string_view>

#include "fuzz_input.hpp"
#include "stride/calibration/targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = stride::fuzz::as_text(data, size);
  try {
    (void)stride::calibration::parse_joint_target(text, "fuzz.csv");
  } catch (const std::exception&) {
  }
  try {
    (void)stride::calibration::parse_plant_target(text, "fuzz.ini");
  } catch (const std::exception&) {
  }
  return 0;
}
