// The Model Exchange runner: an FMI 2.0 Model Exchange instance integrated by an ode_solver,
// presented to the algorithm as a component like a Co-Simulation instance
// (docs/model-exchange.md).
#ifndef STRIDE_COSIM_ME_COMPONENT_HPP
#define STRIDE_COSIM_ME_COMPONENT_HPP

#include <memory>
#include <string>

#include "stride/cosim/component.hpp"
#include "stride/cosim/fmu.hpp"

namespace stride::cosim {

/// Instantiates `owner`'s Model Exchange interface (options.model_exchange, or defaults).
/// \throws component_error naming the instance when the FMU lacks a function or refuses.
std::unique_ptr<component> instantiate_model_exchange(std::shared_ptr<fmu> owner,
                                                      const std::string& instance_name,
                                                      const instance_options& options);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ME_COMPONENT_HPP
