// Exceptions thrown by libstride. Every message names the file, line, component or variable at
// fault, in one line.
#ifndef STRIDE_COSIM_ERROR_HPP
#define STRIDE_COSIM_ERROR_HPP

#include <stdexcept>
#include <string>

namespace stride::cosim {

/// Base class of all libstride errors.
class error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A system description (XML or C++ API) is malformed or inconsistent: unknown names, type or
/// causality mismatches, inputs driven twice, algebraic loops.
class validation_error : public error {
 public:
  using error::error;
};

/// An FMU could not be imported: bad archive, bad modelDescription.xml, missing binary or symbol.
class fmu_import_error : public error {
 public:
  using error::error;
};

/// A component call failed during a run; the message names component, function and time.
class component_error : public error {
 public:
  using error::error;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ERROR_HPP
