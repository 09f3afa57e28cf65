// Picks the reader of a system file by what the path is: Stride's system XML, an SSP archive,
// folder or SSD, or an OSP system structure (docs/ssp.md).
#include "stride/cosim/system_import.hpp"

#include "import_xml.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

namespace {

constexpr const char* k_ssd_file = "SystemStructure.ssd";
constexpr const char* k_osp_file = "OspSystemStructure.xml";

// the local name of the root element; "" when the file is no XML tinyxml2 can read (the
// system XML reader then says what is wrong)
std::string root_name(const fs::path& file) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) {
    return {};
  }
  return std::string(detail::xml_file::local(*doc.RootElement()));
}

system_structure load_archive(const fs::path& archive, const log_sink& log) {
  auto dir = std::make_shared<const temp_dir>("stride-ssp-");
  try {
    extract_archive(archive, dir->path());
  } catch (const fmu_import_error& e) {
    throw validation_error(e.what());
  }
  const fs::path ssd = dir->path() / k_ssd_file;
  if (!fs::is_regular_file(ssd)) {
    throw validation_error(archive.string() + ": no " + k_ssd_file +
                           " at the root of the archive (an SSP's default system)");
  }
  system_structure s = detail::import_ssd(ssd, (archive / k_ssd_file).string(), dir->path(), log);
  s.extracted = std::move(dir);
  return s;
}

}  // namespace

system_format detect_system_format(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) {
    if (fs::is_regular_file(path / k_ssd_file, error)) return system_format::ssp_folder;
    if (fs::is_regular_file(path / k_osp_file, error)) return system_format::osp;
    throw validation_error(path.string() + ": a folder holding neither " + k_ssd_file +
                           " (SSP) nor " + k_osp_file + " (OSP)");
  }
  if (!fs::exists(path, error)) {
    throw validation_error(path.string() + ": cannot open the system file");
  }
  const std::string extension = text::lower(path.extension().string());
  if (extension == ".ssp") return system_format::ssp_archive;
  if (extension == ".ssd") return system_format::ssd;
  if (path.filename() == k_osp_file || root_name(path) == "OspSystemStructure") {
    return system_format::osp;
  }
  return system_format::stride_xml;
}

system_structure load_system_file(const fs::path& path, const log_sink& log) {
  switch (detect_system_format(path)) {
    case system_format::ssp_archive:
      return load_archive(path, log);
    case system_format::ssp_folder:
      return detail::import_ssd(path / k_ssd_file, (path / k_ssd_file).string(), {}, log);
    case system_format::ssd:
      return detail::import_ssd(path, path.string(), {}, log);
    case system_format::osp: {
      const fs::path file = fs::is_directory(path) ? path / k_osp_file : path;
      return detail::import_osp(detail::xml_file(file, file.string()));
    }
    case system_format::stride_xml:
      break;
  }
  return parse_system_file(path);
}

}  // namespace stride::cosim
