#include "fmi_harness.hpp"

#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdio>
#include <stdexcept>

#include "stride/sdk/fmu.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::test {

fmi_harness::fmi_harness() : callbacks_{&fmi_harness::logger, nullptr, nullptr, nullptr, this} {
  component_ = fmi2Instantiate("test", fmi2CoSimulation, guid().c_str(), "file:///tmp", &callbacks_,
                               fmi2False, fmi2False);
  if (component_ == nullptr) throw std::runtime_error("fmi2Instantiate failed");
}

fmi_harness::~fmi_harness() {
  if (component_ != nullptr) fmi2FreeInstance(component_);
}

std::string fmi_harness::guid() {
  return sdk::compute_guid(sdk::detail::registered_fmu());
}

fmi2ValueReference fmi_harness::vr(const std::string& name) {
  const sdk::variable* v = sdk::detail::registered_fmu().table.find(name);
  if (v == nullptr) throw std::runtime_error("no variable " + name);
  return v->value_reference;
}

bool fmi_harness::logged(const std::string& fragment) const {
  for (const log_record& r : log_) {
    if (r.message.find(fragment) != std::string::npos) return true;
  }
  return false;
}

void fmi_harness::to_initialization_mode() {
  ASSERT_EQ(fmi2SetupExperiment(component_, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(fmi2EnterInitializationMode(component_), fmi2OK);
}

void fmi_harness::to_step_complete() {
  to_initialization_mode();
  ASSERT_EQ(fmi2ExitInitializationMode(component_), fmi2OK);
}

double fmi_harness::get_real(const std::string& name) {
  const fmi2ValueReference r = vr(name);
  double value = -1;
  EXPECT_EQ(fmi2GetReal(component_, &r, 1, &value), fmi2OK) << name;
  return value;
}

int fmi_harness::get_integer(const std::string& name) {
  const fmi2ValueReference r = vr(name);
  int value = -1;
  EXPECT_EQ(fmi2GetInteger(component_, &r, 1, &value), fmi2OK) << name;
  return value;
}

fmi2Status fmi_harness::set_real(const std::string& name, double value) {
  const fmi2ValueReference r = vr(name);
  return fmi2SetReal(component_, &r, 1, &value);
}

fmi2Status fmi_harness::set_integer(const std::string& name, int value) {
  const fmi2ValueReference r = vr(name);
  return fmi2SetInteger(component_, &r, 1, &value);
}

void fmi_harness::logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status,
                         fmi2String category, fmi2String message, ...) {
  char text[2048];
  va_list args;
  va_start(args, message);
  std::vsnprintf(text, sizeof text, message, args);
  va_end(args);
  static_cast<fmi_harness*>(env)->log_.push_back({status, category ? category : "", text});
}

}  // namespace stride::test
