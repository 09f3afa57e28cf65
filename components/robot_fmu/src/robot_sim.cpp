// robot_sim: the plant's run — load and weld the model, build the world, reset, the sequence of
// one physics step, state images. The parts live in ode_world, servos, contacts, sensors,
// stance and state_image.
#include "stride/robot/robot_sim.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "config_check.hpp"
#include "contacts.hpp"
#include "frames.hpp"
#include "mimic.hpp"
#include "ode_world.hpp"
#include "plant_state.hpp"
#include "sensors.hpp"
#include "servo_joints.hpp"
#include "servos.hpp"
#include "stance.hpp"
#include "state_image.hpp"
#include "stride/robot/fall.hpp"

namespace stride::robot {

namespace {

robot_model load_checked_model(const robot_config& c) {
  check_config(c);
  model_options options;
  options.package_path = c.package_path;
  options.use_ros_package_path = c.use_ros_package_path;
  robot_model m = load_robot_model(c.urdf_path, options);
  assign_servo_joints(m, c);
  check_joint_servos(m, c);
  check_initial_pose(c, m.servo_count());
  return m;
}

// a configured link that must be on a movable body
const link_frame& movable_link(const robot_model& model, const robot_config& c,
                               const std::string& key, const std::string& name) {
  const int l = model.find_link(name);
  require(l >= 0, key, "link '" + name + "' is not in " + c.urdf_path);
  const link_frame& f = model.links[static_cast<std::size_t>(l)];
  require(f.body >= 0, key, "link '" + name + "' is welded to the world");
  return f;
}

sensor_mounts find_sensors(const robot_model& model, const robot_config& c, int servo_n,
                           std::vector<double> weld_angle) {
  require(!model.bodies.empty(), "urdf_path", c.urdf_path + " has no movable body");
  sensor_mounts m;
  if (!c.imu_link.empty()) {
    const link_frame& f = movable_link(model, c, "imu_link", c.imu_link);
    m.imu_body = f.body;
    m.imu_in_body = to_eigen(f.in_body);
  }
  m.joint_of_servo.assign(static_cast<std::size_t>(servo_n), -1);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (model.joints[j].servo_id > 0) {
      m.joint_of_servo[static_cast<std::size_t>(model.joints[j].servo_id - 1)] =
          static_cast<int>(j);
    }
  }
  m.weld_angle = std::move(weld_angle);
  return m;
}

std::pair<foot_frame, foot_frame> find_feet(const robot_model& model, const robot_config& c) {
  require(c.left_foot_link.empty() == c.right_foot_link.empty(), "left_foot_link",
          "set both foot links or neither");
  if (c.left_foot_link.empty()) return {};
  const link_frame& l = movable_link(model, c, "left_foot_link", c.left_foot_link);
  const link_frame& r = movable_link(model, c, "right_foot_link", c.right_foot_link);
  return {foot_frame{l.body, to_eigen(l.in_body.rotation)},
          foot_frame{r.body, to_eigen(r.in_body.rotation)}};
}

// the body of each robot_config::contact_links entry
std::vector<int> find_contact_links(const robot_model& model, const robot_config& c) {
  std::vector<int> bodies;
  for (const std::string& name : c.contact_links) {
    bodies.push_back(movable_link(model, c, "contact_links", name).body);
  }
  return bodies;
}

}  // namespace

struct robot_sim::impl {
  // ---- run constants (members in construction order)
  robot_config cfg;
  robot_model model;
  int servo_n;  // of the model as loaded: welding a servo keeps its ID
  sensor_mounts sensors;
  std::pair<foot_frame, foot_frame> feet;  // left, right
  std::vector<int> contact_bodies;         // by contact_links entry
  std::vector<servo_config> servos;        // by model joint (after welding)
  ode_world world;
  contacts contact;

  // ---- evolving
  plant_state state;
  robot_outputs out;

  explicit impl(robot_config c)
      : cfg(std::move(c)),
        model(load_checked_model(cfg)),
        servo_n(model.servo_count()),
        sensors(find_sensors(model, cfg, servo_n, weld_rigid_servos(model, cfg))),
        feet(find_feet(model, cfg)),
        contact_bodies(find_contact_links(model, cfg)),
        servos(servo_models(model, cfg)),
        world(model, cfg),
        contact(world, cfg.contact, measured_bodies()) {
    set_up_joint_motors(world, servos);
    reset();
  }

  // bodies whose floor force is reported: the feet, then the contact links
  [[nodiscard]] std::vector<int> measured_bodies() const {
    std::vector<int> b = {feet.first.body, feet.second.body};
    b.insert(b.end(), contact_bodies.begin(), contact_bodies.end());
    return b;
  }

  void reset() {
    ensure_thread_data();
    std::vector<double> q(model.joints.size(), 0.0);
    state = plant_state{};
    state.targets.assign(static_cast<std::size_t>(servo_n), 0.0);
    for (int id = 1; id <= servo_n; ++id) {
      const int j = sensors.joint_of_servo[static_cast<std::size_t>(id - 1)];
      const double v =
          cfg.initial_pose.empty() ? 0.0 : cfg.initial_pose[static_cast<std::size_t>(id - 1)];
      state.targets[static_cast<std::size_t>(id - 1)] = v;
      if (j >= 0) {
        q[static_cast<std::size_t>(j)] = clamp_target(servos[static_cast<std::size_t>(j)],
                                                      model.joints[static_cast<std::size_t>(j)], v);
      }
    }
    // mimic joints start where they will be held (their masters come first or later in q)
    for (std::size_t j = 0; j < q.size(); ++j) {
      const model_joint& mj = model.joints[j];
      if (mj.mimic_joint >= 0) {
        q[j] = mj.mimic_multiplier * q[static_cast<std::size_t>(mj.mimic_joint)] + mj.mimic_offset;
      }
    }
    state.servo_velocity.assign(model.joints.size(), 0.0);
    state.joint_torques.assign(static_cast<std::size_t>(servo_n), 0.0);
    state.link_forces.assign(contact_bodies.size(), Eigen::Vector3d::Zero());

    pose root;
    if (!model.fixed_base) {
      root = standing_root(model, q, feet.first, feet.second, cfg.reset_clearance);
    }
    world.place_bodies(model.forward_kinematics(root, q));
    contact.clear(world);
    // at rest the accelerometer reads the gravity reaction
    state.acc = imu_rotation(world, sensors).transpose() * Eigen::Vector3d(0, 0, cfg.gravity);
    read_sensors(world, sensors, cfg.imu, state, out);
  }

  void physics_step() {
    const double dt = cfg.physics_step;
    const Eigen::Vector3d v_before = imu_velocity(world, sensors);
    drive_joints(world, servos, dt, state.targets, state.servo_velocity);
    drive_mimic_joints(world, dt, cfg.mimic_force_limit, state.servo_velocity);
    if (state.push_x != 0.0 || state.push_y != 0.0) {
      dBodyAddForce(world.bodies[0], state.push_x, state.push_y, 0.0);
    }
    state.max_penetration = contact.collide(world);
    if (cfg.solver == physics_solver::world_step) {
      dWorldStep(world.world, dt);
    } else {
      dWorldQuickStep(world.world, dt);
    }
    read_step_forces();
    contact.clear(world);
    world.renormalize();
    ++state.steps;
    state.time = static_cast<double>(state.steps) * dt;

    const Eigen::Vector3d a = (imu_velocity(world, sensors) - v_before) / dt;
    state.acc = specific_force(imu_rotation(world, sensors), a, cfg.gravity);

    for (std::size_t b = 0; b < world.bodies.size(); ++b) {
      const dReal* p = dBodyGetPosition(world.bodies[b]);
      const dReal* w = dBodyGetAngularVel(world.bodies[b]);
      if (!std::isfinite(p[0] + p[1] + p[2] + w[0] + w[1] + w[2])) {
        throw std::runtime_error(cfg.urdf_path +
                                 ": simulation diverged at t = " + std::to_string(state.time) +
                                 " s (body of link '" + model.bodies[b].link + "')");
      }
    }
    if (!model.fixed_base && !state.fallen) {
      Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
      root.linear() = body_rotation(world.bodies[0]);
      root.translation() = world.root_origin();
      if (is_fallen(to_pose(root), cfg)) state.fallen = true;
    }
  }

  // the forces of the physics step just taken, kept in the state (ODE's feedback is not)
  void read_step_forces() {
    const std::vector<Eigen::Vector3d> floor = contact.floor_forces();
    auto floor_force = [&](int body) {
      return body >= 0 ? floor[static_cast<std::size_t>(body)] : Eigen::Vector3d::Zero();
    };
    state.left_force = floor_force(feet.first.body);
    state.right_force = floor_force(feet.second.body);
    for (std::size_t k = 0; k < contact_bodies.size(); ++k) {
      state.link_forces[k] = floor_force(contact_bodies[k]);
    }
    for (std::size_t i = 0; i < sensors.joint_of_servo.size(); ++i) {
      const int j = sensors.joint_of_servo[i];
      state.joint_torques[i] = j >= 0 ? motor_effort(world, static_cast<std::size_t>(j)) : 0.0;
    }
  }

  void step(double h) {
    if (!std::isfinite(h) || h < 0.0) {
      throw std::invalid_argument("robot_sim::step: h must be finite and >= 0, got " +
                                  std::to_string(h));
    }
    ensure_thread_data();
    state.requested_time += h;
    const double dt = cfg.physics_step;
    while (static_cast<double>(state.steps + 1) * dt <= state.requested_time + 1e-9 * dt) {
      physics_step();
    }
    read_sensors(world, sensors, cfg.imu, state, out);
  }

  [[nodiscard]] std::vector<std::uint8_t> save() const {
    return encode_state_image({world.body_states(), state});
  }

  void restore(std::span<const std::uint8_t> image) {
    plant_snapshot s =
        decode_state_image(image, world.bodies.size(), model.joints.size(),
                           static_cast<std::size_t>(servo_n), contact_bodies.size(), cfg.urdf_path);
    ensure_thread_data();
    world.set_body_states(s.bodies);
    state = std::move(s.plant);
    contact.clear(world);
    read_sensors(world, sensors, cfg.imu, state, out);
  }
};

robot_sim::robot_sim(robot_config config) : impl_(std::make_unique<impl>(std::move(config))) {}
robot_sim::~robot_sim() = default;
robot_sim::robot_sim(robot_sim&&) noexcept = default;
robot_sim& robot_sim::operator=(robot_sim&&) noexcept = default;

const robot_config& robot_sim::config() const {
  return impl_->cfg;
}
const robot_model& robot_sim::model() const {
  return impl_->model;
}
int robot_sim::servo_count() const {
  return impl_->servo_n;
}

void robot_sim::reset() {
  impl_->reset();
}

void robot_sim::set_joint_targets(std::span<const double> targets) {
  if (static_cast<int>(targets.size()) != impl_->servo_n) {
    throw std::invalid_argument("robot_sim::set_joint_targets: expected " +
                                std::to_string(impl_->servo_n) + " targets, got " +
                                std::to_string(targets.size()));
  }
  for (std::size_t k = 0; k < targets.size(); ++k) {
    if (!std::isfinite(targets[k])) {
      throw std::invalid_argument("robot_sim::set_joint_targets: target of servo " +
                                  std::to_string(k + 1) + " is not finite");
    }
  }
  impl_->state.targets.assign(targets.begin(), targets.end());
}

void robot_sim::set_push(double fx, double fy) {
  if (!std::isfinite(fx) || !std::isfinite(fy)) {
    throw std::invalid_argument("robot_sim::set_push: force is not finite");
  }
  impl_->state.push_x = fx;
  impl_->state.push_y = fy;
}

void robot_sim::step(double h) {
  impl_->step(h);
}

const robot_outputs& robot_sim::outputs() const {
  return impl_->out;
}

std::vector<std::uint8_t> robot_sim::save_state() const {
  return impl_->save();
}

void robot_sim::restore_state(std::span<const std::uint8_t> image) {
  impl_->restore(image);
}

}  // namespace stride::robot
