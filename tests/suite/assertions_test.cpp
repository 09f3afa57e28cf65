// The builtin assertion kinds on signals built in the test: each passing and failing on purpose,
// values exactly at a bound and one ulp beyond, NaN, missing and text signals, windows, and the
// comparison with a reference CSV.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "stride/cosim/archive.hpp"
#include "stride/suite/assertions.hpp"

namespace stride::suite {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_inf = std::numeric_limits<double>::infinity();

using attributes = std::map<std::string, std::string>;

class suite_assertions : public ::testing::Test {
 protected:
  assertion_registry kinds = builtin_assertions();
  cosim::temp_dir scratch{"stride-suite-assertions-"};
  recorded_signals run;

  // the run's recording: one time axis, numeric columns
  void record(std::vector<double> time,
              const std::vector<std::pair<std::string, std::vector<double>>>& columns) {
    run = {};
    run.file = scratch.path() / "results.csv";
    run.time = std::move(time);
    for (const auto& [name, values] : columns) {
      EXPECT_EQ(values.size(), run.time.size()) << name;
      run.names.push_back(name);
      run.values.push_back(values);
      run.is_text.push_back(false);
    }
  }
  void add_text_column(const std::string& name) {
    run.names.push_back(name);
    run.values.emplace_back();
    run.is_text.push_back(true);
  }
  // a CSV in the suite folder (the scratch folder)
  void write(const std::string& name, const std::string& text) {
    std::ofstream(scratch.path() / name, std::ios::binary) << text;
  }

  // checks the assertion as check_suite does (it must be valid), then evaluates it on `run`
  outcome evaluate(const std::string& kind, const attributes& attrs) {
    const assertion_spec a{kind, attrs, {}};
    const assertion_kind& k = kinds.at(kind);
    k.check(a, scratch.path());
    const case_output out{scratch.path(), &run, scratch.path()};
    return k.evaluate(a, out);
  }
};

::testing::AssertionResult passes(const outcome& o) {
  if (o.passed && o.message.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "failed: " << o.message;
}

// ---- never / eventually ----

TEST_F(suite_assertions, never_passes_while_the_signal_is_zero) {
  record({0, 0.1, 0.2}, {{"r.fallen", {0, 0, 0}}});
  EXPECT_TRUE(passes(evaluate("never", {{"signal", "r.fallen"}})));
}

TEST_F(suite_assertions, never_fails_at_the_first_non_zero_sample) {
  record({0, 0.1, 0.2, 0.3}, {{"r.fallen", {0, 0, 1, 1}}});
  const outcome o = evaluate("never", {{"signal", "r.fallen"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, AllOf(HasSubstr("r.fallen is 1 at t = 0.2 s"), HasSubstr("[start, end]")));
}

TEST_F(suite_assertions, never_looks_only_inside_its_window) {
  record({0, 0.1, 0.2, 0.3}, {{"r.fallen", {0, 0, 1, 0}}});
  EXPECT_TRUE(passes(evaluate("never", {{"signal", "r.fallen"}, {"to", "0.1"}})));
  EXPECT_TRUE(passes(evaluate("never", {{"signal", "r.fallen"}, {"from", "0.3"}})));
  const outcome o = evaluate("never", {{"signal", "r.fallen"}, {"from", "0.2"}, {"to", "0.3"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("at t = 0.2 s (never allowed in [0.2 s, 0.3 s])"));
}

TEST_F(suite_assertions, never_fails_on_nan) {
  record({0, 0.1, 0.2}, {{"r.fallen", {0, k_nan, 0}}});
  const outcome o = evaluate("never", {{"signal", "r.fallen"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("r.fallen is NaN at t = 0.1 s"));
}

TEST_F(suite_assertions, eventually_passes_once_the_signal_is_non_zero) {
  record({0, 0.1, 0.2}, {{"r.done", {0, 0, 1}}});
  EXPECT_TRUE(passes(evaluate("eventually", {{"signal", "r.done"}})));
}

TEST_F(suite_assertions, eventually_fails_when_the_signal_stays_zero) {
  record({0, 0.1, 0.2}, {{"r.done", {0, 0, 0}}});
  const outcome o = evaluate("eventually", {{"signal", "r.done"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("r.done never became true in [start, end]"));
  // true only after the window
  record({0, 0.1, 0.2}, {{"r.done", {0, 0, 1}}});
  const outcome late = evaluate("eventually", {{"signal", "r.done"}, {"to", "0.1"}});
  EXPECT_FALSE(late.passed);
  EXPECT_THAT(late.message, HasSubstr("r.done never became true in [start, 0.1 s]"));
}

TEST_F(suite_assertions, eventually_fails_on_nan_even_if_true_later) {
  record({0, 0.1, 0.2}, {{"r.done", {k_nan, 0, 1}}});
  const outcome o = evaluate("eventually", {{"signal", "r.done"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("r.done is NaN at t = 0 s"));
}

// ---- bounds ----

TEST_F(suite_assertions, bounds_include_both_ends) {
  record({0, 0.1, 0.2}, {{"a.y", {0.5, 1, 1.5}}});
  EXPECT_TRUE(passes(evaluate("bounds", {{"signal", "a.y"}, {"min", "0.5"}, {"max", "1.5"}})));
  EXPECT_TRUE(passes(evaluate("bounds", {{"signal", "a.y"}, {"min", "0.5"}})));
  EXPECT_TRUE(passes(evaluate("bounds", {{"signal", "a.y"}, {"max", "1.5"}})));
}

TEST_F(suite_assertions, bounds_fail_one_ulp_beyond_either_end) {
  record({0, 0.1, 0.2}, {{"a.y", {0.5, 1, std::nextafter(1.5, k_inf)}}});
  outcome o = evaluate("bounds", {{"signal", "a.y"}, {"min", "0.5"}, {"max", "1.5"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, AllOf(HasSubstr("a.y = 1.5 at t = 0.2 s"), HasSubstr("within [0.5, 1.5]"),
                               HasSubstr("1 of 3 samples")));
  record({0, 0.1, 0.2}, {{"a.y", {1, std::nextafter(0.5, -k_inf), 1.5}}});
  o = evaluate("bounds", {{"signal", "a.y"}, {"min", "0.5"}, {"max", "1.5"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y = 0.5 at t = 0.1 s"));
  o = evaluate("bounds", {{"signal", "a.y"}, {"min", "0.5"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("not at least 0.5"));
}

TEST_F(suite_assertions, bounds_report_the_worst_sample_and_the_count) {
  record({0, 0.1, 0.2, 0.3}, {{"a.y", {3, 0.5, 7.25, 2}}});
  const outcome o = evaluate("bounds", {{"signal", "a.y"}, {"max", "1.5"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y = 7.25 at t = 0.2 s, not at most 1.5 (3 of 4 samples in "
                                   "[start, end] outside)"));
}

TEST_F(suite_assertions, bounds_look_only_inside_the_window) {
  record({0, 0.1, 0.2, 0.3}, {{"a.y", {9, 1, 1, 9}}});
  const attributes window = {
      {"signal", "a.y"}, {"min", "0"}, {"max", "2"}, {"from", "0.1"}, {"to", "0.2"}};
  EXPECT_TRUE(passes(evaluate("bounds", window)));
  const outcome o = evaluate("bounds", {{"signal", "a.y"}, {"min", "0"}, {"max", "2"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("2 of 4 samples"));
}

TEST_F(suite_assertions, bounds_fail_on_nan) {
  record({0, 0.1, 0.2}, {{"a.y", {1, k_nan, 1}}});
  const outcome o = evaluate("bounds", {{"signal", "a.y"}, {"min", "0"}, {"max", "2"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y is NaN at t = 0.1 s"));
}

TEST_F(suite_assertions, a_window_without_samples_fails) {
  record({0, 0.1, 0.2}, {{"a.y", {1, 1, 1}}});
  const outcome o =
      evaluate("bounds", {{"signal", "a.y"}, {"min", "0"}, {"from", "5"}, {"to", "6"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("no sample of a.y in [5 s, 6 s]"));
}

// ---- final ----

TEST_F(suite_assertions, final_value_with_tolerance_includes_both_ends) {
  const attributes a = {{"signal", "a.x"}, {"value", "2"}, {"tolerance", "0.5"}};
  record({0, 0.1, 0.2}, {{"a.x", {100, 100, 2.5}}});  // only the last sample counts
  EXPECT_TRUE(passes(evaluate("final", a)));
  record({0, 0.1, 0.2}, {{"a.x", {0, 0, 1.5}}});
  EXPECT_TRUE(passes(evaluate("final", a)));
  record({0, 0.1, 0.2}, {{"a.x", {2, 2, std::nextafter(2.5, k_inf)}}});
  outcome o = evaluate("final", a);
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("final a.x = 2.5 at t = 0.2 s, not within [1.5, 2.5]"));
  record({0, 0.1, 0.2}, {{"a.x", {2, 2, std::nextafter(1.5, -k_inf)}}});
  EXPECT_FALSE(evaluate("final", a).passed);
}

TEST_F(suite_assertions, final_value_without_tolerance_is_exact) {
  record({0, 0.1}, {{"a.x", {0, 2}}});
  EXPECT_TRUE(passes(evaluate("final", {{"signal", "a.x"}, {"value", "2"}})));
  record({0, 0.1}, {{"a.x", {0, 4.75}}});
  const outcome o = evaluate("final", {{"signal", "a.x"}, {"value", "2"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("final a.x = 4.75 at t = 0.1 s, not within [2, 2]"));
}

TEST_F(suite_assertions, final_min_max_takes_the_last_sample_of_the_window) {
  record({0, 0.1, 0.2, 0.3}, {{"a.x", {0, 15, 16, 30}}});
  EXPECT_TRUE(
      passes(evaluate("final", {{"signal", "a.x"}, {"min", "14"}, {"max", "18"}, {"to", "0.2"}})));
  EXPECT_TRUE(passes(evaluate("final", {{"signal", "a.x"}, {"min", "30"}})));
  const outcome o = evaluate("final", {{"signal", "a.x"}, {"min", "14"}, {"max", "18"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("final a.x = 30 at t = 0.3 s, not within [14, 18]"));
}

TEST_F(suite_assertions, final_fails_on_nan) {
  record({0, 0.1}, {{"a.x", {2, k_nan}}});
  const outcome o = evaluate("final", {{"signal", "a.x"}, {"value", "2"}, {"tolerance", "1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.x is NaN at t = 0.1 s"));
}

// ---- mean ----

TEST_F(suite_assertions, mean_includes_its_bounds) {
  record({0, 0.1, 0.2, 0.3}, {{"a.z", {1, 2, 3, 6}}});  // mean 3
  EXPECT_TRUE(passes(evaluate("mean", {{"signal", "a.z"}, {"min", "3"}, {"max", "3"}})));
  // over [0.1, 0.2] the mean is 2.5
  EXPECT_TRUE(passes(evaluate(
      "mean",
      {{"signal", "a.z"}, {"min", "2.5"}, {"max", "2.5"}, {"from", "0.1"}, {"to", "0.2"}})));
}

TEST_F(suite_assertions, mean_fails_outside_its_bounds) {
  record({0, 0.1, 0.2, 0.3}, {{"a.z", {1, 2, 3, 6}}});
  outcome o = evaluate("mean", {{"signal", "a.z"}, {"max", "2.75"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("mean of a.z over [start, end] = 3, not at most 2.75"));
  o = evaluate("mean", {{"signal", "a.z"}, {"min", "3.75"}, {"from", "0.1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("mean of a.z over [0.1 s, end] = 3.66667, not at least 3.75"));
}

TEST_F(suite_assertions, mean_fails_on_nan) {
  record({0, 0.1, 0.2}, {{"a.z", {1, 1, k_nan}}});
  const outcome o = evaluate("mean", {{"signal", "a.z"}, {"min", "-1e9"}, {"max", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.z is NaN at t = 0.2 s"));
}

// ---- rate ----

TEST_F(suite_assertions, rate_is_last_minus_first_over_the_time_between) {
  record({0, 0.5, 1, 2}, {{"a.x", {0, 1, 1.5, 4}}});  // 2 per s overall, 1.5 over [0, 1]
  EXPECT_TRUE(passes(evaluate("rate", {{"signal", "a.x"}, {"min", "2"}, {"max", "2"}})));
  EXPECT_TRUE(
      passes(evaluate("rate", {{"signal", "a.x"}, {"min", "1.5"}, {"max", "1.5"}, {"to", "1"}})));
  const outcome o = evaluate("rate", {{"signal", "a.x"}, {"max", "1.75"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("rate of a.x from t = 0 to 2 s = 2 per s, not at most 1.75"));
}

TEST_F(suite_assertions, rate_needs_two_samples) {
  record({0, 0.5, 1}, {{"a.x", {0, 1, 2}}});
  const outcome o = evaluate("rate", {{"signal", "a.x"}, {"min", "0"}, {"from", "1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("one sample of a.x in [1 s, end]"));
}

TEST_F(suite_assertions, rate_fails_on_nan) {
  record({0, 0.5, 1}, {{"a.x", {0, k_nan, 2}}});
  const outcome o = evaluate("rate", {{"signal", "a.x"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.x is NaN at t = 0.5 s"));
}

// ---- speed ----

TEST_F(suite_assertions, speed_is_planar_distance_over_time) {
  // from (0, 0) to (3, 4) in one second: 5 per second, whatever lies between
  record({0, 0.5, 1}, {{"r.x", {0, 10, 3}}, {"r.y", {0, -10, 4}}});
  EXPECT_TRUE(passes(evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "5"}, {"max", "5"}})));
  const outcome o = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"max", "4.5"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message,
              HasSubstr("speed from (r.x, r.y) between t = 0 and 1 s = 5, not at most 4.5"));
  // over [0, 0.5]: hypot(10, 10) / 0.5
  const outcome w = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "30"}, {"to", "0.5"}});
  EXPECT_FALSE(w.passed);
  EXPECT_THAT(w.message, HasSubstr("between t = 0 and 0.5 s = 28.2843, not at least 30"));
}

TEST_F(suite_assertions, speed_fails_on_nan_in_either_coordinate) {
  record({0, 0.5, 1}, {{"r.x", {0, 1, 3}}, {"r.y", {0, k_nan, 4}}});
  outcome o = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("r.y is NaN at t = 0.5 s"));
  record({0, 0.5, 1}, {{"r.x", {k_nan, 1, 3}}, {"r.y", {0, 1, 4}}});
  o = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("r.x is NaN at t = 0 s"));
}

TEST_F(suite_assertions, speed_needs_both_signals_and_two_samples) {
  record({0, 0.5, 1}, {{"r.x", {0, 1, 3}}});
  outcome o = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "0"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("signal r.y was not recorded"));
  record({0, 0.5, 1}, {{"r.x", {0, 1, 3}}, {"r.y", {0, 1, 4}}});
  o = evaluate("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "0"}, {"from", "1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("one sample of r.x in [1 s, end]"));
}

// ---- signals that cannot be checked ----

TEST_F(suite_assertions, a_signal_not_recorded_fails_naming_it) {
  record({0, 0.1}, {{"a.y", {0, 0}}});
  const std::vector<std::pair<std::string, attributes>> cases = {
      {"never", {{"signal", "no.such"}}},
      {"eventually", {{"signal", "no.such"}}},
      {"bounds", {{"signal", "no.such"}, {"min", "0"}}},
      {"final", {{"signal", "no.such"}, {"value", "0"}}},
      {"mean", {{"signal", "no.such"}, {"min", "0"}}},
      {"rate", {{"signal", "no.such"}, {"min", "0"}}},
      {"speed", {{"x", "no.such"}, {"y", "a.y"}, {"min", "0"}}}};
  for (const auto& [kind, attrs] : cases) {
    const outcome o = evaluate(kind, attrs);
    EXPECT_FALSE(o.passed) << kind;
    EXPECT_THAT(o.message,
                HasSubstr("signal no.such was not recorded (results: " + run.file.string() + ")"))
        << kind;
  }
}

TEST_F(suite_assertions, a_text_column_fails) {
  record({0, 0.1}, {{"a.y", {0, 0}}});
  add_text_column("a.label");
  for (const char* kind : {"never", "eventually", "bounds", "final", "mean", "rate"}) {
    attributes attrs = {{"signal", "a.label"}, {"min", "0"}};
    if (std::string(kind) == "never" || std::string(kind) == "eventually") attrs.erase("min");
    const outcome o = evaluate(kind, attrs);
    EXPECT_FALSE(o.passed) << kind;
    EXPECT_THAT(o.message, HasSubstr("signal a.label holds text")) << kind;
  }
}

// ---- reference ----

TEST_F(suite_assertions, reference_interpolates_the_run_onto_its_time_points) {
  write("ref.csv", "time,a.y\n0.25,0.5\n0.75,1.5\n");
  record({0, 0.5, 1}, {{"a.y", {0, 1, 2}}});
  EXPECT_TRUE(passes(evaluate("reference", {{"file", "ref.csv"}})));
}

TEST_F(suite_assertions, reference_reports_the_worst_point_and_its_time) {
  write("ref.csv", "time,a.y\n0.25,0.5\n0.75,1.5\n");
  record({0, 0.5, 1}, {{"a.y", {0, 1, 4}}});  // 0.5 at 0.25 s, 2.5 at 0.75 s
  const outcome o = evaluate("reference", {{"file", "ref.csv"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y differs from the reference by 1 at t = 0.75 s (run 2.5, "
                                   "reference 1.5, allowed 0); 1 of 2 points outside"));
}

TEST_F(suite_assertions, reference_passes_exactly_at_the_absolute_tolerance) {
  write("ref.csv", "time,a.y\n0,1\n1,1\n");
  record({0, 1}, {{"a.y", {1.25, 1}}});
  EXPECT_TRUE(passes(evaluate("reference", {{"file", "ref.csv"}, {"absolute", "0.25"}})));
  record({0, 1}, {{"a.y", {std::nextafter(1.25, k_inf), 1}}});
  const outcome o = evaluate("reference", {{"file", "ref.csv"}, {"absolute", "0.25"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("at t = 0 s (run 1.25, reference 1, allowed 0.25)"));
}

TEST_F(suite_assertions, reference_relative_tolerance_scales_with_the_reference) {
  write("ref.csv", "time,a.y\n0,2\n");
  record({0}, {{"a.y", {3}}});  // off by 1 = 0.5 * |2|
  EXPECT_TRUE(passes(evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.5"}})));
  EXPECT_FALSE(evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.25"}}).passed);
  record({0}, {{"a.y", {std::nextafter(3.0, k_inf)}}});
  EXPECT_FALSE(evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.5"}}).passed);
  // absolute and relative add up: 0.25 + 0.5 * 2
  record({0}, {{"a.y", {3.25}}});
  EXPECT_TRUE(passes(
      evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.5"}, {"absolute", "0.25"}})));
  record({0}, {{"a.y", {std::nextafter(3.25, k_inf)}}});
  EXPECT_FALSE(
      evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.5"}, {"absolute", "0.25"}})
          .passed);
}

TEST_F(suite_assertions, reference_worst_point_is_relative_to_what_was_allowed) {
  // errors 2 (allowed 1) and 0.5 (allowed 0.1): the second is the worse one
  write("ref.csv", "time,a.y\n0,10\n1,1\n");
  record({0, 1}, {{"a.y", {12, 1.5}}});
  const outcome o = evaluate("reference", {{"file", "ref.csv"}, {"relative", "0.1"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y differs from the reference by 0.5 at t = 1 s (run 1.5, "
                                   "reference 1, allowed 0.1); 2 of 2 points outside"));
}

TEST_F(suite_assertions, reference_time_outside_the_run_fails) {
  write("ref.csv", "time,a.y\n0,0\n1,1\n");
  record({0, 0.5}, {{"a.y", {0, 0.5}}});
  outcome o = evaluate("reference", {{"file", "ref.csv"}, {"absolute", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message,
              HasSubstr("the run did not record a.y at the reference's t = 1 s (recorded 0 .. "
                        "0.5 s)"));
  record({0.5, 1}, {{"a.y", {0.5, 1}}});
  o = evaluate("reference", {{"file", "ref.csv"}, {"absolute", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("at the reference's t = 0 s (recorded 0.5 .. 1 s)"));
}

TEST_F(suite_assertions, reference_fails_on_nan_in_run_or_reference) {
  write("ref.csv", "time,a.y\n0,0\n0.5,0.5\n1,1\n");
  record({0, 0.5, 1}, {{"a.y", {0, k_nan, 1}}});
  outcome o = evaluate("reference", {{"file", "ref.csv"}, {"absolute", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y is NaN at t = 0.5 s (run)"));
  // a NaN next to a reference point spoils the interpolated value too
  write("between.csv", "time,a.y\n0.25,0.25\n");
  o = evaluate("reference", {{"file", "between.csv"}, {"absolute", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y is NaN at t = 0.25 s (run)"));
  write("nan_ref.csv", "time,a.y\n0,0\n1,nan\n");
  record({0, 1}, {{"a.y", {0, 1}}});
  o = evaluate("reference", {{"file", "nan_ref.csv"}, {"absolute", "1e9"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("a.y is NaN at t = 1 s (reference)"));
}

TEST_F(suite_assertions, reference_compares_the_chosen_columns_only) {
  write("ref.csv", "time,a.y,a.w,b.z\n0,1,2,3\n1,1,2,3\n");
  record({0, 1}, {{"a.y", {1, 1}}, {"a.w", {2, 2}}, {"b.z", {3, 99}}});
  EXPECT_TRUE(passes(evaluate("reference", {{"file", "ref.csv"}, {"signals", "a.*"}})));
  EXPECT_TRUE(passes(evaluate("reference", {{"file", "ref.csv"}, {"signals", "a.y, a.w"}})));
  const outcome o = evaluate("reference", {{"file", "ref.csv"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("b.z differs from the reference by 96 at t = 1 s"));
  // the signals a case must record are the chosen reference columns
  const assertion_spec a{"reference", {{"file", "ref.csv"}, {"signals", "a.?"}}, {}};
  EXPECT_THAT(kinds.at("reference").signals(a, scratch.path()),
              ::testing::ElementsAre("a.y", "a.w"));
}

TEST_F(suite_assertions, reference_column_missing_or_text_in_the_run_fails) {
  write("ref.csv", "time,a.y,b.z\n0,1,3\n");
  record({0}, {{"a.y", {1}}});
  outcome o = evaluate("reference", {{"file", "ref.csv"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("signal b.z was not recorded"));
  add_text_column("b.z");
  o = evaluate("reference", {{"file", "ref.csv"}});
  EXPECT_FALSE(o.passed);
  EXPECT_THAT(o.message, HasSubstr("signal b.z holds text"));
}

// ---- what each kind asks the run to record ----

TEST_F(suite_assertions, signals_to_record) {
  const auto signals = [&](const std::string& kind, const attributes& attrs) {
    return kinds.at(kind).signals(assertion_spec{kind, attrs, {}}, scratch.path());
  };
  EXPECT_THAT(signals("never", {{"signal", "a.b"}}), ::testing::ElementsAre("a.b"));
  EXPECT_THAT(signals("speed", {{"x", "r.x"}, {"y", "r.y"}, {"min", "0"}}),
              ::testing::ElementsAre("r.x", "r.y"));
  EXPECT_THROW(signals("bounds", {{"min", "0"}}), std::invalid_argument);
}

}  // namespace
}  // namespace stride::suite
