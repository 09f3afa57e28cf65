// The study's assertion kinds for `stride test` (best_state, value_at) on a small V table written
// as the learner writes it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/learner/artefacts.hpp"
#include "stride/learner/grid.hpp"
#include "stride/learner/td_lambda.hpp"
#include "stride/study/suite_assertions.hpp"
#include "stride/suite/runner.hpp"

namespace stride::study {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

using attributes = std::map<std::string, std::string>;

class study_suite_assertions : public ::testing::Test {
 protected:
  suite::assertion_registry kinds = learner_assertions();
  cosim::temp_dir scratch{"stride-study-suite-"};
  suite::recorded_signals no_signals;

  // V over period_time 500..600 (step 50) x swing_right_left 20..30 (step 10), index order; the
  // best state is period_time = 550, swing_right_left = 30 (index 1 + 3 * 1)
  void write_table(const fs::path& dir, std::vector<double> v = {1, 2, 3, 4, 7.5, 5}) {
    const auto grid =
        learner::state_grid::parse("period_time:500:600:50,swing_right_left:20:30:10");
    learner::dense_value_table table(grid.size());
    table.values() = std::move(v);
    fs::create_directories(dir);
    learner::write_value_table(dir / learner::run_files::value_table, grid, table);
  }

  void check(const std::string& kind, const attributes& attrs) {
    kinds.at(kind).check(suite::assertion_spec{kind, attrs, {}}, scratch.path());
  }
  // checks the assertion (it must be valid), then evaluates it on the scratch folder
  suite::outcome evaluate(const std::string& kind, const attributes& attrs) {
    const suite::assertion_spec a{kind, attrs, {}};
    kinds.at(kind).check(a, scratch.path());
    return kinds.at(kind).evaluate(a, {scratch.path(), &no_signals, scratch.path()});
  }
};

TEST_F(study_suite_assertions, the_table_is_the_learners_format) {
  write_table(scratch.path());
  std::ifstream in(scratch.path() / "v_table.csv");
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "period_time,swing_right_left,V");
}

TEST_F(study_suite_assertions, best_state_passes_inside_the_region_ends_included) {
  write_table(scratch.path());
  EXPECT_TRUE(
      evaluate("best_state", {{"region", "period_time=525..575, swing_right_left=25..30"}}).passed);
  EXPECT_TRUE(
      evaluate("best_state", {{"region", "period_time=550..550, swing_right_left=30..30"}}).passed);
  EXPECT_TRUE(evaluate("best_state", {{"region", "period_time=550..600"}}).passed);
}

TEST_F(study_suite_assertions, best_state_fails_outside_naming_the_state_and_its_value) {
  write_table(scratch.path());
  const auto o =
      evaluate("best_state", {{"region", "period_time=500..549, swing_right_left=20..30"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("the best state is period_time = 550, swing_right_left = 30 "
                                   "(V = 7.5), outside period_time=500..549"));
  EXPECT_FALSE(evaluate("best_state", {{"region", "swing_right_left=20..29"}}).passed);
}

TEST_F(study_suite_assertions, best_state_unknown_dimension_or_empty_table_fails) {
  write_table(scratch.path());
  auto o = evaluate("best_state", {{"region", "step_length=0..1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("the V table has no dimension step_length"));
  std::ofstream(scratch.path() / "v_table.csv") << "period_time,swing_right_left,V\n";
  o = evaluate("best_state", {{"region", "period_time=500..600"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("the V table is empty"));
}

TEST_F(study_suite_assertions, best_state_fails_on_nan) {
  // a NaN in the first row must not make that state the best
  write_table(scratch.path(), {std::numeric_limits<double>::quiet_NaN(), 2, 3, 4, 7.5, 5});
  const auto o =
      evaluate("best_state", {{"region", "period_time=500..500, swing_right_left=20..20"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("NaN"));
}

TEST_F(study_suite_assertions, the_table_may_lie_in_a_subfolder) {
  write_table(scratch.path() / "learner");
  EXPECT_TRUE(
      evaluate("best_state", {{"region", "period_time=550..550"}, {"folder", "learner"}}).passed);
  EXPECT_TRUE(evaluate("value_at", {{"state", "period_time=550, swing_right_left=30"},
                                    {"min", "7"},
                                    {"folder", "learner"}})
                  .passed);
  // without the folder there is no table; the runner reports the exception as the failure
  try {
    evaluate("best_state", {{"region", "period_time=550..550"}});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("no V table " + (scratch.path() / "v_table.csv").string()));
  }
}

TEST_F(study_suite_assertions, value_at_passes_within_its_bounds_ends_included) {
  write_table(scratch.path());
  const std::string state = "period_time=550, swing_right_left=30";
  EXPECT_TRUE(evaluate("value_at", {{"state", state}, {"min", "7.5"}, {"max", "7.5"}}).passed);
  EXPECT_TRUE(evaluate("value_at", {{"state", state}, {"min", "7.5"}}).passed);
  EXPECT_TRUE(
      evaluate("value_at",
               {{"state", "swing_right_left=20, period_time=600"}, {"min", "3"}, {"max", "3"}})
          .passed);
}

TEST_F(study_suite_assertions, value_at_fails_outside_its_bounds_naming_the_value) {
  write_table(scratch.path());
  const std::string state = "period_time=550, swing_right_left=30";
  auto o = evaluate("value_at", {{"state", state}, {"min", "7.0"}, {"max", "7.25"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message,
              HasSubstr("V(period_time=550, swing_right_left=30) = 7.5, not within [7, 7.25]"));
  o = evaluate("value_at",
               {{"state", state}, {"min", learner::format_number(std::nextafter(7.5, 8.0))}});
  EXPECT_FALSE(o.passed);
}

TEST_F(study_suite_assertions, value_at_a_state_not_in_the_table_fails) {
  write_table(scratch.path());
  auto o = evaluate("value_at", {{"state", "period_time=525, swing_right_left=30"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("no state period_time=525, swing_right_left=30 in the V table"));
  o = evaluate("value_at", {{"state", "gait_speed=1"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("the V table has no dimension gait_speed"));
}

TEST_F(study_suite_assertions, value_at_fails_on_nan) {
  write_table(scratch.path(), {1, 2, 3, 4, std::numeric_limits<double>::quiet_NaN(), 5});
  const auto o =
      evaluate("value_at", {{"state", "period_time=550, swing_right_left=30"}, {"min", "-1e300"}});
  EXPECT_FALSE(o.passed);
}

TEST_F(study_suite_assertions, checks_reject_bad_attributes) {
  EXPECT_THROW(check("best_state", {{"region", "period_time=600..500"}}), std::invalid_argument);
  EXPECT_THROW(check("best_state", {{"region", "period_time=550"}}), std::invalid_argument);
  EXPECT_THROW(check("best_state", {{"region", "period_time=a..b"}}), std::invalid_argument);
  EXPECT_THROW(check("best_state", {}), std::invalid_argument);
  EXPECT_THROW(check("value_at", {{"state", "period_time=550"}}), std::invalid_argument);
  EXPECT_THROW(check("value_at", {{"state", "period_time=550"}, {"min", "x"}}),
               std::invalid_argument);
  EXPECT_THROW(check("value_at", {{"state", "period_time"}, {"min", "0"}}), std::invalid_argument);
  EXPECT_THROW(check("value_at", {{"state", "period_time=fast"}, {"min", "0"}}),
               std::invalid_argument);
  EXPECT_NO_THROW(check("value_at", {{"state", "period_time=550"}, {"max", "1"}}));
  // they ask the run to record nothing
  EXPECT_TRUE(kinds.at("value_at")
                  .signals({"value_at", {{"state", "period_time=550"}, {"max", "1"}}, {}}, {})
                  .empty());
}

TEST_F(study_suite_assertions, check_suite_names_file_and_line) {
  const fs::path file = scratch.path() / "s.xml";
  std::ofstream(scratch.path() / "x.xml") << "<system/>";  // must exist; the run reads it
  std::ofstream(file) << "<suite>\n<case name='c' system='x.xml'>\n"
                         "<best_state region='period_time=500..600'/>\n"
                         "<value_at state='period_time=550' min='2' nax='3'/>\n"
                         "</case>\n</suite>\n";
  suite::assertion_registry all = suite::builtin_assertions();
  all.merge(learner_assertions());
  try {
    suite::check_suite(suite::parse_suite_file(file), all);
    FAIL() << "no error";
  } catch (const cosim::validation_error& e) {
    EXPECT_THAT(e.what(), StartsWith(file.string() + ":4: unknown attribute 'nax' on <value_at>"));
  }
}

}  // namespace
}  // namespace stride::study
