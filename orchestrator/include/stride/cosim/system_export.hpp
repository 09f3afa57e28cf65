// Writing a system in the exchange formats Stride reads (docs/ssp.md, "Export"): an SSP 1.0
// archive (.ssp) or an OSP system structure folder. What the format cannot say is refused with
// a message naming it; what it can is written so that Stride's importers read back the same
// system, and the same system always gives the same bytes.
#ifndef STRIDE_COSIM_SYSTEM_EXPORT_HPP
#define STRIDE_COSIM_SYSTEM_EXPORT_HPP

#include <filesystem>
#include <string>
#include <vector>

#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

struct export_options {
  /// Replace an existing archive, or write into a non-empty folder (files of the same name are
  /// replaced); otherwise either is an error.
  bool overwrite = false;
  /// Where bundled FMU names ("gait") are looked up, as for a run.
  std::vector<std::filesystem::path> fmu_search_path = default_fmu_search_path();
};

/// What an export wrote: the archive or folder, and the files in it (relative, in order).
struct export_report {
  std::filesystem::path target;
  std::vector<std::string> files;
};

/// Writes `system` as the SSP 1.0 archive `archive` (which must end in .ssp): SystemStructure.ssd,
/// the FMUs under resources/ and the parameter values as resources/parameters.ssv; replica groups
/// expanded into their copies ("gait[1]", ...); base step, algorithm, recording, agents,
/// connection delays and workers as Stride's annotations.
/// \throws validation_error naming the system file, line and what cannot be exported.
export_report export_ssp(const system_structure& system, const std::filesystem::path& archive,
                         const export_options& options = {});

/// Writes `system` as OspSystemStructure.xml with its FMUs into the folder `folder` (created
/// when missing). \throws validation_error as export_ssp.
export_report export_osp(const system_structure& system, const std::filesystem::path& folder,
                         const export_options& options = {});

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_SYSTEM_EXPORT_HPP
