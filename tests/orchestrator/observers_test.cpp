// The observers shipped with libstride: CSV recorder, glob patterns, progress display.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "execution_fixtures.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/deferred_work.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"

namespace stride::cosim {
namespace {

using namespace test;
using ::testing::HasSubstr;

TEST(cosim_observers, csv_recorder_writes_full_names_and_every_type) {
  temp_dir dir("stride-test-");
  execution ex(std::make_unique<fixed_step_algorithm>(250 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  m->real("x", causality::output);
  m->add("n", variable_type::integer, causality::output);
  m->add("flag", variable_type::boolean, causality::output);
  m->add("label", variable_type::string, causality::output);
  m->add("p", variable_type::real, causality::parameter);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("x") += 0.1;
    self.i("n") -= 1;
    self.b("flag") = true;
    self.s("label") = "a,\"b\"";
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto csv = dir.path() / "sub" / "r.csv";
  ex.add_observer(csv_recorder::from_patterns(csv, ex, {"m.*"}, 500 * k_ms));
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  ex.end();
  EXPECT_EQ(result.steps, 4);
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  // the parameter is not matched by a wildcard; rows every 0.5 s
  EXPECT_EQ(text.str(),
            "time,m.x,m.n,m.flag,m.label\n"
            "0,0,0,0,\"\"\n"
            "0.5,0.2,-2,1,\"a,\"\"b\"\"\"\n"
            "1,0.4,-4,1,\"a,\"\"b\"\"\"\n");
}

// A component on a worker lets the run format the last row while it waits for the reply
// (deferred work, done here within every step): each row still holds the values of its own
// time, not those the step has changed, and rows left undone at the end are written.
TEST(cosim_observers, csv_recorder_rows_formatted_while_a_step_waits_hold_their_own_values) {
  const auto record = [](bool wait_in_step, std::optional<duration> interval) {
    temp_dir dir("stride-test-");
    execution ex(std::make_unique<fixed_step_algorithm>(250 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
    auto m = std::make_unique<mock_component>("m");
    m->real("x", causality::output);
    m->add("n", variable_type::integer, causality::output);
    m->add("flag", variable_type::boolean, causality::output);
    m->add("label", variable_type::string, causality::output);
    m->on_step = [wait_in_step](mock_component& self, time_point t, duration) {
      self.r("x") += 0.1;
      self.i("n") -= 1;
      self.b("flag") = !self.b("flag");
      self.s("label") = "at \"" + format_seconds(t) + "\"";
      // the component's values have moved on: the row of the step before must not
      if (wait_in_step) run_deferred_work();
      return step_result::complete;
    };
    ex.add_component(std::move(m));
    const auto csv = dir.path() / "r.csv";
    auto recorder = csv_recorder::from_patterns(csv, ex, {"m.*"}, interval);
    ex.add_observer(recorder);
    ex.simulate_until(time_point(std::chrono::seconds(1)));
    EXPECT_EQ(recorder->rows_written(), interval ? 3u : 5u);
    ex.end();
    std::ifstream in(csv);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const std::string every_step =
      "time,m.x,m.n,m.flag,m.label\n"
      "0,0,0,0,\"\"\n"
      "0.25,0.1,-1,1,\"at \"\"0\"\"\"\n"
      "0.5,0.2,-2,0,\"at \"\"0.25\"\"\"\n"
      "0.75,0.30000000000000004,-3,1,\"at \"\"0.5\"\"\"\n"
      "1,0.4,-4,0,\"at \"\"0.75\"\"\"\n";
  EXPECT_EQ(record(true, std::nullopt), every_step);
  EXPECT_EQ(record(false, std::nullopt), every_step);
  EXPECT_EQ(record(true, 500 * k_ms), record(false, 500 * k_ms));
}

// a resumed run continues the results file of its first part: the rows up to the moment it
// continues from stay, later or incomplete rows go, and none is written twice
TEST(cosim_observers, csv_recorder_continues_a_file_after_a_given_time) {
  temp_dir dir("stride-test-");
  const auto csv = dir.path() / "r.csv";
  const auto run = [&](const std::string& before) {
    std::ofstream(csv, std::ios::binary) << before;
    execution ex(std::make_unique<fixed_step_algorithm>(250 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
    auto m = std::make_unique<mock_component>("m");
    m->real("x", causality::output);
    m->on_step = [](mock_component& self, time_point, duration h) {
      self.r("x") += to_seconds(h);  // x = t
      return step_result::complete;
    };
    ex.add_component(std::move(m));
    auto recorder = csv_recorder::from_patterns(csv, ex, {"m.x"}, 500 * k_ms);
    recorder->continue_after(time_point(std::chrono::seconds(1)));
    ex.add_observer(recorder);
    ex.simulate_until(time_point(std::chrono::seconds(2)));
    ex.end();
    std::ifstream in(csv, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  // the first part wrote a row after the moment (1.5) and half a row (2,9)
  EXPECT_EQ(run("time,m.x\n0,0\n0.5,0.5\n1,1\n1.5,99\n2,9"),
            "time,m.x\n0,0\n0.5,0.5\n1,1\n1.5,1.5\n2,2\n");
  // another header: another recording, not continued
  try {
    run("time,m.y\n0,0\n");
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("its header is not that of the signals recorded now"));
  }
}

// rows are due every interval counted from the run's start, and the time column is absolute
TEST(cosim_observers, csv_recorder_of_a_run_that_starts_later_than_zero) {
  temp_dir dir("stride-test-");
  const time_point start(1250 * k_ms);
  execution ex(std::make_unique<fixed_step_algorithm>(250 * k_ms, algorithm_kind::gauss_seidel),
               start, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  m->real("x", causality::output);
  m->on_step = [](mock_component& self, time_point, duration h) {
    self.r("x") += to_seconds(h);  // x = time since the start
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  const auto csv = dir.path() / "r.csv";
  ex.add_observer(csv_recorder::from_patterns(csv, ex, {"m.x"}, 500 * k_ms));
  ex.simulate_until(time_point(2250 * k_ms));
  ex.end();
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,m.x\n1.25,0\n1.75,0.5\n2.25,1\n");
}

TEST(cosim_observers, recording_interval_must_be_a_multiple_of_the_base_step) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
               time_point{}, quiet_log());
  ex.add_component(counter("a", {}));
  temp_dir dir("stride-test-");
  EXPECT_THROW(ex.add_observer(std::make_shared<csv_recorder>(
                   dir.path() / "x.csv", std::vector<variable_id>{}, 15 * k_ms)),
               validation_error);
}

TEST(cosim_observers, glob_match) {
  EXPECT_TRUE(glob_match("robot.*", "robot.base_x"));
  EXPECT_TRUE(glob_match("*.fallen", "robot.fallen"));
  EXPECT_TRUE(glob_match("gait.joint_angle[?]", "gait.joint_angle[3]"));
  EXPECT_FALSE(glob_match("gait.joint_angle[?]", "gait.joint_angle[13]"));
  EXPECT_TRUE(glob_match("*a*b*", "xxaxxbxx"));
  EXPECT_FALSE(glob_match("robot.*", "gait.x"));
}

// the last line a progress display prints for a mock whose `progress` output grows by `rate`
// per step over 10 steps of 10 ms (stop 1 s)
std::string final_progress_line(double rate) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  m->real("progress", causality::output);
  m->on_step = [rate](mock_component& self, time_point, duration) {
    self.r("progress") += rate;
    return step_result::complete;
  };
  ex.add_component(std::move(m));
  std::FILE* out = std::tmpfile();
  ex.add_observer(std::make_shared<progress_display>(time_point(std::chrono::seconds(1)), out,
                                                     false, std::chrono::milliseconds(0)));
  ex.simulate_until(time_point(100 * k_ms));
  ex.end();
  std::rewind(out);
  std::string text, line;
  for (char buf[256]; std::fgets(buf, sizeof buf, out) != nullptr;) text += buf;
  std::fclose(out);
  return text.substr(text.rfind("stride: "));
}

TEST(cosim_observers, a_components_progress_counts_only_when_it_is_ahead_of_the_clock) {
  // 10 % of the time; a component at 50 % ends the run early: its progress is shown
  EXPECT_THAT(final_progress_line(0.05), HasSubstr("m.progress 50.0%"));
  // the run ended: no time is left to estimate
  EXPECT_THAT(final_progress_line(0.05), ::testing::Not(HasSubstr("ETA")));
  EXPECT_THAT(final_progress_line(0.0), ::testing::Not(HasSubstr("ETA")));
  // a component that reports nothing leaves the simulated time in charge
  EXPECT_THAT(final_progress_line(0.0), HasSubstr("(10.0%)"));
}

TEST(cosim_observers, the_real_time_factor_is_simulated_time_over_wall_time) {
  EXPECT_DOUBLE_EQ(real_time_factor(std::chrono::seconds(30), 10.0), 3.0);
  EXPECT_DOUBLE_EQ(real_time_factor(250 * k_ms, 0.5), 0.5);
  EXPECT_EQ(real_time_factor(std::chrono::seconds(30), 0.0), 0.0);  // no wall time yet
  wall_timer idle;
  EXPECT_EQ(idle.seconds(), 0.0);  // never started
}

// the last line of a display that shares the run's timer shows the figures the run reports
TEST(cosim_observers, the_live_and_the_final_real_time_factor_come_from_one_timer) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  ex.add_component(counter("c", {}));
  const auto timer = std::make_shared<wall_timer>();
  ex.add_observer(timer);
  std::FILE* out = std::tmpfile();
  ex.add_observer(std::make_shared<progress_display>(time_point(std::chrono::seconds(1)), out,
                                                     false, std::chrono::milliseconds(0), timer));
  timer->start();
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  ex.end();
  const double wall = timer->seconds();
  EXPECT_EQ(timer->seconds(), wall);  // stopped when the simulation ended
  std::rewind(out);
  std::string text;
  for (char buf[256]; std::fgets(buf, sizeof buf, out) != nullptr;) text += buf;
  std::fclose(out);
  char expected[96];
  std::snprintf(expected, sizeof expected, "RTF %.2fx, wall %.2f s\n",
                real_time_factor(result.end_time - time_point{}, wall), wall);
  EXPECT_THAT(text.substr(text.rfind("stride: ")), HasSubstr(expected));
}

TEST(cosim_observers, progress_line_shows_time_rtf_and_eta) {
  progress_display p(time_point(std::chrono::seconds(60)), stderr, false);
  const std::string line = p.format(time_point(std::chrono::seconds(30)), 10.0);
  EXPECT_THAT(line, HasSubstr("t = 30.000 / 60.000 s (50.0%)"));
  EXPECT_THAT(line, HasSubstr("RTF 3.00x"));
  EXPECT_THAT(line, HasSubstr("ETA 10 s"));
}

}  // namespace
}  // namespace stride::cosim
