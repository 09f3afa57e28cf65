// robot_sim: robot_model → ODE world, servo model, sensors, bit-exact state images.
#include "stride/robot/robot_sim.hpp"

#include <ode/ode.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

#include "frames.hpp"

namespace stride::robot {

namespace {

constexpr double k_pi = 3.14159265358979323846;
constexpr char k_state_magic[8] = {'S', 'T', 'R', 'I', 'D', 'E', 'R', 'B'};
constexpr std::uint32_t k_state_version = 1;

// dInitODE2 once per process, before any world exists; dCloseODE when the library unloads
// (in an FMU: at dlclose), which frees ODE's global caches
void init_ode_once() {
  struct ode_library {
    ode_library() { dInitODE2(0); }
    ~ode_library() { dCloseODE(); }
  };
  static const ode_library library;
}

// the ODE API asks every thread that uses it to allocate its data (a no-op in Debian's non-TLS
// build, required by builds with TLS)
void ensure_thread_data() {
  thread_local bool done = false;
  if (!done) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    done = true;
  }
}

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw std::invalid_argument("robot_config." + key + ": " + what);
}

void validate(const robot_config& c) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  require(positive(c.physics_step), "physics_step", "must be > 0");
  require(c.quick_step_iterations > 0, "quick_step_iterations", "must be > 0");
  require(non_negative(c.gravity), "gravity", "must be >= 0");
  require(non_negative(c.erp) && c.erp <= 1.0, "erp", "must be in [0, 1]");
  require(non_negative(c.cfm), "cfm", "must be >= 0");
  require(non_negative(c.contact.mu), "contact.mu", "must be >= 0");
  require(non_negative(c.contact.bounce) && c.contact.bounce <= 1.0, "contact.bounce",
          "must be in [0, 1]");
  require(non_negative(c.contact.bounce_velocity), "contact.bounce_velocity", "must be >= 0");
  require(non_negative(c.contact.soft_erp) && c.contact.soft_erp <= 1.0, "contact.soft_erp",
          "must be in [0, 1]");
  require(non_negative(c.contact.soft_cfm), "contact.soft_cfm", "must be >= 0");
  require(c.contact.max_contacts > 0 && c.contact.max_contacts <= 64, "contact.max_contacts",
          "must be in 1..64");
  require(non_negative(c.servo.p_gain), "servo.p_gain", "must be >= 0");
  require(positive(c.servo.max_velocity), "servo.max_velocity", "must be > 0");
  require(non_negative(c.servo.max_acceleration), "servo.max_acceleration", "must be >= 0");
  require(c.servo.torque_limit >= 0.0, "servo.torque_limit", "must be >= 0 (infinity: unlimited)");
  require(non_negative(c.servo.damping), "servo.damping", "must be >= 0");
  require(non_negative(c.servo.compliance), "servo.compliance", "must be >= 0");
  require(non_negative(c.servo.static_friction), "servo.static_friction", "must be >= 0");
  require(positive(c.imu.gyro_counts_per_rad_s), "imu.gyro_counts_per_rad_s", "must be > 0");
  require(positive(c.imu.gyro_range), "imu.gyro_range", "must be > 0");
  require(positive(c.imu.acc_range), "imu.acc_range", "must be > 0");
  require(non_negative(c.fall_tilt), "fall_tilt", "must be >= 0");
  require(std::isfinite(c.fall_height), "fall_height", "must be finite");
  require(std::isfinite(c.reset_clearance), "reset_clearance", "must be finite");
  for (double q : c.initial_pose) require(std::isfinite(q), "initial_pose", "must be finite");
}

// lowest world z of a shape placed at `t`
double lowest_point(const collision_shape& s, const Eigen::Isometry3d& t) {
  const Eigen::Vector3d c = t.translation();
  const Eigen::Matrix3d& r = t.linear();
  switch (s.type) {
    case shape_type::box:
      return c.z() - 0.5 * (std::abs(r(2, 0)) * s.size[0] + std::abs(r(2, 1)) * s.size[1] +
                            std::abs(r(2, 2)) * s.size[2]);
    case shape_type::sphere:
      return c.z() - s.size[0];
    case shape_type::cylinder: {
      const double az = std::abs(r(2, 2));
      return c.z() - 0.5 * az * s.size[1] - s.size[0] * std::sqrt(std::max(0.0, 1.0 - az * az));
    }
    case shape_type::capsule:
      return c.z() - 0.5 * std::abs(r(2, 2)) * s.size[1] - s.size[0];
  }
  return c.z();
}

Eigen::Matrix3d body_rotation(dBodyID b) {
  const dReal* r = dBodyGetRotation(b);  // 3x4 row-major
  Eigen::Matrix3d m;
  m << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
  return m;
}

Eigen::Vector3d vec(const dReal* v) {
  return {v[0], v[1], v[2]};
}

// byte image helpers
class writer {
 public:
  void raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    data.insert(data.end(), b, b + n);
  }
  void f64(double v) { raw(&v, sizeof v); }
  void u32(std::uint32_t v) { raw(&v, sizeof v); }
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
  [[nodiscard]] bool at_end() const { return pos_ == data_.size(); }

 private:
  std::span<const std::uint8_t> data_;
  std::size_t pos_ = 0;
};

}  // namespace

struct robot_sim::impl {
  // ---- run constants
  robot_config cfg;
  robot_model model;
  int servo_n = 0;
  int imu_body = 0;
  Eigen::Isometry3d imu_in_body = Eigen::Isometry3d::Identity();
  int left_foot_body = -1;
  int right_foot_body = -1;
  Eigen::Matrix3d left_foot_in_body = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d right_foot_in_body = Eigen::Matrix3d::Identity();
  std::vector<int> joint_of_servo;  // by servo id - 1, -1 = none
  std::vector<double> weld_angle;   // by servo id - 1, NaN = not welded

  // ---- ODE objects (their body states are part of the dynamic state)
  dWorldID world = nullptr;
  dJointGroupID contact_group = nullptr;
  dThreadingImplementationID threading = nullptr;
  dGeomID floor = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<std::array<dReal, 4>> quat_set;  // last quaternion given to dBodySetQuaternion
  std::vector<dJointID> joints;                // by model joint
  struct geom_entry {
    dGeomID id;
    int body;  // -1 = world
  };
  std::vector<geom_entry> geoms;                 // robot geoms, canonical order
  std::vector<geom_entry> world_geoms;           // fixed-base world shapes
  std::vector<std::pair<int, int>> self_pairs;   // indices into geoms
  std::vector<std::pair<int, int>> world_pairs;  // (geom, world geom)
  std::vector<dContact> contact_buffer;
  std::vector<dJointFeedback> feedback;             // one per possible foot contact
  std::vector<std::pair<int, int>> feedback_owner;  // (slot, foot: 0 left, 1 right) per step
  std::size_t feedback_used = 0;

  // ---- evolving values that ODE does not hold
  struct sim_state {
    double time = 0.0;
    double requested_time = 0.0;
    std::int64_t steps = 0;
    std::vector<double> targets;         // by servo id - 1
    std::vector<double> servo_velocity;  // commanded velocity memory, by model joint
    double push_x = 0.0;
    double push_y = 0.0;
    bool fallen = false;
    Eigen::Vector3d acc = Eigen::Vector3d::Zero();
    Eigen::Vector3d left_force = Eigen::Vector3d::Zero();
    Eigen::Vector3d right_force = Eigen::Vector3d::Zero();
    double max_penetration = 0.0;
  } state;

  robot_outputs out;

  explicit impl(robot_config c) : cfg(std::move(c)) {
    validate(cfg);
    model = load_robot_model(cfg.urdf_path);
    servo_n = model.servo_count();
    require(cfg.initial_pose.empty() || static_cast<int>(cfg.initial_pose.size()) == servo_n,
            "initial_pose",
            "needs " + std::to_string(servo_n) + " values (one per servo ID of " + cfg.urdf_path +
                "), got " + std::to_string(cfg.initial_pose.size()));
    weld_angle.assign(static_cast<std::size_t>(servo_n), std::numeric_limits<double>::quiet_NaN());
    for (int id : cfg.rigid_servos) {
      const int j = model.joint_of_servo(id);
      require(j >= 0, "rigid_servos",
              "servo " + std::to_string(id) + " is not in " + cfg.urdf_path);
      const double q0 =
          cfg.initial_pose.empty() ? 0.0 : cfg.initial_pose[static_cast<std::size_t>(id - 1)];
      const model_joint& mj = model.joints[static_cast<std::size_t>(j)];
      const double q = mj.limited ? std::clamp(q0, mj.lower, mj.upper) : q0;
      weld_angle[static_cast<std::size_t>(id - 1)] = q;
      weld_joint(model, j, q);
    }
    resolve_links();
    init_ode_once();
    ensure_thread_data();
    try {
      build_world();
      reset();
    } catch (...) {
      destroy_world();
      throw;
    }
  }

  ~impl() { destroy_world(); }

  void resolve_links() {
    auto find = [&](const std::string& key, const std::string& name) -> const link_frame& {
      const int l = model.find_link(name);
      require(l >= 0, key, "link '" + name + "' is not in " + cfg.urdf_path);
      const link_frame& f = model.links[static_cast<std::size_t>(l)];
      require(f.body >= 0, key, "link '" + name + "' is welded to the world");
      return f;
    };
    require(!model.bodies.empty(), "urdf_path", cfg.urdf_path + " has no movable body");
    if (!cfg.imu_link.empty()) {
      const link_frame& f = find("imu_link", cfg.imu_link);
      imu_body = f.body;
      imu_in_body = to_eigen(f.in_body);
    }
    require(cfg.left_foot_link.empty() == cfg.right_foot_link.empty(), "left_foot_link",
            "set both foot links or neither");
    if (!cfg.left_foot_link.empty()) {
      const link_frame& l = find("left_foot_link", cfg.left_foot_link);
      const link_frame& r = find("right_foot_link", cfg.right_foot_link);
      left_foot_body = l.body;
      right_foot_body = r.body;
      left_foot_in_body = to_eigen(l.in_body.rotation);
      right_foot_in_body = to_eigen(r.in_body.rotation);
    }
    joint_of_servo.assign(static_cast<std::size_t>(servo_n), -1);
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (model.joints[j].servo_id > 0) {
        joint_of_servo[static_cast<std::size_t>(model.joints[j].servo_id - 1)] =
            static_cast<int>(j);
      }
    }
  }

  dGeomID make_geom(const collision_shape& s) {
    switch (s.type) {
      case shape_type::box:
        return dCreateBox(nullptr, s.size[0], s.size[1], s.size[2]);
      case shape_type::sphere:
        return dCreateSphere(nullptr, s.size[0]);
      case shape_type::cylinder:
        return dCreateCylinder(nullptr, s.size[0], s.size[1]);
      case shape_type::capsule:
        return dCreateCapsule(nullptr, s.size[0], s.size[1]);
    }
    return nullptr;
  }

  static void set_rotation(dGeomID g, const Eigen::Matrix3d& r, bool offset) {
    dMatrix3 m = {r(0, 0), r(0, 1), r(0, 2), 0,       r(1, 0), r(1, 1),
                  r(1, 2), 0,       r(2, 0), r(2, 1), r(2, 2), 0};
    if (offset) {
      dGeomSetOffsetRotation(g, m);
    } else {
      dGeomSetRotation(g, m);
    }
  }

  void build_world() {
    world = dWorldCreate();
    threading = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                         threading);
    dWorldSetGravity(world, 0, 0, -cfg.gravity);
    dWorldSetERP(world, cfg.erp);
    dWorldSetCFM(world, cfg.cfm);
    dWorldSetAutoDisableFlag(world, 0);
    dWorldSetQuickStepNumIterations(world, cfg.quick_step_iterations);
    contact_group = dJointGroupCreate(0);
    // geoms live in no space: pairs are collided explicitly in a fixed order (see collide())
    floor = dCreatePlane(nullptr, 0, 0, 1, 0);

    // bodies at the zero pose with the root frame at the world origin; joints attached now
    // measure their positions from this configuration
    const std::vector<Eigen::Isometry3d> frames =
        forward_kinematics(Eigen::Isometry3d::Identity(), {});
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const rigid_body& rb = model.bodies[b];
      dBodyID body = dBodyCreate(world);
      dMass m;
      dMassSetParameters(&m, rb.mass, 0, 0, 0, rb.inertia[0], rb.inertia[1], rb.inertia[2],
                         rb.inertia[3], rb.inertia[4], rb.inertia[5]);
      if (dMassCheck(&m) == 0) {
        throw model_error(cfg.urdf_path + ": link '" + rb.link +
                          "': mass parameters rejected by ODE");
      }
      dBodySetMass(body, &m);
      bodies.push_back(body);
      quat_set.push_back({1.0, 0.0, 0.0, 0.0});
      for (const collision_shape& s : rb.shapes) {
        dGeomID g = make_geom(s);
        dGeomSetBody(g, body);
        const Eigen::Vector3d p = to_eigen(s.origin.position) - to_eigen(rb.com);
        dGeomSetOffsetPosition(g, p.x(), p.y(), p.z());
        set_rotation(g, to_eigen(s.origin.rotation), true);
        geoms.push_back({g, static_cast<int>(b)});
      }
    }
    place_bodies(frames);
    for (const collision_shape& s : model.world_shapes) {
      dGeomID g = make_geom(s);
      const Eigen::Isometry3d t = to_eigen(s.origin);
      dGeomSetPosition(g, t.translation().x(), t.translation().y(), t.translation().z());
      set_rotation(g, t.linear(), false);
      world_geoms.push_back({g, -1});
    }

    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const model_joint& mj = model.joints[j];
      const Eigen::Isometry3d& child = frames[static_cast<std::size_t>(mj.child_body)];
      const Eigen::Vector3d axis = child.linear() * to_eigen(mj.axis);
      const Eigen::Vector3d anchor = child.translation();
      dBodyID b1 = bodies[static_cast<std::size_t>(mj.child_body)];
      dBodyID b2 = mj.parent_body >= 0 ? bodies[static_cast<std::size_t>(mj.parent_body)] : nullptr;
      dJointID id = nullptr;
      if (mj.type == joint_type::prismatic) {
        id = dJointCreateSlider(world, nullptr);
        dJointAttach(id, b1, b2);
        dJointSetSliderAxis(id, axis.x(), axis.y(), axis.z());
        if (mj.limited) {
          dJointSetSliderParam(id, dParamLoStop, mj.lower);
          dJointSetSliderParam(id, dParamHiStop, mj.upper);
        }
      } else {
        id = dJointCreateHinge(world, nullptr);
        dJointAttach(id, b1, b2);
        dJointSetHingeAnchor(id, anchor.x(), anchor.y(), anchor.z());
        dJointSetHingeAxis(id, axis.x(), axis.y(), axis.z());
        // ODE hinge stops only work inside [-pi, pi]
        if (mj.limited && (mj.lower > -k_pi || mj.upper < k_pi)) {
          dJointSetHingeParam(id, dParamLoStop, std::max(mj.lower, -k_pi));
          dJointSetHingeParam(id, dParamHiStop, std::min(mj.upper, k_pi));
        }
      }
      joints.push_back(id);
      // passive joints: Coulomb friction through a zero-velocity motor
      if (mj.servo_id == 0) {
        set_motor(j, 0.0, mj.friction);
      } else if (cfg.servo.compliance > 0.0) {
        // motor row λ = (v − ω)/CFM: a viscous, back-EMF-like servo instead of a rigid one
        if (mj.type == joint_type::prismatic) {
          dJointSetSliderParam(id, dParamCFM, 1.0 / cfg.servo.compliance);
        } else {
          dJointSetHingeParam(id, dParamCFM, 1.0 / cfg.servo.compliance);
        }
      }
    }

    // collision pairs: every robot geom against the floor; robot geom pairs on bodies that are
    // not joined by a joint; fixed-base world shapes against bodies not jointed to the world
    auto connected = [&](int a, int b) {
      for (const model_joint& mj : model.joints) {
        if ((mj.parent_body == a && mj.child_body == b) ||
            (mj.parent_body == b && mj.child_body == a)) {
          return true;
        }
      }
      return false;
    };
    if (cfg.contact.self_collision) {
      for (std::size_t a = 0; a < geoms.size(); ++a) {
        for (std::size_t b = a + 1; b < geoms.size(); ++b) {
          if (geoms[a].body == geoms[b].body || connected(geoms[a].body, geoms[b].body)) continue;
          self_pairs.push_back({static_cast<int>(a), static_cast<int>(b)});
        }
      }
    }
    for (std::size_t a = 0; a < geoms.size(); ++a) {
      for (std::size_t w = 0; w < world_geoms.size(); ++w) {
        if (connected(geoms[a].body, -1)) continue;
        world_pairs.push_back({static_cast<int>(a), static_cast<int>(w)});
      }
    }
    contact_buffer.resize(static_cast<std::size_t>(cfg.contact.max_contacts));
    std::size_t foot_geoms = 0;
    for (const geom_entry& g : geoms) {
      if (g.body >= 0 && (g.body == left_foot_body || g.body == right_foot_body)) ++foot_geoms;
    }
    feedback.resize(foot_geoms * static_cast<std::size_t>(cfg.contact.max_contacts) * 2 + 1);
  }

  void destroy_world() {
    if (world == nullptr) return;
    ensure_thread_data();
    for (const geom_entry& g : geoms) dGeomDestroy(g.id);
    for (const geom_entry& g : world_geoms) dGeomDestroy(g.id);
    if (floor != nullptr) dGeomDestroy(floor);
    if (contact_group != nullptr) dJointGroupDestroy(contact_group);
    dWorldSetStepThreadingImplementation(world, nullptr, nullptr);
    dWorldDestroy(world);  // destroys bodies and joints
    dThreadingFreeImplementation(threading);
    world = nullptr;
  }

  // robot_model::forward_kinematics in Eigen frames
  std::vector<Eigen::Isometry3d> forward_kinematics(const Eigen::Isometry3d& root,
                                                    const std::vector<double>& q) const {
    std::vector<Eigen::Isometry3d> frames;
    for (const pose& p : model.forward_kinematics(to_pose(root), q)) frames.push_back(to_eigen(p));
    return frames;
  }

  void place_bodies(const std::vector<Eigen::Isometry3d>& frames) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const Eigen::Isometry3d& t = frames[b];
      const Eigen::Vector3d p = t * to_eigen(model.bodies[b].com);
      Eigen::Quaterniond q(t.linear());
      q.normalize();
      const dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
      dBodySetPosition(bodies[b], p.x(), p.y(), p.z());
      dBodySetQuaternion(bodies[b], dq);
      dBodySetLinearVel(bodies[b], 0, 0, 0);
      dBodySetAngularVel(bodies[b], 0, 0, 0);
      dBodySetForce(bodies[b], 0, 0, 0);
      dBodySetTorque(bodies[b], 0, 0, 0);
    }
    renormalize();
  }

  // ODE normalises a quaternion whenever it is set, and normalising is not idempotent in floating
  // point. After every change the quaternion is read back and set once more; the value that was
  // set (quat_set) goes into state images, so a restore sets the very same value and ODE ends
  // with bit-identical orientations on both paths.
  void renormalize() {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      std::memcpy(quat_set[b].data(), dBodyGetQuaternion(bodies[b]), sizeof(dQuaternion));
      dBodySetQuaternion(bodies[b], quat_set[b].data());
    }
  }

  double joint_position(std::size_t j) const {
    return model.joints[j].type == joint_type::prismatic ? dJointGetSliderPosition(joints[j])
                                                         : dJointGetHingeAngle(joints[j]);
  }

  double joint_rate(std::size_t j) const {
    return model.joints[j].type == joint_type::prismatic ? dJointGetSliderPositionRate(joints[j])
                                                         : dJointGetHingeAngleRate(joints[j]);
  }

  void set_motor(std::size_t j, double velocity, double fmax) {
    if (model.joints[j].type == joint_type::prismatic) {
      dJointSetSliderParam(joints[j], dParamVel, velocity);
      dJointSetSliderParam(joints[j], dParamFMax, fmax);
    } else {
      dJointSetHingeParam(joints[j], dParamVel, velocity);
      dJointSetHingeParam(joints[j], dParamFMax, fmax);
    }
  }

  void add_joint_effort(std::size_t j, double effort) {
    if (model.joints[j].type == joint_type::prismatic) {
      dJointAddSliderForce(joints[j], effort);
    } else {
      dJointAddHingeTorque(joints[j], effort);
    }
  }

  double clamp_target(std::size_t j, double target) const {
    const model_joint& mj = model.joints[j];
    if (cfg.servo.clamp_to_limits && mj.limited) return std::clamp(target, mj.lower, mj.upper);
    return target;
  }

  void reset() {
    ensure_thread_data();
    std::vector<double> q(model.joints.size(), 0.0);
    state = sim_state{};
    state.targets.assign(static_cast<std::size_t>(servo_n), 0.0);
    for (int id = 1; id <= servo_n; ++id) {
      const int j = joint_of_servo[static_cast<std::size_t>(id - 1)];
      const double v =
          cfg.initial_pose.empty() ? 0.0 : cfg.initial_pose[static_cast<std::size_t>(id - 1)];
      state.targets[static_cast<std::size_t>(id - 1)] = v;
      if (j >= 0) q[static_cast<std::size_t>(j)] = clamp_target(static_cast<std::size_t>(j), v);
    }
    state.servo_velocity.assign(model.joints.size(), 0.0);

    Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
    if (!model.fixed_base) {
      // level the feet: the root orientation undoes the mean foot orientation
      if (left_foot_body >= 0) {
        const auto frames = forward_kinematics(Eigen::Isometry3d::Identity(), q);
        const Eigen::Quaterniond ql(frames[static_cast<std::size_t>(left_foot_body)].linear() *
                                    left_foot_in_body);
        const Eigen::Quaterniond qr(frames[static_cast<std::size_t>(right_foot_body)].linear() *
                                    right_foot_in_body);
        root.linear() = ql.slerp(0.5, qr).normalized().toRotationMatrix().transpose();
      }
      // drop the robot so its lowest collision point is at reset_clearance
      const auto frames = forward_kinematics(root, q);
      double lowest = std::numeric_limits<double>::infinity();
      for (std::size_t b = 0; b < model.bodies.size(); ++b) {
        for (const collision_shape& s : model.bodies[b].shapes) {
          lowest = std::min(lowest, lowest_point(s, frames[b] * to_eigen(s.origin)));
        }
      }
      if (std::isfinite(lowest)) root.translation().z() = cfg.reset_clearance - lowest;
    }
    place_bodies(forward_kinematics(root, q));
    dJointGroupEmpty(contact_group);
    feedback_used = 0;
    feedback_owner.clear();
    const Eigen::Matrix3d r_imu =
        body_rotation(bodies[static_cast<std::size_t>(imu_body)]) * imu_in_body.linear();
    state.acc = r_imu.transpose() * Eigen::Vector3d(0, 0, cfg.gravity);
    update_outputs();
  }

  void add_contacts(int n, dBodyID b1, dBodyID b2, int foot) {
    const contact_config& cc = cfg.contact;
    for (int k = 0; k < n; ++k) {
      dContact& c = contact_buffer[static_cast<std::size_t>(k)];
      c.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
      if (cc.bounce > 0.0) c.surface.mode |= dContactBounce;
      c.surface.mu = cc.mu;
      c.surface.bounce = cc.bounce;
      c.surface.bounce_vel = cc.bounce_velocity;
      c.surface.soft_erp = cc.soft_erp;
      c.surface.soft_cfm = cc.soft_cfm;
      dJointID id = dJointCreateContact(world, contact_group, &c);
      dJointAttach(id, b1, b2);
      if (foot >= 0 && feedback_used < feedback.size()) {
        dJointSetFeedback(id, &feedback[feedback_used]);
        feedback_owner.push_back({static_cast<int>(feedback_used), foot});
        ++feedback_used;
      }
    }
  }

  // contact joints for this step, always created in the same order
  void collide() {
    const int max_c = cfg.contact.max_contacts;
    const int stride = static_cast<int>(sizeof(dContact));
    feedback_used = 0;
    feedback_owner.clear();
    state.max_penetration = 0.0;
    for (const geom_entry& g : geoms) {
      const int n = dCollide(g.id, floor, max_c, &contact_buffer[0].geom, stride);
      if (n <= 0) continue;
      for (int k = 0; k < n; ++k) {
        state.max_penetration =
            std::max(state.max_penetration, contact_buffer[static_cast<std::size_t>(k)].geom.depth);
      }
      const int foot = g.body == left_foot_body ? 0 : (g.body == right_foot_body ? 1 : -1);
      add_contacts(n, bodies[static_cast<std::size_t>(g.body)], nullptr, foot);
    }
    auto overlap = [](dGeomID a, dGeomID b) {
      dReal aa[6];
      dReal bb[6];
      dGeomGetAABB(a, aa);
      dGeomGetAABB(b, bb);
      return aa[0] <= bb[1] && bb[0] <= aa[1] && aa[2] <= bb[3] && bb[2] <= aa[3] &&
             aa[4] <= bb[5] && bb[4] <= aa[5];
    };
    for (const auto& [a, b] : self_pairs) {
      const geom_entry& ga = geoms[static_cast<std::size_t>(a)];
      const geom_entry& gb = geoms[static_cast<std::size_t>(b)];
      if (!overlap(ga.id, gb.id)) continue;
      const int n = dCollide(ga.id, gb.id, max_c, &contact_buffer[0].geom, stride);
      if (n > 0) {
        add_contacts(n, bodies[static_cast<std::size_t>(ga.body)],
                     bodies[static_cast<std::size_t>(gb.body)], -1);
      }
    }
    for (const auto& [a, w] : world_pairs) {
      const geom_entry& ga = geoms[static_cast<std::size_t>(a)];
      const geom_entry& gw = world_geoms[static_cast<std::size_t>(w)];
      if (!overlap(ga.id, gw.id)) continue;
      const int n = dCollide(ga.id, gw.id, max_c, &contact_buffer[0].geom, stride);
      if (n > 0) add_contacts(n, bodies[static_cast<std::size_t>(ga.body)], nullptr, -1);
    }
  }

  Eigen::Vector3d imu_point_velocity() const {
    dBodyID b = bodies[static_cast<std::size_t>(imu_body)];
    const Eigen::Vector3d p =
        imu_in_body.translation() - to_eigen(model.bodies[static_cast<std::size_t>(imu_body)].com);
    dVector3 v;
    dBodyGetRelPointVel(b, p.x(), p.y(), p.z(), v);
    return vec(v);
  }

  void physics_step() {
    const double dt = cfg.physics_step;
    const Eigen::Vector3d v_before = imu_point_velocity();
    const servo_config& sc = cfg.servo;
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const model_joint& mj = model.joints[j];
      const double rate = joint_rate(j);
      if (mj.servo_id > 0) {
        const double target =
            clamp_target(j, state.targets[static_cast<std::size_t>(mj.servo_id - 1)]);
        double v = sc.p_gain * (target - joint_position(j));
        v = std::clamp(v, -sc.max_velocity, sc.max_velocity);
        if (sc.max_acceleration > 0.0) {
          const double dv = sc.max_acceleration * dt;
          v = std::clamp(v, state.servo_velocity[j] - dv, state.servo_velocity[j] + dv);
        }
        state.servo_velocity[j] = v;
        set_motor(j, v, std::max(sc.torque_limit, sc.static_friction));
        if (sc.damping > 0.0) add_joint_effort(j, -sc.damping * rate);
      } else if (mj.damping > 0.0) {
        add_joint_effort(j, -mj.damping * rate);
      }
    }
    if (state.push_x != 0.0 || state.push_y != 0.0) {
      dBodyAddForce(bodies[0], state.push_x, state.push_y, 0.0);
    }
    collide();
    if (cfg.solver == physics_solver::world_step) {
      dWorldStep(world, dt);
    } else {
      dWorldQuickStep(world, dt);
    }
    state.left_force.setZero();
    state.right_force.setZero();
    for (const auto& [slot, foot] : feedback_owner) {
      const Eigen::Vector3d f = vec(feedback[static_cast<std::size_t>(slot)].f1);
      (foot == 0 ? state.left_force : state.right_force) += f;
    }
    dJointGroupEmpty(contact_group);
    renormalize();
    ++state.steps;
    state.time = static_cast<double>(state.steps) * dt;

    const Eigen::Matrix3d r_imu =
        body_rotation(bodies[static_cast<std::size_t>(imu_body)]) * imu_in_body.linear();
    const Eigen::Vector3d a = (imu_point_velocity() - v_before) / dt;
    state.acc = r_imu.transpose() * (a + Eigen::Vector3d(0, 0, cfg.gravity));

    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const dReal* p = dBodyGetPosition(bodies[b]);
      const dReal* w = dBodyGetAngularVel(bodies[b]);
      if (!std::isfinite(p[0] + p[1] + p[2] + w[0] + w[1] + w[2])) {
        throw std::runtime_error(cfg.urdf_path +
                                 ": simulation diverged at t = " + std::to_string(state.time) +
                                 " s (body of link '" + model.bodies[b].link + "')");
      }
    }
    if (!model.fixed_base && !state.fallen) {
      const Eigen::Matrix3d r = body_rotation(bodies[0]);
      const Eigen::Vector3d origin =
          vec(dBodyGetPosition(bodies[0])) - r * to_eigen(model.bodies[0].com);
      const double tilt = std::acos(std::clamp(r(2, 2), -1.0, 1.0));
      if (tilt > cfg.fall_tilt || origin.z() < cfg.fall_height) state.fallen = true;
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
    update_outputs();
  }

  void update_outputs() {
    robot_outputs& o = out;
    o.time = state.time;
    o.joint_angles.assign(static_cast<std::size_t>(servo_n), 0.0);
    o.joint_velocities.assign(static_cast<std::size_t>(servo_n), 0.0);
    for (int id = 1; id <= servo_n; ++id) {
      const int j = joint_of_servo[static_cast<std::size_t>(id - 1)];
      if (!std::isnan(weld_angle[static_cast<std::size_t>(id - 1)])) {
        o.joint_angles[static_cast<std::size_t>(id - 1)] =
            weld_angle[static_cast<std::size_t>(id - 1)];
      }
      if (j < 0) continue;
      o.joint_angles[static_cast<std::size_t>(id - 1)] =
          joint_position(static_cast<std::size_t>(j));
      o.joint_velocities[static_cast<std::size_t>(id - 1)] =
          joint_rate(static_cast<std::size_t>(j));
    }
    dBodyID imu = bodies[static_cast<std::size_t>(imu_body)];
    const Eigen::Matrix3d r_imu = body_rotation(imu) * imu_in_body.linear();
    Eigen::Vector3d w = r_imu.transpose() * vec(dBodyGetAngularVel(imu));
    const double gr = cfg.imu.gyro_range;
    w = w.cwiseMax(-gr).cwiseMin(gr);
    o.gyro = {w.x(), w.y(), w.z()};
    // CM-730 board: gyro axes are the body axes rotated 180 deg about z (fact sheet 1.4)
    o.gyro_rl = -cfg.imu.gyro_counts_per_rad_s * w.x();
    o.gyro_fb = -cfg.imu.gyro_counts_per_rad_s * w.y();
    const double ar = cfg.imu.acc_range;
    const Eigen::Vector3d acc = state.acc.cwiseMax(-ar).cwiseMin(ar);
    o.acc = {acc.x(), acc.y(), acc.z()};

    const Eigen::Matrix3d r = body_rotation(bodies[0]);
    const Eigen::Vector3d origin =
        vec(dBodyGetPosition(bodies[0])) - r * to_eigen(model.bodies[0].com);
    o.base_position = {origin.x(), origin.y(), origin.z()};
    o.pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
    o.roll = std::atan2(r(2, 1), r(2, 2));
    o.yaw = std::atan2(r(1, 0), r(0, 0));

    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    double m = 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      c += model.bodies[b].mass * vec(dBodyGetPosition(bodies[b]));
      m += model.bodies[b].mass;
    }
    c /= m;
    o.com = {c.x(), c.y(), c.z()};
    o.left_foot_force = {state.left_force.x(), state.left_force.y(), state.left_force.z()};
    o.right_foot_force = {state.right_force.x(), state.right_force.y(), state.right_force.z()};
    o.max_penetration = state.max_penetration;
    o.fallen = state.fallen;
  }

  // ---- state images
  std::vector<std::uint8_t> save() const {
    writer w;
    w.raw(k_state_magic, sizeof k_state_magic);
    w.u32(k_state_version);
    w.u32(static_cast<std::uint32_t>(bodies.size()));
    w.u32(static_cast<std::uint32_t>(model.joints.size()));
    w.u32(static_cast<std::uint32_t>(servo_n));
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      dBodyID b = bodies[i];
      const dReal* p = dBodyGetPosition(b);
      const dReal* q = quat_set[i].data();
      const dReal* v = dBodyGetLinearVel(b);
      const dReal* a = dBodyGetAngularVel(b);
      for (int k = 0; k < 3; ++k) w.f64(p[k]);
      for (int k = 0; k < 4; ++k) w.f64(q[k]);
      for (int k = 0; k < 3; ++k) w.f64(v[k]);
      for (int k = 0; k < 3; ++k) w.f64(a[k]);
    }
    w.f64(state.time);
    w.f64(state.requested_time);
    w.raw(&state.steps, sizeof state.steps);
    for (double t : state.targets) w.f64(t);
    for (double v : state.servo_velocity) w.f64(v);
    w.f64(state.push_x);
    w.f64(state.push_y);
    w.u32(state.fallen ? 1U : 0U);
    for (int k = 0; k < 3; ++k) w.f64(state.acc[k]);
    for (int k = 0; k < 3; ++k) w.f64(state.left_force[k]);
    for (int k = 0; k < 3; ++k) w.f64(state.right_force[k]);
    w.f64(state.max_penetration);
    return std::move(w.data);
  }

  void restore(std::span<const std::uint8_t> image) {
    reader r(image);
    char magic[sizeof k_state_magic];
    r.raw(magic, sizeof magic);
    if (std::memcmp(magic, k_state_magic, sizeof magic) != 0) {
      throw std::invalid_argument("robot state image: not a robot_sim state");
    }
    if (r.u32() != k_state_version) throw std::invalid_argument("robot state image: wrong version");
    if (r.u32() != bodies.size() || r.u32() != model.joints.size() ||
        r.u32() != static_cast<std::uint32_t>(servo_n)) {
      throw std::invalid_argument("robot state image: saved from a different model than " +
                                  cfg.urdf_path);
    }
    struct body_image {
      double p[3], q[4], v[3], a[3];
    };
    std::vector<body_image> images(bodies.size());
    for (body_image& bi : images) {
      for (double& x : bi.p) x = r.f64();
      for (double& x : bi.q) x = r.f64();
      for (double& x : bi.v) x = r.f64();
      for (double& x : bi.a) x = r.f64();
    }
    sim_state s;
    s.time = r.f64();
    s.requested_time = r.f64();
    r.raw(&s.steps, sizeof s.steps);
    s.targets.resize(static_cast<std::size_t>(servo_n));
    for (double& t : s.targets) t = r.f64();
    s.servo_velocity.resize(model.joints.size());
    for (double& v : s.servo_velocity) v = r.f64();
    s.push_x = r.f64();
    s.push_y = r.f64();
    s.fallen = r.u32() != 0;
    for (int k = 0; k < 3; ++k) s.acc[k] = r.f64();
    for (int k = 0; k < 3; ++k) s.left_force[k] = r.f64();
    for (int k = 0; k < 3; ++k) s.right_force[k] = r.f64();
    s.max_penetration = r.f64();
    if (!r.at_end()) throw std::invalid_argument("robot state image: trailing bytes");

    ensure_thread_data();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const body_image& bi = images[b];
      dBodySetPosition(bodies[b], bi.p[0], bi.p[1], bi.p[2]);
      std::copy(std::begin(bi.q), std::end(bi.q), quat_set[b].begin());
      dBodySetQuaternion(bodies[b], quat_set[b].data());
      dBodySetLinearVel(bodies[b], bi.v[0], bi.v[1], bi.v[2]);
      dBodySetAngularVel(bodies[b], bi.a[0], bi.a[1], bi.a[2]);
      dBodySetForce(bodies[b], 0, 0, 0);
      dBodySetTorque(bodies[b], 0, 0, 0);
    }
    state = std::move(s);
    dJointGroupEmpty(contact_group);
    update_outputs();
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
