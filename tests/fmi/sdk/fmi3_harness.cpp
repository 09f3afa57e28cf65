#include "fmi3_harness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "stride/sdk/fmu.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::test {

fmi3_harness::fmi3_harness() {
  instance_ = fmi3InstantiateCoSimulation("test3", token().c_str(), "/tmp/", fmi3False, fmi3False,
                                          fmi3False, fmi3False, nullptr, 0, this,
                                          &fmi3_harness::logger, nullptr);
  if (instance_ == nullptr) throw std::runtime_error("fmi3InstantiateCoSimulation failed");
}

fmi3_harness::~fmi3_harness() {
  if (instance_ != nullptr) fmi3FreeInstance(instance_);
}

std::string fmi3_harness::token() {
  return sdk::compute_guid(sdk::detail::registered_fmu());
}

fmi3ValueReference fmi3_harness::vr(const std::string& name) {
  const sdk::variable_table& table = sdk::detail::registered_fmu().table;
  if (name == "time") {  // docs/fmu-interop.md: one above the table's highest value reference
    fmi3ValueReference highest = 0;
    for (const sdk::variable& v : table.variables()) highest = std::max(highest, v.value_reference);
    return highest + 1;
  }
  const sdk::variable* v = table.find(name);
  if (v == nullptr) v = table.find(name + "[1]");
  if (v == nullptr) throw std::runtime_error("no variable " + name);
  return v->value_reference;
}

bool fmi3_harness::logged(const std::string& fragment) const {
  for (const log3_record& r : log_) {
    if (r.message.find(fragment) != std::string::npos) return true;
  }
  return false;
}

void fmi3_harness::to_initialization_mode() {
  ASSERT_EQ(fmi3EnterInitializationMode(instance_, fmi3False, 0, 0, fmi3False, 0), fmi3OK);
}

void fmi3_harness::to_step_mode() {
  to_initialization_mode();
  ASSERT_EQ(fmi3ExitInitializationMode(instance_), fmi3OK);
}

fmi3Status fmi3_harness::step(double t, double h) {
  fmi3Boolean event = fmi3True, terminate = fmi3True, early = fmi3True;
  fmi3Float64 last = -1;
  const fmi3Status s = fmi3DoStep(instance_, t, h, fmi3True, &event, &terminate, &early, &last);
  if (s == fmi3OK) {
    EXPECT_FALSE(event);
    EXPECT_FALSE(early);
    EXPECT_DOUBLE_EQ(last, t + h);
  }
  return s;
}

double fmi3_harness::get_float64(const std::string& name) {
  const fmi3ValueReference r = vr(name);
  double value = -1;
  EXPECT_EQ(fmi3GetFloat64(instance_, &r, 1, &value, 1), fmi3OK) << name;
  return value;
}

fmi3Status fmi3_harness::set_float64(const std::string& name, double value) {
  const fmi3ValueReference r = vr(name);
  return fmi3SetFloat64(instance_, &r, 1, &value, 1);
}

void fmi3_harness::logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                          fmi3String message) {
  static_cast<fmi3_harness*>(env)->log_.push_back(
      {status, category ? category : "", message ? message : ""});
}

}  // namespace stride::test
