// Components with a `worker` attribute run on that worker process (`stride worker`): the FMU
// archive is shipped to it once per content, and a proxy stands in for the instance here.
#ifndef STRIDE_REMOTE_REMOTE_PLACEMENT_HPP
#define STRIDE_REMOTE_REMOTE_PLACEMENT_HPP

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "stride/cosim/placement.hpp"
#include "stride/remote/settings.hpp"

namespace stride::remote {

class client;
class standby_pool;
struct shipped_archives;

/// State images per step of a component with standby workers, when the system sets no
/// snapshot-every (BENCHMARKS.md: what an image costs the walk).
inline constexpr int k_default_snapshot_every = 100;

class remote_placement final : public cosim::placement_resolver {
 public:
  explicit remote_placement(dds_settings settings, timeouts limits = {});
  ~remote_placement() override;

  /// Joins the domain now when a component of `system` has a worker: DDS discovery and, with DDS
  /// Security, the handshakes (which hold a fixed 0.1 s wait in Cyclone DDS) then go on while
  /// the in-process components are imported. A failure is left for create() to report.
  void prepare(const cosim::system_structure& system) noexcept override;
  /// The proxy of a component with a worker, nullptr for one without. Joins the domain on first
  /// use. With standby workers (the system's <failover>) the proxy fails over to one of them when
  /// its worker is lost (docs/failover.md). \throws cosim::fmu_import_error for an FMU that cannot
  /// be read or that the worker rejects, cosim::component_error for a worker that cannot be
  /// reached; both name the component, its file and line, and the worker.
  std::unique_ptr<cosim::component> create(const cosim::component_spec& spec,
                                           const cosim::placement_context& context) override;
  std::filesystem::path source_of(const cosim::component_spec& spec) const override;
  /// A group stepping on the members' worker, when all are proxies this placement made for one
  /// worker; with standby workers, a group that fails over with its members. nullptr otherwise.
  std::unique_ptr<cosim::step_group> create_group(
      const std::vector<cosim::component*>& members) override;
  /// "failovers": the workers lost and replaced so far.
  std::vector<std::pair<std::string, long>> events() const override;

 private:
  std::unique_ptr<cosim::step_group> create_failover_group(
      const std::vector<cosim::component*>& members);

  dds_settings settings_;
  timeouts limits_;
  std::shared_ptr<client> link_;
  std::map<std::string, std::filesystem::path> files_;  // component name → FMU file
  std::shared_ptr<shipped_archives> shipped_;
  std::shared_ptr<standby_pool> standby_;
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REMOTE_PLACEMENT_HPP
