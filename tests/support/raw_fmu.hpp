// A packaged .fmu, unzipped and imported by libstride, with its 34 C functions at hand for tests
// that drive the FMI calls themselves (FMU state, illegal values, step sizes).
#pragma once

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/cosim/fmu.hpp"
#include "stride/fmi2/fmi2_api.h"

namespace stride::test {

class raw_fmu {
 public:
  explicit raw_fmu(const std::filesystem::path& file) : fmu_(cosim::fmu::load(file)) {
    const auto& md = fmu_->model_description();
    const auto library = fmu_->extracted_dir() / "binaries" / "linux64" /
                         (md.co_simulation->model_identifier + ".so");
    handle_ = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr) throw std::runtime_error(dlerror());
#define STRIDE_RESOLVE(name) name = reinterpret_cast<name##TYPE*>(dlsym(handle_, #name));
    STRIDE_FMI2_CS_FUNCTIONS(STRIDE_RESOLVE)
#undef STRIDE_RESOLVE
  }
  ~raw_fmu() {
    for (fmi2Component c : instances_) fmi2FreeInstance(c);
    dlclose(handle_);
  }
  raw_fmu(const raw_fmu&) = delete;
  raw_fmu& operator=(const raw_fmu&) = delete;

  fmi2Component instantiate(const std::string& name = "instance") {
    fmi2Component c =
        fmi2Instantiate(name.c_str(), fmi2CoSimulation, fmu_->model_description().guid.c_str(),
                        fmu_->resource_uri().c_str(), &callbacks_, fmi2False, fmi2False);
    if (c == nullptr) throw std::runtime_error("fmi2Instantiate failed: " + last_message());
    instances_.push_back(c);
    return c;
  }

  fmi2ValueReference vr(const std::string& name) const {
    for (const auto& v : fmu_->model_description().variables) {
      if (v.name == name) return v.reference;
    }
    throw std::runtime_error("no variable " + name);
  }

  void initialize(fmi2Component c) {
    ASSERT_EQ(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
    ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK) << last_message();
  }

  double real(fmi2Component c, const std::string& name) {
    const fmi2ValueReference r = vr(name);
    double v = 0;
    EXPECT_EQ(fmi2GetReal(c, &r, 1, &v), fmi2OK) << name;
    return v;
  }
  int integer(fmi2Component c, const std::string& name) {
    const fmi2ValueReference r = vr(name);
    int v = 0;
    EXPECT_EQ(fmi2GetInteger(c, &r, 1, &v), fmi2OK) << name;
    return v;
  }
  bool boolean(fmi2Component c, const std::string& name) {
    const fmi2ValueReference r = vr(name);
    fmi2Boolean v = fmi2False;
    EXPECT_EQ(fmi2GetBoolean(c, &r, 1, &v), fmi2OK) << name;
    return v != fmi2False;
  }
  fmi2Status set_real(fmi2Component c, const std::string& name, double value) {
    const fmi2ValueReference r = vr(name);
    return fmi2SetReal(c, &r, 1, &value);
  }
  fmi2Status set_integer(fmi2Component c, const std::string& name, int value) {
    const fmi2ValueReference r = vr(name);
    return fmi2SetInteger(c, &r, 1, &value);
  }
  fmi2Status set_boolean(fmi2Component c, const std::string& name, bool value) {
    const fmi2ValueReference r = vr(name);
    const fmi2Boolean v = value ? fmi2True : fmi2False;
    return fmi2SetBoolean(c, &r, 1, &v);
  }
  fmi2Status set_string(fmi2Component c, const std::string& name, const std::string& value) {
    const fmi2ValueReference r = vr(name);
    const fmi2String v = value.c_str();
    return fmi2SetString(c, &r, 1, &v);
  }

  const std::vector<std::string>& messages() const {
    return messages_;
  }
  std::string last_message() const {
    return messages_.empty() ? "" : messages_.back();
  }
  bool logged(const std::string& fragment) const {
    for (const auto& m : messages_) {
      if (m.find(fragment) != std::string::npos) return true;
    }
    return false;
  }

#define STRIDE_DECLARE(name) name##TYPE* name = nullptr;
  STRIDE_FMI2_CS_FUNCTIONS(STRIDE_DECLARE)
#undef STRIDE_DECLARE

 private:
  static void log(fmi2ComponentEnvironment env, fmi2String, fmi2Status, fmi2String,
                  fmi2String message, ...) {
    char text[4096];
    va_list args;
    va_start(args, message);
    std::vsnprintf(text, sizeof text, message, args);
    va_end(args);
    static_cast<raw_fmu*>(env)->messages_.emplace_back(text);
  }

  std::shared_ptr<cosim::fmu> fmu_;
  void* handle_ = nullptr;
  std::vector<fmi2Component> instances_;
  std::vector<std::string> messages_;
  const fmi2CallbackFunctions callbacks_{&raw_fmu::log, nullptr, nullptr, nullptr, this};
};

}  // namespace stride::test
