// The state space of the learner: a regular grid over n gait parameters, written as
// "name:min:max:step,name:min:max:step,...". State indices run with the first dimension fastest
// (index = i0 + n0 * (i1 + n1 * (i2 + ...))), so a 2-D table printed by index walks period_time
// inside swing_right_left, as the paper's tables do.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace stride::learner {

/// A malformed grid, checkpoint, evaluation point or learner setting; the message names the
/// parameter (and the offending text) at fault.
class learner_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Most dimensions a grid may have (the FMU has outputs value[1..4]).
inline constexpr std::size_t k_max_dimensions = 4;
/// Most states a grid may have (the value table is a dense vector of doubles).
inline constexpr std::size_t k_max_states = 50'000'000;

/// One axis of the grid: `count` values min, min + step, ..., max.
struct grid_dimension {
  std::string name;
  double min = 0;
  double max = 0;
  double step = 1;
  int count = 1;
  /// Decimal places of the written bounds and step: values are rounded to them, so that
  /// "0.1:0.5:0.1" gives 0.3 and not 0.30000000000000004.
  int decimals = 0;

  /// The i-th value (0 <= i < count).
  double value(int i) const;
};

/// A regular grid of states over named parameters.
class state_grid {
 public:
  state_grid() = default;

  /// Parses "name:min:max:step[,name:min:max:step...]" (',' or ';' between dimensions, blanks
  /// ignored). Throws learner_error naming `what` (e.g. "grid") and the faulty dimension for an
  /// empty text, a missing field, a non-number, step <= 0, max < min, (max - min) not a whole
  /// number of steps, a duplicate name, more than k_max_dimensions dimensions or too many states.
  static state_grid parse(std::string_view text, std::string_view what = "grid");

  const std::vector<grid_dimension>& dimensions() const { return dims_; }
  std::size_t dimension_count() const { return dims_.size(); }
  /// Position of the dimension called `name`, or nullopt.
  std::optional<std::size_t> dimension(std::string_view name) const;
  std::size_t size() const { return size_; }

  /// Index of a state from per-dimension indices.
  std::size_t index(const std::vector<int>& coords) const;
  /// Per-dimension indices of a state.
  std::vector<int> coords(std::size_t index) const;
  /// Index along dimension d of state `index`.
  int coord(std::size_t index, std::size_t d) const;
  /// The state one step along dimension d (delta = +1 or -1); at the edge of the grid the state
  /// itself (the move is clamped, as in the authors' controller).
  std::size_t neighbour(std::size_t index, std::size_t d, int delta) const;
  /// Parameter values of a state.
  std::vector<double> values(std::size_t index) const;
  /// The state whose values equal `values` (each within 1e-9 of a grid value), or throws
  /// learner_error naming `what`.
  std::size_t find(const std::vector<double>& values, std::string_view what) const;

  /// The canonical text "name:min:max:step,..." (shortest round-trip numbers).
  std::string str() const;

 private:
  std::vector<grid_dimension> dims_;
  std::vector<std::size_t> strides_;
  std::size_t size_ = 0;
};

/// Shortest text that reads back to the same double ("600", "0.1", "-10").
std::string format_number(double v);
/// Parses a whole trimmed string as a finite double; throws learner_error naming `what`.
double parse_number(std::string_view text, std::string_view what);
/// Splits "a,b;c" at ',' and ';', trimming blanks; empty items are kept (and usually rejected by
/// the caller).
std::vector<std::string> split_list(std::string_view text);
/// Parses "v1,v2,..." as numbers (evaluation points); throws learner_error naming `what`.
std::vector<double> parse_number_list(std::string_view text, std::string_view what);
/// Parses "50000,100000" as non-negative integers (snapshot steps), sorted and unique.
std::vector<std::int64_t> parse_step_list(std::string_view text, std::string_view what);

}  // namespace stride::learner
