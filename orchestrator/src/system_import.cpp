// Picks the reader of a system file by what the path is: Stride's system XML, an SSP archive,
// folder or SSD, or an OSP system structure (docs/ssp.md).
#include "stride/cosim/system_import.hpp"

#include <algorithm>

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

// the .ssd files at the root of an SSP archive's or folder's tree, sorted
std::vector<std::string> descriptions_in(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    if (entry.is_regular_file(error) && text::lower(entry.path().extension().string()) == ".ssd") {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

// The system structure description `ssd` (a file name at the root) of the SSP tree in `dir`,
// shown as `shown`/`ssd`.
system_structure load_ssd_in(const fs::path& dir, const fs::path& shown, const std::string& ssd,
                             const fs::path& root, const log_sink& log) {
  const std::vector<std::string> descriptions = descriptions_in(dir);
  if (!fs::is_regular_file(dir / ssd)) {
    std::string message = shown.string() + ": no " + ssd + " at its root";
    if (ssd == k_ssd_file) message += " (an SSP's default system)";
    if (!descriptions.empty()) {
      message += "; the .ssd files there: " + listed(descriptions) + " (pick one as " +
                 shown.string() + "/NAME.ssd or with --ssd NAME)";
    }
    throw validation_error(message);
  }
  system_structure s = detail::import_ssd(dir / ssd, (shown / ssd).string(), root, log);
  s.notes.descriptions = descriptions;
  return s;
}

system_structure load_archive(const fs::path& archive, const std::string& ssd,
                              const log_sink& log) {
  auto dir = std::make_shared<const temp_dir>("stride-ssp-");
  try {
    extract_archive(archive, dir->path());
  } catch (const fmu_import_error& e) {
    throw validation_error(e.what());
  }
  system_structure s = load_ssd_in(dir->path(), archive, ssd, dir->path(), log);
  s.extracted = std::move(dir);
  return s;
}

// "x.ssp/Other.ssd": an SSD other than the default inside the archive x.ssp
bool names_ssd_in_archive(const fs::path& path) {
  std::error_code error;
  return text::lower(path.extension().string()) == ".ssd" &&
         text::lower(path.parent_path().extension().string()) == ".ssp" &&
         fs::is_regular_file(path.parent_path(), error);
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
  if (names_ssd_in_archive(path)) return system_format::ssp_archive;
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
      if (names_ssd_in_archive(path)) {
        return load_archive(path.parent_path(), path.filename().string(), log);
      }
      return load_archive(path, k_ssd_file, log);
    case system_format::ssp_folder:
      return load_ssd_in(path, path, k_ssd_file, {}, log);
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
