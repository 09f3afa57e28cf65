// Where a component runs: a resolver turns a component spec into a component. In-process FMU
// import is the default; resolvers for other placements (worker processes) plug in beside it.
#ifndef STRIDE_COSIM_PLACEMENT_HPP
#define STRIDE_COSIM_PLACEMENT_HPP

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/step_group.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

/// What a resolver may need besides the spec.
struct placement_context {
  const system_structure* system = nullptr;
  std::vector<std::filesystem::path> fmu_search_path;
  fmu_import_options import;
  log_sink log;
  bool fmu_debug_logging = false;
};

/// Creates the components of the specs it is responsible for.
class placement_resolver {
 public:
  virtual ~placement_resolver() = default;
  /// Called once with the whole system before any component is created, so that slow work of
  /// this placement (e.g. joining a network) can go on while the others import their FMUs.
  /// Must not throw: an error belongs to create(), with the spec it concerns.
  virtual void prepare(const system_structure& /*system*/) noexcept {}
  /// The component for `spec`, or nullptr when `spec` is not this resolver's placement.
  /// \throws validation_error / fmu_import_error / component_error naming the spec's file and
  /// line.
  virtual std::unique_ptr<component> create(const component_spec& spec,
                                            const placement_context& context) = 0;
  /// The FMU file a created component came from (for reports), empty if none.
  virtual std::filesystem::path source_of(const component_spec& /*spec*/) const { return {}; }
  /// A step group for `members`: components this resolver created for one worker and connected
  /// to each other, which may step there together; nullptr when they step one by one.
  virtual std::unique_ptr<step_group> create_group(const std::vector<component*>& /*members*/) {
    return nullptr;
  }
  /// What happened to its components during the run, counted, for the run's manifest (e.g.
  /// "failovers"); empty when nothing is counted.
  virtual std::vector<std::pair<std::string, long>> events() const { return {}; }
};

/// Components made by a function (tests; tools that prepare their components themselves): it
/// takes every spec for which the function returns a component.
class function_placement final : public placement_resolver {
 public:
  using function = std::function<std::unique_ptr<component>(const component_spec&)>;
  explicit function_placement(function make) : make_(std::move(make)) {}
  std::unique_ptr<component> create(const component_spec& spec,
                                    const placement_context& /*context*/) override {
    return make_(spec);
  }

 private:
  function make_;
};

/// How `spec` runs `f`: the Model Exchange settings, or nullopt for Co-Simulation (an FMU
/// offering both runs Co-Simulation unless kind="model-exchange").
/// \throws fmu_import_error when the kind or the solver settings do not fit the FMU.
std::optional<model_exchange_options> model_exchange_choice(const component_spec& spec,
                                                            const fmu& f);
/// The same from the FMU's model description alone (`file` names it in messages): for an FMU
/// that runs elsewhere, e.g. on a worker.
std::optional<model_exchange_options> model_exchange_choice(const component_spec& spec,
                                                            const model_description& md,
                                                            const std::filesystem::path& file);

/// Components without a `worker`: the FMU is imported into this process (each file once,
/// however many instances use it) and instantiated.
class in_process_placement final : public placement_resolver {
 public:
  std::unique_ptr<component> create(const component_spec& spec,
                                    const placement_context& context) override;
  std::filesystem::path source_of(const component_spec& spec) const override;

 private:
  std::map<std::filesystem::path, std::shared_ptr<fmu>> imported_;
  std::map<std::string, std::filesystem::path> files_;  // component name → FMU file
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_PLACEMENT_HPP
