#include "stride/sdk/types.hpp"

#include <cmath>

namespace stride::sdk {

time_ns to_time_ns(double seconds) {
  return static_cast<time_ns>(std::llround(seconds * 1e9));
}

}  // namespace stride::sdk
