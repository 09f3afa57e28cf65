// Simulation time: signed 64-bit integer ticks of one nanosecond.
//
// Time is never accumulated in floating point. A communication point is computed as
// start + k * step in integer ticks and converted to seconds only at the FMI boundary.
#ifndef STRIDE_COSIM_TIME_HPP
#define STRIDE_COSIM_TIME_HPP

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

namespace stride::cosim {

/// A span of simulated time in 1 ns ticks.
using duration = std::chrono::duration<std::int64_t, std::nano>;

/// The clock of simulated time; there is no `now()`, time only advances through an execution.
struct sim_clock {
  using rep = std::int64_t;
  using period = std::nano;
  using duration = stride::cosim::duration;
  using time_point = std::chrono::time_point<sim_clock, duration>;
  static constexpr bool is_steady = true;
};

/// A point in simulated time (ticks since t = 0).
using time_point = sim_clock::time_point;

/// Seconds as a double, computed from the integer tick count (no accumulated rounding).
constexpr double to_seconds(duration d) noexcept {
  return static_cast<double>(d.count()) / 1e9;
}
/// Seconds since t = 0 as a double.
constexpr double to_seconds(time_point t) noexcept {
  return to_seconds(t.time_since_epoch());
}

/// The time point `s` seconds after t = 0, rounded to the nearest tick.
time_point time_from_seconds(double s);
/// The duration of `s` seconds, rounded to the nearest tick.
duration duration_from_seconds(double s);

/// Parses a decimal number of seconds ("0.008", "60", "1e-3", "2.5E+1") exactly, without going
/// through a double. \throws std::invalid_argument if the text is not a number or not a whole
/// number of nanoseconds, std::out_of_range if it does not fit in 64-bit ticks.
duration parse_duration(std::string_view seconds);

/// Shortest decimal text of a duration in seconds ("0.008", "60", "-1.5").
std::string format_seconds(duration d);
/// Shortest decimal text of a time point in seconds.
inline std::string format_seconds(time_point t) {
  return format_seconds(t.time_since_epoch());
}

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_TIME_HPP
