#include "stride/calibration/offsets.hpp"

#include <algorithm>
#include <stdexcept>

#include "text.hpp"

namespace stride::calibration {

namespace {

using gait::walking_params;

// Bounds: the foot stays under the hip within a few cm, the crouch between nearly straight and
// deep, angles within what the stance tolerates. Steps: well above the gait's 1-count
// quantization (0.088 deg of a joint, about 0.3 mm of foot position), which makes the settled
// posture a staircase function of the offsets at a finer scale.
constexpr offset_info k_table[offset_count] = {
    {"x_offset", "mm", &walking_params::x_offset, -50, 50, 1.0},
    {"y_offset", "mm", &walking_params::y_offset, -30, 50, 1.0},
    {"z_offset", "mm", &walking_params::z_offset, 1, 80, 1.0},
    {"roll_offset", "deg", &walking_params::roll_offset, -15, 15, 1.0},
    {"pitch_offset", "deg", &walking_params::pitch_offset, -30, 30, 1.0},
    {"yaw_offset", "deg", &walking_params::yaw_offset, -30, 30, 1.0},
    {"hip_pitch_offset", "deg", &walking_params::hip_pitch_offset, -20, 45, 1.0},
};

std::string known_keys() {
  std::string s;
  for (const offset_info& o : k_table) s += (s.empty() ? "" : ", ") + std::string(o.key);
  return s;
}

}  // namespace

std::span<const offset_info> offset_table() {
  return k_table;
}

std::optional<std::size_t> find_offset(std::string_view key) {
  for (std::size_t i = 0; i < offset_count; ++i)
    if (detail::iequals(k_table[i].key, key)) return i;
  return std::nullopt;
}

offset_values get_offsets(const gait::walking_params& params) {
  offset_values v{};
  for (std::size_t i = 0; i < offset_count; ++i) v[i] = params.*(k_table[i].member);
  return v;
}

void set_offsets(gait::walking_params& params, const offset_values& values) {
  for (std::size_t i = 0; i < offset_count; ++i) params.*(k_table[i].member) = values[i];
}

std::vector<std::size_t> parse_offset_selection(std::string_view list) {
  if (detail::iequals(detail::trim(list), "all")) {
    std::vector<std::size_t> all(offset_count);
    for (std::size_t i = 0; i < offset_count; ++i) all[i] = i;
    return all;
  }
  std::vector<std::size_t> out;
  for (std::string_view item : detail::split(list, ',')) {
    item = detail::trim(item);
    if (item.empty()) continue;
    const auto index = find_offset(item);
    if (!index)
      throw std::invalid_argument("unknown offset '" + std::string(item) +
                                  "' (known: " + known_keys() + ")");
    if (std::find(out.begin(), out.end(), *index) != out.end())
      throw std::invalid_argument("offset '" + std::string(item) + "' is listed twice");
    out.push_back(*index);
  }
  if (out.empty()) throw std::invalid_argument("no offset selected (known: " + known_keys() + ")");
  std::sort(out.begin(), out.end());
  return out;
}

offset_bounds offset_bounds::defaults() {
  offset_bounds b;
  for (std::size_t i = 0; i < offset_count; ++i) {
    b.lower[i] = k_table[i].lower;
    b.upper[i] = k_table[i].upper;
  }
  return b;
}

void apply_bound(offset_bounds& bounds, std::string_view assignment) {
  const std::string text(assignment);
  const auto eq = assignment.find('=');
  const auto colon = assignment.find(':', eq == std::string_view::npos ? 0 : eq);
  if (eq == std::string_view::npos || colon == std::string_view::npos)
    throw std::invalid_argument("bound '" + text + "': expected offset=lower:upper");
  const auto index = find_offset(detail::trim(assignment.substr(0, eq)));
  if (!index)
    throw std::invalid_argument("bound '" + text + "': unknown offset (known: " + known_keys() +
                                ")");
  const std::string_view lo = detail::trim(assignment.substr(eq + 1, colon - eq - 1));
  const std::string_view hi = detail::trim(assignment.substr(colon + 1));
  double lower = bounds.lower[*index], upper = bounds.upper[*index];
  if (!lo.empty()) {
    const auto v = detail::parse_double(lo);
    if (!v || !std::isfinite(*v))
      throw std::invalid_argument("bound '" + text + "': lower bound is not a number");
    lower = *v;
  }
  if (!hi.empty()) {
    const auto v = detail::parse_double(hi);
    if (!v || !std::isfinite(*v))
      throw std::invalid_argument("bound '" + text + "': upper bound is not a number");
    upper = *v;
  }
  if (!(lower < upper))
    throw std::invalid_argument("bound '" + text + "': lower bound must be below the upper");
  bounds.lower[*index] = lower;
  bounds.upper[*index] = upper;
}

}  // namespace stride::calibration
