// Drives the FMI 3.0 functions of the linked-in stride_test component, as an importer would.
#pragma once

#include <string>
#include <vector>

#include "stride/fmi3/fmi3_api.h"

namespace stride::test {

/// Messages received through the FMI 3.0 logMessage callback.
struct log3_record {
  fmi3Status status;
  std::string category;
  std::string message;
};

class fmi3_harness {
 public:
  fmi3_harness();
  ~fmi3_harness();
  fmi3_harness(const fmi3_harness&) = delete;
  fmi3_harness& operator=(const fmi3_harness&) = delete;

  static std::string token();
  /// The FMI 3.0 value reference of a variable of the table (an array: its first element).
  static fmi3ValueReference vr(const std::string& name);

  fmi3Instance instance() const { return instance_; }
  const std::vector<log3_record>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  bool logged(const std::string& fragment) const;

  void to_initialization_mode();
  void to_step_mode();
  fmi3Status step(double t, double h);

  double get_float64(const std::string& name);
  fmi3Status set_float64(const std::string& name, double value);

  static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                     fmi3String message);

 private:
  fmi3Instance instance_ = nullptr;
  std::vector<log3_record> log_;
};

}  // namespace stride::test
