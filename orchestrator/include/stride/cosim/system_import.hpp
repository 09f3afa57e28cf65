// One entry point for every system format Stride reads: its own system XML, SSP 1.0 (an .ssp
// archive, a folder holding SystemStructure.ssd, a bare .ssd) and OSP system structures
// (OspSystemStructure.xml). docs/ssp.md says what is read of the foreign formats.
#ifndef STRIDE_COSIM_SYSTEM_IMPORT_HPP
#define STRIDE_COSIM_SYSTEM_IMPORT_HPP

#include <filesystem>

#include "stride/cosim/log.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {

/// The formats load_system_file() tells apart.
enum class system_format {
  stride_xml,   ///< docs/system-xml.md
  ssp_archive,  ///< .ssp: a zip archive with SystemStructure.ssd at its root; "x.ssp/NAME.ssd"
                ///< names another system structure description inside it
  ssp_folder,   ///< a folder holding SystemStructure.ssd
  ssd,          ///< a bare .ssd file
  osp,          ///< an XML file whose root element is OspSystemStructure
};

/// What `path` is, by its kind and name (and for other XML files, the root element).
/// \throws validation_error for a folder without SystemStructure.ssd or OspSystemStructure.xml,
/// or a path that does not exist.
system_format detect_system_format(const std::filesystem::path& path);

/// Reads the system at `path` in whatever format it is. An .ssp is extracted into a temporary
/// folder that lives as long as the returned structure (system_structure::extracted). Messages
/// about names that SSP ignores (a parameter matching no variable) go to `log` (empty: stderr).
/// \throws validation_error naming file, line and element.
system_structure load_system_file(const std::filesystem::path& path, const log_sink& log = {});

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_SYSTEM_IMPORT_HPP
