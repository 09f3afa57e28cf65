// State image format, version 2 (all numbers in the machine's byte order):
//   "STRIDERB", u32 version, u32 bodies, u32 joints, u32 servos, u32 contact links,
//   per body f64 position[3], quaternion[4], linear_velocity[3], angular_velocity[3],
//   f64 time, f64 requested_time, i64 steps, f64 targets[servos], f64 servo_velocity[joints],
//   f64 push_x, push_y, u32 fallen, f64 acc[3], left_force[3], right_force[3], max_penetration,
//   f64 link_forces[contact links][3], f64 joint_torques[servos]
#include "state_image.hpp"

#include <cstring>
#include <stdexcept>

#include "stride/common/bytes.hpp"

namespace stride::robot {

namespace {

constexpr char k_state_magic[8] = {'S', 'T', 'R', 'I', 'D', 'E', 'R', 'B'};
constexpr std::uint32_t k_state_version = 2;

using reader = common::byte_reader<std::invalid_argument>;

// vectors of doubles (std::array, std::vector, Eigen::Vector3d), their length known to the reader
template <class Vector>
void put_all(common::byte_writer& w, const Vector& v) {
  for (double x : v) w.put(x);
}
template <class Vector>
void get_all(reader& r, Vector& v) {
  for (double& x : v) x = r.get<double>();
}

}  // namespace

std::vector<std::uint8_t> encode_state_image(const plant_snapshot& s) {
  const plant_state& p = s.plant;
  common::byte_writer w;
  for (char c : k_state_magic) w.put(c);
  w.put(k_state_version);
  w.put(static_cast<std::uint32_t>(s.bodies.size()));
  w.put(static_cast<std::uint32_t>(p.servo_velocity.size()));
  w.put(static_cast<std::uint32_t>(p.targets.size()));
  w.put(static_cast<std::uint32_t>(p.link_forces.size()));
  for (const body_state& b : s.bodies) {
    put_all(w, b.position);
    put_all(w, b.quaternion);
    put_all(w, b.linear_velocity);
    put_all(w, b.angular_velocity);
  }
  w.put(p.time);
  w.put(p.requested_time);
  w.put(p.steps);
  put_all(w, p.targets);
  put_all(w, p.servo_velocity);
  w.put(p.push_x);
  w.put(p.push_y);
  w.put(std::uint32_t{p.fallen ? 1U : 0U});
  put_all(w, p.acc);
  put_all(w, p.left_force);
  put_all(w, p.right_force);
  w.put(p.max_penetration);
  for (const Eigen::Vector3d& f : p.link_forces) put_all(w, f);
  put_all(w, p.joint_torques);
  const auto& bytes = w.bytes();
  const auto* first = reinterpret_cast<const std::uint8_t*>(bytes.data());
  return {first, first + bytes.size()};
}

plant_snapshot decode_state_image(std::span<const std::uint8_t> image, std::size_t bodies,
                                  std::size_t joints, std::size_t servos, std::size_t contact_links,
                                  const std::string& source) {
  reader r(std::as_bytes(image), "robot state image is truncated");
  char magic[sizeof k_state_magic];
  for (char& c : magic) c = r.get<char>();
  if (std::memcmp(magic, k_state_magic, sizeof magic) != 0) {
    throw std::invalid_argument("robot state image: not a robot_sim state");
  }
  if (r.get<std::uint32_t>() != k_state_version)
    throw std::invalid_argument("robot state image: wrong version");
  if (r.get<std::uint32_t>() != bodies || r.get<std::uint32_t>() != joints ||
      r.get<std::uint32_t>() != servos || r.get<std::uint32_t>() != contact_links) {
    throw std::invalid_argument("robot state image: saved from a different model than " + source);
  }
  plant_snapshot s;
  s.bodies.resize(bodies);
  for (body_state& b : s.bodies) {
    get_all(r, b.position);
    get_all(r, b.quaternion);
    get_all(r, b.linear_velocity);
    get_all(r, b.angular_velocity);
  }
  plant_state& p = s.plant;
  p.time = r.get<double>();
  p.requested_time = r.get<double>();
  p.steps = r.get<decltype(p.steps)>();
  p.targets.resize(servos);
  get_all(r, p.targets);
  p.servo_velocity.resize(joints);
  get_all(r, p.servo_velocity);
  p.push_x = r.get<double>();
  p.push_y = r.get<double>();
  p.fallen = r.get<std::uint32_t>() != 0;
  get_all(r, p.acc);
  get_all(r, p.left_force);
  get_all(r, p.right_force);
  p.max_penetration = r.get<double>();
  p.link_forces.resize(contact_links);
  for (Eigen::Vector3d& f : p.link_forces) get_all(r, f);
  p.joint_torques.resize(servos);
  get_all(r, p.joint_torques);
  if (!r.at_end()) throw std::invalid_argument("robot state image: trailing bytes");
  return s;
}

}  // namespace stride::robot
