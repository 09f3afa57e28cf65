// gait.fmu: the DARwIn-OP walking generator as an FMI 2.0 co-simulation component.
//
// Inputs   x_move (mm), y_move (mm), a_move (deg), aim_on, balance_on, walking, gyro_fb, gyro_rl
// Params   every [Walking Config] key (tunable, latched by the generator), config_file, ik_mode,
//          webots_scaling
// Outputs  servo_count[1..20], joint_angle[1..20] (rad), phase (s), footsteps, is_walking
// Step     8 ms per generator tick; a doStep of h runs floor(h / 8 ms) ticks and drops the
//          remainder, as the Webots gait manager does (a step that is not a multiple of 8 ms
//          makes the gait slower than real time; a warning says so once).
#include <algorithm>
#include <bitset>
#include <cstdint>
#include <string>
#include <vector>

#include "stride/gait/config_ini.hpp"
#include "stride/gait/walking.hpp"
#include "stride/sdk/fmu.hpp"
#include "stride/sdk/resources.hpp"

namespace stride::gait {
namespace {

constexpr sdk::time_ns tick_ns = 8'000'000;
constexpr int param_count = 22;

struct gait_data {
  // inputs
  double x_move = 0.0;
  double y_move = 0.0;
  double a_move = 0.0;
  bool aim_on = false;
  bool balance_on = true;
  bool walking = false;
  int gyro_fb = 0;
  int gyro_rl = 0;
  int restart = 0;
  // parameters
  walking_params params{};
  sdk::text config_file{};
  int ik_mode = 0;
  bool webots_scaling = false;
  // outputs
  int servo_count[servo_total] = {};
  double joint_angle[servo_total] = {};
  double phase = 0.0;
  int footsteps = 0;
  bool is_walking = false;
  // internal state
  walking_state generator{};
  bool was_walking = false;
  int applied_restart = 0;
  bool warned_step_remainder = false;
  std::uint32_t params_set_explicitly = 0;  // bit i: walking_param_table()[i] came from fmi2Set
};

template <class F>
void state_fields(gait_data& d, F&& f) {
  f(d.x_move, d.y_move, d.a_move, d.aim_on, d.balance_on, d.walking, d.gyro_fb, d.gyro_rl,
    d.restart, d.params, d.config_file, d.ik_mode, d.webots_scaling, d.servo_count, d.joint_angle,
    d.phase, d.footsteps, d.is_walking, d.generator, d.was_walking, d.applied_restart,
    d.warned_step_remainder, d.params_set_explicitly);
}

double clamp_unit(double v) {
  return std::clamp(v, -1.0, 1.0);
}

class gait_model : public sdk::model_base<gait_data> {
 public:
  explicit gait_model(const sdk::instance_context& context) : context_(context) {}

  static sdk::model_info info() {
    sdk::model_info i;
    i.model_name = "gait";
    i.model_identifier = "gait";
    i.description =
        "DARwIn-OP walking generator (ROBOTIS framework), servo output bit-exact to the original";
    i.default_step_size = 0.008;
    return i;
  }

  static sdk::variable_table variables() {
    sdk::table_builder<gait_data> t;
    const gait_data& d = t.defaults();
    t.add("x_move", &gait_data::x_move)
        .input()
        .unit("mm")
        .describe("Forward step amplitude X (with webots_scaling: -1..1 for -20..20 mm)");
    t.add("y_move", &gait_data::y_move)
        .input()
        .unit("mm")
        .describe("Sideways step amplitude Y (with webots_scaling: -1..1 for -40..40 mm)");
    t.add("a_move", &gait_data::a_move)
        .input()
        .unit("deg")
        .describe("Turning amplitude A (with webots_scaling: -1..1 for -50..50 deg)");
    t.add("aim_on", &gait_data::aim_on).input().describe("Turning aim: toe-in, reversed turn");
    t.add("balance_on", &gait_data::balance_on).input().describe("Gyro balance feedback on");
    t.add("walking", &gait_data::walking)
        .input()
        .describe("true: Start(); going false: Stop() (the gait ends its step, then stands)");
    t.add("gyro_fb", &gait_data::gyro_fb)
        .input()
        .describe("Front/back (pitch-rate) gyro, raw board counts minus 512");
    t.add("gyro_rl", &gait_data::gyro_rl)
        .input()
        .describe("Right/left (roll-rate) gyro, raw board counts minus 512");
    t.add("restart", &gait_data::restart)
        .input()
        .describe(
            "Any change re-initializes the generator (standing, t = 0); it then starts "
            "again if walking is true");

    for (const param_info& p : walking_param_table()) {
      sdk::variable_group v = p.real_member != nullptr ? t.add_field(p.key, d.params.*p.real_member)
                                                       : t.add_field(p.key, d.params.*p.int_member);
      v.parameter().tunable().describe(std::string(p.description) + " (takes effect: " + p.latch +
                                       ")");
      if (p.real_member != nullptr && *p.unit != '\0') v.unit(p.unit);
      if (std::isfinite(p.min) && !p.min_exclusive) v.min(p.min);
      if (std::isfinite(p.max) && !p.max_exclusive) v.max(p.max);
      v.check([&p](double value) { check_param_value(p, value); });
    }
    t.add("config_file", &gait_data::config_file)
        .parameter()
        .describe(
            "ROBOTIS config.ini ([Walking Config]) loaded before initialization: a path, or "
            "a file name in the FMU's resources/; parameters set explicitly win");
    t.add("ik_mode", &gait_data::ik_mode)
        .parameter()
        .range(0, 1)
        .describe("Leg IK: 0 = darwin (framework, with its I + A*B quirk), 1 = geometric");
    t.add("webots_scaling", &gait_data::webots_scaling)
        .parameter()
        .describe("Inputs x/y/a_move are -1..1 and scaled to 20 mm, 40 mm, 50 deg (Webots)");

    t.add("servo_count", &gait_data::servo_count)
        .output()
        .describe("Goal position by servo ID, MX-28 counts 0..4095 (2048 = 0 deg)");
    t.add("joint_angle", &gait_data::joint_angle)
        .output()
        .unit("rad")
        .describe("Joint angle by servo ID, (count - 2048) * 0.088 deg, URDF joint convention");
    t.add("phase", &gait_data::phase)
        .output()
        .unit("s")
        .describe("Gait-phase time of the last tick within the period");
    t.add("footsteps", &gait_data::footsteps).output().describe("Completed steps since start");
    t.add("is_walking", &gait_data::is_walking).output().describe("The gait clock is running");
    return t.finish();
  }

  void on_set(const sdk::variable& v) override {
    // only the [Walking Config] parameters are remembered (explicit sets win over config_file);
    // inputs such as the gyro are set every step and skip the name search
    if (v.causality_kind != sdk::causality::parameter) return;
    const auto table = walking_param_table();
    for (int i = 0; i < param_count; ++i) {
      if (v.name == table[static_cast<std::size_t>(i)].key) data_.params_set_explicitly |= 1u << i;
    }
  }

  void exit_initialization() override {
    if (!data_.config_file.empty()) load_config_file();
    generator_ = walking(data_.ik_mode == 0 ? ik_mode::darwin : ik_mode::geometric);
    data_.generator = generator_.initialize(data_.params);
    data_.was_walking = false;
    data_.applied_restart = data_.restart;
    publish();
  }

  sdk::step_result do_step(sdk::time_ns, sdk::time_ns h) override {
    if (h % tick_ns != 0 && !data_.warned_step_remainder) {
      data_.warned_step_remainder = true;
      context_.log->warning("step size " + std::to_string(sdk::to_seconds(h)) +
                            " s is not a multiple of 8 ms: the remainder is dropped, the gait "
                            "runs slower than real time");
    }
    if (data_.restart != data_.applied_restart) {
      data_.generator = generator_.initialize(data_.params);
      data_.was_walking = false;
      data_.applied_restart = data_.restart;
    }
    for (sdk::time_ns n = h / tick_ns; n > 0; --n) tick();
    publish();
    return sdk::step_result::ok;
  }

  // the generator object itself is configuration (IK mode): restore it with the data
  void restore_state(std::span<const std::byte> bytes) override {
    sdk::model_base<gait_data>::restore_state(bytes);
    generator_ = walking(data_.ik_mode == 0 ? ik_mode::darwin : ik_mode::geometric);
  }

 private:
  void tick() {
    if (data_.walking && !data_.was_walking) generator_.start(data_.generator);
    if (!data_.walking && data_.was_walking) generator_.stop(data_.generator);
    data_.was_walking = data_.walking;
    if (data_.walking) {
      double x = data_.x_move, y = data_.y_move, a = data_.a_move;
      if (data_.webots_scaling) {
        x = 20.0 * clamp_unit(x);
        y = 40.0 * clamp_unit(y);
        a = 50.0 * clamp_unit(a);
      }
      generator_.set_command(data_.generator, x, y, a, data_.aim_on);
    }
    const walking_feedback feedback{data_.balance_on, data_.gyro_fb, data_.gyro_rl};
    generator_.tick(data_.generator, data_.params, feedback);
  }

  void publish() {
    for (int i = 0; i < servo_total; ++i) {
      data_.servo_count[i] = data_.generator.servo_count[i];
      data_.joint_angle[i] = servo_count_to_rad(data_.generator.servo_count[i]);
    }
    data_.phase = phase_ms(data_.generator) / 1000.0;
    data_.footsteps = footsteps(data_.generator);
    data_.is_walking = is_running(data_.generator);
  }

  void load_config_file() {
    std::vector<std::string> warnings;
    const walking_params from_file =
        read_walking_config(sdk::find_resource(data_.config_file.c_str(), context_.resource_dir),
                            data_.params, &warnings);
    for (const std::string& w : warnings) context_.log->warning(w);
    const auto table = walking_param_table();
    for (int i = 0; i < param_count; ++i) {
      if (data_.params_set_explicitly & (1u << i)) continue;
      const param_info& p = table[static_cast<std::size_t>(i)];
      set_param(data_.params, p, get_param(from_file, p));
    }
    context_.log->info("logEvents", std::string("loaded ") + data_.config_file.c_str());
  }

  sdk::instance_context context_;
  walking generator_;
};

}  // namespace
}  // namespace stride::gait

STRIDE_FMU(stride::gait::gait_model)
