// Helpers to drive the FMI functions of the linked-in stride_test component.
#pragma once

#include <string>
#include <vector>

#include "stride/fmi2/fmi2_api.h"

namespace stride::test {

/// Messages received through the FMI logger callback.
struct log_record {
  fmi2Status status;
  std::string category;
  std::string message;
};

class fmi_harness {
 public:
  fmi_harness();
  ~fmi_harness();
  fmi_harness(const fmi_harness&) = delete;
  fmi_harness& operator=(const fmi_harness&) = delete;

  static std::string guid();
  static fmi2ValueReference vr(const std::string& name);

  fmi2Component c() const { return component_; }
  const std::vector<log_record>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  bool logged(const std::string& fragment) const;

  void to_initialization_mode();
  void to_step_complete();

  double get_real(const std::string& name);
  int get_integer(const std::string& name);
  fmi2Status set_real(const std::string& name, double value);
  fmi2Status set_integer(const std::string& name, int value);

 private:
  static void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String category,
                     fmi2String message, ...);
  std::vector<log_record> log_;
  fmi2CallbackFunctions callbacks_;
  fmi2Component component_ = nullptr;
};

}  // namespace stride::test
