// End to end: models/walk.xml (the default scenario of `stride run`) with the bundled gait and
// robot FMUs. The robot must not fall and must walk forward at 10–30 cm/s.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/run.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;

TEST(cosim_walk, walks_forward_for_60_seconds_without_falling) {
  temp_dir scratch("stride-walk-test-");
  auto system = parse_system_file(fs::path(STRIDE_SOURCE_DIR) / "models" / "walk.xml");
  ASSERT_EQ(*system.stop, time_point(std::chrono::seconds(60)));
  system.record.signals = {"robot.base_x", "robot.base_y", "robot.fallen"};
  run_options o;
  o.output_dir = scratch.path() / "walk";
  o.progress = false;
  o.build.log = stderr_log_sink(log_level::warning);
  const auto report = run_system(system, o);
  ASSERT_FALSE(report.result.terminated_by_component) << report.result.terminated_by;

  std::ifstream csv(report.results_file);
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line, "time,robot.base_x,robot.base_y,robot.fallen");
  double t0 = 0, x0 = 0, t = 0, x = 0, y = 0;
  int fallen = 0;
  bool first = true;
  while (std::getline(csv, line)) {
    double row_t, row_x, row_y;
    int row_fallen;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%d", &row_t, &row_x, &row_y, &row_fallen), 4)
        << line;
    if (first) {
      t0 = row_t;
      x0 = row_x;
      first = false;
    }
    t = row_t;
    x = row_x;
    y = row_y;
    fallen = std::max(fallen, row_fallen);
  }
  EXPECT_EQ(t, 60.0);
  EXPECT_EQ(fallen, 0) << "the robot fell";
  const double speed = (x - x0) / (t - t0);
  EXPECT_GE(speed, 0.10) << "forward speed " << speed << " m/s, lateral drift " << y;
  EXPECT_LE(speed, 0.30) << "forward speed " << speed << " m/s";
}

}  // namespace
}  // namespace stride::cosim
