// Triangle meshes read from the files URDF <mesh> elements name.
#pragma once

#include <memory>
#include <string>

#include "stride/robot/robot_model.hpp"

namespace stride::robot {

/// Reads the triangles of an STL (binary or ASCII) or Collada (.dae) file and multiplies every
/// vertex by `scale` (per axis). Node transforms and a Collada <unit> are applied; a Collada
/// <up_axis> is not (vertices stay in the file's own axes, which the URDF link frame takes).
/// Throws model_error naming the file for an unreadable file, another format, a file without
/// triangles or a zero or non-finite scale.
std::shared_ptr<const triangle_mesh> load_mesh(const std::string& path, const vec3& scale);

}  // namespace stride::robot
