// The Model Exchange runner (orchestrator/src/me_component.cpp) on the project's own ME test
// FMUs (me_fmus/): the oracles are closed-form solutions of their equations.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "me_fixture.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using test::advance;
using test::cvode;
using test::initialise;
using test::make;
using me_component_test = test::me_fixture;

// over one communication step: CVODE restarts at every communication point, so over many the
// global error adds up (docs/model-exchange.md)
TEST_F(me_component_test, decay_error_is_within_the_tolerance_and_shrinks_with_it) {
  auto f = load("decay", STRIDE_ME_DECAY);
  variable_refs x;
  x.reals = {0};
  std::vector<double> errors;
  for (double rtol : {1e-4, 1e-6, 1e-8}) {
    auto c = make(*f, "decay", cvode(rtol));
    initialise(*c, 2.0);
    const auto trace = advance(*c, x, 0.0, 2.0, 1);
    const double error = std::abs(trace.outputs.back().reals[0] - std::exp(-2.0));
    EXPECT_LE(error, rtol) << "rtol " << rtol;
    errors.push_back(error);
  }
  EXPECT_LT(errors[1], errors[0]);
  EXPECT_LT(errors[2], errors[1]);
}

TEST_F(me_component_test, adams_also_follows_the_closed_form) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto o = cvode(1e-8);
  o.method = model_exchange_options::method_kind::adams;
  auto c = make(*f, "decay", o);
  initialise(*c, 1.0);
  variable_refs x;
  x.reals = {0};
  const auto trace = advance(*c, x, 0.0, 0.1, 10);
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    EXPECT_NEAR(trace.outputs[i].reals[0], std::exp(-trace.t[i]), 1e-7) << trace.t[i];
  }
}

// bounce k+1 follows bounce k after a flight of 2 e^k t1, t1 = sqrt(2 h0 / g)
TEST_F(me_component_test, bouncing_ball_bounces_at_the_closed_form_times) {
  auto f = load("ball", STRIDE_ME_BALL);
  auto c = make(*f, "ball", cvode(1e-10));
  initialise(*c, 3.0);
  variable_refs outs;
  outs.reals = {6};     // last_bounce
  outs.integers = {0};  // bounces
  const auto trace = advance(*c, outs, 0.0, 0.01, 249);
  std::vector<double> bounces;
  int count = 0;
  for (const auto& o : trace.outputs) {
    if (o.integers[0] == count) continue;
    EXPECT_EQ(o.integers[0], count + 1);  // never two bounces in one communication step
    count = o.integers[0];
    bounces.push_back(o.reals[0]);
  }
  ASSERT_GE(bounces.size(), 10u);
  const double g = 9.81, e = 0.7, t1 = std::sqrt(2.0 / g);
  double expected = t1;
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(bounces[k], expected, 1e-6) << "bounce " << k + 1;
    expected += 2 * std::pow(e, static_cast<double>(k + 1)) * t1;
  }
}

// level k holds from k * period on; x integrates the level
TEST_F(me_component_test, stair_switches_exactly_at_its_time_events) {
  auto f = load("stair", STRIDE_ME_STAIR);
  auto c = make(*f, "stair", cvode(1e-8));
  initialise(*c, 2.0);
  variable_refs outs;
  outs.reals = {0, 2};  // x, last_switch
  outs.integers = {0};  // level
  const auto trace = advance(*c, outs, 0.0, 0.1, 20);
  const double period = 0.3;
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    int level = 0;
    double x = 0;
    while ((level + 1) * period <= trace.t[i]) {
      ++level;
      x += trace.t[i] - level * period;
    }
    EXPECT_EQ(trace.outputs[i].integers[0], level) << "t " << trace.t[i];
    if (level > 0) {
      EXPECT_EQ(trace.outputs[i].reals[1], level * period) << "t " << trace.t[i];
    }
    EXPECT_NEAR(trace.outputs[i].reals[0], x, 1e-7) << "t " << trace.t[i];
  }
}

// x' = -1000 x: BDF integrates it; explicit Euler at a step of 0.01 s multiplies x by -9 per step
TEST_F(me_component_test, bdf_solves_a_stiff_system_where_euler_diverges) {
  auto f = load("decay", STRIDE_ME_DECAY);
  variable_refs k;
  k.reals = {2};
  value_block stiff;
  stiff.reals = {1000.0};
  variable_refs x;
  x.reals = {0};

  auto bdf = make(*f, "bdf", cvode(1e-6));
  bdf->set_values(k, stiff);
  initialise(*bdf, 1.0);
  const auto trace = advance(*bdf, x, 0.0, 0.1, 10);
  EXPECT_NEAR(trace.outputs.back().reals[0], 0.0, 1e-6);

  model_exchange_options o;
  o.solver = model_exchange_options::solver_kind::euler;
  o.max_step = 0.01;
  auto euler = make(*f, "euler", o);
  euler->set_values(k, stiff);
  initialise(*euler, 1000.0);
  try {
    advance(*euler, x, 0.0, 0.1, 10000);
    FAIL() << "explicit Euler did not diverge";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'euler' at t = "));
    EXPECT_THAT(e.what(), HasSubstr("explicit Euler diverged"));
  }
}

TEST_F(me_component_test, euler_without_a_step_is_refused) {
  auto f = load("decay", STRIDE_ME_DECAY);
  model_exchange_options o;
  o.solver = model_exchange_options::solver_kind::euler;
  EXPECT_THROW(make(*f, "decay", o), component_error);
}

// x = e^-t falls below 1/2 at ln 2: the FMU asks for a step event after the first internal
// step that ends below, within the communication step that holds ln 2
TEST_F(me_component_test, step_events_are_handled_after_the_integrator_step) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-8));
  variable_refs threshold;
  threshold.reals = {4};
  value_block half;
  half.reals = {0.5};
  c->set_values(threshold, half);
  initialise(*c, 1.0);
  variable_refs outs;
  outs.reals = {5};     // crossed_at
  outs.integers = {0};  // crossed
  const auto trace = advance(*c, outs, 0.0, 0.1, 10);
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    EXPECT_EQ(trace.outputs[i].integers[0], trace.t[i] >= std::log(2.0) ? 1 : 0) << trace.t[i];
  }
  const double at = trace.outputs.back().reals[0];
  EXPECT_GE(at, std::log(2.0));
  EXPECT_LE(at, 0.7);  // the communication step (0.6, 0.7] holds ln 2
}

// terminateSimulation at the third bounce ends the step that holds it, and every later one
TEST_F(me_component_test, terminate_simulation_ends_the_run_at_the_event) {
  auto f = load("ball", STRIDE_ME_BALL);
  auto c = make(*f, "ball", cvode(1e-8));
  variable_refs max;
  max.integers = {1};
  value_block three;
  three.integers = {3};
  c->set_values(max, three);
  initialise(*c, 3.0);
  variable_refs outs;
  outs.integers = {0};
  c->expose({}, outs);
  const double t1 = std::sqrt(2.0 / 9.81);
  const double third = t1 + 2 * 0.7 * t1 + 2 * 0.49 * t1;
  const duration dt = duration_from_seconds(0.01);
  time_point t = time_from_seconds(0);
  value_block out;
  while (c->step(t, dt, {}, out) == step_result::complete) t += dt;
  EXPECT_LT(to_seconds(t), third);
  EXPECT_GE(to_seconds(t + dt), third);
  EXPECT_EQ(c->step(t + dt, dt, {}, out), step_result::terminate);
}

// without rtol the FMU's DefaultExperiment/@tolerance (1e-6) is used, with atol = rtol
TEST_F(me_component_test, tolerances_default_to_the_default_experiment) {
  auto f = load("decay", STRIDE_ME_DECAY);
  variable_refs x;
  x.reals = {0};
  const auto run = [&](const model_exchange_options& o) {
    auto c = make(*f, "decay", o);
    initialise(*c, 1.0);
    return advance(*c, x, 0.0, 1.0, 1).outputs.back().reals[0];
  };
  model_exchange_options explicit_default;
  explicit_default.rtol = 1e-6;
  explicit_default.atol = 1e-6;
  model_exchange_options looser;
  looser.rtol = 1e-4;
  EXPECT_EQ(run({}), run(explicit_default));
  EXPECT_NE(run({}), run(looser));
}

// k = NaN makes the FMU's derivative NaN: refused at once, naming the derivative
TEST_F(me_component_test, nan_derivatives_stop_the_run_naming_the_variable) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  variable_refs k;
  k.reals = {2};
  value_block nan;
  nan.reals = {std::nan("")};
  c->set_values(k, nan);
  initialise(*c, 1.0);
  variable_refs x;
  x.reals = {0};
  try {
    advance(*c, x, 0.0, 0.1, 1);
    FAIL() << "NaN derivative accepted";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'decay' at t = 0 s"));
    EXPECT_THAT(e.what(), HasSubstr("fmi2GetDerivatives gave der(x) = NaN"));
  }
}

// fmi2Discard from the equations after t = 0.25 s: the run stops there, naming call and time
TEST_F(me_component_test, an_fmu_refusing_its_equations_stops_the_run_naming_the_time) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  variable_refs fail_after;
  fail_after.reals = {31};
  value_block quarter;
  quarter.reals = {0.25};
  c->set_values(fail_after, quarter);
  initialise(*c, 1.0);
  variable_refs x;
  x.reals = {0};
  advance(*c, x, 0.0, 0.1, 2);  // before 0.25 s all is well
  try {
    advance(*c, x, 0.2, 0.1, 1);
    FAIL() << "fmi2Discard ignored";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), ::testing::MatchesRegex("component 'decay' at t = 0\\.2[5-9][0-9]* s: "
                                                  "fmi2GetDerivatives returned fmi2Discard"));
  }
}

// Adams with fixed-point iteration on x' = -1e6 x must take steps of about 1e-6 s
TEST_F(me_component_test, a_solver_that_cannot_progress_names_the_reason) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto o = cvode(1e-6);
  o.method = model_exchange_options::method_kind::adams;
  auto c = make(*f, "decay", o);
  variable_refs k;
  k.reals = {2};
  value_block stiff;
  stiff.reals = {1e6};
  c->set_values(k, stiff);
  initialise(*c, 10.0);
  variable_refs x;
  x.reals = {0};
  try {
    advance(*c, x, 0.0, 10.0, 1);
    FAIL() << "Adams crossed a very stiff system";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'decay' at t = 0 s"));
    EXPECT_THAT(e.what(), HasSubstr("too much work"));
  }
}

// a saved state restored into a fresh instance continues exactly like the original
TEST_F(me_component_test, a_restored_state_continues_byte_identically) {
  auto f = load("ball", STRIDE_ME_BALL);
  variable_refs outs;
  outs.reals = {0, 2, 6};
  outs.integers = {0};
  auto original = make(*f, "ball", cvode(1e-8));
  initialise(*original, 3.0);
  advance(*original, outs, 0.0, 0.01, 100);
  const auto image = original->save_state();
  const auto expected = advance(*original, outs, 1.0, 0.01, 150);

  auto resumed = make(*f, "ball", cvode(1e-8));
  initialise(*resumed, 3.0);
  resumed->restore_state(image);
  const auto actual = advance(*resumed, outs, 1.0, 0.01, 150);
  ASSERT_EQ(actual.outputs.size(), expected.outputs.size());
  for (std::size_t i = 0; i < actual.outputs.size(); ++i) {
    EXPECT_EQ(actual.outputs[i].reals, expected.outputs[i].reals) << actual.t[i];
    EXPECT_EQ(actual.outputs[i].integers, expected.outputs[i].integers) << actual.t[i];
  }
}

// Inputs of every type are set at the communication point: a frozen x stands still exactly,
// and the string and Boolean echoes come back through fmi2GetString and fmi2GetBoolean.
TEST_F(me_component_test, inputs_of_every_type_reach_the_equations_at_communication_points) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-8));
  initialise(*c, 1.0);
  variable_refs ins;
  ins.reals = {3};     // u
  ins.booleans = {0};  // frozen
  ins.strings = {0};   // tag
  variable_refs outs;
  outs.reals = {0};     // x
  outs.booleans = {1};  // was_frozen
  outs.strings = {1};   // tag_seen
  c->expose(ins, outs);
  const auto step = [&](double t, bool frozen, const std::string& tag) {
    value_block in;
    in.reals = {0.0};
    in.booleans = {frozen};
    in.strings = {tag};
    value_block out;
    out.resize_for(outs);
    EXPECT_EQ(c->step(time_from_seconds(t), duration_from_seconds(0.1), in, out),
              step_result::complete);
    return out;
  };
  const auto moving = step(0.0, false, "first");
  EXPECT_NEAR(moving.reals[0], std::exp(-0.1), 1e-6);
  EXPECT_EQ(moving.booleans[0], false);
  EXPECT_EQ(moving.strings[0], "first");
  const auto held = step(0.1, true, "second");
  EXPECT_EQ(held.reals[0], moving.reals[0]);
  EXPECT_EQ(held.booleans[0], true);
  EXPECT_EQ(held.strings[0], "second");
  const auto again = step(0.2, false, "third");
  EXPECT_NEAR(again.reals[0], std::exp(-0.2), 1e-6);
}

// the FMU's printf-style messages reach the instance's sink, formatted, at their status' level
TEST_F(me_component_test, fmu_log_messages_reach_the_sink_with_their_level) {
  auto f = load("decay", STRIDE_ME_DECAY);
  std::vector<std::tuple<log_level, std::string, std::string>> got;
  instance_options io;
  io.model_exchange = cvode(1e-6);
  io.logging_on = true;
  io.log = [&](log_level level, std::string_view source, std::string_view, std::string_view text) {
    got.emplace_back(level, std::string(source), std::string(text));
  };
  auto c = f->instantiate("logged", io);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0], std::make_tuple(log_level::info, std::string("logged"),
                                    std::string("instantiated with 1 continuous states")));
  variable_refs fail_after;
  fail_after.reals = {31};
  value_block soon;
  soon.reals = {0.05};
  c->set_values(fail_after, soon);
  initialise(*c, 1.0);
  variable_refs x;
  x.reals = {0};
  EXPECT_THROW(advance(*c, x, 0.0, 0.1, 1), component_error);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(std::get<0>(got[1]), log_level::error);
  // the first evaluation of the equations after 0.05 s within the step (0, 0.1]
  EXPECT_THAT(std::get<2>(got[1]),
              ::testing::MatchesRegex("equations refused at t = 0\\.0[5-9][0-9]*"));
}

// a throwing sink is contained: the C code of the FMU is never unwound
TEST_F(me_component_test, a_throwing_log_sink_does_not_unwind_through_the_fmu) {
  auto f = load("decay", STRIDE_ME_DECAY);
  instance_options io;
  io.logging_on = true;
  io.log = [](log_level, std::string_view, std::string_view, std::string_view) {
    throw std::runtime_error("sink full");
  };
  EXPECT_NO_THROW(f->instantiate("logged", io));
}

TEST_F(me_component_test, an_event_iteration_that_never_settles_is_stopped) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  variable_refs chatter;
  chatter.reals = {30};
  value_block on;
  on.reals = {1.0};
  c->set_values(chatter, on);
  c->setup(time_from_seconds(0), time_from_seconds(1.0));
  c->enter_initialization();
  try {
    c->exit_initialization();
    FAIL() << "an endless event iteration was accepted";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'decay': event iteration did not settle after"));
  }
}

// threshold = +inf exposed as an output: refused, naming the value reference
TEST_F(me_component_test, a_non_finite_output_is_refused_naming_the_reference) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  variable_refs threshold;
  threshold.reals = {4};
  value_block inf;
  inf.reals = {std::numeric_limits<double>::infinity()};
  c->set_values(threshold, inf);
  initialise(*c, 1.0);
  try {
    advance(*c, threshold, 0.0, 0.1, 1);
    FAIL() << "an infinite output was passed on";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("fmi2GetReal gave value reference 4 a non-finite value"));
  }
}

// a value reference the FMU does not have: its fmi2Error is reported with the function
TEST_F(me_component_test, an_fmu_error_names_the_component_and_the_function) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  const auto refused = [&](variable_refs refs, value_block values, const std::string& function) {
    try {
      c->set_values(refs, values);
      FAIL() << function << " accepted an unknown value reference";
    } catch (const component_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("component 'decay': " + function + " returned fmi2Error"));
    }
  };
  variable_refs r;
  r.integers = {99};
  value_block v;
  v.integers = {1};
  refused(r, v, "fmi2SetInteger");
  r = {};
  r.booleans = {99};
  v = {};
  v.booleans = {true};
  refused(r, v, "fmi2SetBoolean");
  r = {};
  r.strings = {99};
  v = {};
  v.strings = {"x"};
  refused(r, v, "fmi2SetString");
  variable_refs unknown;
  unknown.integers = {99};
  value_block out;
  EXPECT_THROW(c->get_values(unknown, out), component_error);
}

TEST_F(me_component_test, an_fmu_without_state_support_says_so) {
  auto f = load("decay", STRIDE_ME_DECAY, {"canGetAndSetFMUstate=\"true\"", ""});
  auto c = make(*f, "decay", cvode(1e-6));
  initialise(*c, 1.0);
  try {
    c->save_state();
    FAIL() << "a state was saved without canGetAndSetFMUstate";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot save its state"));
  }
  EXPECT_THROW(c->restore_state({}), component_error);
}

TEST_F(me_component_test, a_foreign_or_truncated_image_is_refused) {
  auto f = load("decay", STRIDE_ME_DECAY);
  auto c = make(*f, "decay", cvode(1e-6));
  initialise(*c, 1.0);
  const std::vector<std::byte> foreign(64, std::byte{7});
  try {
    c->restore_state(foreign);
    FAIL() << "a foreign image was restored";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("not a Model Exchange runner's"));
  }
  auto image = c->save_state();
  image.resize(image.size() / 2);
  EXPECT_THROW(c->restore_state(image), validation_error);
}

// the ten-state chain: every state follows t^i e^-t / i! within the tolerance, by Model Exchange
// (CVODE) and by its Co-Simulation twin (the same library's RK4 at 1 ms), one FMU offering both
std::vector<double> chain_at_one_second(fmu& f, std::optional<model_exchange_options> me) {
  instance_options io;
  io.model_exchange = me;
  auto c = f.instantiate("chain", io);
  initialise(*c, 1.0);
  variable_refs x;
  for (std::uint32_t i = 0; i < 10; ++i) x.reals.push_back(i);
  return advance(*c, x, 0.0, 0.1, 10).outputs.back().reals;
}

TEST_F(me_component_test, a_ten_state_chain_follows_its_closed_form_in_both_kinds) {
  // <CoSimulation> after <ModelExchange/>, as the schema orders them
  auto f =
      load("chain", STRIDE_ME_CHAIN,
           {"canSerializeFMUstate=\"true\"/>",
            "canSerializeFMUstate=\"true\"/>\n  <CoSimulation modelIdentifier=\"me_chain\"/>"});
  const auto by_cvode = chain_at_one_second(*f, cvode(1e-8));
  const auto by_rk4 = chain_at_one_second(*f, std::nullopt);  // both offered: Co-Simulation
  ASSERT_EQ(by_cvode.size(), 10u);
  ASSERT_EQ(by_rk4.size(), 10u);
  double factorial = 1;
  for (int i = 0; i < 10; ++i) {
    if (i > 0) factorial *= i;
    const double exact = std::exp(-1.0) / factorial;  // t = 1
    EXPECT_NEAR(by_cvode[i], exact, 1e-7) << "x" << i;
    EXPECT_NEAR(by_rk4[i], exact, 1e-10) << "x" << i;
  }
  EXPECT_NE(by_cvode, by_rk4);  // two different integrators did the work
}

}  // namespace
}  // namespace stride::cosim
