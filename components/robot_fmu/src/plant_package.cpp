// `stride robot-fmu`: stage resources/, generate modelDescription.xml from them with the same
// code the FMU binary runs, and zip it all with the binaries of a built plant FMU.
#include "stride/robot/plant_package.hpp"

#include <tinyxml2.h>
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "stride/robot/plant_fmu.hpp"
#include "stride/robot/resource_path.hpp"
#include "stride/robot/robot_model.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::robot {

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& content) {
  std::ofstream out(p, std::ios::binary);
  out << content;
  if (!out) throw std::runtime_error(p.string() + ": cannot write");
}

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = std::strtoll(epoch, nullptr, 10);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return stamp;
}

// a private staging folder, removed with everything in it
class staging_dir {
 public:
  staging_dir() {
    std::string pattern = (fs::temp_directory_path() / "stride-plant-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temp folder");
    path_ = pattern;
  }
  ~staging_dir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  staging_dir(const staging_dir&) = delete;
  staging_dir& operator=(const staging_dir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// entries of an archive being written; libzip reads the buffers when it closes the archive
class zip_writer {
 public:
  explicit zip_writer(const std::string& path) : path_(path) {
    int error = 0;
    archive_ = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (archive_ == nullptr) throw std::runtime_error(path + ": cannot create the archive");
  }
  ~zip_writer() {
    if (archive_ != nullptr) zip_discard(archive_);
  }
  zip_writer(const zip_writer&) = delete;
  zip_writer& operator=(const zip_writer&) = delete;

  void add(const std::string& name, std::string content, bool executable = false) {
    contents_.push_back(std::make_unique<std::string>(std::move(content)));
    const std::string& data = *contents_.back();
    add_source(name, zip_source_buffer(archive_, data.data(), data.size(), 0), executable);
  }

  /// Entry `index` of the open archive `from`, copied as it is compressed there (`from` must stay
  /// open until close()).
  void add_copy(const std::string& name, zip_t* from, zip_uint64_t index, bool executable) {
    add_source(name, zip_source_zip(archive_, from, index, ZIP_FL_COMPRESSED, 0, -1), executable);
  }

  void close() {
    if (zip_close(archive_) != 0) {
      const std::string why = zip_strerror(archive_);
      throw std::runtime_error(path_ + ": cannot write the archive (" + why + ")");
    }
    archive_ = nullptr;
  }

 private:
  void add_source(const std::string& name, zip_source_t* source, bool executable) {
    const zip_int64_t index =
        source ? zip_file_add(archive_, name.c_str(), source, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8)
               : -1;
    if (index < 0) {
      if (source) zip_source_free(source);
      throw std::runtime_error(path_ + ": cannot add " + name + " (" + zip_strerror(archive_) +
                               ")");
    }
    const auto i = static_cast<zip_uint64_t>(index);
    // a fixed time and mode: the same inputs give the same archive
    zip_file_set_mtime(archive_, i, 315532800, 0);  // 1980-01-01, the zip epoch
    const zip_uint32_t mode = executable ? 0100755 : 0100644;
    zip_file_set_external_attributes(archive_, i, 0, ZIP_OPSYS_UNIX, mode << 16);
  }

  std::string path_;
  zip_t* archive_ = nullptr;
  std::vector<std::unique_ptr<std::string>> contents_;
};

// A built plant FMU, open for its binaries/<platform>/* (the model's library renamed after
// `identifier`): entries to copy as they are.
class plant_binaries {
 public:
  plant_binaries(const std::string& fmu, const std::string& identifier) {
    int error = 0;
    archive_ = zip_open(fmu.c_str(), ZIP_RDONLY, &error);
    if (archive_ == nullptr) {
      throw std::runtime_error(fmu + ": cannot open the plant FMU whose binaries are packaged");
    }
    std::string own;  // the template's identifier names its library
    const zip_int64_t n = zip_get_num_entries(archive_, 0);
    for (zip_int64_t i = 0; i < n; ++i) {
      const auto index = static_cast<zip_uint64_t>(i);
      const std::string name = zip_get_name(archive_, index, 0);
      if (name == "modelDescription.xml") {
        own = identifier_in(fmu, index);
      } else if (name.starts_with("binaries/") && name.back() != '/') {
        entries_.emplace_back(name, index);
      }
    }
    if (own.empty() || entries_.empty()) {
      zip_discard(archive_);
      throw std::runtime_error(fmu +
                               ": not a plant FMU with binaries (no modelIdentifier or no "
                               "binaries/)");
    }
    for (auto& [name, index] : entries_) {
      const fs::path p(name);
      if (p.stem() == own &&
          (p.extension() == ".so" || p.extension() == ".dll" || p.extension() == ".dylib")) {
        name = (p.parent_path() / (identifier + p.extension().string())).generic_string();
      }
    }
    std::sort(entries_.begin(), entries_.end());
  }
  ~plant_binaries() { zip_discard(archive_); }
  plant_binaries(const plant_binaries&) = delete;
  plant_binaries& operator=(const plant_binaries&) = delete;

  void copy_into(zip_writer& zip) const {
    for (const auto& [name, index] : entries_) zip.add_copy(name, archive_, index, true);
  }

 private:
  std::string identifier_in(const std::string& fmu, zip_uint64_t index) const {
    zip_stat_t st;
    zip_stat_index(archive_, index, 0, &st);
    std::string xml(static_cast<std::size_t>(st.size), '\0');
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> f(zip_fopen_index(archive_, index, 0),
                                                        zip_fclose);
    if (!f || zip_fread(f.get(), xml.data(), st.size) != static_cast<zip_int64_t>(st.size)) {
      throw std::runtime_error(fmu + ": cannot read modelDescription.xml");
    }
    const auto at = xml.find("modelIdentifier=\"");
    if (at == std::string::npos) return {};
    return xml.substr(at + 17, xml.find('"', at + 17) - (at + 17));
  }

  zip_t* archive_ = nullptr;
  std::vector<std::pair<std::string, zip_uint64_t>> entries_;
};

// Folder of resources/ for the files named package://NAME/...; the FMU searches it for them.
constexpr const char* k_packages = "packages";

// Copies every file the URDF's collisions name into `resources` where the packaged URDF finds
// it: package://NAME/REST under packages/NAME/REST, a relative name at the same relative place.
// Returns whether any package:// name was copied.
bool stage_urdf_files(const plant_fmu_request& r, const fs::path& resources) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(r.urdf.c_str()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error(r.urdf + ": cannot read as XML (" + doc.ErrorStr() + ")");
  }
  const std::string base = fs::path(r.urdf).parent_path().string();
  const char* ros = std::getenv("ROS_PACKAGE_PATH");
  const std::vector<std::string> search = package_search_path(r.package_path, ros);
  bool packages = false;
  const tinyxml2::XMLElement* robot = doc.RootElement();
  for (const auto* link = robot ? robot->FirstChildElement("link") : nullptr; link;
       link = link->NextSiblingElement("link")) {
    for (const auto* c = link->FirstChildElement("collision"); c;
         c = c->NextSiblingElement("collision")) {
      const auto* g = c->FirstChildElement("geometry");
      const auto* mesh = g ? g->FirstChildElement("mesh") : nullptr;
      const char* name = mesh ? mesh->Attribute("filename") : nullptr;
      if (name == nullptr) continue;
      const std::string uri = name;
      const std::string from = resolve_resource(uri, base, search);
      fs::path to;
      if (uri.starts_with("package://")) {
        to = fs::path(k_packages) / uri.substr(10);
        packages = true;
      } else {
        to = fs::path(uri.starts_with("file://") ? uri.substr(7) : uri).lexically_normal();
        if (to.is_absolute() || to.empty() || *to.begin() == "..") {
          throw std::runtime_error(r.urdf + ": link '" +
                                   (link->Attribute("name") ? link->Attribute("name") : "") +
                                   "': mesh '" + uri +
                                   "' cannot travel in an FMU: name it relative to the URDF's "
                                   "folder (inside it) or as package://");
        }
      }
      fs::create_directories((resources / to).parent_path());
      write_file(resources / to, read_file(from));
    }
  }
  return packages;
}

}  // namespace

std::string model_identifier_from(const std::string& name) {
  if (name.empty()) throw std::invalid_argument("an empty model name");
  std::string id;
  for (char c : name) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (std::isdigit(static_cast<unsigned char>(id[0]))) id = "_" + id;
  return id;
}

plant_fmu_result write_plant_fmu(const plant_fmu_request& r) {
  const fs::path urdf(r.urdf);
  const fs::path output(r.output);
  if (output.extension() != ".fmu") throw std::invalid_argument(r.output + ": must end in .fmu");
  const std::string name = r.model_name.empty() ? output.stem().string() : r.model_name;
  plant_manifest manifest;
  manifest.model_name = name;
  manifest.model_identifier = model_identifier_from(name);
  manifest.description =
      r.description.empty() ? name + " (" + urdf.filename().string() + ") on ODE" : r.description;
  manifest.urdf = urdf.filename().string();

  staging_dir staging;
  const fs::path resources = staging.path() / "resources";
  fs::create_directories(resources);
  // the URDF must load where it is (its relative paths) before it is staged
  model_options options;
  options.package_path = r.package_path;
  (void)load_robot_model(r.urdf, options);
  write_file(resources / manifest.urdf, read_file(urdf));
  if (stage_urdf_files(r, resources)) manifest.package_path.push_back(k_packages);
  if (!r.profile.empty()) {
    manifest.profile = fs::path(r.profile).filename().string();
    if (manifest.profile == manifest.urdf || manifest.profile == k_plant_manifest) {
      manifest.profile = "profile.xml";
    }
    write_file(resources / manifest.profile, read_file(r.profile));
  }
  write_file(resources / k_plant_manifest, write_plant_manifest(manifest));

  plant_fmu_result result;
  const auto fmu = load_plant_fmu(resources.string(), &result.warnings);
  result.guid = sdk::compute_guid(*fmu);
  result.variables = fmu->table.variables().size();
  for (const sdk::variable& v : fmu->table.variables()) {
    if (v.name.starts_with("joint_target[")) ++result.joints;
  }
  const std::string description =
      sdk::write_model_description(*fmu, r.generation_time.empty() ? utc_now() : r.generation_time);

  const plant_binaries binaries(r.binaries_from, manifest.model_identifier);
  if (!output.parent_path().empty()) fs::create_directories(output.parent_path());
  const fs::path partial = output.string() + ".partial";
  {
    zip_writer zip(partial.string());
    zip.add("modelDescription.xml", description);
    binaries.copy_into(zip);
    std::vector<fs::path> staged;  // sorted: the same inputs give the same archive
    for (const auto& f : fs::recursive_directory_iterator(resources)) {
      if (f.is_regular_file()) staged.push_back(f.path().lexically_relative(resources));
    }
    std::sort(staged.begin(), staged.end());
    for (const fs::path& f : staged) {
      zip.add("resources/" + f.generic_string(), read_file(resources / f));
    }
    zip.close();
  }
  fs::rename(partial, output);
  return result;
}

}  // namespace stride::robot
