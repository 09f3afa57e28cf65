// The execution: run to a stop, termination requests, errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "execution_fixtures.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"

namespace stride::cosim {
namespace {

using namespace test;
using ::testing::HasSubstr;

TEST(cosim_execution, component_requested_stop_ends_the_run_cleanly) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  auto m = counter("stopper", {});
  auto* mp = m.get();
  m->on_step = [](mock_component& self, time_point, duration) {
    if (self.r("y") >= 4) return step_result::terminate;
    self.r("y") += 1;
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  EXPECT_TRUE(result.terminated_by_component);
  EXPECT_EQ(result.terminated_by, "stopper");
  EXPECT_EQ(result.end_time, time_point(40 * k_ms));
  EXPECT_EQ(result.steps, 4);
  EXPECT_TRUE(ex.ended());
  EXPECT_TRUE(mp->terminated);
}

TEST(cosim_execution, component_error_names_component_and_time_and_flushes_results) {
  temp_dir dir("stride-test-");
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  auto m = counter("broken", {});
  m->on_step = [](mock_component& self, time_point, duration) -> step_result {
    if (self.r("y") >= 3) throw std::runtime_error("doStep failed");
    self.r("y") += 1;
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto csv = dir.path() / "out.csv";
  ex.add_observer(std::make_shared<csv_recorder>(csv, std::vector<variable_id>{}));
  try {
    ex.simulate_until(time_point(std::chrono::seconds(1)));
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'broken'"));
    EXPECT_THAT(e.what(), HasSubstr("doStep failed"));
    EXPECT_THAT(e.what(), HasSubstr("t = 0.03 s"));
  }
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,broken.y\n0,0\n0.01,1\n0.02,2\n0.03,3\n");
}

}  // namespace
}  // namespace stride::cosim
