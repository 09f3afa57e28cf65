// The Model Exchange runner: a Model Exchange instance (FMI 2.0 or 3.0, me_instance.hpp)
// integrated by an ode_solver and presented to the algorithm as a component like a
// Co-Simulation instance (docs/model-exchange.md).
#ifndef STRIDE_COSIM_ME_COMPONENT_HPP
#define STRIDE_COSIM_ME_COMPONENT_HPP

#include <memory>
#include <string>

#include "me_instance.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/fmu.hpp"

namespace stride::cosim {

/// The runner around `instance` (options.model_exchange, or defaults).
/// \throws component_error naming the instance for unusable solver settings.
std::unique_ptr<component> run_model_exchange(std::unique_ptr<detail::me_instance> instance,
                                              const std::string& instance_name,
                                              const instance_options& options);

/// An FMI 2.0 Model Exchange instance of `owner` (fmi2_me_instance.cpp).
/// \throws component_error naming the instance when the FMU lacks a function or refuses.
std::unique_ptr<detail::me_instance> instantiate_fmi2_model_exchange(
    std::shared_ptr<fmu> owner, const std::string& instance_name, const instance_options& options);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_ME_COMPONENT_HPP
