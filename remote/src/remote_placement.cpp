#include "stride/remote/remote_placement.hpp"

#include <fstream>
#include <iterator>

#include "client.hpp"
#include "remote_component.hpp"
#include "remote_group.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::remote {

namespace fs = std::filesystem;

namespace {

std::vector<std::byte> read_bytes(const fs::path& file, std::uint64_t limit) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw cosim::fmu_import_error("cannot read " + file.string());
  std::vector<char> text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.size() > limit) {
    throw cosim::fmu_import_error(file.string() + " is larger than the import limit");
  }
  const auto* p = reinterpret_cast<const std::byte*>(text.data());
  return {p, p + text.size()};
}

// the model description only: the binary stays unloaded here
cosim::model_description describe(const fs::path& file, const cosim::fmu_import_options& import) {
  cosim::temp_dir dir("stride-remote-", import.extract_root);
  cosim::extract_archive(file, dir.path(), import.limits);
  const fs::path md = dir.path() / "modelDescription.xml";
  if (!fs::is_regular_file(md)) {
    throw cosim::fmu_import_error(file.string() + ": no modelDescription.xml at the archive root");
  }
  return cosim::parse_model_description(md);
}

}  // namespace

remote_placement::remote_placement(dds_settings settings, timeouts limits)
    : settings_(std::move(settings)), limits_(limits) {}

remote_placement::~remote_placement() = default;

std::unique_ptr<cosim::component> remote_placement::create(
    const cosim::component_spec& spec, const cosim::placement_context& context) {
  if (spec.worker.empty()) return nullptr;
  const std::string where = (spec.where.str().empty() ? std::string() : spec.where.str() + ": ") +
                            "component '" + spec.name + "' on worker '" + spec.worker + "': ";
  const fs::path file = cosim::resolve_fmu(spec, *context.system, context.fmu_search_path);
  std::vector<std::byte> archive;
  cosim::model_description description;
  std::string hash;
  std::optional<cosim::model_exchange_options> model_exchange;
  try {
    archive = read_bytes(file, context.import.limits.max_total_size);
    hash = content_hash(archive);
    description = describe(file, context.import);
    // the kind and the integrator settings travel with the instantiate request
    model_exchange = cosim::model_exchange_choice(spec, description, file);
  } catch (const cosim::error& e) {
    throw cosim::fmu_import_error(where + e.what());
  }
  try {
    if (!link_) link_ = std::make_shared<client>(settings_, limits_);
    const dds_entity_t writer = link_->connect(spec.worker);
    if (shipped_.insert({spec.worker, hash}).second) {
      // ask first: a worker that has the archive from an earlier run keeps it
      stride_remote_request r{};
      r.op = static_cast<std::int32_t>(op::load);
      r.component = const_cast<char*>(spec.name.c_str());
      r.text = hash.data();
      reply_data reply = link_->call(writer, spec.worker, r);
      if (reply.result == status::need_archive) {
        put_blob(archive, r.blob);
        reply = link_->call(writer, spec.worker, r);
      }
      if (reply.result != status::ok) {
        shipped_.erase({spec.worker, hash});
        throw cosim::fmu_import_error(where + "the worker cannot load " + file.string() + ": " +
                                      reply.message);
      }
    }
    auto c = std::make_unique<remote_component>(link_, spec.worker, spec.name, hash,
                                                std::move(description), context.log,
                                                context.fmu_debug_logging, model_exchange);
    files_[spec.name] = fs::absolute(file);
    return c;
  } catch (const cosim::error&) {
    throw;
  } catch (const std::exception& e) {
    throw cosim::component_error(where + e.what());
  }
}

std::unique_ptr<cosim::step_group> remote_placement::create_group(
    const std::vector<cosim::component*>& members) {
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

fs::path remote_placement::source_of(const cosim::component_spec& spec) const {
  const auto it = files_.find(spec.name);
  return it == files_.end() ? fs::path() : it->second;
}

}  // namespace stride::remote
