// robot.fmu: the DARwIn-OP plant (ODE, URDF) as an FMI 2.0 co-simulation component.
//
// Inputs   joint_target[1..20] (rad, by servo ID), reset (a change re-stands the robot at the
//          origin), push_x, push_y (N, on the torso)
// Params   profile (stiff | webots), urdf, physics and contact settings, servo model, fall
//          thresholds (all fixed)
// Outputs  joint_angle[1..20], gyro_fb, gyro_rl (board counts − 512, for gait.fmu), gyro[1..3],
//          acc[1..3], base_x/y/z, roll/pitch/yaw, com_x/y/z, foot forces, fallen
// Step     any h: the plant runs every whole physics step that fits and carries the remainder.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <memory>
#include <string>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_sim.hpp"
#include "stride/sdk/fmu.hpp"
#include "stride/sdk/resources.hpp"

namespace stride::robot {
namespace {

constexpr int k_servos = darwin::k_servo_count;
constexpr double k_max_push = 1e4;  // N

// The plant's numeric parameters, ONE list: FMU variable, where it lives in robot_config, how it
// is declared. The start values and the profile defaults come from robot_config itself.
struct plant_parameter {
  const char* name;
  double& (*field)(robot_config&);
  const char* unit;
  double min;
  double max;
  const char* description;
};

// clang-format off
constexpr plant_parameter k_plant_parameters[] = {
    {"physics_step", [](robot_config& c) -> double& { return c.physics_step; }, "s", 1e-4, 0.05,
     "Internal physics step; each doStep runs the whole steps that fit"},
    {"erp", [](robot_config& c) -> double& { return c.erp; }, "", 0, 1, "World error reduction"},
    {"cfm", [](robot_config& c) -> double& { return c.cfm; }, "", 0, 1,
     "World constraint force mixing"},
    {"friction", [](robot_config& c) -> double& { return c.contact.mu; }, "", 0, 1e3,
     "Coulomb friction coefficient of contacts"},
    {"bounce", [](robot_config& c) -> double& { return c.contact.bounce; }, "", 0, 1,
     "Contact restitution"},
    {"contact_soft_erp", [](robot_config& c) -> double& { return c.contact.soft_erp; }, "", 0, 1,
     "Contact softness: error reduction"},
    {"contact_soft_cfm", [](robot_config& c) -> double& { return c.contact.soft_cfm; }, "", 0, 1,
     "Contact softness: constraint force mixing"},
    {"servo_p_gain", [](robot_config& c) -> double& { return c.servo.p_gain; }, "1/s", 0, 1e4,
     "Velocity target = gain * position error"},
    {"servo_max_velocity", [](robot_config& c) -> double& { return c.servo.max_velocity; },
     "rad/s", 0, 1e3, "Servo speed limit"},
    {"servo_max_acceleration", [](robot_config& c) -> double& { return c.servo.max_acceleration; },
     "rad/s2", 0, 1e6, "Servo acceleration limit (0: none)"},
    {"servo_torque_limit", [](robot_config& c) -> double& { return c.servo.torque_limit; }, "N.m",
     0, 1e3, "Servo torque limit"},
    {"servo_damping", [](robot_config& c) -> double& { return c.servo.damping; }, "N.m.s/rad", 0,
     1e3, "Joint viscous damping"},
    {"servo_static_friction", [](robot_config& c) -> double& { return c.servo.static_friction; },
     "N.m", 0, 1e3, "Joint static friction"},
    {"servo_compliance", [](robot_config& c) -> double& { return c.servo.compliance; },
     "N.m.s/rad", 0, 1e6, "Motor compliance (0: rigid velocity servo)"},
    {"fall_tilt", [](robot_config& c) -> double& { return c.fall_tilt; }, "rad", 0, 3.2,
     "fallen when the torso tilts more than this"},
    {"fall_height", [](robot_config& c) -> double& { return c.fall_height; }, "m", -10, 10,
     "fallen when the torso origin is lower than this"},
};
// clang-format on
constexpr std::size_t k_plant_parameter_count = std::size(k_plant_parameters);

struct robot_data {
  // inputs
  double joint_target[k_servos];
  int reset = 0;
  double push_x = 0.0;
  double push_y = 0.0;
  // parameters
  sdk::text profile{"stiff"};
  sdk::text urdf{};
  double plant[k_plant_parameter_count];  // by k_plant_parameters
  int solver = 0;
  bool weld_arms_and_head = true;
  // outputs
  double joint_angle[k_servos] = {};
  int gyro_fb = 0;
  int gyro_rl = 0;
  double gyro[3] = {};
  double acc[3] = {};
  double base_x = 0, base_y = 0, base_z = 0;
  double roll = 0, pitch = 0, yaw = 0;
  double com_x = 0, com_y = 0, com_z = 0;
  double left_foot_force = 0, right_foot_force = 0;
  double max_penetration = 0;
  bool fallen = false;
  // internal
  int applied_reset = 0;
  std::uint32_t plant_set_explicitly = 0;  // bit i: k_plant_parameters[i] came from fmi2Set

  // start values: the default profile, standing in the walk-ready pose
  robot_data() {
    const auto pose = darwin::walk_ready_pose();
    for (int i = 0; i < k_servos; ++i) joint_target[i] = pose[static_cast<std::size_t>(i)];
    apply_profile(darwin::plant_profile::stiff);
  }

  // the profile's value of every plant parameter not set explicitly
  void apply_profile(darwin::plant_profile p) {
    robot_config c = darwin::default_config("", p);
    for (std::size_t i = 0; i < k_plant_parameter_count; ++i) {
      if ((plant_set_explicitly & (1u << i)) == 0) plant[i] = k_plant_parameters[i].field(c);
    }
  }
};
static_assert(k_plant_parameter_count <= 32);

class robot_model_fmu : public sdk::model_base<robot_data> {
 public:
  explicit robot_model_fmu(const sdk::instance_context& context) : context_(context) {}

  static sdk::model_info info() {
    sdk::model_info i;
    i.model_name = "robot";
    i.model_identifier = "robot";
    i.description = "DARwIn-OP humanoid on ODE, loaded from URDF, with Webots-like servos";
    i.default_step_size = 0.008;
    return i;
  }

  static sdk::variable_table variables() {
    sdk::table_builder<robot_data> t;
    t.add("joint_target", &robot_data::joint_target)
        .input()
        .unit("rad")
        .describe("Servo target by servo ID, URDF joint convention");
    t.add("reset", &robot_data::reset)
        .input()
        .describe("Any change puts the robot back standing in the walk-ready pose at the origin");
    // a bound far beyond any push the plant is meant for (10 kN on a 2.9 kg robot): forces of
    // about 1e154 N and more overflow inside ODE, which then aborts the process
    t.add("push_x", &robot_data::push_x)
        .input()
        .unit("N")
        .range(-k_max_push, k_max_push)
        .describe("Push on the torso, world x");
    t.add("push_y", &robot_data::push_y)
        .input()
        .unit("N")
        .range(-k_max_push, k_max_push)
        .describe("Push on the torso, world y");

    t.add("profile", &robot_data::profile)
        .parameter()
        .describe(
            "Plant profile: stiff (servo P 18, no ramp) or webots (Webots' servo: P 10, "
            "55 rad/s2 ramp); parameters set explicitly win");
    t.add("urdf", &robot_data::urdf)
        .parameter()
        .describe("URDF to load: a path, or a file in resources/ (empty: darwin-op.urdf)");
    const robot_data& d = t.defaults();
    for (std::size_t i = 0; i < k_plant_parameter_count; ++i) {
      const plant_parameter& p = k_plant_parameters[i];
      sdk::variable_group v = t.add_field(p.name, d.plant[i]);
      v.parameter().range(p.min, p.max).describe(p.description);
      if (*p.unit != '\0') v.unit(p.unit);
    }
    t.add("solver", &robot_data::solver)
        .parameter()
        .range(0, 1)
        .describe("0 = dWorldStep (deterministic), 1 = dWorldQuickStep (faster, not reproducible)");
    t.add("weld_arms_and_head", &robot_data::weld_arms_and_head)
        .parameter()
        .describe("Hold servos 3-6, 19, 20 rigid in the walk-ready pose (about 2x faster)");

    t.add("joint_angle", &robot_data::joint_angle)
        .output()
        .unit("rad")
        .describe("Joint angle by servo ID");
    t.add("gyro_fb", &robot_data::gyro_fb)
        .output()
        .describe("Front/back gyro as the CM-730 reports it, counts minus 512");
    t.add("gyro_rl", &robot_data::gyro_rl)
        .output()
        .describe("Right/left gyro as the CM-730 reports it, counts minus 512");
    t.add("gyro", &robot_data::gyro).output().unit("rad/s").describe("Torso angular velocity");
    t.add("acc", &robot_data::acc).output().unit("m/s2").describe("Torso specific force");
    t.add("base_x", &robot_data::base_x).output().unit("m").describe("Torso position x");
    t.add("base_y", &robot_data::base_y).output().unit("m").describe("Torso position y");
    t.add("base_z", &robot_data::base_z).output().unit("m").describe("Torso position z");
    t.add("roll", &robot_data::roll).output().unit("rad").describe("Torso roll");
    t.add("pitch", &robot_data::pitch).output().unit("rad").describe("Torso pitch (+ forward)");
    t.add("yaw", &robot_data::yaw).output().unit("rad").describe("Torso yaw");
    t.add("com_x", &robot_data::com_x).output().unit("m").describe("Centre of mass x");
    t.add("com_y", &robot_data::com_y).output().unit("m").describe("Centre of mass y");
    t.add("com_z", &robot_data::com_z).output().unit("m").describe("Centre of mass z");
    t.add("left_foot_force", &robot_data::left_foot_force)
        .output()
        .unit("N")
        .describe("Normal floor force on the left foot");
    t.add("right_foot_force", &robot_data::right_foot_force)
        .output()
        .unit("N")
        .describe("Normal floor force on the right foot");
    t.add("max_penetration", &robot_data::max_penetration)
        .output()
        .unit("m")
        .describe("Deepest floor penetration in the last physics step");
    t.add("fallen", &robot_data::fallen)
        .output()
        .describe("Torso tilt past fall_tilt or torso below fall_height (held until reset)");
    return t.finish();
  }

  void on_set(const sdk::variable& v) override {
    if (v.causality_kind != sdk::causality::parameter) return;
    if (v.name == "profile") {
      data_.apply_profile(profile());
      return;
    }
    for (std::size_t i = 0; i < k_plant_parameter_count; ++i) {
      if (v.name == k_plant_parameters[i].name) data_.plant_set_explicitly |= 1u << i;
    }
  }

  void exit_initialization() override {
    build_plant();
    data_.applied_reset = data_.reset;
    sim_->set_joint_targets(
        std::span<const double>(data_.joint_target, static_cast<std::size_t>(sim_->servo_count())));
    publish();
  }

  sdk::step_result do_step(sdk::time_ns, sdk::time_ns h) override {
    if (data_.reset != data_.applied_reset) {
      sim_->reset();
      data_.applied_reset = data_.reset;
    }
    sim_->set_joint_targets(
        std::span<const double>(data_.joint_target, static_cast<std::size_t>(sim_->servo_count())));
    sim_->set_push(data_.push_x, data_.push_y);
    sim_->step(sdk::to_seconds(h));
    publish();
    return sdk::step_result::ok;
  }

  // state = the data struct followed by the plant's own image (empty before initialization)
  std::vector<std::byte> save_state() const override {
    std::vector<std::byte> bytes = sdk::model_base<robot_data>::save_state();
    if (sim_) {
      const std::vector<std::uint8_t> image = sim_->save_state();
      const auto* begin = reinterpret_cast<const std::byte*>(image.data());
      bytes.insert(bytes.end(), begin, begin + image.size());
    }
    return bytes;
  }

  void restore_state(std::span<const std::byte> bytes) override {
    if (bytes.size() < sizeof(robot_data)) throw sdk::model_error("robot state is too short");
    sdk::model_base<robot_data>::restore_state(bytes.first(sizeof(robot_data)));
    const auto image = bytes.subspan(sizeof(robot_data));
    if (image.empty()) {
      sim_.reset();
      return;
    }
    if (!sim_) build_plant();
    sim_->restore_state(std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(image.data()), image.size()));
  }

 private:
  std::string urdf_path() const {
    if (data_.urdf.empty()) {
      return (std::filesystem::path(context_.resource_dir) / "darwin-op.urdf").string();
    }
    return sdk::find_resource(data_.urdf.c_str(), context_.resource_dir).string();
  }

  darwin::plant_profile profile() const {
    const auto p = darwin::parse_plant_profile(data_.profile.view());
    if (!p) {
      throw sdk::model_error("profile '" + std::string(data_.profile.view()) +
                             "' is not a plant profile (stiff, webots)");
    }
    return *p;
  }

  void build_plant() {
    robot_config c = darwin::default_config(urdf_path(), profile());
    for (std::size_t i = 0; i < k_plant_parameter_count; ++i) {
      k_plant_parameters[i].field(c) = data_.plant[i];
    }
    c.solver = data_.solver == 0 ? physics_solver::world_step : physics_solver::quick_step;
    if (!data_.weld_arms_and_head) c.rigid_servos.clear();
    sim_ = std::make_unique<robot_sim>(std::move(c));
    if (sim_->servo_count() > k_servos) {
      throw sdk::model_error(urdf_path() + ": servo IDs above " + std::to_string(k_servos) +
                             " are not supported by robot.fmu");
    }
    context_.log->info("logEvents", "loaded " + urdf_path());
  }

  void publish() {
    const robot_outputs& o = sim_->outputs();
    for (int i = 0; i < k_servos; ++i) {
      const auto index = static_cast<std::size_t>(i);
      data_.joint_angle[i] = index < o.joint_angles.size() ? o.joint_angles[index] : 0.0;
    }
    const darwin::gyro_counts board = darwin::board_gyro(o.gyro);
    data_.gyro_fb = darwin::board_integer(board.fb);
    data_.gyro_rl = darwin::board_integer(board.rl);
    for (int i = 0; i < 3; ++i) {
      data_.gyro[i] = o.gyro[static_cast<std::size_t>(i)];
      data_.acc[i] = o.acc[static_cast<std::size_t>(i)];
    }
    data_.base_x = o.base_position[0];
    data_.base_y = o.base_position[1];
    data_.base_z = o.base_position[2];
    data_.roll = o.roll;
    data_.pitch = o.pitch;
    data_.yaw = o.yaw;
    data_.com_x = o.com[0];
    data_.com_y = o.com[1];
    data_.com_z = o.com[2];
    data_.left_foot_force = o.left_foot_force[2];
    data_.right_foot_force = o.right_foot_force[2];
    data_.max_penetration = o.max_penetration;
    data_.fallen = o.fallen;
  }

  sdk::instance_context context_;
  std::unique_ptr<robot_sim> sim_;
};

}  // namespace
}  // namespace stride::robot

STRIDE_FMU(stride::robot::robot_model_fmu)
