// stride_test: a gain with a counter, an integrator, vectors and strings, plus switches that make
// it end the run or fail on request. It exists to test the SDK, the FMU tooling and importers.
#include <cstring>
#include <string>
#include <string_view>

#include "stride/sdk/fmu.hpp"

namespace stride::test_component {

struct test_data {
  double gain = 2.0;
  double offset = 0.0;
  double u = 0.0;
  double y = 0.0;
  double integral = 0.0;
  int n = 0;
  int counter = 0;
  bool enable = true;
  bool active = true;
  sdk::fixed_string<63> label{"stride"};
  sdk::fixed_string<63> suffix{};
  sdk::fixed_string<127> echo{};
  int stop_after_steps = 0;
  int fail_at_step = 0;
  double vec_in[3] = {0.0, 0.0, 0.0};
  double vec_out[3] = {0.0, 0.0, 0.0};
};

template <class F>
void state_fields(test_data& d, F&& f) {
  f(d.gain, d.offset, d.u, d.y, d.integral, d.n, d.counter, d.enable, d.active, d.label, d.suffix,
    d.echo, d.stop_after_steps, d.fail_at_step, d.vec_in, d.vec_out);
}

class test_model : public sdk::model_base<test_data> {
 public:
  explicit test_model(const sdk::instance_context& context) : context_(context) {}

  static sdk::model_info info() {
    sdk::model_info i;
    i.model_name = "stride_test";
    i.model_identifier = "stride_test";
    i.description = "Gain, counter and integrator exercising every variable type of the SDK";
    i.default_step_size = 0.01;
    return i;
  }

  static sdk::variable_table variables() {
    sdk::table_builder<test_data> t;
    t.add("gain", &test_data::gain)
        .parameter()
        .tunable()
        .range(-1e6, 1e6)
        .describe("y = gain*u + offset");
    t.add("offset", &test_data::offset)
        .parameter()
        .range(-1000, 1000)
        .describe("Constant added to y");
    t.add("u", &test_data::u).input().describe("Input signal");
    t.add("y", &test_data::y).output().depends_on({"u"}).describe("gain*u + offset (feedthrough)");
    t.add("integral", &test_data::integral)
        .output()
        .unit("s")
        .describe("Integral of u over the steps taken");
    t.add("n", &test_data::n).input().describe("Integer input added to the counter increment");
    t.add("counter", &test_data::counter)
        .output()
        .describe("Completed steps, each adding 1 + n (wraps around at 2^31)");
    t.add("enable", &test_data::enable).input().describe("Boolean input");
    t.add("active", &test_data::active)
        .output()
        .depends_on({"enable"})
        .describe("Equals enable (feedthrough)");
    t.add("label", &test_data::label).parameter().describe("Free text copied to echo");
    t.add("suffix", &test_data::suffix).input().describe("Free text appended to echo");
    t.add("echo", &test_data::echo).output().depends_on({"suffix"}).describe("label + suffix");
    t.add("stop_after_steps", &test_data::stop_after_steps)
        .parameter()
        .min(0)
        .describe("End the run after this many steps (0: never)");
    t.add("fail_at_step", &test_data::fail_at_step)
        .parameter()
        .min(0)
        .describe("Fail with an error at this step (0: never)");
    t.add("vec_in", &test_data::vec_in).input().describe("Vector input");
    t.add("vec_out", &test_data::vec_out).output().describe("2*vec_in, updated by each step");
    return t.finish();
  }

  void calculate_values() override {
    data_.y = data_.gain * data_.u + data_.offset;
    data_.active = data_.enable;
    // label and suffix together always fit into echo (63 + 63 ≤ 127)
    const std::string_view label = data_.label.view(), suffix = data_.suffix.view();
    std::memcpy(data_.echo.text, label.data(), label.size());
    std::memcpy(data_.echo.text + label.size(), suffix.data(), suffix.size());
    data_.echo.text[label.size() + suffix.size()] = '\0';
  }

  sdk::step_result do_step(sdk::time_ns, sdk::time_ns h) override {
    if (data_.fail_at_step > 0 && data_.counter + 1 == data_.fail_at_step) {
      throw sdk::model_error("step " + std::to_string(data_.fail_at_step) +
                             " fails on request (fail_at_step)");
    }
    data_.integral += data_.u * sdk::to_seconds(h);
    // wraps around at 2^31 like a hardware counter (in unsigned arithmetic: no overflow UB),
    // which long chained runs reach
    data_.counter = static_cast<int>(static_cast<unsigned>(data_.counter) + 1u +
                                     static_cast<unsigned>(data_.n));
    for (int i = 0; i < 3; ++i) data_.vec_out[i] = 2.0 * data_.vec_in[i];
    if (context_.log->enabled("logEvents")) {
      context_.log->info("logEvents", "step " + std::to_string(data_.counter));
    }
    if (data_.stop_after_steps > 0 && data_.counter >= data_.stop_after_steps) {
      return sdk::step_result::terminate;
    }
    return sdk::step_result::ok;
  }

 private:
  sdk::instance_context context_;
};

}  // namespace stride::test_component

STRIDE_FMU(stride::test_component::test_model)
