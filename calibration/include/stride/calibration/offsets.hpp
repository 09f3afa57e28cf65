// The seven DARwIn-OP walking offsets a calibration can fit: table, selection and bounds.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "stride/gait/walking_params.hpp"

namespace stride::calibration {

/// Number of calibratable offsets.
inline constexpr std::size_t offset_count = 7;

/// One calibratable offset, in [Walking Config] order.
struct offset_info {
  std::string_view key;                  ///< INI key, e.g. "x_offset"
  std::string_view unit;                 ///< "mm" or "deg"
  double gait::walking_params::*member;  ///< where it lives in walking_params
  double lower, upper;                   ///< default fit bounds
  double fd_step;                        ///< central-difference step of the plant mode
};

/// x_offset, y_offset, z_offset, roll_offset, pitch_offset, yaw_offset, hip_pitch_offset.
std::span<const offset_info> offset_table();

/// Index into offset_table() of a key (case-insensitive), or nullopt.
std::optional<std::size_t> find_offset(std::string_view key);

/// The seven offsets as values, in offset_table() order (mm / deg).
using offset_values = std::array<double, offset_count>;

offset_values get_offsets(const gait::walking_params& params);
void set_offsets(gait::walking_params& params, const offset_values& values);

/// Parses a comma-separated list of offset keys ("x_offset,z_offset", or "all") into sorted
/// indices. Throws std::invalid_argument naming an unknown or repeated key, or an empty list.
std::vector<std::size_t> parse_offset_selection(std::string_view list);

/// Lower/upper bounds of every offset during a fit.
struct offset_bounds {
  offset_values lower{};
  offset_values upper{};
  /// The table's defaults: wide enough for any sensible stance, tight enough to keep the leg IK
  /// in reach.
  static offset_bounds defaults();
};

/// Applies "key=lo:hi" (either side may be empty to keep it). Throws std::invalid_argument
/// naming the text when it is malformed, the key unknown or lo >= hi.
void apply_bound(offset_bounds& bounds, std::string_view assignment);

}  // namespace stride::calibration
