// robot_model → ODE world: bodies with their mass, geoms, hinge and slider joints, welds.
#include "ode_world.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "config_check.hpp"
#include "frames.hpp"

namespace stride::robot {

namespace {

constexpr double k_pi = 3.14159265358979323846;

// ODE's process-wide set-up when this library loads and its tear-down (freeing ODE's global
// caches) when it unloads (in an FMU: dlopen and dlclose). ODE counts them without atomics, so
// they must not run concurrently with another copy's: the importer loads and unloads FMU
// binaries one at a time, which covers static constructors and destructors, not lazy set-up.
struct ode_library {
  ode_library() { dInitODE2(0); }
  ~ode_library() { dCloseODE(); }
  ode_library(const ode_library&) = delete;
  ode_library& operator=(const ode_library&) = delete;
};
const ode_library g_ode_library;

void set_rotation(dGeomID g, const Eigen::Matrix3d& r, bool offset) {
  dMatrix3 m = {r(0, 0), r(0, 1), r(0, 2), 0,       r(1, 0), r(1, 1),
                r(1, 2), 0,       r(2, 0), r(2, 1), r(2, 2), 0};
  if (offset) {
    dGeomSetOffsetRotation(g, m);
  } else {
    dGeomSetRotation(g, m);
  }
}

}  // namespace

// the ODE API asks every thread that uses it to allocate its data (a no-op in Debian's non-TLS
// build, required by builds with TLS)
void ensure_thread_data() {
  thread_local bool done = false;
  if (!done) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    done = true;
  }
}

std::vector<double> weld_rigid_servos(robot_model& model, const robot_config& config) {
  std::vector<double> weld_angle(static_cast<std::size_t>(model.servo_count()),
                                 std::numeric_limits<double>::quiet_NaN());
  for (int id : config.rigid_servos) {
    const int j = model.joint_of_servo(id);
    require(j >= 0, "rigid_servos",
            "servo " + std::to_string(id) + " is not in " + config.urdf_path);
    const double q0 =
        config.initial_pose.empty() ? 0.0 : config.initial_pose[static_cast<std::size_t>(id - 1)];
    const model_joint& mj = model.joints[static_cast<std::size_t>(j)];
    const double q = mj.limited ? std::clamp(q0, mj.lower, mj.upper) : q0;
    weld_angle[static_cast<std::size_t>(id - 1)] = q;
    weld_joint(model, j, q);
  }
  return weld_angle;
}

dGeomID ode_world::make_geom(const collision_shape& s) {
  switch (s.type) {
    case shape_type::box:
      return dCreateBox(nullptr, s.size[0], s.size[1], s.size[2]);
    case shape_type::sphere:
      return dCreateSphere(nullptr, s.size[0]);
    case shape_type::cylinder:
      return dCreateCylinder(nullptr, s.size[0], s.size[1]);
    case shape_type::capsule:
      return dCreateCapsule(nullptr, s.size[0], s.size[1]);
    case shape_type::mesh: {
      static_assert(sizeof(dTriIndex) == sizeof(std::uint32_t), "ODE built with 16-bit indices");
      const triangle_mesh& m = *s.mesh;
      meshes.push_back(s.mesh);
      dTriMeshDataID data = dGeomTriMeshDataCreate();
      mesh_data.push_back(data);
      dGeomTriMeshDataBuildDouble(data, m.vertices.data(), 3 * sizeof(double),
                                  static_cast<int>(m.vertices.size() / 3), m.indices.data(),
                                  static_cast<int>(m.indices.size()), 3 * sizeof(std::uint32_t));
      dGeomID g = dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
      // temporal coherence would carry collision caches from step to step, which a state image
      // does not hold: contacts come from the current poses only
      for (int geom_class : {dSphereClass, dBoxClass, dCapsuleClass}) {
        dGeomTriMeshEnableTC(g, geom_class, 0);
      }
      return g;
    }
  }
  return nullptr;
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

ode_world::ode_world(const robot_model& m, const robot_config& config) : model(m) {
  ensure_thread_data();
  try {
    build(config);
  } catch (...) {
    destroy();
    throw;
  }
}

ode_world::~ode_world() {
  destroy();
}

void ode_world::build(const robot_config& config) {
  world = dWorldCreate();
  threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                       threading);
  dWorldSetGravity(world, 0, 0, -config.gravity);
  dWorldSetERP(world, config.erp);
  dWorldSetCFM(world, config.cfm);
  dWorldSetAutoDisableFlag(world, 0);
  dWorldSetQuickStepNumIterations(world, config.quick_step_iterations);
  contact_group = dJointGroupCreate(0);
  // geoms live in no space: pairs are collided explicitly in a fixed order (contacts.cpp)
  floor = dCreatePlane(nullptr, 0, 0, 1, 0);

  // bodies at the zero pose with the root frame at the world origin; joints attached now
  // measure their positions from this configuration
  const std::vector<pose> frames = model.forward_kinematics(pose{}, {});
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const rigid_body& rb = model.bodies[b];
    dBodyID body = dBodyCreate(world);
    dMass m;
    dMassSetParameters(&m, rb.mass, 0, 0, 0, rb.inertia[0], rb.inertia[1], rb.inertia[2],
                       rb.inertia[3], rb.inertia[4], rb.inertia[5]);
    if (dMassCheck(&m) == 0) {
      throw model_error(config.urdf_path + ": link '" + rb.link +
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

  for (const model_joint& mj : model.joints) {
    const Eigen::Isometry3d child = to_eigen(frames[static_cast<std::size_t>(mj.child_body)]);
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
  }
}

void ode_world::destroy() {
  if (world == nullptr) return;
  ensure_thread_data();
  for (const geom_entry& g : geoms) dGeomDestroy(g.id);
  for (const geom_entry& g : world_geoms) dGeomDestroy(g.id);
  if (floor != nullptr) dGeomDestroy(floor);
  // after the geoms that use them
  for (dTriMeshDataID d : mesh_data) dGeomTriMeshDataDestroy(d);
  if (contact_group != nullptr) dJointGroupDestroy(contact_group);
  dWorldSetStepThreadingImplementation(world, nullptr, nullptr);
  dWorldDestroy(world);  // destroys bodies and joints
  dThreadingFreeImplementation(threading);
  world = nullptr;
}

void ode_world::place_bodies(const std::vector<pose>& frames) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Eigen::Isometry3d t = to_eigen(frames[b]);
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
void ode_world::renormalize() {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    std::memcpy(quat_set[b].data(), dBodyGetQuaternion(bodies[b]), sizeof(dQuaternion));
    dBodySetQuaternion(bodies[b], quat_set[b].data());
  }
}

double ode_world::joint_position(std::size_t j) const {
  return model.joints[j].type == joint_type::prismatic ? dJointGetSliderPosition(joints[j])
                                                       : dJointGetHingeAngle(joints[j]);
}

double ode_world::joint_rate(std::size_t j) const {
  return model.joints[j].type == joint_type::prismatic ? dJointGetSliderPositionRate(joints[j])
                                                       : dJointGetHingeAngleRate(joints[j]);
}

void ode_world::set_motor(std::size_t j, double velocity, double fmax) {
  if (model.joints[j].type == joint_type::prismatic) {
    dJointSetSliderParam(joints[j], dParamVel, velocity);
    dJointSetSliderParam(joints[j], dParamFMax, fmax);
  } else {
    dJointSetHingeParam(joints[j], dParamVel, velocity);
    dJointSetHingeParam(joints[j], dParamFMax, fmax);
  }
}

void ode_world::add_joint_effort(std::size_t j, double effort) {
  if (model.joints[j].type == joint_type::prismatic) {
    dJointAddSliderForce(joints[j], effort);
  } else {
    dJointAddHingeTorque(joints[j], effort);
  }
}

Eigen::Vector3d ode_world::root_origin() const {
  const Eigen::Matrix3d r = body_rotation(bodies[0]);
  return vec(dBodyGetPosition(bodies[0])) - r * to_eigen(model.bodies[0].com);
}

std::vector<body_state> ode_world::body_states() const {
  std::vector<body_state> states(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const dReal* p = dBodyGetPosition(bodies[b]);
    const dReal* v = dBodyGetLinearVel(bodies[b]);
    const dReal* a = dBodyGetAngularVel(bodies[b]);
    body_state& s = states[b];
    std::copy(p, p + 3, s.position.begin());
    std::copy(quat_set[b].begin(), quat_set[b].end(), s.quaternion.begin());
    std::copy(v, v + 3, s.linear_velocity.begin());
    std::copy(a, a + 3, s.angular_velocity.begin());
  }
  return states;
}

void ode_world::set_body_states(const std::vector<body_state>& states) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const body_state& s = states[b];
    dBodySetPosition(bodies[b], s.position[0], s.position[1], s.position[2]);
    std::copy(s.quaternion.begin(), s.quaternion.end(), quat_set[b].begin());
    dBodySetQuaternion(bodies[b], quat_set[b].data());
    dBodySetLinearVel(bodies[b], s.linear_velocity[0], s.linear_velocity[1], s.linear_velocity[2]);
    dBodySetAngularVel(bodies[b], s.angular_velocity[0], s.angular_velocity[1],
                       s.angular_velocity[2]);
    dBodySetForce(bodies[b], 0, 0, 0);
    dBodySetTorque(bodies[b], 0, 0, 0);
  }
}

}  // namespace stride::robot
