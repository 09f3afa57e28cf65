// The FMI 3.0 lifecycle of glue3.cpp, driven on the linked-in stride_test component: what an
// importer may call in which state, stepping, termination and reset (docs/fmi3-rules.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fmi3_harness.hpp"

namespace stride::test {
namespace {

struct quiet_log {
  std::vector<log3_record> records;
  bool logged(const std::string& fragment) const {
    for (const log3_record& r : records) {
      if (r.message.find(fragment) != std::string::npos) return true;
    }
    return false;
  }
  static void callback(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                       fmi3String message) {
    static_cast<quiet_log*>(env)->records.push_back({status, category, message});
  }
};

TEST(glue3, version_is_3_0) {
  EXPECT_STREQ(fmi3GetVersion(), "3.0");
}

TEST(glue3, wrong_instantiation_token_is_refused_with_a_message) {
  quiet_log log;
  fmi3Instance i =
      fmi3InstantiateCoSimulation("x", "{not-the-token}", "/tmp/", fmi3False, fmi3False, fmi3False,
                                  fmi3False, nullptr, 0, &log, &quiet_log::callback, nullptr);
  EXPECT_EQ(i, nullptr);
  EXPECT_TRUE(log.logged("wrong instantiationToken {not-the-token}"));
}

TEST(glue3, event_mode_and_intermediate_variables_are_refused) {
  quiet_log log;
  const std::string token = fmi3_harness::token();
  EXPECT_EQ(fmi3InstantiateCoSimulation("x", token.c_str(), "/tmp/", fmi3False, fmi3False, fmi3True,
                                        fmi3False, nullptr, 0, &log, &quiet_log::callback, nullptr),
            nullptr);
  EXPECT_TRUE(log.logged("no Event Mode"));
  const fmi3ValueReference vr = fmi3_harness::vr("y");
  EXPECT_EQ(
      fmi3InstantiateCoSimulation("x", token.c_str(), "/tmp/", fmi3False, fmi3False, fmi3False,
                                  fmi3False, &vr, 1, &log, &quiet_log::callback, nullptr),
      nullptr);
  EXPECT_TRUE(log.logged("no intermediate update"));
}

TEST(glue3, model_exchange_and_scheduled_execution_are_refused_with_a_message) {
  quiet_log log;
  const std::string token = fmi3_harness::token();
  EXPECT_EQ(fmi3InstantiateModelExchange("x", token.c_str(), "/tmp/", fmi3False, fmi3False, &log,
                                         &quiet_log::callback),
            nullptr);
  EXPECT_TRUE(log.logged("fmi3InstantiateModelExchange: the FMU offers Co-Simulation only"));
  EXPECT_EQ(
      fmi3InstantiateScheduledExecution("x", token.c_str(), "/tmp/", fmi3False, fmi3False, &log,
                                        &quiet_log::callback, nullptr, nullptr, nullptr),
      nullptr);
  EXPECT_TRUE(log.logged("fmi3InstantiateScheduledExecution"));
}

TEST(glue3, do_step_before_initialization_is_an_illegal_call) {
  fmi3_harness h;
  EXPECT_EQ(h.step(0, 0.01), fmi3Error);
  EXPECT_TRUE(h.logged("fmi3DoStep: illegal call in state Instantiated"));
}

TEST(glue3, a_step_integrates_the_input_and_the_output_follows_it) {
  fmi3_harness h;
  h.to_initialization_mode();
  ASSERT_EQ(h.set_float64("u", 3.0), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  const double gain = h.get_float64("gain"), offset = h.get_float64("offset");
  EXPECT_DOUBLE_EQ(h.get_float64("y"), gain * 3.0 + offset);
  ASSERT_EQ(h.step(0.0, 0.25), fmi3OK);
  ASSERT_EQ(h.step(0.25, 0.25), fmi3OK);
  EXPECT_DOUBLE_EQ(h.get_float64("integral"), 3.0 * 0.5);  // u * (two steps of 0.25 s)
}

TEST(glue3, invalid_step_sizes_and_null_outputs_are_refused) {
  fmi3_harness h;
  h.to_step_mode();
  EXPECT_EQ(h.step(0, 0), fmi3Error);
  EXPECT_EQ(h.step(0, -0.1), fmi3Error);
  EXPECT_EQ(h.step(0, std::numeric_limits<double>::quiet_NaN()), fmi3Error);
  EXPECT_EQ(h.step(std::numeric_limits<double>::infinity(), 0.1), fmi3Error);
  EXPECT_TRUE(h.logged("invalid communication point or step size"));
  fmi3Boolean b;
  fmi3Float64 last;
  EXPECT_EQ(fmi3DoStep(h.instance(), 0, 0.1, fmi3True, &b, nullptr, &b, &last), fmi3Error);
  EXPECT_TRUE(h.logged("null out argument"));
  EXPECT_DOUBLE_EQ(h.get_float64("integral"), 0.0);  // none of these stepped
}

TEST(glue3, a_component_asking_to_stop_sets_terminate_simulation) {
  fmi3_harness h;
  h.to_initialization_mode();
  const fmi3ValueReference vr = fmi3_harness::vr("stop_after_steps");
  const fmi3Int32 two = 2;
  ASSERT_EQ(fmi3SetInt32(h.instance(), &vr, 1, &two, 1), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  fmi3Boolean event, terminate, early;
  fmi3Float64 last;
  ASSERT_EQ(fmi3DoStep(h.instance(), 0, 0.1, fmi3True, &event, &terminate, &early, &last), fmi3OK);
  EXPECT_FALSE(terminate);
  ASSERT_EQ(fmi3DoStep(h.instance(), 0.1, 0.1, fmi3True, &event, &terminate, &early, &last),
            fmi3OK);
  EXPECT_TRUE(terminate);
  EXPECT_EQ(fmi3DoStep(h.instance(), 0.2, 0.1, fmi3True, &event, &terminate, &early, &last),
            fmi3Error);
  EXPECT_TRUE(h.logged("asked to end the simulation"));
  EXPECT_EQ(fmi3Terminate(h.instance()), fmi3OK);
}

TEST(glue3, a_failing_step_puts_the_instance_in_error_until_reset) {
  fmi3_harness h;
  h.to_initialization_mode();
  const fmi3ValueReference vr = fmi3_harness::vr("fail_at_step");
  const fmi3Int32 one = 1;
  ASSERT_EQ(fmi3SetInt32(h.instance(), &vr, 1, &one, 1), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  EXPECT_EQ(h.step(0, 0.1), fmi3Error);
  EXPECT_TRUE(h.logged("step 1 fails on request"));
  EXPECT_EQ(h.step(0, 0.1), fmi3Error);  // the error state takes no more steps
  EXPECT_TRUE(h.logged("illegal call in state"));
  ASSERT_EQ(fmi3Reset(h.instance()), fmi3OK);
  h.to_step_mode();  // fail_at_step is back to its start value 0
  EXPECT_EQ(h.step(0, 0.1), fmi3OK);
}

TEST(glue3, a_step_past_the_declared_stop_time_is_refused) {
  fmi3_harness h;
  ASSERT_EQ(fmi3EnterInitializationMode(h.instance(), fmi3False, 0, 0, fmi3True, 0.5), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  ASSERT_EQ(h.step(0.0, 0.25), fmi3OK);
  ASSERT_EQ(h.step(0.25, 0.25), fmi3OK);  // ends exactly at stopTime
  EXPECT_EQ(h.step(0.5, 0.25), fmi3Error);
  EXPECT_TRUE(h.logged("fmi3DoStep: the step ends at 0.75 s, past the stopTime 0.5 s"));
  ASSERT_EQ(fmi3Reset(h.instance()), fmi3OK);  // a reset forgets the stop time
  h.to_step_mode();
  EXPECT_EQ(h.step(0.0, 1.0), fmi3OK);
}

TEST(glue3, reset_restores_start_values) {
  fmi3_harness h;
  h.to_initialization_mode();
  ASSERT_EQ(h.set_float64("u", 5.0), fmi3OK);
  ASSERT_EQ(fmi3ExitInitializationMode(h.instance()), fmi3OK);
  ASSERT_EQ(h.step(0, 1.0), fmi3OK);
  ASSERT_EQ(fmi3Reset(h.instance()), fmi3OK);
  h.to_initialization_mode();
  EXPECT_DOUBLE_EQ(h.get_float64("u"), 0.0);
  EXPECT_DOUBLE_EQ(h.get_float64("integral"), 0.0);
}

TEST(glue3, functions_of_features_not_offered_answer_error_with_the_reason) {
  fmi3_harness h;
  h.to_step_mode();
  EXPECT_EQ(fmi3EnterEventMode(h.instance()), fmi3Error);
  EXPECT_TRUE(h.logged("fmi3EnterEventMode: not supported"));
  EXPECT_EQ(fmi3EnterConfigurationMode(h.instance()), fmi3Error);
  EXPECT_TRUE(h.logged("fmi3EnterConfigurationMode: not supported"));
  EXPECT_EQ(h.step(0, 0.1), fmi3OK);  // a refused call leaves the instance usable
}

TEST(glue3, unknown_debug_log_category_is_refused) {
  fmi3_harness h;
  const fmi3String known[] = {"logEvents"};
  EXPECT_EQ(fmi3SetDebugLogging(h.instance(), fmi3True, 1, known), fmi3OK);
  const fmi3String unknown[] = {"logEverything"};
  EXPECT_EQ(fmi3SetDebugLogging(h.instance(), fmi3True, 1, unknown), fmi3Error);
  EXPECT_TRUE(h.logged("unknown log category 'logEverything'"));
}

}  // namespace
}  // namespace stride::test
