// Rigid-body description of a robot loaded from URDF, independent of the physics engine.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace stride::robot {

/// Thrown for unreadable, malformed or unsupported robot descriptions; the message names the file
/// and the URDF element (link or joint) at fault.
class model_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using vec3 = std::array<double, 3>;
/// Row-major 3x3 rotation matrix.
using mat3 = std::array<double, 9>;

/// Rigid transform: `position` and `rotation` of a child frame expressed in its parent frame.
struct pose {
  vec3 position{0.0, 0.0, 0.0};
  mat3 rotation{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
};

enum class shape_type { box, cylinder, sphere, capsule, mesh };

/// Triangles read from a mesh file, scaled, in the frame of the <collision> origin.
struct triangle_mesh {
  /// x, y, z of every vertex, m.
  std::vector<double> vertices;
  /// Three vertex indices per triangle, counter-clockwise seen from outside.
  std::vector<std::uint32_t> indices;
  /// Resolved path of the file (for messages).
  std::string file;
};

/// One collision primitive. Cylinders and capsules have their axis along z of `origin`.
struct collision_shape {
  shape_type type = shape_type::box;
  /// box: full lengths x, y, z; cylinder/capsule: radius, length (capsule: cylinder part), 0;
  /// sphere: radius, 0, 0; mesh: the scale applied to the file's vertices.
  vec3 size{0.0, 0.0, 0.0};
  /// mesh only: the triangles, shared by every copy of the shape (immutable once loaded).
  std::shared_ptr<const triangle_mesh> mesh;
  /// Pose in the frame of the body's root link.
  pose origin;
  /// URDF link the shape was declared in (for messages).
  std::string link;
};

/// One simulated rigid body: a link plus every link welded to it by fixed joints.
struct rigid_body {
  /// Name of the body's root link; the body frame is that link's frame.
  std::string link;
  double mass = 0.0;
  /// Centre of mass in the body frame.
  vec3 com{0.0, 0.0, 0.0};
  /// Inertia about the centre of mass in the body frame: ixx, iyy, izz, ixy, ixz, iyz.
  std::array<double, 6> inertia{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  std::vector<collision_shape> shapes;
};

enum class joint_type { revolute, continuous, prismatic };

/// One movable joint. Fixed joints do not appear: their links are merged into the parent body.
struct model_joint {
  std::string name;
  joint_type type = joint_type::revolute;
  /// Index into robot_model::bodies, or -1 for the static world of a fixed-base model.
  int parent_body = -1;
  int child_body = -1;
  /// Child body frame in the parent body frame at joint position 0.
  pose origin;
  /// Unit axis in the child body frame.
  vec3 axis{1.0, 0.0, 0.0};
  bool limited = false;
  double lower = 0.0;
  double upper = 0.0;
  /// URDF <dynamics>; used for passive joints only (servo joints take robot_config::servo).
  double damping = 0.0;
  double friction = 0.0;
  /// Servo ID from the <servo id="N"/> extension element; 0 = passive joint.
  int servo_id = 0;
  /// URDF <mimic>: index into robot_model::joints of the joint this one follows (-1: none); the
  /// plant drives this joint to mimic_multiplier · q_master + mimic_offset.
  int mimic_joint = -1;
  double mimic_multiplier = 1.0;
  double mimic_offset = 0.0;
};

/// Where every URDF link sits: on which body (-1 = world) and where in that body's frame.
struct link_frame {
  std::string name;
  int body = -1;
  pose in_body;
};

/// The whole robot. Bodies and joints are in tree order (a parent before its children);
/// bodies[0] is the floating base unless `fixed_base`.
struct robot_model {
  std::string name;
  /// File (or label) the model was read from.
  std::string source;
  /// True when the URDF root link is named "world": it is the static environment.
  bool fixed_base = false;
  std::vector<rigid_body> bodies;
  std::vector<model_joint> joints;
  std::vector<link_frame> links;
  /// Collision shapes welded to the world (fixed-base models only), in world coordinates.
  std::vector<collision_shape> world_shapes;

  /// Largest servo ID (servo IDs need not be contiguous; missing IDs read as 0 rad).
  [[nodiscard]] int servo_count() const;
  /// Index of the joint that carries servo `id`, or -1.
  [[nodiscard]] int joint_of_servo(int id) const;
  /// Index into `links`, or -1.
  [[nodiscard]] int find_link(const std::string& name) const;
  /// Sum of body masses.
  [[nodiscard]] double total_mass() const;
  /// World frame of every body (the frame of its root link), by body index: bodies[0] at `root`
  /// (ignored by a fixed-base model, whose first joints hang from the world origin), every child
  /// at parent frame · joint origin · joint motion. `q`: joint positions by model joint, rad (m
  /// for prismatic joints); empty = all 0. Throws std::invalid_argument for another size.
  [[nodiscard]] std::vector<pose> forward_kinematics(const pose& root,
                                                     std::span<const double> q) const;
};

/// Replaces movable joint `joint` by a weld at joint position `q`: its child body (mass, inertia,
/// shapes, link frames and child joints) is merged into the parent body; later body and joint
/// indices shift down by one. Throws model_error if the child is the world or if a mimic joint
/// follows `joint`.
void weld_joint(robot_model& model, int joint, double q);

/// How files named inside a URDF (meshes) are found.
struct model_options {
  /// Searched for package://NAME/... before the folders of ROS_PACKAGE_PATH: each entry is the
  /// package folder itself (last component NAME) or a folder holding NAME/.
  std::vector<std::string> package_path;
  /// Read ROS_PACKAGE_PATH (colon-separated) from the environment.
  bool use_ros_package_path = true;
  /// Folder that relative file names are resolved against; empty: the folder of the URDF file
  /// (of `source` for parse_robot_model).
  std::string base_dir;
};

/// Reads and validates a URDF file. Supported: revolute, continuous, prismatic and fixed joints,
/// <mimic> on revolute, continuous and prismatic joints; box, cylinder, sphere, mesh (STL, DAE)
/// and (extension) capsule collisions. Visual elements are ignored (the plant does not render).
/// Throws model_error naming the file and element for anything else.
robot_model load_robot_model(const std::string& urdf_path, const model_options& options = {});

/// Same as load_robot_model for a URDF held in memory; `source` names it in messages.
robot_model parse_robot_model(const std::string& urdf_xml, const std::string& source,
                              const model_options& options = {});

}  // namespace stride::robot
