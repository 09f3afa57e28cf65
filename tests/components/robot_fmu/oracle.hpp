// Expected values for the plant's tests, computed independently of the code under test: the
// DARwIn-OP facts of docs/robot-model.md by hand, and a fresh reading of a URDF (link masses,
// link frames at given joint angles) with tinyxml2 and Eigen, NOT through stride::robot (whose
// model loader, body merging and forward kinematics the tests check).
#pragma once

#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace stride::test {

/// Servo count → rad as documented (docs/robot-model.md §1.1: 2048 centre, 0.088° per count).
inline double count_rad(int count) {
  return (count - 2048) * 0.088 * std::numbers::pi / 180.0;
}

/// Page 9 ("walkready") by servo ID − 1, rad, from the counts of docs/robot-model.md §5.1.
inline std::vector<double> page_9() {
  const int counts[20] = {1498, 2518, 1845, 2248, 2381, 1712, 2048, 2048, 2052, 2044,
                          1637, 2459, 2653, 1443, 2389, 1707, 2057, 2039, 2048, 2161};
  std::vector<double> q;
  for (int c : counts) q.push_back(count_rad(c));
  return q;
}

/// Torso lean of the walk-ready pose, rad, by hand (docs/robot-model.md §5.2): a leg's pitch
/// joints turn the sole about y by hip_pitch + knee − ankle_pitch (right leg: page 9 counts
/// 1637, 2653, 2389; axes +y, +y, −y); level soles lean the torso forward by minus that.
inline double walk_ready_lean() {
  return -(count_rad(1637) + count_rad(2653) - count_rad(2389));
}

/// Gravity of the DARwIn-OP worlds (docs/robot-model.md §4.3), m/s².
inline constexpr double k_gravity = 9.81;

/// CM-730 gyro counts per rad/s: the lookup table maps ±27.925 rad/s to 0…1024 around the 512
/// centre (docs/robot-model.md §1.4).
inline constexpr double k_gyro_counts_per_rad_s = 512.0 / 27.925;

class urdf_oracle {
 public:
  explicit urdf_oracle(const std::string& path) {
    if (doc_.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
      throw std::runtime_error("urdf_oracle: cannot read " + path);
    }
    const tinyxml2::XMLElement* robot = doc_.FirstChildElement("robot");
    for (auto* l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
      link_data d;
      if (const auto* in = l->FirstChildElement("inertial")) {
        d.mass = in->FirstChildElement("mass")->DoubleAttribute("value");
        d.com = transform_of(in->FirstChildElement("origin")).translation();
      }
      links_[l->Attribute("name")] = d;
    }
    for (auto* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
      joint_data d;
      d.parent = j->FirstChildElement("parent")->Attribute("link");
      d.origin = transform_of(j->FirstChildElement("origin"));
      d.fixed = std::string(j->Attribute("type")) == "fixed";
      if (const auto* a = j->FirstChildElement("axis")) d.axis = vector_of(a->Attribute("xyz"));
      if (const auto* s = j->FirstChildElement("servo")) d.servo = s->IntAttribute("id");
      joints_[j->FirstChildElement("child")->Attribute("link")] = d;
    }
  }

  /// Sum of every link's <mass>, kg.
  [[nodiscard]] double total_mass() const {
    double m = 0.0;
    for (const auto& [name, l] : links_) m += l.mass;
    return m;
  }

  /// Frame of `link` in the root link's frame; q: joint angles by servo ID − 1, rad.
  [[nodiscard]] Eigen::Isometry3d link_in_root(const std::string& link,
                                               const std::vector<double>& q) const {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    for (std::string l = link; joints_.count(l) != 0;) {
      const joint_data& j = joints_.at(l);
      Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
      if (!j.fixed && j.servo > 0) {
        motion.linear() =
            Eigen::AngleAxisd(q.at(static_cast<std::size_t>(j.servo - 1)), j.axis.normalized())
                .toRotationMatrix();
      }
      t = j.origin * motion * t;
      l = j.parent;
    }
    return t;
  }

  /// Whole-body centre of mass in the root link's frame at joint angles q (by servo ID − 1).
  [[nodiscard]] Eigen::Vector3d com_in_root(const std::vector<double>& q) const {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& [name, l] : links_) sum += l.mass * (link_in_root(name, q) * l.com);
    return sum / total_mass();
  }

 private:
  struct link_data {
    double mass = 0.0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
  };
  struct joint_data {
    std::string parent;
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    bool fixed = false;
    int servo = 0;
  };

  static Eigen::Vector3d vector_of(const char* text) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (text == nullptr) return v;
    std::istringstream in(text);
    in >> v.x() >> v.y() >> v.z();
    return v;
  }

  // URDF <origin xyz rpy>: R = Rz(yaw)·Ry(pitch)·Rx(roll), fixed axes
  static Eigen::Isometry3d transform_of(const tinyxml2::XMLElement* origin) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    if (origin == nullptr) return t;
    const Eigen::Vector3d rpy = vector_of(origin->Attribute("rpy"));
    t.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    t.translation() = vector_of(origin->Attribute("xyz"));
    return t;
  }

  tinyxml2::XMLDocument doc_;
  std::map<std::string, link_data> links_;
  std::map<std::string, joint_data> joints_;  // by child link
};

}  // namespace stride::test
