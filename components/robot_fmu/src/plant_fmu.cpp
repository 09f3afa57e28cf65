// The plant FMU's variable table, built from a URDF and a plant profile, and the model that
// steps robot_sim through it. Inputs: joint targets (array and by joint name), reset, push.
// Parameters: the preset, the plant settings, the solver, weld switches, the URDF. Outputs:
// joint angles/velocities/torques, IMU, base pose, centre of mass, contact forces, board
// channels, max_penetration, fallen.
#include "stride/robot/plant_fmu.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "stride/robot/plant_profile.hpp"
#include "stride/robot/robot_sim.hpp"
#include "stride/sdk/resources.hpp"

namespace stride::robot {

namespace {

constexpr double k_max_push = 1e4;  // N; far beyond any push; ~1e154 N overflows inside ODE
constexpr double k_unset = std::numeric_limits<double>::quiet_NaN();

// where each value lives in the model's buffer
struct plant_layout {
  std::size_t joints = 0;  // actuated joints = array length
  std::size_t target = 0, angle = 0, velocity = 0, torque = 0;
  std::size_t reset = 0, push_x = 0, push_y = 0;
  std::size_t preset = 0, urdf = 0, solver = 0;
  std::size_t settings = 0;    // one double per plant_settings()
  std::size_t explicitly = 0;  // one bool per plant_settings(): set through the FMU
  std::size_t welds = 0;       // one bool per weld group
  std::size_t gyro = 0, acc = 0, base = 0, rpy = 0, com = 0, base_v = 0, base_w = 0;
  std::size_t forces = 0;            // one double per contact output
  std::vector<std::size_t> channel;  // per board channel: a double or an int
  std::size_t max_penetration = 0, fallen = 0, applied_reset = 0;
};

// everything an instance needs, shared by the instances of one unpacked FMU
struct plant_spec {
  std::string urdf_path;
  std::vector<std::string> package_path;
  robot_model model;
  plant_profile profile;
  std::vector<std::string> joint_names;  // actuated, in array order
  plant_layout at;
};

// a packaged FMU finds its files in its resources only, whatever the machine's ROS_PACKAGE_PATH
model_options model_options_of(const plant_spec& s) {
  model_options o;
  o.package_path = s.package_path;
  o.use_ros_package_path = false;
  return o;
}

const char* unit_of(const model_joint& j) {
  return j.type == joint_type::prismatic ? "m" : "rad";
}

std::string limits_text(const model_joint& j) {
  if (!j.limited) return "";
  return " (URDF limits " + std::to_string(j.lower) + " to " + std::to_string(j.upper) + " " +
         unit_of(j) + ")";
}

double board_value(const board_channel& c, const robot_outputs& o) {
  const int k = static_cast<int>(c.from);
  const double signal =
      k < 3 ? o.gyro[static_cast<std::size_t>(k)] : o.acc[static_cast<std::size_t>(k - 3)];
  return c.gain * signal + c.offset;
}

// the values of plant_settings() a preset gives
std::vector<double> preset_values(const plant_spec& s, std::string_view preset) {
  const resolved_plant r = resolve_plant(s.profile, s.model, preset);
  std::vector<double> v;
  for (const plant_setting& p : plant_settings()) {
    robot_config c = r.config;
    v.push_back(p.field(c));
  }
  return v;
}

sdk::variable_table build_table(plant_spec& s, const resolved_plant& r) {
  sdk::buffer_table_builder t;
  plant_layout& at = s.at;
  const std::size_t n = r.actuated.size();
  at.joints = n;
  const auto joint = [&](std::size_t k) -> const model_joint& {
    return s.model.joints[static_cast<std::size_t>(r.actuated[k])];
  };
  // joint arrays and the same values by joint name
  const auto joint_values = [&](const char* array, const char* suffix, std::size_t& offset,
                                const char* what, bool input) {
    offset = t.reserve<double>(n, 0.0);
    if (input) {
      for (std::size_t k = 0; k < n; ++k) {
        t.set_start(offset + k * sizeof(double), r.config.initial_pose[k]);
      }
    }
    if (n == 0) return;
    auto group = t.declare<double>(array, offset, n, true);
    input ? group.input() : group.output();
    group.describe(std::string(what) + " by position in the joint order (" + s.profile.joint_order +
                   ")");
    if (std::string(suffix) != "torque") group.unit(unit_of(joint(0)));
    for (std::size_t k = 0; k < n; ++k) {
      const model_joint& j = joint(k);
      auto v = t.declare<double>(j.name + "." + suffix, offset + k * sizeof(double));
      input ? v.input() : v.output();
      const bool torque = std::string(suffix) == "torque";
      v.unit(torque ? (j.type == joint_type::prismatic ? "N" : "N.m") : unit_of(j))
          .describe(std::string(what) + " of joint " + j.name + limits_text(j));
    }
  };
  joint_values("joint_target", "target", at.target, "Servo target", true);
  at.reset = t.reserve<int>(1, 0);
  t.declare<int>("reset", at.reset)
      .input()
      .describe("Any change puts the robot back in its initial pose at the origin");
  t.add<double>("push_x", 0.0, &at.push_x)
      .input()
      .unit("N")
      .range(-k_max_push, k_max_push)
      .describe("Push on the root link, world x");
  t.add<double>("push_y", 0.0, &at.push_y)
      .input()
      .unit("N")
      .range(-k_max_push, k_max_push)
      .describe("Push on the root link, world y");

  if (!s.profile.presets.empty()) {
    sdk::text preset;
    preset.assign(s.profile.default_preset);
    std::string names;
    for (const auto& p : s.profile.presets) names += (names.empty() ? "" : ", ") + p.name;
    t.add<sdk::text>(s.profile.preset_parameter, preset, &at.preset)
        .parameter()
        .describe("Plant preset: " + names + "; settings set explicitly win");
  }
  t.add<sdk::text>("urdf", sdk::text{}, &at.urdf)
      .parameter()
      .describe(
          "URDF to load instead of the packaged one (same joints): a path, or a file in "
          "resources/");
  const std::span<const plant_setting> settings = plant_settings();
  at.settings = t.reserve<double>(settings.size(), 0.0);
  for (std::size_t i = 0; i < settings.size(); ++i) {
    const plant_setting& p = settings[i];
    robot_config c = r.config;
    t.set_start(at.settings + i * sizeof(double), p.field(c));
    auto v = t.declare<double>(p.fmu_name, at.settings + i * sizeof(double));
    v.parameter().range(p.min, p.max).describe(p.description);
    if (*p.unit != '\0') v.unit(p.unit);
  }
  at.explicitly = t.reserve<bool>(settings.size(), false);
  t.add<int>("solver", 0, &at.solver)
      .parameter()
      .range(0, 1)
      .describe("0 = dWorldStep (deterministic), 1 = dWorldQuickStep (faster, not reproducible)");
  at.welds = t.reserve<bool>(s.profile.welds.size(), true);
  for (std::size_t g = 0; g < s.profile.welds.size(); ++g) {
    const weld_group& w = s.profile.welds[g];
    if (w.parameter.empty()) continue;
    t.declare<bool>(w.parameter, at.welds + g)
        .parameter()
        .describe(w.description.empty() ? "Weld these joints at their initial position"
                                        : w.description);
  }

  joint_values("joint_angle", "angle", at.angle, "Joint position", false);
  joint_values("joint_velocity", "velocity", at.velocity, "Joint velocity", false);
  joint_values("joint_torque", "torque", at.torque, "Motor torque (force for prismatic)", false);
  // the board channels before the IMU they are made of (recorded columns keep this order)
  for (const board_channel& c : s.profile.board) {
    std::size_t offset = 0;
    auto v = c.round == board_channel::rounding::none ? t.add<double>(c.name, 0.0, &offset)
                                                      : t.add<int>(c.name, 0, &offset);
    v.output().describe(c.description.empty() ? "Board channel" : c.description);
    at.channel.push_back(offset);
  }
  at.gyro = t.reserve<double>(3, 0.0);
  t.declare<double>("gyro", at.gyro, 3, true)
      .output()
      .unit("rad/s")
      .describe("Angular velocity of the IMU link in its frame");
  at.acc = t.reserve<double>(3, 0.0);
  t.declare<double>("acc", at.acc, 3, true)
      .output()
      .unit("m/s2")
      .describe("Specific force at the IMU in its frame");
  at.base = t.reserve<double>(3, 0.0);
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < 3; ++i) {
    t.declare<double>(std::string("base_") + axes[i], at.base + i * sizeof(double))
        .output()
        .unit("m")
        .describe(std::string("Root link position ") + axes[i]);
  }
  at.rpy = t.reserve<double>(3, 0.0);
  const char* angles[] = {"roll", "pitch", "yaw"};
  for (std::size_t i = 0; i < 3; ++i) {
    t.declare<double>(angles[i], at.rpy + i * sizeof(double))
        .output()
        .unit("rad")
        .describe(std::string("Root link ") + angles[i]);
  }
  at.base_v = t.reserve<double>(3, 0.0);
  at.base_w = t.reserve<double>(3, 0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    t.declare<double>(std::string("base_v") + axes[i], at.base_v + i * sizeof(double))
        .output()
        .unit("m/s")
        .describe(std::string("Root link origin velocity, world ") + axes[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    t.declare<double>(std::string("base_w") + axes[i], at.base_w + i * sizeof(double))
        .output()
        .unit("rad/s")
        .describe(std::string("Root link angular velocity, world ") + axes[i]);
  }
  at.com = t.reserve<double>(3, 0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    t.declare<double>(std::string("com_") + axes[i], at.com + i * sizeof(double))
        .output()
        .unit("m")
        .describe(std::string("Centre of mass ") + axes[i]);
  }
  at.forces = t.reserve<double>(s.profile.contact_forces.size(), 0.0);
  for (std::size_t i = 0; i < s.profile.contact_forces.size(); ++i) {
    t.declare<double>(s.profile.contact_forces[i].name, at.forces + i * sizeof(double))
        .output()
        .unit("N")
        .describe("Normal floor force on link " + s.profile.contact_forces[i].link);
  }
  t.add<double>("max_penetration", 0.0, &at.max_penetration)
      .output()
      .unit("m")
      .describe("Deepest floor penetration in the last physics step");
  t.add<bool>("fallen", false, &at.fallen)
      .output()
      .describe("Root link tilted past fall_tilt or below fall_height (held until reset)");
  at.applied_reset = t.reserve<int>(1, 0);
  return t.finish();
}

class plant_model final : public sdk::buffer_model {
 public:
  plant_model(std::shared_ptr<const plant_spec> spec, const sdk::variable_table& table,
              const sdk::instance_context& context)
      : sdk::buffer_model(table), spec_(std::move(spec)), context_(context) {}

  void on_set(const sdk::variable& v) override {
    if (v.causality_kind != sdk::causality::parameter) return;
    const plant_layout& at = spec_->at;
    if (!spec_->profile.presets.empty() && v.offset == at.preset) {
      const std::vector<double> values = preset_values(*spec_, value<sdk::text>(at.preset).view());
      for (std::size_t i = 0; i < values.size(); ++i) {
        if (!value<bool>(at.explicitly + i)) setting(i) = values[i];
      }
      return;
    }
    if (v.offset >= at.settings && v.offset < at.settings + values_count() * sizeof(double)) {
      value<bool>(at.explicitly + (v.offset - at.settings) / sizeof(double)) = true;
    }
  }

  void exit_initialization() override {
    build_plant();
    value<int>(spec_->at.applied_reset) = value<int>(spec_->at.reset);
    sim_->set_joint_targets(targets());
    publish();
  }

  sdk::step_result do_step(sdk::time_ns, sdk::time_ns h) override {
    const plant_layout& at = spec_->at;
    if (value<int>(at.reset) != value<int>(at.applied_reset)) {
      sim_->reset();
      value<int>(at.applied_reset) = value<int>(at.reset);
    }
    sim_->set_joint_targets(targets());
    sim_->set_push(value<double>(at.push_x), value<double>(at.push_y));
    sim_->step(sdk::to_seconds(h));
    publish();
    return sdk::step_result::ok;
  }

  // state = the values followed by the plant's own image (none before initialization)
  std::vector<std::byte> save_state() const override {
    common::byte_writer w;
    save_buffer(w);
    if (sim_) {
      const std::vector<std::uint8_t> image = sim_->save_state();
      w.put_raw(std::as_bytes(std::span(image)));
    }
    return w.take();
  }

  void restore_state(std::span<const std::byte> bytes) override {
    sdk::state_reader r(bytes);
    restore_buffer(r);
    const auto image = r.get_rest();
    if (image.empty()) {
      sim_.reset();
      return;
    }
    if (!sim_) build_plant();
    sim_->restore_state(std::span<const std::uint8_t>(
        reinterpret_cast<const std::uint8_t*>(image.data()), image.size()));
  }

 private:
  std::size_t values_count() const { return plant_settings().size(); }
  double& setting(std::size_t i) { return value<double>(spec_->at.settings + i * sizeof(double)); }

  std::span<const double> targets() const {
    return {&value<double>(spec_->at.target), spec_->at.joints};
  }

  void build_plant() {
    const plant_layout& at = spec_->at;
    std::vector<double> overrides(values_count(), k_unset);
    for (std::size_t i = 0; i < overrides.size(); ++i) {
      // the others come from the preset, per joint where its servo rules differ by joint
      if (value<bool>(at.explicitly + i)) overrides[i] = setting(i);
    }
    std::string urdf = spec_->urdf_path;
    const std::string_view chosen = value<sdk::text>(at.urdf).view();
    if (!chosen.empty()) {
      urdf = sdk::find_resource(std::string(chosen), context_.resource_dir).string();
    }
    robot_model model =
        urdf == spec_->urdf_path ? spec_->model : load_robot_model(urdf, model_options_of(*spec_));
    const std::string preset =
        spec_->profile.presets.empty() ? "" : std::string(value<sdk::text>(at.preset).view());
    const std::span<const bool> welds_on(&value<bool>(at.welds), spec_->profile.welds.size());
    resolved_plant r = resolve_plant(spec_->profile, model, preset, overrides, welds_on);
    if (r.config.servo_joints != spec_->joint_names) {
      throw sdk::model_error(urdf + ": its servo joints differ from those of the packaged URDF " +
                             spec_->urdf_path + ", which the FMU's variables are made of");
    }
    r.config.urdf_path = urdf;
    r.config.package_path = spec_->package_path;
    r.config.use_ros_package_path = false;
    r.config.solver =
        value<int>(at.solver) == 0 ? physics_solver::world_step : physics_solver::quick_step;
    sim_ = std::make_unique<robot_sim>(std::move(r.config));
    context_.log->info("logEvents", "loaded " + urdf);
  }

  void publish() {
    const plant_layout& at = spec_->at;
    const robot_outputs& o = sim_->outputs();
    for (std::size_t k = 0; k < at.joints; ++k) {
      value<double>(at.angle + k * sizeof(double)) = o.joint_angles[k];
      value<double>(at.velocity + k * sizeof(double)) = o.joint_velocities[k];
      value<double>(at.torque + k * sizeof(double)) = o.joint_torques[k];
    }
    for (std::size_t i = 0; i < 3; ++i) {
      value<double>(at.gyro + i * sizeof(double)) = o.gyro[i];
      value<double>(at.acc + i * sizeof(double)) = o.acc[i];
      value<double>(at.base + i * sizeof(double)) = o.base_position[i];
      value<double>(at.com + i * sizeof(double)) = o.com[i];
      value<double>(at.base_v + i * sizeof(double)) = o.base_velocity[i];
      value<double>(at.base_w + i * sizeof(double)) = o.base_angular_velocity[i];
    }
    value<double>(at.rpy) = o.roll;
    value<double>(at.rpy + sizeof(double)) = o.pitch;
    value<double>(at.rpy + 2 * sizeof(double)) = o.yaw;
    for (std::size_t i = 0; i < spec_->profile.contact_forces.size(); ++i) {
      value<double>(at.forces + i * sizeof(double)) = o.link_forces[i][2];
    }
    for (std::size_t i = 0; i < spec_->profile.board.size(); ++i) {
      const board_channel& c = spec_->profile.board[i];
      const double x = board_value(c, o);
      switch (c.round) {
        case board_channel::rounding::none:
          value<double>(at.channel[i]) = x;
          break;
        case board_channel::rounding::floor:
          value<int>(at.channel[i]) = static_cast<int>(std::floor(x));
          break;
        case board_channel::rounding::nearest:
          value<int>(at.channel[i]) = static_cast<int>(std::nearbyint(x));
          break;
      }
    }
    value<double>(at.max_penetration) = o.max_penetration;
    value<bool>(at.fallen) = o.fallen;
  }

  std::shared_ptr<const plant_spec> spec_;
  sdk::instance_context context_;
  std::unique_ptr<robot_sim> sim_;
};

}  // namespace

std::shared_ptr<const sdk::fmu_definition> load_plant_fmu(const std::string& resource_dir,
                                                          std::vector<std::string>* warnings) {
  namespace fs = std::filesystem;
  const fs::path dir(resource_dir);
  const plant_manifest manifest = read_plant_manifest((dir / k_plant_manifest).string());
  auto spec = std::make_shared<plant_spec>();
  spec->urdf_path = (dir / manifest.urdf).string();
  for (const std::string& p : manifest.package_path) {
    spec->package_path.push_back((dir / p).string());
  }
  try {
    spec->model = load_robot_model(spec->urdf_path, model_options_of(*spec));
    spec->profile = manifest.profile.empty()
                        ? default_plant_profile()
                        : load_plant_profile((dir / manifest.profile).string());
    const resolved_plant r = resolve_plant(spec->profile, spec->model, "");
    if (warnings != nullptr) *warnings = r.warnings;
    spec->joint_names = r.config.servo_joints;
    sdk::model_info info;
    info.model_name = manifest.model_name;
    info.model_identifier = manifest.model_identifier;
    info.description = manifest.description;
    info.default_step_size = manifest.default_step;
    sdk::variable_table table = build_table(*spec, r);
    std::shared_ptr<const plant_spec> shared = spec;
    auto definition = std::make_shared<sdk::fmu_definition>(
        sdk::fmu_definition{std::move(info), std::move(table), nullptr});
    const sdk::variable_table* table_ptr = &definition->table;
    definition->create = [shared, table_ptr](const sdk::instance_context& context) {
      return std::unique_ptr<sdk::model>(new plant_model(shared, *table_ptr, context));
    };
    return definition;
  } catch (const model_error& e) {
    throw sdk::model_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw sdk::model_error(e.what());
  }
}

}  // namespace stride::robot
