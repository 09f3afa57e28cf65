// URDF → robot_model: urdfdom for the standard content, tinyxml2 for the two extensions
// (<servo id> in joints, <capsule> collisions), fixed joints merged into their parent body.
#include "stride/robot/robot_model.hpp"

#include <cstdlib>
#include <filesystem>

#include <tinyxml2.h>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "frames.hpp"
#include "stride/robot/mesh_file.hpp"
#include "stride/robot/resource_path.hpp"

namespace stride::robot {

namespace {

// console_bridge has one global handler; urdfdom parses are serialised while it is redirected
std::mutex g_console_mutex;

// collects urdfdom's console_bridge messages instead of printing them
class capture_handler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_WARN) return;
    if (!messages_.empty()) messages_ += "; ";
    messages_ += text;
  }
  [[nodiscard]] const std::string& messages() const { return messages_; }

 private:
  std::string messages_;
};

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw model_error(source + ": " + what);
}

// what the tinyxml2 pre-pass learns about the document
struct extensions {
  std::map<std::string, int> servo_of_joint;
  std::set<std::pair<std::string, int>> capsules;  // (link, collision index)
  std::map<std::string, int> joint_order;          // document order of joints
};

int parse_servo_id(const tinyxml2::XMLElement& servo, const std::string& source,
                   const std::string& joint) {
  const char* text = servo.Attribute("id");
  if (text == nullptr) fail(source, "joint '" + joint + "': <servo> has no id attribute");
  std::istringstream in(text);
  long id = 0;
  in >> id;
  if (!in || !in.eof() || id < 1 || id > 4096) {
    fail(source, "joint '" + joint + "': servo id '" + text + "' is not an integer in 1..4096");
  }
  return static_cast<int>(id);
}

// The joints must form a tree: urdfdom detects neither a link that is the child of two joints
// nor a loop of joints, and leaks the links it has tied together when it then fails.
void check_tree(const tinyxml2::XMLElement& robot, const std::string& source) {
  const auto link_of = [](const tinyxml2::XMLElement& joint, const char* role) -> std::string {
    const auto* e = joint.FirstChildElement(role);
    const char* name = e != nullptr ? e->Attribute("link") : nullptr;
    return name != nullptr ? name : "";
  };
  std::map<std::string, std::pair<std::string, std::string>> parent_of;  // child: joint, parent
  for (auto* joint = robot.FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const char* name_attr = joint->Attribute("name");
    const std::string name = name_attr != nullptr ? name_attr : "";
    const std::string parent = link_of(*joint, "parent");
    const std::string child = link_of(*joint, "child");
    if (parent.empty() || child.empty()) continue;  // urdfdom names what is missing
    if (parent == child)
      fail(source, "joint '" + name + "': link '" + child + "' is its own parent");
    if (const auto it = parent_of.find(child); it != parent_of.end()) {
      fail(source, "link '" + child + "' is the child of two joints, '" + it->second.first +
                       "' and '" + name + "'");
    }
    parent_of[child] = {name, parent};
  }
  for (const auto& [start, first] : parent_of) {
    std::string path = first.first;
    std::string link = first.second;
    for (std::size_t steps = 0; steps <= parent_of.size(); ++steps) {
      if (link == start) fail(source, "the joints form a loop: " + path);
      const auto up = parent_of.find(link);
      if (up == parent_of.end()) break;
      path += " -> " + up->second.first;
      link = up->second.second;
    }
  }
}

// reads the extensions and rewrites <capsule> to <cylinder> so urdfdom accepts the document
extensions pre_pass(tinyxml2::XMLDocument& doc, const std::string& source) {
  extensions ext;
  tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) fail(source, "no <robot> root element");
  for (auto* link = robot->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    const char* name_attr = link->Attribute("name");
    const std::string name = name_attr != nullptr ? name_attr : "";
    int index = 0;
    for (auto* col = link->FirstChildElement("collision"); col != nullptr;
         col = col->NextSiblingElement("collision"), ++index) {
      // urdfdom would drop such a collision silently
      const std::string what = "link '" + name + "': <collision> " + std::to_string(index + 1);
      auto* geometry = col->FirstChildElement("geometry");
      if (geometry == nullptr) fail(source, what + " has no <geometry>");
      auto* shape = geometry->FirstChildElement();
      if (shape == nullptr) fail(source, what + ": <geometry> is empty");
      const std::string kind = shape->Name();
      if (kind != "box" && kind != "cylinder" && kind != "sphere" && kind != "capsule" &&
          kind != "mesh") {
        fail(source, what + ": unsupported geometry <" + kind +
                         "> (collision shapes: box, cylinder, sphere, capsule, mesh)");
      }
      if (kind == "capsule") {
        ext.capsules.insert({name, index});
        shape->SetName("cylinder");
      }
    }
  }
  std::map<int, std::string> joint_of_servo;
  int order = 0;
  for (auto* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const char* name_attr = joint->Attribute("name");
    const std::string name = name_attr != nullptr ? name_attr : "";
    ext.joint_order[name] = order++;
    const auto* servo = joint->FirstChildElement("servo");
    if (servo == nullptr) continue;
    if (servo->NextSiblingElement("servo") != nullptr) {
      fail(source, "joint '" + name + "': more than one <servo> element");
    }
    const int id = parse_servo_id(*servo, source, name);
    if (auto it = joint_of_servo.find(id); it != joint_of_servo.end()) {
      fail(source, "joint '" + name + "': servo id " + std::to_string(id) +
                       " is already used by joint '" + it->second + "'");
    }
    joint_of_servo[id] = name;
    ext.servo_of_joint[name] = id;
  }
  check_tree(*robot, source);
  return ext;
}

Eigen::Isometry3d from_urdf(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  return t;
}

bool finite(double v) {
  return std::isfinite(v);
}

// mass accumulator for one body: inertia about the body origin plus first moment
struct mass_sum {
  double mass = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();

  void add(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& i_com) {
    mass += m;
    moment += m * c;
    inertia_origin +=
        i_com + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  }
};

void check_inertia(const Eigen::Matrix3d& inertia, const std::string& source,
                   const std::string& what) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  const Eigen::Vector3d l = solver.eigenvalues();
  const double scale = std::max(l.cwiseAbs().maxCoeff(), 1e-300);
  if (!(l.minCoeff() > 1e-12 * scale) || l.minCoeff() <= 0.0) {
    fail(source, what + ": inertia tensor is not positive definite");
  }
  // principal moments must satisfy the triangle inequality (small tolerance for rounding)
  if (l(0) + l(1) < l(2) * (1.0 - 1e-6)) {
    fail(source, what + ": principal moments violate the triangle inequality");
  }
}

void check_positive(double v, const std::string& source, const std::string& what) {
  if (!finite(v) || v <= 0.0) fail(source, what + " must be a positive number");
}

// where the files a URDF names are looked for
struct file_context {
  std::string base_dir;
  std::vector<std::string> search_path;
};

collision_shape make_mesh(const urdf::Mesh& m, const std::string& link, const std::string& source,
                          const file_context& files) {
  collision_shape s;
  s.link = link;
  s.type = shape_type::mesh;
  s.size = {m.scale.x, m.scale.y, m.scale.z};
  try {
    s.mesh = load_mesh(resolve_resource(m.filename, files.base_dir, files.search_path), s.size);
  } catch (const model_error& e) {
    fail(source, "link '" + link + "' collision mesh: " + e.what() +
                     " (collision shapes: box, cylinder, sphere, capsule, mesh)");
  }
  return s;
}

collision_shape make_shape(const urdf::Collision& col, bool capsule, const std::string& link,
                           const std::string& source, const file_context& files) {
  if (!col.geometry) fail(source, "link '" + link + "': collision without geometry");
  collision_shape s;
  s.link = link;
  const std::string where = "link '" + link + "' collision";
  switch (col.geometry->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*col.geometry);
      check_positive(b.dim.x, source, where + " box size x");
      check_positive(b.dim.y, source, where + " box size y");
      check_positive(b.dim.z, source, where + " box size z");
      s.type = shape_type::box;
      s.size = {b.dim.x, b.dim.y, b.dim.z};
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(*col.geometry);
      check_positive(c.radius, source, where + " radius");
      if (capsule) {
        if (!finite(c.length) || c.length < 0.0) fail(source, where + " capsule length < 0");
      } else {
        check_positive(c.length, source, where + " cylinder length");
      }
      s.type = capsule ? shape_type::capsule : shape_type::cylinder;
      s.size = {c.radius, c.length, 0.0};
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& sp = static_cast<const urdf::Sphere&>(*col.geometry);
      check_positive(sp.radius, source, where + " sphere radius");
      s.type = shape_type::sphere;
      s.size = {sp.radius, 0.0, 0.0};
      break;
    }
    case urdf::Geometry::MESH:
      return make_mesh(static_cast<const urdf::Mesh&>(*col.geometry), link, source, files);
    default:
      fail(source, "link '" + link + "': unsupported collision geometry");
  }
  return s;
}

// mimic masters by joint index, once every movable joint has one
void resolve_mimics(const urdf::ModelInterface& urdf_model, robot_model& model,
                    const std::string& source) {
  for (model_joint& mj : model.joints) {
    const auto follower = urdf_model.getJoint(mj.name);
    if (!follower || !follower->mimic) continue;
    const std::string jwhat = "joint '" + mj.name + "'";
    const std::string master = follower->mimic->joint_name;
    const auto it = std::find_if(model.joints.begin(), model.joints.end(),
                                 [&](const model_joint& j) { return j.name == master; });
    if (it == model.joints.end()) {
      const auto fixed = urdf_model.getJoint(master);
      fail(source, jwhat + ": <mimic> joint '" + master + "' " +
                       (fixed ? "is a fixed joint" : "does not exist"));
    }
    if (it->name == mj.name) fail(source, jwhat + ": <mimic> names the joint itself");
    const auto master_urdf = urdf_model.getJoint(master);
    if (master_urdf->mimic) {
      fail(source, jwhat + ": <mimic> joint '" + master + "' is itself a mimic joint (chains of " +
                       "mimic joints are not supported)");
    }
    mj.mimic_joint = static_cast<int>(it - model.joints.begin());
  }
}

struct link_slot {
  int body = -1;
  Eigen::Isometry3d in_body = Eigen::Isometry3d::Identity();
};

robot_model convert(const urdf::ModelInterface& urdf_model, const extensions& ext,
                    const std::string& source, const file_context& files) {
  robot_model model;
  model.name = urdf_model.getName();
  model.source = source;

  auto root = urdf_model.getRoot();
  if (!root) fail(source, "no root link");
  model.fixed_base = root->name == "world";

  std::vector<mass_sum> sums;
  std::map<std::string, link_slot> slots;

  // children in document order of their joints, so body and joint indices follow the file
  auto sorted_children = [&](const urdf::Link& link) {
    std::vector<urdf::JointSharedPtr> joints = link.child_joints;
    std::sort(joints.begin(), joints.end(), [&](const auto& a, const auto& b) {
      return ext.joint_order.at(a->name) < ext.joint_order.at(b->name);
    });
    return joints;
  };

  auto add_link_content = [&](const urdf::Link& link, const link_slot& slot) {
    if (link.inertial) {
      const auto& in = *link.inertial;
      const std::string what = "link '" + link.name + "'";
      if (!finite(in.mass) || in.mass < 0.0) fail(source, what + ": mass must be >= 0");
      if (in.mass > 0.0) {
        Eigen::Matrix3d i_local;
        i_local << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
        if (!i_local.allFinite()) fail(source, what + ": inertia is not finite");
        check_inertia(i_local, source, what);
        if (slot.body >= 0) {
          const Eigen::Isometry3d t = slot.in_body * from_urdf(in.origin);
          sums[static_cast<std::size_t>(slot.body)].add(
              in.mass, t.translation(), t.linear() * i_local * t.linear().transpose());
        }
      }
    }
    for (std::size_t k = 0; k < link.collision_array.size(); ++k) {
      const auto& col = *link.collision_array[k];
      collision_shape s = make_shape(col, ext.capsules.count({link.name, static_cast<int>(k)}) > 0,
                                     link.name, source, files);
      s.origin = to_pose(slot.in_body * from_urdf(col.origin));
      if (slot.body >= 0) {
        model.bodies[static_cast<std::size_t>(slot.body)].shapes.push_back(s);
      } else {
        model.world_shapes.push_back(s);
      }
    }
    model.links.push_back({link.name, slot.body, to_pose(slot.in_body)});
  };

  std::vector<std::pair<urdf::LinkConstSharedPtr, urdf::JointConstSharedPtr>> pending;
  // root
  {
    link_slot slot;
    if (!model.fixed_base) {
      model.bodies.push_back({root->name, 0.0, {}, {}, {}});
      sums.emplace_back();
      slot.body = 0;
    }
    slots[root->name] = slot;
    add_link_content(*root, slot);
    auto children = sorted_children(*root);
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      pending.push_back({urdf_model.getLink((*it)->child_link_name), *it});
    }
  }
  // depth-first, parents before children
  while (!pending.empty()) {
    auto [link, joint] = pending.back();
    pending.pop_back();
    const std::string jwhat = "joint '" + joint->name + "'";
    if (joint->mimic && joint->type == urdf::Joint::FIXED) {
      fail(source, jwhat + ": a fixed joint cannot <mimic> another joint");
    }
    const link_slot& parent = slots.at(joint->parent_link_name);
    const Eigen::Isometry3d origin =
        parent.in_body * from_urdf(joint->parent_to_joint_origin_transform);
    if (!origin.matrix().allFinite()) fail(source, jwhat + ": origin is not finite");
    link_slot slot;
    if (joint->type == urdf::Joint::FIXED) {
      slot.body = parent.body;
      slot.in_body = origin;
    } else {
      model_joint mj;
      mj.name = joint->name;
      switch (joint->type) {
        case urdf::Joint::REVOLUTE:
          mj.type = joint_type::revolute;
          break;
        case urdf::Joint::CONTINUOUS:
          mj.type = joint_type::continuous;
          break;
        case urdf::Joint::PRISMATIC:
          mj.type = joint_type::prismatic;
          break;
        case urdf::Joint::FLOATING:
          fail(source, jwhat + ": floating joints are not supported");
        case urdf::Joint::PLANAR:
          fail(source, jwhat + ": planar joints are not supported");
        default:
          fail(source, jwhat + ": unsupported joint type");
      }
      Eigen::Vector3d axis(joint->axis.x, joint->axis.y, joint->axis.z);
      if (!axis.allFinite() || axis.norm() < 1e-9) fail(source, jwhat + ": axis is zero");
      axis.normalize();
      mj.axis = {axis.x(), axis.y(), axis.z()};
      if (mj.type != joint_type::continuous && joint->limits) {
        mj.limited = true;
        mj.lower = joint->limits->lower;
        mj.upper = joint->limits->upper;
        if (!finite(mj.lower) || !finite(mj.upper) || mj.lower > mj.upper) {
          fail(source, jwhat + ": limit lower > upper");
        }
      }
      if (joint->dynamics) {
        mj.damping = joint->dynamics->damping;
        mj.friction = joint->dynamics->friction;
        if (!finite(mj.damping) || mj.damping < 0.0 || !finite(mj.friction) || mj.friction < 0.0) {
          fail(source, jwhat + ": dynamics damping/friction must be >= 0");
        }
      }
      if (auto it = ext.servo_of_joint.find(joint->name); it != ext.servo_of_joint.end()) {
        mj.servo_id = it->second;
      }
      if (joint->mimic) {
        if (mj.servo_id > 0) fail(source, jwhat + ": a <mimic> joint cannot carry a <servo>");
        mj.mimic_multiplier = joint->mimic->multiplier;
        mj.mimic_offset = joint->mimic->offset;
        if (!finite(mj.mimic_multiplier) || !finite(mj.mimic_offset)) {
          fail(source, jwhat + ": <mimic> multiplier and offset must be finite");
        }
      }
      mj.parent_body = parent.body;
      mj.child_body = static_cast<int>(model.bodies.size());
      mj.origin = to_pose(origin);
      model.bodies.push_back({link->name, 0.0, {}, {}, {}});
      sums.emplace_back();
      model.joints.push_back(mj);
      slot.body = mj.child_body;
    }
    if (joint->type == urdf::Joint::FIXED && ext.servo_of_joint.count(joint->name) > 0) {
      fail(source, jwhat + ": a fixed joint cannot carry a <servo>");
    }
    slots[link->name] = slot;
    add_link_content(*link, slot);
    auto children = sorted_children(*link);
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      pending.push_back({urdf_model.getLink((*it)->child_link_name), *it});
    }
  }

  resolve_mimics(urdf_model, model, source);

  // finish the mass properties of every body
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    auto& body = model.bodies[b];
    const mass_sum& s = sums[b];
    if (!(s.mass > 0.0)) {
      std::string why =
          b == 0 && !model.fixed_base ? "it is the floating base" : "it is moved by a joint";
      fail(source, "link '" + body.link + "' has no mass (no <inertial> on it or on links fixed " +
                       "to it) but " + why);
    }
    const Eigen::Vector3d c = s.moment / s.mass;
    const Eigen::Matrix3d i =
        s.inertia_origin -
        s.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    check_inertia(i, source, "body of link '" + body.link + "'");
    body.mass = s.mass;
    body.com = {c.x(), c.y(), c.z()};
    body.inertia = {i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2), i(1, 2)};
  }
  return model;
}

}  // namespace

int robot_model::servo_count() const {
  int n = 0;
  for (const auto& j : joints) n = std::max(n, j.servo_id);
  return n;
}

int robot_model::joint_of_servo(int id) const {
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].servo_id == id) return static_cast<int>(j);
  }
  return -1;
}

int robot_model::find_link(const std::string& link_name) const {
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (links[l].name == link_name) return static_cast<int>(l);
  }
  return -1;
}

double robot_model::total_mass() const {
  double m = 0.0;
  for (const auto& b : bodies) m += b.mass;
  return m;
}

std::vector<pose> robot_model::forward_kinematics(const pose& root,
                                                  std::span<const double> q) const {
  if (!q.empty() && q.size() != joints.size()) {
    throw std::invalid_argument(source + ": forward_kinematics: " + std::to_string(q.size()) +
                                " joint positions for " + std::to_string(joints.size()) +
                                " joints");
  }
  // joints are in tree order: a parent's frame is known before its children's
  std::vector<Eigen::Isometry3d> frames(bodies.size(), Eigen::Isometry3d::Identity());
  if (!fixed_base && !frames.empty()) frames[0] = to_eigen(root);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const model_joint& mj = joints[j];
    const Eigen::Isometry3d parent = mj.parent_body >= 0
                                         ? frames[static_cast<std::size_t>(mj.parent_body)]
                                         : Eigen::Isometry3d::Identity();
    const double qj = q.empty() ? 0.0 : q[j];
    frames[static_cast<std::size_t>(mj.child_body)] =
        parent * to_eigen(mj.origin) * joint_motion(mj, qj);
  }
  std::vector<pose> out;
  out.reserve(frames.size());
  for (const Eigen::Isometry3d& f : frames) out.push_back(to_pose(f));
  return out;
}

void weld_joint(robot_model& model, int joint, double q) {
  if (joint < 0 || joint >= static_cast<int>(model.joints.size())) {
    throw model_error(model.source + ": weld_joint: no joint index " + std::to_string(joint));
  }
  const model_joint mj = model.joints[static_cast<std::size_t>(joint)];
  const int child = mj.child_body;
  const int parent = mj.parent_body;
  if (parent < 0) {
    throw model_error(model.source + ": joint '" + mj.name + "' connects to the world; it cannot " +
                      "be welded");
  }
  for (const model_joint& f : model.joints) {
    if (f.mimic_joint == joint) {
      throw model_error(model.source + ": joint '" + mj.name + "' is followed by mimic joint '" +
                        f.name + "'; it cannot be welded");
    }
  }
  // child body frame in the parent body frame at position q
  const Eigen::Isometry3d t = to_eigen(mj.origin) * joint_motion(mj, q);

  rigid_body& pb = model.bodies[static_cast<std::size_t>(parent)];
  const rigid_body& cb = model.bodies[static_cast<std::size_t>(child)];
  auto inertia_matrix = [](const std::array<double, 6>& i) {
    Eigen::Matrix3d m;
    m << i[0], i[3], i[4], i[3], i[1], i[5], i[4], i[5], i[2];
    return m;
  };
  mass_sum sum;
  sum.add(pb.mass, to_eigen(pb.com), inertia_matrix(pb.inertia));
  sum.add(cb.mass, t * to_eigen(cb.com),
          t.linear() * inertia_matrix(cb.inertia) * t.linear().transpose());
  const Eigen::Vector3d c = sum.moment / sum.mass;
  const Eigen::Matrix3d i =
      sum.inertia_origin -
      sum.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  pb.mass = sum.mass;
  pb.com = to_vec3(c);
  pb.inertia = {i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2), i(1, 2)};
  for (collision_shape shape : cb.shapes) {
    shape.origin = to_pose(t * to_eigen(shape.origin));
    pb.shapes.push_back(shape);
  }
  for (link_frame& l : model.links) {
    if (l.body == child) {
      l.body = parent;
      l.in_body = to_pose(t * to_eigen(l.in_body));
    }
  }
  for (model_joint& j : model.joints) {
    if (j.parent_body == child) {
      j.parent_body = parent;
      j.origin = to_pose(t * to_eigen(j.origin));
    }
  }
  model.joints.erase(model.joints.begin() + joint);
  model.bodies.erase(model.bodies.begin() + child);
  auto shift = [child](int& b) {
    if (b > child) --b;
  };
  for (model_joint& j : model.joints) {
    shift(j.parent_body);
    shift(j.child_body);
    if (j.mimic_joint > joint) --j.mimic_joint;
  }
  for (link_frame& l : model.links) shift(l.body);
}

robot_model parse_robot_model(const std::string& urdf_xml, const std::string& source,
                              const model_options& options) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS) {
    fail(source, std::string("XML error: ") + doc.ErrorStr());
  }
  const extensions ext = pre_pass(doc, source);
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);

  urdf::ModelInterfaceSharedPtr parsed;
  std::string messages;
  {
    std::lock_guard<std::mutex> lock(g_console_mutex);
    capture_handler capture;
    console_bridge::useOutputHandler(&capture);
    try {
      parsed = urdf::parseURDF(printer.CStr());
    } catch (const std::exception& e) {
      console_bridge::restorePreviousOutputHandler();
      fail(source, std::string("URDF error: ") + e.what());
    }
    console_bridge::restorePreviousOutputHandler();
    messages = capture.messages();
  }
  if (!parsed) {
    fail(source,
         "URDF error: " + (messages.empty() ? std::string("urdfdom rejected the file") : messages));
  }
  file_context files;
  files.base_dir = options.base_dir.empty() ? std::filesystem::path(source).parent_path().string()
                                            : options.base_dir;
  files.search_path =
      package_search_path(options.package_path,
                          options.use_ros_package_path ? std::getenv("ROS_PACKAGE_PATH") : nullptr);
  return convert(*parsed, ext, source, files);
}

robot_model load_robot_model(const std::string& urdf_path, const model_options& options) {
  if (urdf_path.empty()) throw model_error("robot URDF path is empty");
  std::ifstream in(urdf_path, std::ios::binary);
  if (!in) fail(urdf_path, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_robot_model(text.str(), urdf_path, options);
}

}  // namespace stride::robot
