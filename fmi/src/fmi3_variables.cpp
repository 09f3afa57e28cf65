#include "fmi3_variables.hpp"

#include <algorithm>
#include <stdexcept>

namespace stride::sdk {

fmi3_variables::fmi3_variables(const variable_table& table) {
  const std::vector<variable>& elements = table.variables();
  std::uint32_t next_free = 0;
  for (std::size_t i = 0; i < elements.size();) {
    const variable& v = elements[i];
    if (v.name == "time") {
      throw std::logic_error(
          "variable 'time': the name is taken by FMI 3.0's independent variable");
    }
    fmi3_variable out;
    out.value_reference = v.value_reference;
    out.first = &v;
    if (v.array_index == 1) {
      out.name = v.name.substr(0, v.name.rfind('['));
      out.count = v.array_size;
      out.is_array = true;
    } else {
      out.name = v.name;
    }
    vars_.push_back(out);
    for (std::size_t k = 0; k < out.count; ++k) {
      next_free = std::max(next_free, elements[i + k].value_reference + 1);
    }
    i += out.count;
  }
  fmi3_variable time;
  time.name = "time";
  time.value_reference = next_free;
  vars_.push_back(time);

  by_vr_.assign(next_free + 1, k_none);
  for (std::size_t i = 0; i < vars_.size(); ++i) by_vr_[vars_[i].value_reference] = i;
}

const fmi3_variable& fmi3_variables::owner(const variable& element) const {
  return *find(element.value_reference -
               static_cast<std::uint32_t>(element.array_index == 0 ? 0 : element.array_index - 1));
}

}  // namespace stride::sdk
