// The execution: run to a stop, termination requests, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "execution_fixtures.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"

namespace stride::cosim {
namespace {

using namespace test;
using ::testing::HasSubstr;

TEST(cosim_execution, component_requested_stop_ends_the_run_cleanly) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  auto m = counter("stopper", {});
  auto* mp = m.get();
  m->on_step = [](mock_component& self, time_point, duration) {
    if (self.r("y") >= 4) return step_result::terminate;
    self.r("y") += 1;
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  EXPECT_TRUE(result.terminated_by_component);
  EXPECT_EQ(result.terminated_by, "stopper");
  EXPECT_EQ(result.end_time, time_point(40 * k_ms));
  EXPECT_EQ(result.steps, 4);
  EXPECT_TRUE(ex.ended());
  EXPECT_TRUE(mp->terminated);
}

TEST(cosim_execution, component_error_names_component_and_time_and_flushes_results) {
  temp_dir dir("stride-test-");
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  auto m = counter("broken", {});
  m->on_step = [](mock_component& self, time_point, duration) -> step_result {
    if (self.r("y") >= 3) throw std::runtime_error("doStep failed");
    self.r("y") += 1;
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto csv = dir.path() / "out.csv";
  ex.add_observer(std::make_shared<csv_recorder>(csv, std::vector<variable_id>{}));
  try {
    ex.simulate_until(time_point(std::chrono::seconds(1)));
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'broken'"));
    EXPECT_THAT(e.what(), HasSubstr("doStep failed"));
    EXPECT_THAT(e.what(), HasSubstr("t = 0.03 s"));
  }
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,broken.y\n0,0\n0.01,1\n0.02,2\n0.03,3\n");
}

// one output of each kind that becomes true / non-zero at step `at`
std::unique_ptr<mock_component> flags(int at) {
  auto m = std::make_unique<mock_component>("m");
  m->add("flag", variable_type::boolean, causality::output);
  m->add("count", variable_type::integer, causality::output);
  m->real("level", causality::output);
  m->real("u", causality::input);
  m->add("label", variable_type::string, causality::output);
  m->on_step = [at, steps = 0](mock_component& self, time_point, duration) mutable {
    if (++steps == at) {
      self.b("flag") = true;
      self.i("count") = 3;
      self.r("level") = -0.5;
    }
    return step_result::complete;
  };
  return m;
}

TEST(cosim_execution, a_stop_condition_ends_the_run_when_its_output_turns_true_or_non_zero) {
  for (const char* output : {"flag", "count", "level"}) {
    execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
    ex.add_component(flags(7));
    ex.stop_when(var(ex, "m", output));
    const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
    EXPECT_EQ(result.stopped_by, std::string("m.") + output);
    EXPECT_EQ(result.end_time, time_point(70 * k_ms)) << output;
    EXPECT_EQ(result.steps, 7);
    EXPECT_FALSE(result.terminated_by_component);
    EXPECT_TRUE(ex.ended());
  }
  // a condition that never holds leaves the stop time in charge
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  ex.add_component(flags(0));
  ex.stop_when(var(ex, "m", "flag"));
  const auto result = ex.simulate_until(time_point(100 * k_ms));
  EXPECT_EQ(result.stopped_by, "");
  EXPECT_EQ(result.steps, 10);
}

TEST(cosim_execution, a_stop_condition_that_holds_at_the_start_ends_the_run_before_a_step) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  auto m = flags(0);
  m->b("flag") = true;
  ex.add_component(std::move(m));
  ex.stop_when(var(ex, "m", "flag"));
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  EXPECT_EQ(result.stopped_by, "m.flag");
  EXPECT_EQ(result.steps, 0);
}

TEST(cosim_execution, a_stop_condition_needs_a_boolean_integer_or_real_output) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  ex.add_component(flags(1));
  const auto error_of = [&](const char* name) -> std::string {
    try {
      ex.stop_when(var(ex, "m", name));
    } catch (const validation_error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error_of("u"), "m.u is input; a stop condition needs an output");
  EXPECT_THAT(error_of("label"), HasSubstr("m.label is a String output"));
  ex.initialize(time_point(std::chrono::seconds(1)));
  EXPECT_THAT(error_of("flag"), HasSubstr("after initialize()"));
}

}  // namespace
}  // namespace stride::cosim
