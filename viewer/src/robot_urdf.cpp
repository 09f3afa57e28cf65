#include "robot_urdf.hpp"

#include <fstream>
#include <sstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::viewer {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw cosim::validation_error(file.string() + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

cosim::system_structure run_system(const fs::path& run_dir) {
  const fs::path file = run_dir / "system.xml";
  if (!fs::is_regular_file(file)) {
    throw cosim::validation_error(run_dir.string() +
                                  " holds no system.xml: not a run folder (stride run writes one)");
  }
  return cosim::expand_replicas(cosim::parse_system_file(file));
}

}  // namespace

urdf_source find_run_urdf(const fs::path& run_dir, const std::string& component) {
  const cosim::system_structure system = run_system(run_dir);
  const cosim::component_spec* spec = nullptr;
  for (const auto& c : system.components) {
    if (c.name == component) spec = &c;
  }
  if (spec == nullptr) {
    throw cosim::validation_error((run_dir / "system.xml").string() + " has no component '" +
                                  component + "' (the results name its pose)");
  }
  std::string urdf;  // the last setting wins, as when the run applied them
  for (const auto& p : spec->parameters) {
    if (p.variable == "urdf") urdf = p.value;
  }
  // a path as given (absolute, or relative to where the viewer runs) wins, as in the plant
  if (!urdf.empty() && fs::is_regular_file(urdf)) return {read_text(urdf), urdf};

  const fs::path fmu = cosim::resolve_fmu(*spec, system, cosim::default_fmu_search_path());
  cosim::temp_dir unpacked("stride-view-");
  cosim::extract_archive(fmu, unpacked.path());
  const fs::path resources = unpacked.path() / "resources";
  if (!urdf.empty()) {
    const fs::path in_fmu = resources / urdf;
    if (!fs::is_regular_file(in_fmu)) {
      throw cosim::validation_error(component + ".urdf = '" + urdf +
                                    "': no such file, neither as a path nor in the resources of " +
                                    fmu.string() + " (stride view --urdf FILE names it)");
    }
    return {read_text(in_fmu), fmu.filename().string() + ":resources/" + urdf};
  }
  std::vector<fs::path> found;
  if (fs::is_directory(resources)) {
    for (const auto& e : fs::directory_iterator(resources)) {
      if (e.is_regular_file() && e.path().extension() == ".urdf") found.push_back(e.path());
    }
  }
  if (found.size() != 1) {
    throw cosim::validation_error(
        component + " sets no urdf parameter and " + fmu.string() + " ships " +
        std::to_string(found.size()) +
        " .urdf files in resources/ (one is needed): name the robot with stride view --urdf FILE");
  }
  return {read_text(found.front()),
          fmu.filename().string() + ":resources/" + found.front().filename().string()};
}

std::vector<std::string> other_parameters(const fs::path& run_dir, const std::string& component) {
  std::vector<std::string> out;
  for (const auto& c : run_system(run_dir).components) {
    if (c.name == component) continue;
    for (const auto& p : c.parameters) out.push_back(c.name + "." + p.variable + " = " + p.value);
  }
  return out;
}

std::map<std::string, std::string> connection_targets(const fs::path& run_dir) {
  std::map<std::string, std::string> out;
  for (const auto& c : run_system(run_dir).connections) {
    if (c.from.find_first_of("*:") == std::string::npos) out.emplace(c.from, c.to);
  }
  return out;
}

}  // namespace stride::viewer
