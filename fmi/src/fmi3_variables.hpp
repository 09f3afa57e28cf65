// A component's variable table as FMI 3.0 sees it: the elements `name[1]`..`name[N]` of an array
// member become one array variable `name` with a <Dimension> of N, whose value reference is that
// of its first element; and the independent variable `time`, which FMI 3.0 requires and the
// table does not hold (docs/fmi3-rules.md §5).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {

struct fmi3_variable {
  std::string name;  ///< the array's name without the element index
  std::uint32_t value_reference = 0;
  const variable* first = nullptr;  ///< the first element (a scalar: itself); nullptr for time
  std::size_t count = 1;            ///< elements
  bool is_array = false;

  bool is_time() const { return first == nullptr; }
  /// Element k (0-based) of the array, or the scalar itself.
  const variable& element(std::size_t k) const { return first[k]; }
};

class fmi3_variables {
 public:
  /// \throws std::logic_error when the table already has a variable called "time".
  explicit fmi3_variables(const variable_table& table);

  const std::vector<fmi3_variable>& all() const { return vars_; }
  /// The variable with this FMI 3.0 value reference, or nullptr (element references other than
  /// an array's first do not exist in FMI 3.0).
  const fmi3_variable* find(std::uint32_t value_reference) const {
    if (value_reference >= by_vr_.size() || by_vr_[value_reference] == k_none) return nullptr;
    return &vars_[by_vr_[value_reference]];
  }
  const fmi3_variable& time() const { return vars_.back(); }
  /// The FMI 3.0 variable an element of the table belongs to.
  const fmi3_variable& owner(const variable& element) const;

 private:
  std::vector<fmi3_variable> vars_;
  static constexpr std::size_t k_none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> by_vr_;  // value reference → index into vars_ (npos: none)
};

}  // namespace stride::sdk
