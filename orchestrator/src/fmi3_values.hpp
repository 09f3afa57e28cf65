// Stride's scalar value channels over the FMI 3.0 typed, array-aware get and set calls.
//
// A port is one element of an FMI 3 variable. FMI 3 reads and writes arrays only whole, so each
// variable keeps a copy of its last known elements: setting one element writes the whole array
// with the others unchanged. Float64/Float32 travel as reals, Int8..UInt64 and enumerations as
// Stride's 32-bit integers (a value that does not fit is an error either way), Boolean as bool,
// String as string and Binary as hex text.
#ifndef STRIDE_COSIM_SRC_FMI3_VALUES_HPP
#define STRIDE_COSIM_SRC_FMI3_VALUES_HPP

#include <cstddef>
#include <string>
#include <vector>

#include "fmi3_fmu.hpp"
#include "stride/cosim/component.hpp"

namespace stride::cosim::fmi3 {

class value_io {
 public:
  /// One port of a call: an element of a variable and its place in the value_block.
  struct touch {
    std::size_t variable;
    std::size_t element;
    variable_type channel;
    std::size_t position;  // in the channel's list of the value_block
  };

  /// `check` throws for a failing status, naming the function.
  using checker = call_checker;

  value_io(const binary& bin, std::string component_name, checker check, void* context);

  void set(fmi3Instance instance, const variable_refs& refs, const value_block& values);
  void get(fmi3Instance instance, const variable_refs& refs, value_block& values);
  /// Re-reads the copies of the settable arrays (after the FMU state was replaced).
  void refresh(fmi3Instance instance);

 private:
  std::vector<touch> touches(const variable_refs& refs) const;
  void set_variables(fmi3Instance instance, const std::vector<std::size_t>& variables);
  void get_variables(fmi3Instance instance, const std::vector<std::size_t>& variables);
  void store(const touch& t, const value_block& values);
  void load(const touch& t, value_block& values) const;
  [[noreturn]] void range_error(const touch& t, const std::string& value,
                                const std::string& target) const;
  std::string port_name(const touch& t) const;

  const binary& bin_;
  const description& d_;
  std::string name_;
  checker check_;
  void* context_;
  std::vector<std::vector<std::byte>> cells_;    // numeric and Boolean elements, per variable
  std::vector<std::vector<std::string>> texts_;  // String and (raw) Binary elements
  std::vector<std::byte> scratch_;
  std::vector<fmi3ValueReference> vrs_;
};

}  // namespace stride::cosim::fmi3

#endif  // STRIDE_COSIM_SRC_FMI3_VALUES_HPP
