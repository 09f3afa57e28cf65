// Components with a `worker` attribute run on that worker process (`stride worker`): the FMU
// archive is shipped to it once per content, and a proxy stands in for the instance here.
#ifndef STRIDE_REMOTE_REMOTE_PLACEMENT_HPP
#define STRIDE_REMOTE_REMOTE_PLACEMENT_HPP

#include <map>
#include <memory>
#include <set>
#include <string>

#include "stride/cosim/placement.hpp"
#include "stride/remote/settings.hpp"

namespace stride::remote {

class client;

class remote_placement final : public cosim::placement_resolver {
 public:
  explicit remote_placement(dds_settings settings, timeouts limits = {});
  ~remote_placement() override;

  /// The proxy of a component with a worker, nullptr for one without. Joins the domain on first
  /// use. \throws cosim::fmu_import_error for an FMU that cannot be read or that the worker
  /// rejects, cosim::component_error for a worker that cannot be reached; both name the
  /// component, its file and line, and the worker.
  std::unique_ptr<cosim::component> create(const cosim::component_spec& spec,
                                           const cosim::placement_context& context) override;
  std::filesystem::path source_of(const cosim::component_spec& spec) const override;
  /// A group stepping on the members' worker, when all are proxies this placement made for one
  /// worker; nullptr otherwise.
  std::unique_ptr<cosim::step_group> create_group(
      const std::vector<cosim::component*>& members) override;

 private:
  dds_settings settings_;
  timeouts limits_;
  std::shared_ptr<client> link_;
  std::map<std::string, std::filesystem::path> files_;     // component name → FMU file
  std::set<std::pair<std::string, std::string>> shipped_;  // (worker, content hash)
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REMOTE_PLACEMENT_HPP
