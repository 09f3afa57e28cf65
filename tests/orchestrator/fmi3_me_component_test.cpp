// FMI 3.0 Model Exchange through the runner (fmi3_me_instance.cpp): the ball and the stair of
// me_fmus/ behind the 3.0 wrapper. The same equations behind the 2.0 wrapper are the reference:
// one solver on one set of equations must give the same numbers through either standard.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "me_fixture.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::cosim {
namespace {

using test::advance;
using test::cvode;
using test::initialise;
using test::make;
using ::testing::HasSubstr;
using fmi3_me_component_test = test::me_fixture;

// FMI 3 ports are numbered in declaration order: the ball's h, v and last_bounce are ports 0, 2
// and 6, its bounces port 7 (an Int32, value reference 100 inside the FMU).
variable_refs ball3_outputs() {
  variable_refs r;
  r.reals = {0, 2, 6};
  r.integers = {7};
  return r;
}
variable_refs ball2_outputs() {
  variable_refs r;
  r.reals = {0, 2, 6};
  r.integers = {0};
  return r;
}

TEST_F(fmi3_me_component_test, the_description_gives_states_indicators_and_capabilities) {
  const auto f = load3("ball", STRIDE_ME3_BALL);
  const auto& md = f->model_description();
  EXPECT_EQ(md.fmi_version, "3.0");
  EXPECT_FALSE(md.co_simulation.has_value());
  ASSERT_TRUE(md.model_exchange.has_value());
  EXPECT_EQ(md.model_exchange->model_identifier, "me3_ball");
  EXPECT_TRUE(md.model_exchange->completed_integrator_step_not_needed);
  EXPECT_TRUE(md.model_exchange->can_serialize_fmu_state);
  ASSERT_EQ(md.derivatives.size(), 2u);
  EXPECT_EQ(md.variables[md.derivatives[0]].name, "der(h)");
  EXPECT_EQ(md.variables[md.derivatives[1]].name, "der(v)");
  EXPECT_EQ(md.number_of_event_indicators, 1u);
}

TEST_F(fmi3_me_component_test, the_ball_runs_bit_identically_through_both_standards) {
  const auto f3 = load3("ball", STRIDE_ME3_BALL);
  const auto f2 = load("ball", STRIDE_ME_BALL);
  auto c3 = make(*f3, "ball", cvode(1e-8));
  auto c2 = make(*f2, "ball", cvode(1e-8));
  initialise(*c3, 3.0);
  initialise(*c2, 3.0);
  const auto t3 = advance(*c3, ball3_outputs(), 0.0, 0.01, 300);
  const auto t2 = advance(*c2, ball2_outputs(), 0.0, 0.01, 300);
  ASSERT_EQ(t3.outputs.size(), t2.outputs.size());
  for (std::size_t i = 0; i < t3.outputs.size(); ++i) {
    ASSERT_EQ(t3.outputs[i].reals, t2.outputs[i].reals) << t3.t[i];
    ASSERT_EQ(t3.outputs[i].integers, t2.outputs[i].integers) << t3.t[i];
  }
  EXPECT_GE(t3.outputs.back().integers[0], 10);  // state events happened
}

// bounce k+1 follows bounce k after a flight of 2 e^k t1, t1 = sqrt(2 h0 / g)
TEST_F(fmi3_me_component_test, the_ball_bounces_at_the_closed_form_times) {
  const auto f = load3("ball", STRIDE_ME3_BALL);
  auto c = make(*f, "ball", cvode(1e-10));
  initialise(*c, 3.0);
  const auto trace = advance(*c, ball3_outputs(), 0.0, 0.01, 249);
  std::vector<double> bounces;
  for (std::size_t i = 0; i < trace.outputs.size(); ++i) {
    const int count = trace.outputs[i].integers[0];
    if (count > static_cast<int>(bounces.size())) bounces.push_back(trace.outputs[i].reals[2]);
  }
  ASSERT_GE(bounces.size(), 10u);
  const double e = 0.7, t1 = std::sqrt(2.0 / 9.81);
  double expected = t1;
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(bounces[k], expected, 1e-6) << "bounce " << k + 1;
    expected += 2 * std::pow(e, static_cast<double>(k + 1)) * t1;
  }
}

// level k holds from k * period on: the time events land exactly
TEST_F(fmi3_me_component_test, the_stair_switches_exactly_at_its_time_events) {
  const auto f = load3("stair", STRIDE_ME3_STAIR);
  auto c = make(*f, "stair", cvode(1e-8));
  initialise(*c, 2.0);
  variable_refs outs;
  outs.reals = {0, 2};  // x, last_switch
  outs.integers = {4};  // level
  const auto trace = advance(*c, outs, 0.0, 0.1, 20);
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    const int level = static_cast<int>(std::floor(trace.t[i] / 0.3 + 1e-9));
    EXPECT_EQ(trace.outputs[i].integers[0], level) << "t " << trace.t[i];
    if (level > 0) {
      EXPECT_EQ(trace.outputs[i].reals[1], level * 0.3) << "t " << trace.t[i];
    }
  }
}

TEST_F(fmi3_me_component_test, a_restored_state_continues_byte_identically) {
  const auto f = load3("ball", STRIDE_ME3_BALL);
  auto original = make(*f, "ball", cvode(1e-8));
  initialise(*original, 3.0);
  advance(*original, ball3_outputs(), 0.0, 0.01, 100);
  const auto image = original->save_state();
  const auto expected = advance(*original, ball3_outputs(), 1.0, 0.01, 150);

  auto resumed = make(*f, "ball", cvode(1e-8));
  initialise(*resumed, 3.0);
  resumed->restore_state(image);
  const auto actual = advance(*resumed, ball3_outputs(), 1.0, 0.01, 150);
  for (std::size_t i = 0; i < actual.outputs.size(); ++i) {
    EXPECT_EQ(actual.outputs[i].reals, expected.outputs[i].reals) << actual.t[i];
    EXPECT_EQ(actual.outputs[i].integers, expected.outputs[i].integers) << actual.t[i];
  }
}

// terminateSimulation from fmi3UpdateDiscreteStates at the third bounce ends the run there
TEST_F(fmi3_me_component_test, terminate_simulation_ends_the_run_at_the_event) {
  const auto f = load3("ball", STRIDE_ME3_BALL);
  auto c = make(*f, "ball", cvode(1e-8));
  variable_refs max;
  max.integers = {8};  // max_bounces
  value_block three;
  three.integers = {3};
  c->set_values(max, three);
  initialise(*c, 3.0);
  c->expose({}, ball3_outputs());
  const double t1 = std::sqrt(2.0 / 9.81);
  const double third = t1 + 2 * 0.7 * t1 + 2 * 0.49 * t1;
  const duration dt = duration_from_seconds(0.01);
  time_point t = time_from_seconds(0);
  value_block out;
  while (c->step(t, dt, {}, out) == step_result::complete) t += dt;
  EXPECT_LT(to_seconds(t), third);
  EXPECT_GE(to_seconds(t + dt), third);
}

// fmi3Discard from the equations after 0.25 s: the run stops naming the 3.0 call and the time
TEST_F(fmi3_me_component_test, an_fmu_refusing_its_equations_names_the_call_and_the_time) {
  // the wrapper's "fail after" real (value reference 31) as a parameter the 3.0 description lists
  const auto f = load3("ball", STRIDE_ME3_BALL,
                       {"  </ModelVariables>",
                        "    <Float64 name=\"fail_after\" valueReference=\"31\" "
                        "causality=\"parameter\" variability=\"tunable\" start=\"0\"/>\n"
                        "  </ModelVariables>"});
  auto c = make(*f, "ball", cvode(1e-6));
  variable_refs fail_after;
  fail_after.reals = {10};  // after time, port 9
  value_block quarter;
  quarter.reals = {0.25};
  c->set_values(fail_after, quarter);
  initialise(*c, 1.0);
  try {
    advance(*c, ball3_outputs(), 0.0, 0.1, 5);
    FAIL() << "fmi3Discard ignored";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), ::testing::MatchesRegex("component 'ball' at t = 0\\.2[5-9][0-9]* s: "
                                                  "fmi3GetContinuousStateDerivatives returned "
                                                  "fmi3Discard"));
  }
}

// the description says 2 states and no indicator; the binary has one indicator
TEST_F(fmi3_me_component_test, a_binary_that_disagrees_with_its_description_is_refused) {
  const auto f =
      load3("ball", STRIDE_ME3_BALL, {"    <EventIndicator valueReference=\"0\"/>\n", ""});
  EXPECT_EQ(f->model_description().number_of_event_indicators, 0u);
  auto c = make(*f, "ball", cvode(1e-6));
  try {
    initialise(*c, 1.0);
    FAIL() << "a binary with an undeclared event indicator was run";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'ball': the binary reports 2 continuous states and "
                                    "1 event indicators, modelDescription.xml declares 2 "
                                    "<ContinuousStateDerivative> and 0 <EventIndicator>"));
  }
}

TEST_F(fmi3_me_component_test, a_derivative_that_is_not_a_float64_is_refused_with_its_line) {
  try {
    load3("ball", STRIDE_ME3_BALL,
          {"<ContinuousStateDerivative valueReference=\"3\"/>",
           "<ContinuousStateDerivative valueReference=\"100\"/>"});
    FAIL() << "an Int32 derivative was accepted";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("!modelDescription.xml:"));
    EXPECT_THAT(e.what(), HasSubstr("<ContinuousStateDerivative> names variable \"bounces\", a "
                                    "Int32, not a Float64"));
  }
}

// an FMI 2.0 binary under a 3.0 description: refused at load, naming the first missing function
TEST_F(fmi3_me_component_test, a_binary_without_the_3_0_functions_is_refused) {
  try {
    load("stair", STRIDE_ME_STAIR, {}, test::standard::fmi3);
    FAIL() << "a 2.0 binary was loaded as 3.0";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("binaries/x86_64-linux/me3_stair.so does not export "
                                    "fmi3GetVersion"));
  }
}

// 3.0's Model Exchange binaries need no Co-Simulation functions, and the other way round: a
// Co-Simulation request of a Model Exchange-only FMU runs it as Model Exchange
TEST_F(fmi3_me_component_test, a_model_exchange_only_fmu_needs_no_kind) {
  const auto f = load3("stair", STRIDE_ME3_STAIR);
  auto c = f->instantiate("stair");
  initialise(*c, 1.0);
  variable_refs level;
  level.integers = {4};
  EXPECT_EQ(advance(*c, level, 0.0, 0.35, 1).outputs[0].integers[0], 1);
}

// in a system: no kind needed, and a checkpoint of the execution resumes bit for bit
TEST_F(fmi3_me_component_test, a_system_with_a_3_0_model_exchange_fmu_resumes_byte_identically) {
  system_structure s;
  s.stop = time_from_seconds(3.0);
  s.base_step = duration_from_seconds(0.01);
  s.add_component("ball", pack("ball", STRIDE_ME3_BALL, {}, test::standard::fmi3).string());
  const auto run = [&](const std::vector<std::byte>* image, std::vector<std::byte>* save) {
    auto built = build_system(s);
    auto& ex = *built.execution;
    const std::size_t c = *ex.find_component("ball");
    const auto h = ex.observe({c, *ex.component_at(c).model_description().index_of("h")});
    ex.initialize(built.stop);
    if (image != nullptr) ex.restore_state_bytes(*image);
    if (save != nullptr) {
      ex.simulate_until(time_from_seconds(1.2));
      *save = ex.save_state_bytes();
    }
    std::vector<double> heights;
    for (int i = 0; i < 100; ++i) {
      ex.step();
      heights.push_back(ex.real_value(h));
    }
    return heights;
  };
  std::vector<std::byte> image;
  const auto expected = run(nullptr, &image);
  const auto resumed = run(&image, nullptr);
  EXPECT_EQ(resumed, expected);
  EXPECT_GT(*std::max_element(expected.begin(), expected.end()), 0.01);  // still bouncing
}

}  // namespace
}  // namespace stride::cosim
