// Typed access to the lanes of variable_refs and value_block, and the rule by which an input
// reads its source's cached values: shared by the fixed-step algorithm and step groups, so that
// a component reads the same value however it is stepped.
#ifndef STRIDE_COSIM_VALUE_LANES_HPP
#define STRIDE_COSIM_VALUE_LANES_HPP

#include <string>
#include <type_traits>

#include "stride/cosim/component.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim::detail {

// the list of one exchange type inside a batch
template <class T>
auto& lane(variable_refs& r) {
  if constexpr (std::is_same_v<T, double>) return r.reals;
  if constexpr (std::is_same_v<T, int>) return r.integers;
  if constexpr (std::is_same_v<T, bool>) return r.booleans;
  if constexpr (std::is_same_v<T, std::string>) return r.strings;
}
template <class T>
auto& lane(value_block& b) {
  if constexpr (std::is_same_v<T, double>) return b.reals;
  if constexpr (std::is_same_v<T, int>) return b.integers;
  if constexpr (std::is_same_v<T, bool>) return b.booleans;
  if constexpr (std::is_same_v<T, std::string>) return b.strings;
}
template <class T>
const auto& lane(const value_block& b) {
  return lane<T>(const_cast<value_block&>(b));
}

// calls f.template operator()<T>() for the four exchange types
template <class F>
void for_each_type(F&& f) {
  f.template operator()<double>();
  f.template operator()<int>();
  f.template operator()<bool>();
  f.template operator()<std::string>();
}

// calls f.template operator()<T>() for the exchange type `type`
template <class F>
void with_type(variable_type type, F&& f) {
  switch (exchange_type(type)) {
    case variable_type::real:
      f.template operator()<double>();
      break;
    case variable_type::integer:
    case variable_type::enumeration:
      f.template operator()<int>();
      break;
    case variable_type::boolean:
      f.template operator()<bool>();
      break;
    case variable_type::string:
      f.template operator()<std::string>();
      break;
  }
}

// Whether an input reads its source's values of the previous communication point (`published`)
// rather than those at the source's current time (`latest`), when read at time `at`. A source
// that steps in this macro step and is read at the previous point gives its published values,
// written before any component stepped: that read never races with the source's own step.
inline bool reads_published(bool previous, bool source_steps_now, time_point source_time,
                            time_point at) noexcept {
  if (previous && source_steps_now) return true;
  return source_time > at;
}

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_VALUE_LANES_HPP
