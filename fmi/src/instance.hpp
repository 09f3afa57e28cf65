// One FMU instance as the glue sees it: the component model, its lifecycle state, time and the
// importer's logger. The same instance serves the FMI 2.0 glue (glue.cpp) and the FMI 3.0 glue
// (glue3*.cpp); only the way a message reaches the importer differs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lifecycle.hpp"
#include "stride/sdk/fmu.hpp"

namespace stride::sdk::glue {

/// Delivers one message to the importer's logging callback (fmi2CallbackLogger or
/// fmi3LogMessageCallback); empty when the importer gave none.
using log_sink = std::function<void(log_level, const char* category, const std::string& message)>;

/// Logger with the FMI debug-category filter, forwarding to the importer through a log_sink.
class fmi_logger final : public logger {
 public:
  explicit fmi_logger(log_sink sink) : sink_(std::move(sink)) {}

  bool enabled(const char* category) const override;
  void log(log_level level, const char* category, const std::string& message) override;

  /// fmi2SetDebugLogging; returns the first unknown category name, or "" when all are known.
  std::string set_debug_logging(bool on, const std::vector<std::string>& categories,
                                const std::vector<std::string>& known);
  bool calls_enabled() const { return calls_; }
  void enable_all(bool on);

 private:
  log_sink sink_;
  bool all_ = false;
  bool calls_ = false;
  std::vector<std::string> enabled_;  // a handful of names: a vector beats a set here
};

/// A saved FMU state: serialised bytes, so get/set and (de)serialisation share one format.
struct saved_state {
  std::vector<std::byte> bytes;
};

/// An FMU definition as the glue keeps it: loaded once, with its GUID.
struct loaded_fmu {
  std::shared_ptr<const fmu_definition> fmu;
  std::string guid;
};

struct instance {
  instance(const loaded_fmu& definition, std::string name, std::string resource_dir, log_sink sink);

  const loaded_fmu& loaded;
  const fmu_definition& fmu;
  fmi_logger log;
  instance_context context;
  std::unique_ptr<model> component;
  char* data = nullptr;  // base of the component's value storage
  std::uint32_t state = instantiated;
  time_ns time = 0;
  std::optional<time_ns> stop_time;  // the importer's stopTime, when it defined one
  bool terminate_requested = false;
  bool values_dirty = true;
  std::set<saved_state*> saved_states;  // every FMUstate handed out and not yet freed

  void create_component();
};

}  // namespace stride::sdk::glue
