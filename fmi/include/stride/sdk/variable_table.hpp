// The ONE variable table of a component. Each entry says what a variable is (name, type,
// causality, variability, initial, unit, range, description) and where its value lives (a byte
// offset into the component's data struct). From it come the fmi2Get/Set dispatch, the checks
// on sets, the start values and modelDescription.xml.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "stride/sdk/types.hpp"

namespace stride::sdk {

/// One scalar variable. Array members of the data struct become N variables `name[1]`..`name[N]`.
struct variable {
  std::string name;
  std::uint32_t value_reference = 0;
  value_type type = value_type::real;
  causality causality_kind = causality::local;
  variability variability_kind = variability::continuous;
  initial_kind initial = initial_kind::none;
  std::size_t offset = 0;           // where the value lives inside the data struct
  std::size_t string_capacity = 0;  // for String variables stored as fixed_string
  /// Element `array_index` (1-based) of an array of `array_size` elements; 0 and 0 for a scalar.
  /// FMI 2.0 sees the elements as scalars; FMI 3.0 as one array variable.
  std::size_t array_index = 0;
  std::size_t array_size = 0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool has_min = false;
  bool has_max = false;
  std::string unit;
  std::string description;
  /// Inputs this output depends on directly (feedthrough), by value reference.
  std::vector<std::uint32_t> direct_dependencies;
  /// Extra validation for Real/Integer values beyond min/max; throws std::invalid_argument.
  std::function<void(double)> check;

  bool has_start() const {
    return causality_kind == causality::input || initial == initial_kind::exact ||
           initial == initial_kind::approx || variability_kind == variability::constant;
  }
};

/// Values a buffer_table_builder set aside: `count` values of `element_size` bytes from `offset`.
struct storage_run {
  std::size_t offset = 0;
  std::size_t count = 0;
  std::size_t element_size = 0;
  value_type type = value_type::real;
};

/// The finished, immutable table plus a default-constructed data struct holding start values.
class variable_table {
 public:
  variable_table(std::vector<variable> vars, std::shared_ptr<const void> defaults,
                 std::size_t data_size);

  const std::vector<variable>& variables() const { return vars_; }
  /// nullptr when no variable has this value reference and type.
  const variable* find(std::uint32_t value_reference) const {
    return value_reference < by_vr_.size() ? by_vr_[value_reference] : nullptr;
  }
  const variable* find(std::string_view name) const;
  /// Position (1-based) of the variable in ModelVariables.
  std::size_t index_of(const variable& v) const {
    return static_cast<std::size_t>(&v - vars_.data()) + 1;
  }
  /// The data struct as default-constructed: the start values.
  const void* defaults() const { return defaults_.get(); }
  std::size_t data_size() const { return data_size_; }
  /// For a buffer table: every reserved run of values, in order (what a state image holds).
  const std::vector<storage_run>& storage() const { return storage_; }

 private:
  friend class buffer_table_builder;
  std::vector<variable> vars_;
  std::vector<const variable*> by_vr_;
  std::shared_ptr<const void> defaults_;
  std::size_t data_size_;
  std::vector<storage_run> storage_;
};

namespace detail {
template <class T>
struct storage_traits;
template <>
struct storage_traits<double> {
  static constexpr value_type type = value_type::real;
};
template <>
struct storage_traits<int> {
  static constexpr value_type type = value_type::integer;
};
template <>
struct storage_traits<bool> {
  static constexpr value_type type = value_type::boolean;
};
template <std::size_t N>
struct storage_traits<fixed_string<N>> {
  static constexpr value_type type = value_type::string;
};
}  // namespace detail

class table_builder_base;

/// Handle on one or more just-declared variables (an array declares several); every call
/// applies to all of them.
class variable_group {
 public:
  variable_group(table_builder_base& builder, std::size_t first, std::size_t count)
      : builder_(&builder), first_(first), count_(count) {}

  variable_group& parameter();             // fixed parameter (initial exact)
  variable_group& tunable();               // parameter that may change during the run
  variable_group& calculated_parameter();  // computed from parameters during initialization
  variable_group& input();
  variable_group& output();  // initial calculated, no feedthrough by default
  variable_group& local();
  variable_group& discrete();  // variability discrete instead of continuous
  variable_group& unit(std::string u);
  variable_group& describe(std::string d);
  variable_group& min(double v);
  variable_group& max(double v);
  variable_group& range(double lo, double hi) { return min(lo).max(hi); }
  /// Extra validation (e.g. an exclusive bound) run on every set; throws std::invalid_argument.
  variable_group& check(std::function<void(double)> f);
  /// Declares direct feedthrough from the named inputs (each element i depends on all of them).
  variable_group& depends_on(std::vector<std::string> input_names);

 private:
  template <class F>
  variable_group& each(F f);
  table_builder_base* builder_;
  std::size_t first_;
  std::size_t count_;
};

class table_builder_base {
 public:
  variable_table finish(std::shared_ptr<const void> defaults, std::size_t data_size);

 protected:
  friend class variable_group;
  variable_group add(std::string name, value_type type, std::size_t offset, std::size_t count,
                     std::size_t stride, std::size_t string_capacity, bool is_array);
  std::vector<variable> vars_;
  std::vector<std::pair<std::size_t, std::vector<std::string>>> pending_dependencies_;
};

/// Builds the table of a component whose values live in `Data` (trivially copyable, default
/// member initialisers = start values).
template <class Data>
class table_builder : public table_builder_base {
  static_assert(std::is_trivially_copyable_v<Data>, "component data must be trivially copyable");

 public:
  table_builder() : defaults_(std::make_shared<Data>()) {}

  /// A scalar member: `t.add("gain", &data::gain).parameter().tunable()`.
  template <class T>
  variable_group add(std::string name, T Data::*member) {
    return table_builder_base::add(std::move(name), detail::storage_traits<T>::type,
                                   offset_of(member), 1, sizeof(T), string_capacity<T>(), false);
  }
  /// An array member: declares `name[1]`..`name[N]` with consecutive value references.
  template <class T, std::size_t N>
  variable_group add(std::string name, T (Data::*member)[N]) {
    return table_builder_base::add(std::move(name), detail::storage_traits<T>::type,
                                   offset_of(member), N, sizeof(T), string_capacity<T>(), true);
  }

  /// A field reached through nested members, given as a reference into defaults():
  /// `t.add_field("x_offset", t.defaults().params.x_offset)`.
  template <class T>
  variable_group add_field(std::string name, const T& field_in_defaults) {
    const char* base = reinterpret_cast<const char*>(defaults_.get());
    const char* field = reinterpret_cast<const char*>(&field_in_defaults);
    if (field < base || field + sizeof(T) > base + sizeof(Data)) {
      throw std::logic_error("variable '" + name + "': field is not inside the data struct");
    }
    return table_builder_base::add(std::move(name), detail::storage_traits<T>::type,
                                   static_cast<std::size_t>(field - base), 1, sizeof(T),
                                   string_capacity<T>(), false);
  }

  variable_table finish() { return table_builder_base::finish(defaults_, sizeof(Data)); }
  const Data& defaults() const { return *defaults_; }

 private:
  template <class M>
  std::size_t offset_of(M Data::*member) const {
    const Data& d = *defaults_;
    return static_cast<std::size_t>(reinterpret_cast<const char*>(&(d.*member)) -
                                    reinterpret_cast<const char*>(&d));
  }
  template <class T>
  static constexpr std::size_t string_capacity() {
    if constexpr (detail::storage_traits<T>::type == value_type::string) {
      return T::capacity();
    } else {
      return 0;
    }
  }
  std::shared_ptr<Data> defaults_;
};

/// Builds the table of a component whose interface is only known at run time (e.g. read from a
/// file in its resources): each variable gets room in a byte buffer, in declaration order, and
/// the component reads and writes its values there (buffer_model). Two declarations may share
/// storage: `declare` names values that `reserve` set aside.
class buffer_table_builder : public table_builder_base {
 public:
  /// Sets aside `count` values of T (double, int, bool or fixed_string<N>), each starting at
  /// `start`; returns the offset of the first.
  template <class T>
  std::size_t reserve(std::size_t count, const T& start) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t offset = (defaults_.size() + alignof(T) - 1) / alignof(T) * alignof(T);
    defaults_.resize(offset + count * sizeof(T));
    for (std::size_t i = 0; i < count; ++i) {
      std::memcpy(defaults_.data() + offset + i * sizeof(T), &start, sizeof(T));
    }
    storage_.push_back({offset, count, sizeof(T), detail::storage_traits<T>::type});
    return offset;
  }
  /// Declares `name` over the value of T at `offset` (count 1), or `name[1]`..`name[count]`
  /// over `count` consecutive values when `array`.
  template <class T>
  variable_group declare(std::string name, std::size_t offset, std::size_t count = 1,
                         bool array = false) {
    if (offset + count * sizeof(T) > defaults_.size()) {
      throw std::logic_error("variable '" + name + "': storage not reserved");
    }
    std::size_t capacity = 0;
    if constexpr (detail::storage_traits<T>::type == value_type::string) capacity = T::capacity();
    return table_builder_base::add(std::move(name), detail::storage_traits<T>::type, offset, count,
                                   sizeof(T), capacity, array || count != 1);
  }
  /// Changes the start value of the T at `offset`.
  template <class T>
  void set_start(std::size_t offset, const T& start) {
    if (offset + sizeof(T) > defaults_.size()) throw std::logic_error("start value not reserved");
    std::memcpy(defaults_.data() + offset, &start, sizeof(T));
  }
  /// reserve() and declare() in one: a scalar variable of its own.
  template <class T>
  variable_group add(std::string name, const T& start, std::size_t* offset = nullptr) {
    const std::size_t at = reserve<T>(1, start);
    if (offset != nullptr) *offset = at;
    return declare<T>(std::move(name), at);
  }

  /// The start values as laid out so far.
  std::span<const std::byte> defaults() const { return defaults_; }
  variable_table finish();

 private:
  std::vector<std::byte> defaults_;
  std::vector<storage_run> storage_;
};

}  // namespace stride::sdk
