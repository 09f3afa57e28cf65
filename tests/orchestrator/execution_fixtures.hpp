// Mock components and helpers shared by the tests of the algorithm, the execution and the
// observers.
#ifndef STRIDE_TESTS_ORCHESTRATOR_EXECUTION_FIXTURES_HPP
#define STRIDE_TESTS_ORCHESTRATOR_EXECUTION_FIXTURES_HPP

#include <memory>
#include <string>

#include "mock_component.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/execution.hpp"

namespace stride::cosim::test {

inline constexpr duration k_ms{1'000'000};

inline log_sink quiet_log() {
  return [](log_level, std::string_view, std::string_view, std::string_view) {};
}

// y = number of completed steps (no feedthrough)
inline std::unique_ptr<mock_component> counter(const std::string& name,
                                               std::shared_ptr<call_log> log) {
  auto m = std::make_unique<mock_component>(name, std::move(log));
  m->real("y", causality::output);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("y") += 1;
    return step_result::complete;
  };
  return m;
}

// y = the value of u when the step started (latched in the step: no feedthrough)
inline std::unique_ptr<mock_component> latch(const std::string& name,
                                             std::shared_ptr<call_log> log) {
  auto m = std::make_unique<mock_component>(name, std::move(log));
  m->real("u", causality::input);
  m->real("y", causality::output);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("y") = self.r("u");
    return step_result::complete;
  };
  return m;
}

inline variable_id var(const execution& a, const std::string& comp, const std::string& v) {
  const auto c = *a.find_component(comp);
  return {c, *a.component_at(c).model_description().index_of(v)};
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_EXECUTION_FIXTURES_HPP
