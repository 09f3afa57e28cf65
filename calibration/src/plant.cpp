#include "stride/calibration/plant.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "stride/cosim/error.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/gait/walking.hpp"
#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_model.hpp"
#include "stride/sdk/resources.hpp"
#include "text.hpp"

namespace stride::calibration {

namespace fs = std::filesystem;

namespace {

constexpr double k_rad_to_deg = 180.0 / std::numbers::pi;

// the robot outputs a settle reads, in this order
enum output : std::size_t {
  o_pitch,
  o_roll,
  o_yaw,
  o_base_x,
  o_base_y,
  o_base_z,
  o_com_x,
  o_com_y,
  o_left_force,
  o_right_force,
  o_joint0,  // joint_angle[1] .. joint_angle[20]
  o_count = o_joint0 + robot::darwin::k_servo_count
};

std::string output_name(std::size_t i) {
  static const char* const names[] = {
      "pitch",  "roll",  "yaw",   "base_x",          "base_y",
      "base_z", "com_x", "com_y", "left_foot_force", "right_foot_force"};
  if (i < o_joint0) return names[i];
  return "joint_angle[" + std::to_string(i - o_joint0 + 1) + "]";
}

Eigen::Isometry3d to_isometry(const robot::pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = p.rotation[static_cast<std::size_t>(3 * i + j)];
  t.linear() = r;
  t.translation() = Eigen::Vector3d(p.position[0], p.position[1], p.position[2]);
  return t;
}

robot::pose to_pose(const Eigen::Isometry3d& t) {
  robot::pose p;
  for (int i = 0; i < 3; ++i) {
    p.position[static_cast<std::size_t>(i)] = t.translation()(i);
    for (int j = 0; j < 3; ++j) p.rotation[static_cast<std::size_t>(3 * i + j)] = t.linear()(i, j);
  }
  return p;
}

}  // namespace

cosim::system_structure make_standing_system() {
  cosim::system_structure s;
  s.name = "calibration-stand";
  s.description = "DARwIn-OP standing still: gait (not walking) drives the robot";
  s.base_step = std::chrono::milliseconds(8);
  s.record.enabled = false;
  cosim::component_spec& gait = s.add_component("gait", "gait");
  gait.parameters.push_back({"walking", "false", {}});
  // a robot at rest reads -1 gyro counts (the board truncates towards -inf); keep that out
  gait.parameters.push_back({"balance_on", "false", {}});
  s.add_component("robot", "robot");
  s.connect("gait.joint_angle[*]", "robot.joint_target[*]");
  s.connect("robot.gyro_fb", "gait.gyro_fb", true);
  s.connect("robot.gyro_rl", "gait.gyro_rl", true);
  return s;
}

struct plant_simulator::impl {
  cosim::system_structure system;
  std::map<std::string, std::shared_ptr<cosim::fmu>> fmus;  // by component name
  cosim::log_sink log;
  gait::walking_params params;
  gait::ik_mode mode = gait::ik_mode::darwin;
  std::int64_t settle_steps = 0;
  std::int64_t average_steps = 0;
  cosim::duration base_step{};
  std::int64_t evaluations = 0;

  // support polygon: the robot model and its feet
  robot::robot_model model;
  int foot_body[2] = {-1, -1};     // left, right
  Eigen::Vector3d sole_centre[2];  // centre of each foot's lowest collision shape, body frame

  void load_fmus(const plant_options& options) {
    const auto search = options.fmu_search_path.empty() ? cosim::default_fmu_search_path()
                                                        : options.fmu_search_path;
    std::map<fs::path, std::shared_ptr<cosim::fmu>> by_file;
    for (const cosim::component_spec& c : system.components) {
      const fs::path file = cosim::resolve_fmu(c, system, search);
      auto& f = by_file[fs::weakly_canonical(file)];
      if (!f) {
        try {
          f = cosim::fmu::load(file);
        } catch (const cosim::error& e) {
          throw cosim::fmu_import_error(c.where.str() + (c.where.str().empty() ? "" : ": ") +
                                        "component '" + c.name + "': " + e.what());
        }
      }
      fmus[c.name] = f;
    }
  }

  void load_robot_model() {
    const cosim::component_spec* robot = system.find_component("robot");
    std::string urdf;
    for (const auto& p : robot->parameters)
      if (p.variable == "urdf") urdf = p.value;
    const fs::path resources = fmus.at("robot")->extracted_dir() / "resources";
    const fs::path path =
        urdf.empty() ? resources / "darwin-op.urdf" : sdk::find_resource(urdf, resources);
    model = robot::load_robot_model(path.string());
    const robot::robot_config c = robot::darwin::default_config("");
    const std::string feet[2] = {c.left_foot_link, c.right_foot_link};
    for (int side = 0; side < 2; ++side) {
      const int link = model.find_link(feet[side]);
      if (link < 0)
        throw robot::model_error(path.string() + ": no foot link '" + feet[side] +
                                 "' for the support polygon");
      const robot::link_frame& lf = model.links[static_cast<std::size_t>(link)];
      foot_body[side] = lf.body;
      const robot::rigid_body& body = model.bodies[static_cast<std::size_t>(lf.body)];
      if (body.shapes.empty())
        throw robot::model_error(path.string() + ": foot link '" + feet[side] +
                                 "' has no collision shape");
      // the sole: the shape whose centre lies lowest when the body frame is upright
      const robot::collision_shape* sole = &body.shapes.front();
      for (const auto& s : body.shapes)
        if (s.origin.position[2] < sole->origin.position[2]) sole = &s;
      sole_centre[side] = Eigen::Vector3d(sole->origin.position[0], sole->origin.position[1],
                                          sole->origin.position[2]);
    }
  }

  // world pose of every body from the root pose and the joint angles by servo ID
  std::vector<Eigen::Isometry3d> body_poses(const Eigen::Isometry3d& root,
                                            const std::vector<double>& angle_by_id) const {
    std::vector<double> q(model.joints.size(), 0.0);
    for (std::size_t j = 0; j < q.size(); ++j) {
      const int id = model.joints[j].servo_id;
      if (id >= 1 && static_cast<std::size_t>(id) <= angle_by_id.size())
        q[j] = angle_by_id[static_cast<std::size_t>(id - 1)];
    }
    std::vector<Eigen::Isometry3d> t;
    for (const robot::pose& p : model.forward_kinematics(to_pose(root), q))
      t.push_back(to_isometry(p));
    return t;
  }

  void prepare(const plant_options& options, const gait::walking_params& p, gait::ik_mode m) {
    system = options.system ? *options.system : make_standing_system();
    log = options.log ? options.log : cosim::stderr_log_sink(cosim::log_level::warning);
    params = p;
    mode = m;
    const std::string where = system.where.str().empty() ? system.name : system.where.str();
    if (!system.find_component("gait") || !system.find_component("robot"))
      throw cosim::validation_error(where +
                                    ": the plant mode needs components named 'gait' and 'robot'");
    system.record.enabled = false;
    system.set("gait.walking", "false");
    system.set("gait.ik_mode", mode == gait::ik_mode::darwin ? "0" : "1");
    for (const gait::param_info& info : gait::walking_param_table())
      system.set("gait." + std::string(info.key),
                 detail::format_double(gait::get_param(params, info)));

    load_fmus(options);
    load_robot_model();

    // base step: the system's, or the smallest default step of the FMUs (as build_system does)
    if (system.base_step) {
      base_step = *system.base_step;
    } else {
      double smallest = 0.008;
      bool found = false;
      for (const auto& [name, f] : fmus) {
        if (const auto s = f->model_description().default_experiment.step_size; s && *s > 0) {
          smallest = found ? std::min(smallest, *s) : *s;
          found = true;
        }
      }
      base_step = cosim::duration_from_seconds(smallest);
      system.base_step = base_step;
    }
    const double h = cosim::to_seconds(base_step);
    settle_steps = std::max<std::int64_t>(1, std::llround(options.settle_s / h));
    average_steps = std::clamp<std::int64_t>(std::llround(options.average_s / h), 1, settle_steps);
    system.stop = system.start + settle_steps * base_step;
  }

  plant_posture settle(const offset_values& offsets) {
    gait::walking_params p = params;
    set_offsets(p, offsets);
    // the gait keeps its last servo values when the IK fails: reject such offsets here
    std::array<double, gait::servo_total> counts;
    if (!gait::standing_servo_counts(gait::standing_params<double>::from(p), mode, counts))
      throw std::domain_error("the standing foot targets are out of the leg's reach");

    cosim::system_structure s = system;
    for (std::size_t i = 0; i < offset_count; ++i) {
      const std::string key(offset_table()[i].key);
      s.set("gait." + key, detail::format_double(offsets[i]));
    }
    cosim::build_options bo;
    bo.log = log;
    bo.placements.push_back(
        std::make_shared<cosim::function_placement>([this](const cosim::component_spec& spec) {
          cosim::instance_options io;
          io.log = log;
          return fmus.at(spec.name)->instantiate(spec.name, io);
        }));
    cosim::built_system built = cosim::build_system(s, bo);
    cosim::execution& algo = *built.execution;
    const std::size_t robot = *algo.find_component("robot");
    const auto& md = algo.component_at(robot).model_description();
    std::vector<cosim::observed_variable> observed;
    for (std::size_t i = 0; i < o_count; ++i) {
      const std::string name = output_name(i);
      const auto index = md.index_of(name);
      if (!index)
        throw cosim::validation_error("component 'robot' has no output '" + name +
                                      "' (the plant mode needs robot.fmu)");
      observed.push_back(algo.observe(cosim::variable_id{robot, *index}));
    }
    const auto fallen_index = md.index_of("fallen");
    std::optional<cosim::observed_variable> fallen;
    if (fallen_index) fallen = algo.observe(cosim::variable_id{robot, *fallen_index});

    ++evaluations;
    built.execution->initialize(built.stop);
    std::vector<double> sum(o_count, 0.0);
    bool has_fallen = false;
    for (std::int64_t k = 1; k <= settle_steps; ++k) {
      const auto r = built.execution->simulate_until(built.start + k * base_step);
      if (r.terminated_by_component)
        throw cosim::component_error(
            "component '" + r.terminated_by +
            "' ended the settle at t = " + cosim::format_seconds(r.end_time) + " s");
      if (fallen && algo.boolean_value(*fallen)) has_fallen = true;
      if (k > settle_steps - average_steps)
        for (std::size_t i = 0; i < o_count; ++i) sum[i] += algo.real_value(observed[i]);
    }
    built.execution->end();
    for (double& v : sum) v /= static_cast<double>(average_steps);

    plant_posture out;
    out.pitch_deg = sum[o_pitch] * k_rad_to_deg;
    out.roll_deg = sum[o_roll] * k_rad_to_deg;
    out.height_m = sum[o_base_z];
    out.com_x = sum[o_com_x];
    out.com_y = sum[o_com_y];
    out.left_force = sum[o_left_force];
    out.right_force = sum[o_right_force];
    out.fallen = has_fallen;

    // support polygon: the soles carrying load; two congruent parallel soles have the midpoint of
    // their centres as the centre of their convex hull
    Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
    root.linear() = (Eigen::AngleAxisd(sum[o_yaw], Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(sum[o_pitch], Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(sum[o_roll], Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
    root.translation() = Eigen::Vector3d(sum[o_base_x], sum[o_base_y], sum[o_base_z]);
    const std::vector<double> angles(sum.begin() + o_joint0, sum.end());
    const auto poses = body_poses(root, angles);
    const double total = std::max(out.left_force + out.right_force, 1e-9);
    const double force[2] = {out.left_force, out.right_force};
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    int feet = 0;
    for (int side = 0; side < 2; ++side) {
      if (force[side] < 0.05 * total) continue;  // this foot carries (almost) nothing
      centre += poses[static_cast<std::size_t>(foot_body[side])] * sole_centre[side];
      ++feet;
    }
    if (feet == 0) {  // airborne: fall back to both feet
      for (int side = 0; side < 2; ++side)
        centre += poses[static_cast<std::size_t>(foot_body[side])] * sole_centre[side];
      feet = 2;
    }
    centre /= feet;
    out.support_x = centre.x();
    out.support_y = centre.y();
    return out;
  }
};

plant_simulator::plant_simulator(const plant_options& options, const gait::walking_params& params,
                                 gait::ik_mode mode)
    : impl_(std::make_unique<impl>()) {
  impl_->prepare(options, params, mode);
}

plant_simulator::~plant_simulator() = default;

plant_posture plant_simulator::settle(const offset_values& offsets) {
  return impl_->settle(offsets);
}

std::int64_t plant_simulator::evaluations() const noexcept {
  return impl_->evaluations;
}

}  // namespace stride::calibration
