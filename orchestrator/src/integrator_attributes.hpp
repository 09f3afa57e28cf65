// The integrator of a Model Exchange component as attributes (solver, method, rtol, atol,
// max_step; docs/system-xml.md): read and written alike by the system XML and by Stride's
// component annotation in SSP files (docs/ssp.md).
#ifndef STRIDE_COSIM_SRC_INTEGRATOR_ATTRIBUTES_HPP
#define STRIDE_COSIM_SRC_INTEGRATOR_ATTRIBUTES_HPP

#include <tinyxml2.h>

#include <functional>
#include <string>

#include "stride/cosim/system_structure.hpp"

namespace stride::cosim::detail {

/// Says what is wrong with the element being read; must throw.
using attribute_failure = std::function<void(const std::string& message)>;

/// Whether `e` has any of the integrator attributes.
bool has_integrator_attributes(const tinyxml2::XMLElement& e);

/// Reads the integrator attributes of `e` into `c.model_exchange` when it has any; refused for
/// a component of kind "co-simulation", and for values out of range.
void read_integrator(const tinyxml2::XMLElement& e, component_spec& c,
                     const attribute_failure& fail);

/// Writes `o` as the attributes read_integrator reads back to the same options.
void write_integrator(tinyxml2::XMLElement& e, const model_exchange_options& o);

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_SRC_INTEGRATOR_ATTRIBUTES_HPP
