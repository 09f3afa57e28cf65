// How a Model Exchange FMU is integrated when it runs as a component (docs/model-exchange.md).
#ifndef STRIDE_COSIM_MODEL_EXCHANGE_HPP
#define STRIDE_COSIM_MODEL_EXCHANGE_HPP

#include <optional>

namespace stride::cosim {

/// The integrator of a Model Exchange component and its settings.
struct model_exchange_options {
  enum class solver_kind { cvode, euler };
  enum class method_kind { bdf, adams };  ///< CVODE's linear multistep family

  solver_kind solver = solver_kind::cvode;
  method_kind method = method_kind::bdf;
  /// relative tolerance; empty = DefaultExperiment/@tolerance, else 1e-6
  std::optional<double> rtol;
  /// absolute tolerance (scaled by each state's nominal); empty = rtol
  std::optional<double> atol;
  /// largest internal step in seconds; the fixed step of explicit Euler (required there)
  std::optional<double> max_step;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_MODEL_EXCHANGE_HPP
