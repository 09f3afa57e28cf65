#include "stride/cosim/placement.hpp"

#include <map>
#include <mutex>
#include <string>

#include "stride/cosim/error.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

namespace {

// One import per FMU file and process while any run uses it: concurrent runs (agents, sweeps)
// then share one loaded binary, so process-wide state inside it (ODE's global initialisation in
// the robot) is set up once, by its own thread-safe statics, instead of once per private copy.
std::shared_ptr<fmu> shared_import(const fs::path& file, const fmu_import_options& options) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<fmu>> imported;
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  const auto written = fs::last_write_time(file, ec).time_since_epoch().count();
  // a changed file is imported afresh
  const std::string key = fs::weakly_canonical(file).string() + '\n' + std::to_string(size) + '\n' +
                          std::to_string(written) + '\n' + options.extract_root.string() + '\n' +
                          std::to_string(options.limits.max_entry_size) + ',' +
                          std::to_string(options.limits.max_total_size) + ',' +
                          std::to_string(options.limits.max_entries);
  std::lock_guard lock(mutex);
  if (auto f = imported[key].lock()) return f;
  std::erase_if(imported, [](const auto& entry) { return entry.second.expired(); });
  auto f = fmu::load(file, options);
  imported[key] = f;
  return f;
}

}  // namespace

std::optional<model_exchange_options> model_exchange_choice(const component_spec& spec,
                                                            const model_description& md,
                                                            const fs::path& file) {
  if (spec.kind == "co-simulation" && !md.co_simulation) {
    throw fmu_import_error("kind=\"co-simulation\", but " + file.string() +
                           " offers only Model Exchange");
  }
  if (spec.kind.empty() && spec.model_exchange && md.co_simulation) {
    throw fmu_import_error(file.string() +
                           " offers Co-Simulation, which is used unless kind=\"model-exchange\"; "
                           "solver settings need that kind");
  }
  if (spec.kind == "model-exchange" && !md.model_exchange) {
    throw fmu_import_error("kind=\"model-exchange\", but " + file.string() +
                           " has no <ModelExchange> interface");
  }
  if (spec.kind == "model-exchange" || !md.co_simulation) {
    return spec.model_exchange.value_or(model_exchange_options{});
  }
  return std::nullopt;
}

std::optional<model_exchange_options> model_exchange_choice(const component_spec& spec,
                                                            const fmu& f) {
  return model_exchange_choice(spec, f.model_description(), f.file());
}

std::unique_ptr<component> in_process_placement::create(const component_spec& spec,
                                                        const placement_context& context) {
  if (!spec.worker.empty()) return nullptr;
  const std::string where = spec.where.str().empty() ? std::string() : spec.where.str() + ": ";
  const fs::path file = resolve_fmu(spec, *context.system, context.fmu_search_path);
  auto& f = imported_[fs::weakly_canonical(file)];
  try {
    if (!f) f = shared_import(file, context.import);
    instance_options io;
    io.log = context.log;
    io.logging_on = context.fmu_debug_logging;
    io.model_exchange = model_exchange_choice(spec, *f);
    auto c = f->instantiate(spec.name, io);
    files_[spec.name] = fs::absolute(file);
    return c;
  } catch (const error& e) {
    throw fmu_import_error(where + "component '" + spec.name + "': " + e.what());
  }
}

fs::path in_process_placement::source_of(const component_spec& spec) const {
  const auto it = files_.find(spec.name);
  return it == files_.end() ? fs::path() : it->second;
}

}  // namespace stride::cosim
