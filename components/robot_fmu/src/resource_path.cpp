// package:// resolution follows the ROS convention: a package is a folder named like the package,
// found either as a search-path entry itself or directly inside one.
#include "stride/robot/resource_path.hpp"

#include <filesystem>
#include <string_view>

#include "stride/robot/robot_model.hpp"

namespace stride::robot {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view k_package = "package://";
constexpr std::string_view k_file = "file://";

std::string relative_to(const std::string& base_dir, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute() || base_dir.empty()) return path;
  return (fs::path(base_dir) / path).lexically_normal().string();
}

bool is_file(const fs::path& p) {
  std::error_code ec;  // an unreadable folder is a place where the file is not
  return fs::is_regular_file(p, ec);
}

}  // namespace

std::vector<std::string> package_search_path(const std::vector<std::string>& configured,
                                             const char* ros_package_path) {
  std::vector<std::string> out;
  for (const std::string& e : configured) {
    if (!e.empty()) out.push_back(e);
  }
  if (ros_package_path == nullptr) return out;
  const std::string_view env(ros_package_path);
  std::size_t start = 0;
  while (start <= env.size()) {
    const std::size_t end = std::min(env.find(':', start), env.size());
    if (end > start) out.emplace_back(env.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::string resolve_resource(const std::string& uri, const std::string& base_dir,
                             const std::vector<std::string>& search_path) {
  const std::string_view u(uri);
  if (u.starts_with(k_file)) return relative_to(base_dir, std::string(u.substr(k_file.size())));
  if (!u.starts_with(k_package)) {
    const std::size_t scheme = u.find("://");
    if (scheme != std::string_view::npos) {
      throw model_error("'" + uri + "': unsupported URI scheme (package://, file:// or a path)");
    }
    return relative_to(base_dir, uri);
  }
  const std::string_view rest = u.substr(k_package.size());
  const std::size_t slash = rest.find('/');
  if (slash == 0 || slash == std::string_view::npos || slash + 1 == rest.size()) {
    throw model_error("'" + uri + "': a package URI needs the form package://NAME/PATH");
  }
  const std::string name(rest.substr(0, slash));
  const std::string inside(rest.substr(slash + 1));
  std::string searched;
  for (const std::string& entry : search_path) {
    fs::path dir(entry);
    // "a/b/" has an empty filename; its package name is "b"
    const std::string last = (dir.has_filename() ? dir : dir.parent_path()).filename().string();
    std::vector<fs::path> candidates;
    if (last == name) candidates.push_back(dir / inside);
    candidates.push_back(dir / name / inside);
    for (const fs::path& c : candidates) {
      if (is_file(c)) return c.lexically_normal().string();
      searched += (searched.empty() ? "" : ", ") + c.lexically_normal().string();
    }
  }
  if (searched.empty()) {
    throw model_error("'" + uri + "': package '" + name +
                      "' not found: the package path is empty (robot_config::package_path, "
                      "ROS_PACKAGE_PATH)");
  }
  throw model_error("'" + uri + "': package '" + name + "' not found; searched " + searched);
}

}  // namespace stride::robot
