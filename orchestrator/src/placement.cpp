#include "stride/cosim/placement.hpp"

#include "stride/cosim/error.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

std::unique_ptr<component> in_process_placement::create(const component_spec& spec,
                                                        const placement_context& context) {
  if (!spec.worker.empty()) return nullptr;
  const std::string where = spec.where.str().empty() ? std::string() : spec.where.str() + ": ";
  const fs::path file = resolve_fmu(spec, *context.system, context.fmu_search_path);
  auto& f = imported_[fs::weakly_canonical(file)];
  try {
    if (!f) f = fmu::load(file, context.import);
    instance_options io;
    io.log = context.log;
    io.logging_on = context.fmu_debug_logging;
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
