// Every FMI function in every reachable state: allowed calls succeed, all others return
// fmi2Error with a message and never crash. The expected table is written here independently
// of the glue's, from the FMI 2.0 co-simulation state machine.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>
#include <string>

#include "fmi_harness.hpp"

namespace stride::test {
namespace {

enum class state {
  instantiated,
  initialization_mode,
  step_complete,
  step_failed,
  terminated,
  error
};

const std::map<state, std::string> state_names = {
    {state::instantiated, "instantiated"},  {state::initialization_mode, "initializationMode"},
    {state::step_complete, "stepComplete"}, {state::step_failed, "stepFailed"},
    {state::terminated, "terminated"},      {state::error, "error"}};

void drive_to(fmi_harness& h, state s) {
  switch (s) {
    case state::instantiated:
      return;
    case state::initialization_mode:
      h.to_initialization_mode();
      return;
    case state::step_complete:
      h.to_step_complete();
      return;
    case state::step_failed:
      ASSERT_EQ(h.set_integer("stop_after_steps", 1), fmi2OK);
      h.to_step_complete();
      ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2Discard);
      return;
    case state::terminated:
      h.to_step_complete();
      ASSERT_EQ(fmi2Terminate(h.c()), fmi2OK);
      return;
    case state::error:
      ASSERT_EQ(h.set_integer("fail_at_step", 1), fmi2OK);
      h.to_step_complete();
      ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2Error);
      return;
  }
}

struct call {
  std::string name;
  std::set<state> allowed;
  fmi2Status success;  // what an allowed call returns
  std::function<fmi2Status(fmi_harness&)> invoke;
};

const std::set<state> all = {state::instantiated, state::initialization_mode, state::step_complete,
                             state::step_failed,  state::terminated,          state::error};
const std::set<state> readable = {state::initialization_mode, state::step_complete,
                                  state::step_failed, state::terminated, state::error};
const std::set<state> writable = {state::instantiated, state::initialization_mode,
                                  state::step_complete};
const std::set<state> status_readable = {state::step_complete, state::step_failed,
                                         state::terminated};

std::vector<call> calls() {
  return {
      {"fmi2SetDebugLogging", all, fmi2OK,
       [](fmi_harness& h) { return fmi2SetDebugLogging(h.c(), fmi2True, 0, nullptr); }},
      {"fmi2SetupExperiment",
       {state::instantiated},
       fmi2OK,
       [](fmi_harness& h) { return fmi2SetupExperiment(h.c(), fmi2False, 0, 0, fmi2False, 0); }},
      {"fmi2EnterInitializationMode",
       {state::instantiated},
       fmi2OK,
       [](fmi_harness& h) { return fmi2EnterInitializationMode(h.c()); }},
      {"fmi2ExitInitializationMode",
       {state::initialization_mode},
       fmi2OK,
       [](fmi_harness& h) { return fmi2ExitInitializationMode(h.c()); }},
      {"fmi2Terminate",
       {state::step_complete, state::step_failed},
       fmi2OK,
       [](fmi_harness& h) { return fmi2Terminate(h.c()); }},
      {"fmi2Reset", all, fmi2OK, [](fmi_harness& h) { return fmi2Reset(h.c()); }},
      {"fmi2GetReal", readable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("y");
         double v;
         return fmi2GetReal(h.c(), &vr, 1, &v);
       }},
      {"fmi2GetInteger", readable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("counter");
         int v;
         return fmi2GetInteger(h.c(), &vr, 1, &v);
       }},
      {"fmi2GetBoolean", readable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("active");
         fmi2Boolean v;
         return fmi2GetBoolean(h.c(), &vr, 1, &v);
       }},
      {"fmi2GetString", readable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("echo");
         fmi2String v;
         return fmi2GetString(h.c(), &vr, 1, &v);
       }},
      {"fmi2SetReal", writable, fmi2OK, [](fmi_harness& h) { return h.set_real("u", 1.5); }},
      {"fmi2SetInteger", writable, fmi2OK, [](fmi_harness& h) { return h.set_integer("n", 1); }},
      {"fmi2SetBoolean", writable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("enable");
         const fmi2Boolean v = fmi2False;
         return fmi2SetBoolean(h.c(), &vr, 1, &v);
       }},
      {"fmi2SetString", writable, fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("suffix");
         const fmi2String v = "!";
         return fmi2SetString(h.c(), &vr, 1, &v);
       }},
      {"fmi2GetFMUstate+FreeFMUstate", all, fmi2OK,
       [](fmi_harness& h) {
         fmi2FMUstate s = nullptr;
         const fmi2Status got = fmi2GetFMUstate(h.c(), &s);
         if (got != fmi2OK) return got;
         return fmi2FreeFMUstate(h.c(), &s);
       }},
      {"fmi2SetFMUstate", all, fmi2OK,
       [](fmi_harness& h) {
         fmi2FMUstate s = nullptr;
         if (fmi2GetFMUstate(h.c(), &s) != fmi2OK) return fmi2Error;
         const fmi2Status set = fmi2SetFMUstate(h.c(), s);
         fmi2FreeFMUstate(h.c(), &s);
         return set;
       }},
      {"fmi2SerializeFMUstate+DeSerializeFMUstate", all, fmi2OK,
       [](fmi_harness& h) {
         fmi2FMUstate s = nullptr;
         if (fmi2GetFMUstate(h.c(), &s) != fmi2OK) return fmi2Error;
         size_t size = 0;
         fmi2Status r = fmi2SerializedFMUstateSize(h.c(), s, &size);
         std::vector<fmi2Byte> bytes(size);
         if (r == fmi2OK) r = fmi2SerializeFMUstate(h.c(), s, bytes.data(), size);
         fmi2FMUstate copy = nullptr;
         if (r == fmi2OK) r = fmi2DeSerializeFMUstate(h.c(), bytes.data(), size, &copy);
         fmi2FreeFMUstate(h.c(), &s);
         fmi2FreeFMUstate(h.c(), &copy);
         return r;
       }},
      {"fmi2DoStep",
       {state::step_complete},
       fmi2OK,
       [](fmi_harness& h) { return fmi2DoStep(h.c(), 0.0, 0.01, fmi2True); }},
      {"fmi2GetStatus", status_readable, fmi2Discard,
       [](fmi_harness& h) {
         fmi2Status v;
         return fmi2GetStatus(h.c(), fmi2DoStepStatus, &v);
       }},
      {"fmi2GetRealStatus", status_readable, fmi2OK,
       [](fmi_harness& h) {
         fmi2Real v;
         return fmi2GetRealStatus(h.c(), fmi2LastSuccessfulTime, &v);
       }},
      {"fmi2GetIntegerStatus", status_readable, fmi2Discard,
       [](fmi_harness& h) {
         fmi2Integer v;
         return fmi2GetIntegerStatus(h.c(), fmi2DoStepStatus, &v);
       }},
      {"fmi2GetBooleanStatus", status_readable, fmi2OK,
       [](fmi_harness& h) {
         fmi2Boolean v;
         return fmi2GetBooleanStatus(h.c(), fmi2Terminated, &v);
       }},
      {"fmi2GetStringStatus", status_readable, fmi2Discard,
       [](fmi_harness& h) {
         fmi2String v;
         return fmi2GetStringStatus(h.c(), fmi2PendingStatus, &v);
       }},
      // capabilities the FMU declares absent: an error in every state
      {"fmi2GetDirectionalDerivative",
       {},
       fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference u = fmi_harness::vr("y"), k = fmi_harness::vr("u");
         const double dk = 1;
         double du;
         return fmi2GetDirectionalDerivative(h.c(), &u, 1, &k, 1, &dk, &du);
       }},
      {"fmi2SetRealInputDerivatives",
       {},
       fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("u");
         const fmi2Integer order = 1;
         const double v = 0;
         return fmi2SetRealInputDerivatives(h.c(), &vr, 1, &order, &v);
       }},
      {"fmi2GetRealOutputDerivatives",
       {},
       fmi2OK,
       [](fmi_harness& h) {
         const fmi2ValueReference vr = fmi_harness::vr("y");
         const fmi2Integer order = 1;
         double v;
         return fmi2GetRealOutputDerivatives(h.c(), &vr, 1, &order, &v);
       }},
      {"fmi2CancelStep", {}, fmi2OK, [](fmi_harness& h) { return fmi2CancelStep(h.c()); }},
  };
}

TEST(lifecycle, every_function_in_every_state) {
  for (const auto& [s, state_name] : state_names) {
    for (const call& c : calls()) {
      fmi_harness h;
      drive_to(h, s);
      h.clear_log();
      const fmi2Status result = c.invoke(h);
      if (c.allowed.count(s)) {
        EXPECT_EQ(result, c.success) << c.name << " in " << state_name;
      } else {
        EXPECT_EQ(result, fmi2Error) << c.name << " in " << state_name;
        EXPECT_FALSE(h.log().empty()) << c.name << " in " << state_name << " gave no message";
      }
    }
  }
}

TEST(lifecycle, illegal_call_names_function_and_state_and_changes_nothing) {
  fmi_harness h;
  EXPECT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2Error);
  EXPECT_TRUE(h.logged("fmi2DoStep: illegal call in state instantiated"));
  // still instantiated: the normal sequence works
  h.to_step_complete();
  EXPECT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2OK);
}

TEST(lifecycle, null_instance_is_an_error_not_a_crash) {
  EXPECT_EQ(fmi2DoStep(nullptr, 0, 0.01, fmi2True), fmi2Error);
  EXPECT_EQ(fmi2EnterInitializationMode(nullptr), fmi2Error);
  const fmi2ValueReference vr = 0;
  double v;
  EXPECT_EQ(fmi2GetReal(nullptr, &vr, 1, &v), fmi2Error);
  fmi2FreeInstance(nullptr);
}

void collect(fmi2ComponentEnvironment env, fmi2String, fmi2Status, fmi2String, fmi2String m, ...) {
  static_cast<std::vector<std::string>*>(env)->push_back(m);
}

TEST(lifecycle, instantiate_rejects_wrong_guid_and_model_exchange) {
  std::vector<std::string> messages;
  fmi2CallbackFunctions callbacks{&collect, nullptr, nullptr, nullptr, &messages};
  EXPECT_EQ(fmi2Instantiate("x", fmi2CoSimulation, "{wrong}", nullptr, &callbacks, 0, 0), nullptr);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_NE(messages[0].find("wrong GUID"), std::string::npos);
  EXPECT_EQ(fmi2Instantiate("x", fmi2ModelExchange, fmi_harness::guid().c_str(), nullptr,
                            &callbacks, 0, 0),
            nullptr);
  EXPECT_EQ(
      fmi2Instantiate("x", fmi2CoSimulation, fmi_harness::guid().c_str(), nullptr, nullptr, 0, 0),
      nullptr);
}

TEST(lifecycle, version_and_platform) {
  EXPECT_STREQ(fmi2GetVersion(), "2.0");
  EXPECT_STREQ(fmi2GetTypesPlatform(), "default");
}

TEST(lifecycle, requested_termination_is_reported) {
  fmi_harness h;
  ASSERT_EQ(h.set_integer("stop_after_steps", 3), fmi2OK);
  h.to_step_complete();
  EXPECT_EQ(fmi2DoStep(h.c(), 0.00, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(fmi2DoStep(h.c(), 0.01, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(fmi2DoStep(h.c(), 0.02, 0.01, fmi2True), fmi2Discard);
  fmi2Boolean terminated = fmi2False;
  EXPECT_EQ(fmi2GetBooleanStatus(h.c(), fmi2Terminated, &terminated), fmi2OK);
  EXPECT_EQ(terminated, fmi2True);
  fmi2Real last = 0;
  EXPECT_EQ(fmi2GetRealStatus(h.c(), fmi2LastSuccessfulTime, &last), fmi2OK);
  EXPECT_DOUBLE_EQ(last, 0.03);
  EXPECT_EQ(h.get_integer("counter"), 3);
}

TEST(lifecycle, component_failure_enters_error_state_with_message) {
  fmi_harness h;
  ASSERT_EQ(h.set_integer("fail_at_step", 2), fmi2OK);
  h.to_step_complete();
  EXPECT_EQ(fmi2DoStep(h.c(), 0.00, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(fmi2DoStep(h.c(), 0.01, 0.01, fmi2True), fmi2Error);
  EXPECT_TRUE(h.logged("fmi2DoStep: step 2 fails on request"));
  EXPECT_EQ(fmi2DoStep(h.c(), 0.02, 0.01, fmi2True), fmi2Error);  // error state
  EXPECT_EQ(fmi2Reset(h.c()), fmi2OK);
  h.to_step_complete();
  EXPECT_EQ(fmi2DoStep(h.c(), 0.00, 0.01, fmi2True), fmi2OK);
}

TEST(lifecycle, a_step_past_the_declared_stop_time_is_refused) {
  fmi_harness h;
  ASSERT_EQ(fmi2SetupExperiment(h.c(), fmi2False, 0, 0, fmi2True, 0.02), fmi2OK);
  ASSERT_EQ(fmi2EnterInitializationMode(h.c()), fmi2OK);
  ASSERT_EQ(fmi2ExitInitializationMode(h.c()), fmi2OK);
  EXPECT_EQ(fmi2DoStep(h.c(), 0.00, 0.01, fmi2True), fmi2OK);
  EXPECT_EQ(fmi2DoStep(h.c(), 0.01, 0.01, fmi2True), fmi2OK);  // ends exactly at stopTime
  EXPECT_EQ(fmi2DoStep(h.c(), 0.02, 0.01, fmi2True), fmi2Error);
  EXPECT_TRUE(h.logged("fmi2DoStep: the step ends at 0.03 s, past the stopTime 0.02 s"));
  EXPECT_EQ(h.get_integer("counter"), 2);  // the refused step did not run
  ASSERT_EQ(fmi2Reset(h.c()), fmi2OK);     // a reset forgets the stop time
  h.to_step_complete();
  EXPECT_EQ(fmi2DoStep(h.c(), 0.00, 0.05, fmi2True), fmi2OK);
}

TEST(lifecycle, reset_restores_start_values) {
  fmi_harness h;
  h.to_step_complete();
  ASSERT_EQ(h.set_real("gain", 5.0), fmi2OK);
  ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2OK);
  ASSERT_EQ(fmi2Reset(h.c()), fmi2OK);
  h.to_step_complete();
  EXPECT_EQ(h.get_real("gain"), 2.0);
  EXPECT_EQ(h.get_integer("counter"), 0);
}

TEST(lifecycle, debug_logging_categories) {
  fmi_harness h;
  const fmi2String unknown[] = {"logNoSuchThing"};
  EXPECT_EQ(fmi2SetDebugLogging(h.c(), fmi2True, 1, unknown), fmi2Error);
  EXPECT_TRUE(h.logged("unknown log category 'logNoSuchThing'"));
  const fmi2String events[] = {"logEvents"};
  ASSERT_EQ(fmi2SetDebugLogging(h.c(), fmi2True, 1, events), fmi2OK);
  h.to_step_complete();
  h.clear_log();
  ASSERT_EQ(fmi2DoStep(h.c(), 0.0, 0.01, fmi2True), fmi2OK);
  EXPECT_TRUE(h.logged("step 1"));
  ASSERT_EQ(fmi2SetDebugLogging(h.c(), fmi2False, 1, events), fmi2OK);
  h.clear_log();
  ASSERT_EQ(fmi2DoStep(h.c(), 0.01, 0.01, fmi2True), fmi2OK);
  EXPECT_TRUE(h.log().empty());
}

}  // namespace
}  // namespace stride::test
