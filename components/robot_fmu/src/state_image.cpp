// State image format, version 1 (all numbers in the machine's byte order):
//   "STRIDERB", u32 version, u32 bodies, u32 joints, u32 servos,
//   per body f64 position[3], quaternion[4], linear_velocity[3], angular_velocity[3],
//   f64 time, f64 requested_time, i64 steps, f64 targets[servos], f64 servo_velocity[joints],
//   f64 push_x, push_y, u32 fallen, f64 acc[3], left_force[3], right_force[3], max_penetration
#include "state_image.hpp"

#include <cstring>
#include <stdexcept>

namespace stride::robot {

namespace {

constexpr char k_state_magic[8] = {'S', 'T', 'R', 'I', 'D', 'E', 'R', 'B'};
constexpr std::uint32_t k_state_version = 1;

class writer {
 public:
  void raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    data.insert(data.end(), b, b + n);
  }
  void f64(double v) { raw(&v, sizeof v); }
  void u32(std::uint32_t v) { raw(&v, sizeof v); }
  template <std::size_t n>
  void f64s(const std::array<double, n>& v) {
    for (double x : v) f64(x);
  }
  void f64s(const Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) f64(v[k]);
  }
  std::vector<std::uint8_t> data;
};

class reader {
 public:
  explicit reader(std::span<const std::uint8_t> d) : data_(d) {}
  void raw(void* p, std::size_t n) {
    if (pos_ + n > data_.size()) throw std::invalid_argument("robot state image is truncated");
    std::memcpy(p, data_.data() + pos_, n);
    pos_ += n;
  }
  double f64() {
    double v = 0.0;
    raw(&v, sizeof v);
    return v;
  }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  template <std::size_t n>
  void f64s(std::array<double, n>& v) {
    for (double& x : v) x = f64();
  }
  void f64s(Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) v[k] = f64();
  }
  [[nodiscard]] bool at_end() const { return pos_ == data_.size(); }

 private:
  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<std::uint8_t> encode_state_image(const plant_snapshot& s) {
  const plant_state& p = s.plant;
  writer w;
  w.raw(k_state_magic, sizeof k_state_magic);
  w.u32(k_state_version);
  w.u32(static_cast<std::uint32_t>(s.bodies.size()));
  w.u32(static_cast<std::uint32_t>(p.servo_velocity.size()));
  w.u32(static_cast<std::uint32_t>(p.targets.size()));
  for (const body_state& b : s.bodies) {
    w.f64s(b.position);
    w.f64s(b.quaternion);
    w.f64s(b.linear_velocity);
    w.f64s(b.angular_velocity);
  }
  w.f64(p.time);
  w.f64(p.requested_time);
  w.raw(&p.steps, sizeof p.steps);
  for (double t : p.targets) w.f64(t);
  for (double v : p.servo_velocity) w.f64(v);
  w.f64(p.push_x);
  w.f64(p.push_y);
  w.u32(p.fallen ? 1U : 0U);
  w.f64s(p.acc);
  w.f64s(p.left_force);
  w.f64s(p.right_force);
  w.f64(p.max_penetration);
  return std::move(w.data);
}

plant_snapshot decode_state_image(std::span<const std::uint8_t> image, std::size_t bodies,
                                  std::size_t joints, std::size_t servos,
                                  const std::string& source) {
  reader r(image);
  char magic[sizeof k_state_magic];
  r.raw(magic, sizeof magic);
  if (std::memcmp(magic, k_state_magic, sizeof magic) != 0) {
    throw std::invalid_argument("robot state image: not a robot_sim state");
  }
  if (r.u32() != k_state_version) throw std::invalid_argument("robot state image: wrong version");
  if (r.u32() != bodies || r.u32() != joints || r.u32() != servos) {
    throw std::invalid_argument("robot state image: saved from a different model than " + source);
  }
  plant_snapshot s;
  s.bodies.resize(bodies);
  for (body_state& b : s.bodies) {
    r.f64s(b.position);
    r.f64s(b.quaternion);
    r.f64s(b.linear_velocity);
    r.f64s(b.angular_velocity);
  }
  plant_state& p = s.plant;
  p.time = r.f64();
  p.requested_time = r.f64();
  r.raw(&p.steps, sizeof p.steps);
  p.targets.resize(servos);
  for (double& t : p.targets) t = r.f64();
  p.servo_velocity.resize(joints);
  for (double& v : p.servo_velocity) v = r.f64();
  p.push_x = r.f64();
  p.push_y = r.f64();
  p.fallen = r.u32() != 0;
  r.f64s(p.acc);
  r.f64s(p.left_force);
  r.f64s(p.right_force);
  p.max_penetration = r.f64();
  if (!r.at_end()) throw std::invalid_argument("robot state image: trailing bytes");
  return s;
}

}  // namespace stride::robot
