// walk_then_turn: commands the DARwIn-OP gait to walk straight ahead for `forward_time`
// seconds, then to keep walking while it turns. A complete Stride component: the data struct
// holds every value (parameters, outputs and the evolving time), the table says which is which.
#include <cstdint>

#include "stride/sdk/fmu.hpp"

namespace {

struct controller_data {
  // parameters
  double forward_time = 5.0;   // s
  double forward_step = 20.0;  // mm, the gait's x_move while going straight
  double turn_step = 10.0;     // mm, the gait's x_move while turning
  double turn_rate = 15.0;     // deg, the gait's a_move while turning (positive: left)
  // outputs, always computed from the rest of the struct
  double x_move = 0.0;
  double a_move = 0.0;
  bool walking = true;
  bool turning = false;
  // state: simulated time reached, integer nanoseconds (not an FMI variable)
  stride::sdk::time_ns now = 0;
};

// Every member, in a fixed order: what a saved state (fmi2GetFMUstate) holds, the same bytes on
// any host. A member left out would be lost by a restore, so the SDK refuses to instantiate then.
template <class F>
void state_fields(controller_data& d, F&& f) {
  f(d.forward_time, d.forward_step, d.turn_step, d.turn_rate, d.x_move, d.a_move, d.walking,
    d.turning, d.now);
}

class walk_then_turn : public stride::sdk::model_base<controller_data> {
 public:
  explicit walk_then_turn(const stride::sdk::instance_context&) {}

  static stride::sdk::model_info info() {
    stride::sdk::model_info i;
    i.model_name = "walk_then_turn";
    i.model_identifier = "walk_then_turn";
    i.description = "Walk straight ahead, then turn: x_move/a_move commands for the gait";
    i.default_step_size = 0.008;
    return i;
  }

  static stride::sdk::variable_table variables() {
    stride::sdk::table_builder<controller_data> t;
    t.add("forward_time", &controller_data::forward_time)
        .parameter()
        .unit("s")
        .range(0, 1e6)
        .describe("Time spent walking straight before turning");
    t.add("forward_step", &controller_data::forward_step)
        .parameter()
        .unit("mm")
        .range(-20, 20)
        .describe("x_move while walking straight");
    t.add("turn_step", &controller_data::turn_step)
        .parameter()
        .unit("mm")
        .range(-20, 20)
        .describe("x_move while turning");
    t.add("turn_rate", &controller_data::turn_rate)
        .parameter()
        .unit("deg")
        .range(-25, 25)
        .describe("a_move while turning (positive: to the left)");
    t.add("x_move", &controller_data::x_move).output().unit("mm").describe("Forward step command");
    t.add("a_move", &controller_data::a_move).output().unit("deg").describe("Turning command");
    t.add("walking", &controller_data::walking).output().discrete().describe("Always true");
    t.add("turning", &controller_data::turning).output().discrete().describe("In the turn phase");
    return t.finish();
  }

  // Outputs are a pure function of the struct: the SDK calls this after every set and every
  // step, before the next get.
  void calculate_values() override {
    auto& d = data_;
    d.turning = stride::sdk::to_seconds(d.now) >= d.forward_time;
    d.x_move = d.turning ? d.turn_step : d.forward_step;
    d.a_move = d.turning ? d.turn_rate : 0.0;
    d.walking = true;
  }

  stride::sdk::step_result do_step(stride::sdk::time_ns t, stride::sdk::time_ns h) override {
    data_.now = t + h;
    return stride::sdk::step_result::ok;
  }
};

}  // namespace

STRIDE_FMU(walk_then_turn)
