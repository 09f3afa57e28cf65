#include "stride/cosim/component.hpp"

namespace stride::cosim {

std::size_t variable_refs::add(variable_type type, value_reference var) {
  std::vector<value_reference>* list = nullptr;
  switch (exchange_type(type)) {
    case variable_type::real:
      list = &reals;
      break;
    case variable_type::integer:
    case variable_type::enumeration:
      list = &integers;
      break;
    case variable_type::boolean:
      list = &booleans;
      break;
    case variable_type::string:
      list = &strings;
      break;
  }
  list->push_back(var);
  return list->size() - 1;
}

void value_block::resize_for(const variable_refs& refs) {
  reals.resize(refs.reals.size());
  integers.resize(refs.integers.size());
  booleans.resize(refs.booleans.size());
  strings.resize(refs.strings.size());
}

}  // namespace stride::cosim
