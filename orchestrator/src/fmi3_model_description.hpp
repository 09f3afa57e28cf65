// The FMI 3.0 modelDescription.xml as Stride imports it (docs/fmi3-rules.md §5): the FMU's own
// variables (typed, possibly arrays) and their flattening into Stride's scalar ports, one port per
// array element named `name[1]`, `name[2]`, ... exactly like the elements of Stride's 2.0 FMUs.
#ifndef STRIDE_COSIM_SRC_FMI3_MODEL_DESCRIPTION_HPP
#define STRIDE_COSIM_SRC_FMI3_MODEL_DESCRIPTION_HPP

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/model_description.hpp"

namespace stride::cosim::fmi3 {

/// The FMI 3.0 variable types Stride exchanges (Clock is refused).
enum class kind {
  float32,
  float64,
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  int64,
  uint64,
  boolean,
  string,
  binary,
  enumeration,  ///< exchanged with fmi3Get/SetInt64
};

/// The element name of `k` in modelDescription.xml ("Float64", "UInt8", ...).
std::string_view to_string(kind k) noexcept;

/// One variable as the FMU declares it.
struct variable {
  std::string name;
  value_reference reference = 0;
  stride::cosim::fmi3::kind kind = kind::float64;
  bool structural = false;              ///< causality="structuralParameter"
  bool constant = false;                ///< variability="constant"
  std::vector<std::size_t> dimensions;  ///< resolved sizes; empty for a scalar
  std::vector<std::string> start;       ///< one text per element (hex for Binary); may be empty
  int line = 0;

  /// Number of elements (1 for a scalar).
  std::size_t size() const noexcept;
};

/// One of Stride's scalar ports: an element of a variable.
struct port {
  std::size_t variable = 0;  ///< index into description::variables
  std::size_t element = 0;   ///< row-major, 0-based
};

/// A parsed FMI 3.0 model description. `scalar.variables[i]` is the Stride port `ports[i]`; its
/// value reference is `i` (FMI 3 value references name whole arrays, ports name elements).
struct description {
  stride::cosim::model_description scalar;
  std::vector<variable> variables;
  std::vector<port> ports;
  bool has_event_mode = false;
};

/// The fmiVersion attribute of a modelDescription.xml held in memory ("" when unreadable).
std::string declared_fmi_version(std::string_view xml);

/// Reads an FMI 3.0 modelDescription.xml; `origin` names it in error messages.
/// \throws fmu_import_error naming the origin, the line and the variable.
description parse_description(std::string_view xml, const std::string& origin);

}  // namespace stride::cosim::fmi3

#endif  // STRIDE_COSIM_SRC_FMI3_MODEL_DESCRIPTION_HPP
