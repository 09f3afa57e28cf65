// The robot plant's URDF loader (urdfdom, then the plant's own checks) on arbitrary bytes.
#include <exception>
#include <string>

#include "fuzz_input.hpp"
#include "stride/robot/robot_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)stride::robot::parse_robot_model(std::string(stride::fuzz::as_text(data, size)),
                                           "fuzz.urdf");
  } catch (const std::exception&) {
  }
  return 0;
}
