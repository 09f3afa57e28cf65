// An FMI 3.0 instance as a Stride component: the life cycle, logging, termination requested by
// the FMU, and state images (fmi3GetFMUState + serialization) that resume identically.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fmi3_fixture.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {
namespace {

using test::batch;
using ::testing::HasSubstr;

const duration k_step = std::chrono::milliseconds(100);

class fmi3_component_test : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-fmi3-component-test-"};
  std::shared_ptr<fmu> f = fmu::load(test::k_fmi3_kinds, test::extract_into(scratch.path()));
};

// The outputs a test watches: the step counter, the float relation, an array, a string.
variable_refs watched(const component& c) {
  variable_refs out;
  out.integers = {test::ref(c, "steps")};
  out.reals = {test::ref(c, "f64_out"), test::ref(c, "f64_aout[1]"), test::ref(c, "f64_aout[3]")};
  out.strings = {test::ref(c, "s_out")};
  return out;
}

// `n` steps from `t` with f64_in = t and f64_ain[1] = 2 t; the outputs after each.
std::vector<value_block> run(component& c, time_point& t, int n) {
  std::vector<value_block> outputs;
  const auto out = watched(c);
  for (int i = 0; i < n; ++i) {
    batch in;
    in.real(c, "f64_in", to_seconds(t)).real(c, "f64_ain[1]", 2 * to_seconds(t));
    in.string(c, "s_in", "t" + std::to_string(i));
    c.expose(in.refs, out);
    value_block o;
    o.resize_for(out);
    EXPECT_EQ(c.step(t, k_step, in.values, o), step_result::complete);
    outputs.push_back(o);
    t += k_step;
  }
  return outputs;
}

TEST_F(fmi3_component_test, parameters_and_start_values_are_set_before_initialization) {
  auto c = f->instantiate("k");
  c->setup(time_point{}, time_from_seconds(1));
  const auto p = batch().real(*c, "gain", 10).real(*c, "f64_in", 3);
  c->set_values(p.refs, p.values);
  c->enter_initialization();
  c->exit_initialization();
  variable_refs out;
  out.reals = {test::ref(*c, "f64_out"), test::ref(*c, "time")};
  value_block v;
  c->get_values(out, v);
  EXPECT_EQ(v.reals[0], 10 * 3);  // computed at the end of initialization, no step yet
  EXPECT_EQ(v.reals[1], 0.0);
  time_point t{};
  const auto steps = run(*c, t, 2);
  EXPECT_EQ(steps[1].reals[0], 10 * 0.1 + 2);  // gain * f64_in + steps
  EXPECT_EQ(steps[1].integers[0], 2);
  c->terminate();
}

TEST_F(fmi3_component_test, the_start_time_reaches_the_fmu) {
  auto c = f->instantiate("k");
  c->setup(time_from_seconds(2.5), std::nullopt);
  c->enter_initialization();
  c->exit_initialization();
  variable_refs t;
  t.reals = {test::ref(*c, "time")};
  value_block v;
  c->get_values(t, v);
  EXPECT_EQ(v.reals[0], 2.5);
}

TEST_F(fmi3_component_test, fmu_log_messages_go_to_the_instance_sink_when_logging_is_on) {
  test::log_lines on;
  auto c = f->instantiate("loud", {on.sink(), true});
  ASSERT_EQ(on.lines.size(), 1u);
  EXPECT_EQ(on.lines[0], "info loud: fmi3_kinds instantiated");
  test::log_lines off;
  auto quiet = f->instantiate("quiet", {off.sink(), false});
  EXPECT_TRUE(off.lines.empty());
}

TEST_F(fmi3_component_test, terminate_simulation_ends_the_run_and_is_logged_with_the_time) {
  test::log_lines log;
  auto c = test::stepping_fmi3_kinds(f, {log.sink(), false});
  time_point t{};
  run(*c, t, 2);
  const auto stop = batch().boolean(*c, "stop", true);
  c->expose(stop.refs, {});
  value_block none;
  EXPECT_EQ(c->step(t, k_step, stop.values, none), step_result::terminate);
  ASSERT_FALSE(log.lines.empty());
  EXPECT_EQ(log.lines.back(), "warning k: fmi3DoStep at t = 0.200000 set terminateSimulation");
  EXPECT_NO_THROW(c->terminate());
}

TEST_F(fmi3_component_test, an_fmu_error_names_the_component_and_the_function) {
  auto c = f->instantiate("k");
  c->setup(time_point{}, std::nullopt);
  // stepping before initialization is refused by the FMU
  value_block none;
  try {
    c->step(time_point{}, k_step, none, none);
    FAIL() << "stepped";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'k': fmi3DoStep returned fmi3Error"));
  }
}

TEST_F(fmi3_component_test, a_state_image_resumes_identically) {
  auto c = test::stepping_fmi3_kinds(f);
  time_point t{};
  run(*c, t, 3);
  const auto image = c->save_state();
  EXPECT_FALSE(image.empty());
  const time_point saved_at = t;
  const auto first = run(*c, t, 4);
  c->restore_state(image);
  t = saved_at;
  const auto again = run(*c, t, 4);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].integers, again[i].integers) << i;
    EXPECT_EQ(first[i].reals, again[i].reals) << i;
    EXPECT_EQ(first[i].strings, again[i].strings) << i;
  }
  EXPECT_EQ(again.back().integers[0], 3 + 4);
  // into a second instance: the same continuation
  auto other = test::stepping_fmi3_kinds(f);
  other->restore_state(image);
  t = saved_at;
  const auto elsewhere = run(*other, t, 4);
  EXPECT_EQ(elsewhere.back().reals, first.back().reals);
}

TEST_F(fmi3_component_test, array_elements_set_after_a_restore_build_on_the_restored_array) {
  auto c = test::stepping_fmi3_kinds(f);
  const auto image = c->save_state();  // f64_ain = 10 20 30
  auto b = batch().real(*c, "f64_ain[2]", 99);
  c->set_values(b.refs, b.values);
  c->restore_state(image);
  // only element 1 is set: elements 2 and 3 must come from the restored state, not from 99
  b = batch().real(*c, "f64_ain[1]", 5);
  variable_refs out;
  for (int i = 1; i <= 3; ++i) {
    out.reals.push_back(test::ref(*c, "f64_aout[" + std::to_string(i) + "]"));
  }
  c->expose(b.refs, out);
  value_block o;
  o.resize_for(out);
  c->step(time_point{}, k_step, b.values, o);
  EXPECT_EQ(o.reals, (std::vector<double>{5 + 1, 20 + 2, 30 + 3}));
}

TEST_F(fmi3_component_test, a_damaged_image_is_refused) {
  auto c = test::stepping_fmi3_kinds(f);
  auto image = c->save_state();
  image.pop_back();
  EXPECT_THAT([&] { c->restore_state(image); }, ::testing::ThrowsMessage<component_error>(HasSubstr(
                                                    "fmi3DeserializeFMUState returned fmi3Error")));
}

TEST_F(fmi3_component_test, an_fmu_without_state_support_says_so) {
  const auto file = scratch.path() / "stateless.fmu";
  test::write_fmi3_kinds_variant(
      file, test::replaced(test::fmi3_kinds_xml(),
                           "canGetAndSetFMUState=\"true\" canSerializeFMUState=\"true\"", ""));
  auto stateless = fmu::load(file, test::extract_into(scratch.path()));
  auto c = test::stepping_fmi3_kinds(stateless);
  EXPECT_THAT([&] { c->save_state(); }, ::testing::ThrowsMessage<component_error>(HasSubstr(
                                            "cannot save its state (canGetAndSetFMUState and "
                                            "canSerializeFMUState are not both true)")));
}

}  // namespace
}  // namespace stride::cosim
