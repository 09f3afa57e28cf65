// `stride worker`: a process that hosts component instances for orchestrators on the same DDS
// domain (docs/distributed.md), and the list of workers a domain has.
#ifndef STRIDE_REMOTE_WORKER_HPP
#define STRIDE_REMOTE_WORKER_HPP

#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "stride/cosim/fmu.hpp"
#include "stride/remote/allow_list.hpp"
#include "stride/remote/settings.hpp"

namespace stride::remote {

struct worker_options {
  std::string name;  ///< unique on the domain; empty = "<host>-<pid>"
  dds_settings dds;
  cosim::fmu_import_options import;  ///< how shipped FMUs are unpacked (same checks as locally)
  std::FILE* log = stderr;           ///< the ready line and one line per run begun and ended
  /// The FMU archives it accepts, by SHA-256; nullopt: any. Others are refused before their
  /// bytes are written anywhere.
  std::optional<fmu_allow_list> allowed_fmus;
};

/// Announces the worker and serves requests until `stop` becomes true (checked every 100 ms),
/// then withdraws. Instances of a run go away when the run ends or its orchestrator vanishes;
/// the worker outlives failed runs. \throws std::runtime_error when the domain cannot be joined
/// or another worker of that name is already there.
void serve(const worker_options& options, const std::atomic<bool>& stop);

struct worker_description {
  std::string name;
  std::string host;
  long long pid = 0;
  std::string version;
};

/// The workers announced on the domain, after waiting `discovery` for announcements to arrive.
std::vector<worker_description> visible_workers(const dds_settings& dds,
                                                std::chrono::milliseconds discovery);

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_WORKER_HPP
