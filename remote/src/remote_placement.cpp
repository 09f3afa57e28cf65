#include "stride/remote/remote_placement.hpp"

#include <algorithm>
#include <fstream>
#include <mutex>
#include <set>

#include "client.hpp"
#include "failover_component.hpp"
#include "failover_group.hpp"
#include "remote_component.hpp"
#include "remote_group.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::remote {

namespace fs = std::filesystem;

namespace {

// One read into a buffer of the file's size: the robot FMU is 6 MB, and reading it character by
// character took longer than the rest of a secure run's start-up.
std::vector<std::byte> read_bytes(const fs::path& file, std::uint64_t limit) {
  std::error_code error;
  const auto size = fs::file_size(file, error);
  if (error) throw cosim::fmu_import_error("cannot read " + file.string() + ": " + error.message());
  if (size > limit) {
    throw cosim::fmu_import_error(file.string() + " is larger than the import limit");
  }
  std::vector<std::byte> bytes(size);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw cosim::fmu_import_error("cannot read " + file.string());
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (!in || in.gcount() != static_cast<std::streamsize>(size) || in.peek() != EOF) {
    throw cosim::fmu_import_error("cannot read " + file.string() + " (it changed while read)");
  }
  return bytes;
}

// whether the instance of the kind chosen can give state images (failover needs them)
bool saves_state(const cosim::model_description& md, bool model_exchange) {
  if (model_exchange) {
    return md.model_exchange && md.model_exchange->can_get_and_set_fmu_state &&
           md.model_exchange->can_serialize_fmu_state;
  }
  return md.co_simulation && md.co_simulation->can_get_and_set_fmu_state &&
         md.co_simulation->can_serialize_fmu_state;
}

// makes `worker` hold the archive: it keeps one from an earlier run, else it is sent
void ship(client& link, const std::string& worker, const std::string& component,
          const std::string& hash, const std::vector<std::byte>& archive, const fs::path& file) {
  const dds_entity_t writer = link.connect(worker);
  stride_remote_request r{};
  r.op = static_cast<std::int32_t>(op::load);
  r.component = const_cast<char*>(component.c_str());
  r.text = const_cast<char*>(hash.c_str());
  reply_data reply = link.call(writer, worker, r);
  if (reply.result == status::need_archive) {
    put_blob(archive, r.blob);
    reply = link.call(writer, worker, r);
  }
  if (reply.result != status::ok) {
    throw cosim::fmu_import_error("the worker cannot load " + file.string() + ": " + reply.message);
  }
}

}  // namespace

// what it takes to instantiate a component on any worker (a standby's too)
struct instance_recipe {
  std::filesystem::path file;
  std::vector<std::byte> archive;
  std::string hash;
  cosim::model_description description;
  std::optional<cosim::model_exchange_options> model_exchange;
};

// the archives each worker holds, as (worker, content hash)
struct shipped_archives {
  std::mutex mutex;
  std::set<std::pair<std::string, std::string>> pairs;
};

namespace {

// Instances of the recipe on any worker, the archive shipped first where needed. Also called
// during the run, on the thread of a component that fails over: it holds only what outlives the
// placement.
failover_component::factory instance_factory(std::shared_ptr<client> link,
                                             std::shared_ptr<shipped_archives> shipped,
                                             std::shared_ptr<const instance_recipe> recipe,
                                             std::string name, cosim::log_sink log, bool debug) {
  return [=](const std::string& worker) -> std::unique_ptr<cosim::component> {
    {
      std::lock_guard lock(shipped->mutex);
      if (!shipped->pairs.contains({worker, recipe->hash})) {
        ship(*link, worker, name, recipe->hash, recipe->archive, recipe->file);
        shipped->pairs.insert({worker, recipe->hash});
      }
    }
    return std::make_unique<remote_component>(link, worker, name, recipe->hash, recipe->description,
                                              log, debug, recipe->model_exchange);
  };
}

}  // namespace

remote_placement::remote_placement(dds_settings settings, timeouts limits)
    : settings_(std::move(settings)),
      limits_(limits),
      shipped_(std::make_shared<shipped_archives>()) {}

remote_placement::~remote_placement() = default;

void remote_placement::prepare(const cosim::system_structure& system) noexcept {
  const bool remote = std::ranges::any_of(
      system.components, [](const cosim::component_spec& spec) { return !spec.worker.empty(); });
  if (!remote || link_) return;
  try {
    link_ = std::make_shared<client>(settings_, limits_);
  } catch (...) {
    // create() joins again and reports the error with the component it concerns
  }
}

std::unique_ptr<cosim::component> remote_placement::create(
    const cosim::component_spec& spec, const cosim::placement_context& context) {
  if (spec.worker.empty()) return nullptr;
  const std::string where = (spec.where.str().empty() ? std::string() : spec.where.str() + ": ") +
                            "component '" + spec.name + "' on worker '" + spec.worker + "': ";
  const fs::path file = cosim::resolve_fmu(spec, *context.system, context.fmu_search_path);
  auto recipe = std::make_shared<instance_recipe>();
  recipe->file = file;
  try {
    recipe->archive = read_bytes(file, context.import.limits.max_total_size);
    recipe->hash = content_hash(recipe->archive);
    recipe->description = cosim::read_archive_description(file);
    // the kind and the integrator settings travel with the instantiate request
    recipe->model_exchange = cosim::model_exchange_choice(spec, recipe->description, file);
    if (!context.system->failover.standby.empty() &&
        !saves_state(recipe->description, recipe->model_exchange.has_value())) {
      throw cosim::fmu_import_error(
          "cannot fail over to a standby worker (<failover>, --standby): its FMU cannot save "
          "and serialize its state (canGetAndSetFMUstate, canSerializeFMUstate)");
    }
  } catch (const cosim::error& e) {
    throw cosim::fmu_import_error(where + e.what());
  }
  try {
    if (!link_) link_ = std::make_shared<client>(settings_, limits_);
    const failover_component::factory instantiate = instance_factory(
        link_, shipped_, recipe, spec.name, context.log, context.fmu_debug_logging);
    std::unique_ptr<cosim::component> c;
    const cosim::failover_spec& failover = context.system->failover;
    if (failover.standby.empty()) {
      c = instantiate(spec.worker);
    } else {
      if (!standby_) standby_ = std::make_shared<standby_pool>(failover.standby);
      c = failover_component::start(spec.worker, instantiate, standby_,
                                    failover.snapshot_every.value_or(k_default_snapshot_every),
                                    context.log);
    }
    files_[spec.name] = fs::absolute(file);
    return c;
  } catch (const worker_lost& e) {
    throw cosim::component_error(where + e.what());
  } catch (const cosim::fmu_import_error& e) {
    throw cosim::fmu_import_error(where + e.what());
  } catch (const cosim::error&) {
    throw;
  } catch (const std::exception& e) {
    throw cosim::component_error(where + e.what());
  }
}

std::vector<std::pair<std::string, long>> remote_placement::events() const {
  std::vector<std::pair<std::string, long>> counted;
  if (standby_) counted.emplace_back("failovers", standby_->failovers());
  if (link_ && link_->stalls() > 0) counted.emplace_back("stalls", link_->stalls());
  return counted;
}

std::unique_ptr<cosim::step_group> remote_placement::create_group(
    const std::vector<cosim::component*>& members) {
  if (standby_) return create_failover_group(members);
  std::vector<remote_component*> parts;
  for (auto* m : members) {
    auto* part = dynamic_cast<remote_component*>(m);
    if (part == nullptr ||
        part->worker() != dynamic_cast<remote_component*>(members.front())->worker()) {
      return nullptr;
    }
    parts.push_back(part);
  }
  if (parts.empty() || !link_) return nullptr;
  return std::make_unique<remote_group>(link_, parts.front()->worker(), std::move(parts));
}

std::unique_ptr<cosim::step_group> remote_placement::create_failover_group(
    const std::vector<cosim::component*>& members) {
  std::vector<failover_component*> movers;
  for (auto* m : members) {
    auto* mover = dynamic_cast<failover_component*>(m);
    if (mover == nullptr || (!movers.empty() && mover->worker() != movers.front()->worker())) {
      return nullptr;
    }
    movers.push_back(mover);
  }
  if (movers.empty()) return nullptr;
  auto make = [link = link_](const std::vector<cosim::component*>& instances,
                             const std::string& worker) -> std::unique_ptr<cosim::step_group> {
    std::vector<remote_component*> parts;
    for (auto* c : instances) parts.push_back(&dynamic_cast<remote_component&>(*c));
    return std::make_unique<remote_group>(link, worker, std::move(parts));
  };
  return std::make_unique<failover_group>(std::move(movers), make, standby_);
}

fs::path remote_placement::source_of(const cosim::component_spec& spec) const {
  const auto it = files_.find(spec.name);
  return it == files_.end() ? fs::path() : it->second;
}

}  // namespace stride::remote
