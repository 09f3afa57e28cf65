// Where a file named inside a URDF (package://, file:// or a plain path) lives on this machine.
#pragma once

#include <string>
#include <vector>

namespace stride::robot {

/// The folders searched for package:// URIs: `configured` first, then the non-empty entries of
/// `ros_package_path` (the value of ROS_PACKAGE_PATH, colon-separated; nullptr when unset).
std::vector<std::string> package_search_path(const std::vector<std::string>& configured,
                                             const char* ros_package_path);

/// The path of the file `uri` names:
///  - package://NAME/REST: the first existing file among, for each entry E of `search_path` in
///    order, E/REST when E's last component is NAME, and E/NAME/REST;
///  - file://PATH and plain PATH: PATH, relative ones resolved against `base_dir` (existence is
///    left to the reader of the file).
/// Throws model_error naming the URI and, for package://, every place searched.
std::string resolve_resource(const std::string& uri, const std::string& base_dir,
                             const std::vector<std::string>& search_path);

}  // namespace stride::robot
