// The runner: checks before anything runs, the summary, JUnit XML, and whole suites run through
// the real stride executable on the stride_test FMU.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/suite/runner.hpp"

namespace stride::suite {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_cli = STRIDE_CLI;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class suite_runner : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-suite-runner-"};
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = scratch.path() / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
  fs::path suite_file() const { return scratch.path() / "s.xml"; }
  // "<suite file>:<line>: "
  std::string at_line(int line) const {
    return suite_file().string() + ":" + std::to_string(line) + ": ";
  }
  // the validation_error check_suite throws for a suite whose one case holds `assertions` from
  // line 3 on, or ""
  std::string check_error(const std::string& assertions) {
    write("x.xml", "<system/>");  // the system must exist; its content is the run's business
    write("s.xml",
          "<suite>\n<case name='c' system='x.xml'>\n" + assertions + "\n</case>\n</suite>");
    const suite_spec s = parse_suite_file(suite_file());
    try {
      check_suite(s, builtin_assertions());
    } catch (const cosim::validation_error& e) {
      return e.what();
    }
    return "";
  }
};

// ---- check_suite ----

TEST_F(suite_runner, check_accepts_every_kind_well_written) {
  write("ref.csv", "time,a.y\n0,1\n");
  EXPECT_EQ(check_error("<never signal='a.b' from='0' to='1'/>\n"
                        "<eventually signal='a.b'/>\n"
                        "<bounds signal='a.b' min='-1' max='1'/>\n"
                        "<final signal='a.b' value='1' tolerance='0.5'/>\n"
                        "<final signal='a.b' min='1' max='1'/>\n"
                        "<mean signal='a.b' max='1e3'/>\n"
                        "<rate signal='a.b' min='0'/>\n"
                        "<speed x='a.x' y='a.y' min='0.1' max='0.2' from='1'/>\n"
                        "<reference file='ref.csv' signals='a.*' absolute='1e-12' relative='0'/>"),
            "");
}

TEST_F(suite_runner, check_rejects_a_missing_system_file) {
  write("s.xml",
        "<suite>\n<case name='c' system='none.xml'>\n<never signal='a.b'/>\n</case>\n"
        "</suite>");
  try {
    check_suite(parse_suite_file(suite_file()), builtin_assertions());
    FAIL() << "a missing system file passed the check";
  } catch (const cosim::validation_error& e) {
    EXPECT_THAT(e.what(), StartsWith(at_line(2) + "system file " +
                                     (scratch.path() / "none.xml").string() + " not found"));
  }
}

TEST_F(suite_runner, check_rejects_final_with_value_and_bounds) {
  EXPECT_THAT(check_error("<final signal='a.b' value='1' max='2'/>"),
              StartsWith(at_line(3) + "<final>: takes value and tolerance, or min and max"));
}

TEST_F(suite_runner, check_rejects_an_unknown_kind) {
  EXPECT_THAT(check_error("<never signal='a.b'/>\n<sometimes signal='a.b'/>"),
              AllOf(StartsWith(at_line(4) + "unknown assertion <sometimes>"), HasSubstr("bounds"),
                    HasSubstr("reference")));
}

TEST_F(suite_runner, check_rejects_an_unknown_attribute) {
  EXPECT_THAT(check_error("<bounds signal='a.b' min='0' maximum='1'/>"),
              StartsWith(at_line(3) + "unknown attribute 'maximum' on <bounds>"));
  EXPECT_THAT(check_error("<never signal='a.b' min='0'/>"),
              StartsWith(at_line(3) + "unknown attribute 'min' on <never>"));
}

TEST_F(suite_runner, check_rejects_min_above_max) {
  for (const char* kind : {"bounds", "mean", "rate", "final"}) {
    EXPECT_THAT(check_error("\n<" + std::string(kind) + " signal='a.b' min='2' max='1'/>"),
                StartsWith(at_line(4) + "<" + kind + ">: min is above max"))
        << kind;
  }
  EXPECT_THAT(check_error("<speed x='a' y='b' min='2' max='1'/>"),
              StartsWith(at_line(3) + "<speed>: min is above max"));
  // min == max is a point, not an error
  EXPECT_EQ(check_error("<bounds signal='a.b' min='1' max='1'/>"), "");
}

TEST_F(suite_runner, check_rejects_values_that_are_not_finite_numbers) {
  EXPECT_THAT(check_error("<bounds signal='a.b' max='1.5m'/>"),
              StartsWith(at_line(3) + "<bounds>: max=\"1.5m\" is not a finite number"));
  EXPECT_THAT(check_error("<bounds signal='a.b' min='inf'/>"),
              StartsWith(at_line(3) + "<bounds>: min=\"inf\" is not a finite number"));
  EXPECT_THAT(check_error("<never signal='a.b' from='nan'/>"),
              StartsWith(at_line(3) + "<never>: from=\"nan\" is not a finite number"));
  EXPECT_THAT(check_error("<final signal='a.b' value=' 1'/>"),
              StartsWith(at_line(3) + "<final>: value=\" 1\" is not a finite number"));
  EXPECT_THAT(check_error("<final signal='a.b' value='1' tolerance='x'/>"),
              StartsWith(at_line(3) + "<final>: tolerance=\"x\""));
}

TEST_F(suite_runner, check_rejects_inconsistent_attributes) {
  EXPECT_THAT(check_error("<never signal='a.b' from='2' to='1'/>"),
              StartsWith(at_line(3) + "<never>: from is after to"));
  EXPECT_THAT(check_error("<bounds signal='a.b'/>"),
              StartsWith(at_line(3) + "<bounds>: needs min, max or both"));
  EXPECT_THAT(check_error("<bounds min='0'/>"),
              StartsWith(at_line(3) + "<bounds>: needs a signal attribute"));
  EXPECT_THAT(check_error("<speed x='a.x' min='0'/>"),
              StartsWith(at_line(3) + "<speed>: needs a y attribute"));
  EXPECT_THAT(check_error("<final signal='a.b' min='0' tolerance='1'/>"),
              StartsWith(at_line(3) + "<final>: tolerance goes with value"));
  EXPECT_THAT(check_error("<final signal='a.b' value='0' tolerance='-1'/>"),
              StartsWith(at_line(3) + "<final>: tolerance is negative"));
  EXPECT_THAT(check_error("<final signal='a.b'/>"),
              StartsWith(at_line(3) + "<final>: needs min, max or both"));
}

TEST_F(suite_runner, check_rejects_a_missing_or_unusable_reference) {
  EXPECT_THAT(check_error("<reference file='missing.csv'/>"),
              StartsWith(at_line(3) + "<reference>: reference file " +
                         (scratch.path() / "missing.csv").string() + " not found"));
  write("ref.csv", "time,a.y\n0,1\n");
  EXPECT_THAT(check_error("<reference file='ref.csv' signals='b.*'/>"),
              StartsWith(at_line(3) + "<reference>: no column of " +
                         (scratch.path() / "ref.csv").string() + " matches signals=\"b.*\""));
  EXPECT_THAT(check_error("<reference file='ref.csv' absolute='-1'/>"),
              StartsWith(at_line(3) + "<reference>: tolerances must not be negative"));
  // a header without rows would compare nothing and pass
  write("empty.csv", "time,a.y\n");
  EXPECT_THAT(check_error("<reference file='empty.csv'/>"),
              StartsWith(at_line(3) + "<reference>: reference file " +
                         (scratch.path() / "empty.csv").string() + " has no rows"));
  write("bad.csv", "time,a.y\n0,1,2\n");
  EXPECT_THAT(
      check_error("<reference file='bad.csv'/>"),
      StartsWith(at_line(3) + "<reference>: " + (scratch.path() / "bad.csv").string() + ":2:"));
}

// ---- format_summary ----

suite_report three_cases() {
  suite_report r;
  r.cases.resize(3);
  r.cases[0].name = "walks";
  r.cases[0].status = case_status::passed;
  r.cases[0].seconds = 0.25;
  r.cases[1].name = "stands";
  r.cases[1].status = case_status::failed;
  r.cases[1].seconds = 1.5;
  r.cases[1].failures = {"s.xml:7: bounds: a.y = 3 at t = 0 s, not at most 2.5 & <more>",
                         "s.xml:8: final: final \"a.counter\" = 20 at t = 0.2 s"};
  r.cases[2].name = "crashes";
  r.cases[2].status = case_status::error;
  r.cases[2].error = "the run failed: component 'a' <broke>\x01 (log: run.log)";
  r.seconds = 2;
  return r;
}

TEST_F(suite_runner, summary_lists_failures_under_their_case_and_counts_errors_as_failed) {
  const suite_report r = three_cases();
  const auto lines = lines_of(format_summary(r));
  ASSERT_EQ(lines.size(), 7u) << format_summary(r);
  EXPECT_THAT(lines[0], AllOf(StartsWith("PASS"), HasSubstr("walks")));
  EXPECT_THAT(lines[1], AllOf(StartsWith("FAIL"), HasSubstr("stands")));
  EXPECT_THAT(lines[2], AllOf(StartsWith(" "), HasSubstr(r.cases[1].failures[0])));
  EXPECT_THAT(lines[3], AllOf(StartsWith(" "), HasSubstr(r.cases[1].failures[1])));
  EXPECT_THAT(lines[4], AllOf(StartsWith("ERROR"), HasSubstr("crashes")));
  EXPECT_THAT(lines[5], AllOf(StartsWith(" "), HasSubstr("the run failed")));
  EXPECT_THAT(lines[6], StartsWith("1 passed, 2 failed (1 could not run) in "));
}

TEST_F(suite_runner, summary_closing_line_counts) {
  suite_report r = three_cases();
  r.cases[1].status = case_status::passed;
  r.cases[1].failures.clear();
  r.cases[2].status = case_status::passed;
  EXPECT_THAT(lines_of(format_summary(r)).back(), StartsWith("3 passed, 0 failed in "));
  r.cases[0].status = case_status::failed;
  r.cases[0].failures = {"x"};
  const std::string s = format_summary(r);
  EXPECT_THAT(lines_of(s).back(), StartsWith("2 passed, 1 failed in "));
  EXPECT_THAT(s, ::testing::Not(HasSubstr("could not run")));
}

// ---- write_junit ----

TEST_F(suite_runner, junit_holds_one_testcase_per_case) {
  suite_spec suite;
  suite.name = "darwin & co";
  const suite_report report = three_cases();
  const fs::path file = scratch.path() / "sub" / "folder" / "junit.xml";  // created
  write_junit(file, suite, report);

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(file.c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
  const auto* root = doc.RootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Name(), "testsuites");
  EXPECT_EQ(root->IntAttribute("tests", -1), 3);
  EXPECT_EQ(root->IntAttribute("failures", -1), 1);
  EXPECT_EQ(root->IntAttribute("errors", -1), 1);
  const auto* ts = root->FirstChildElement("testsuite");
  ASSERT_NE(ts, nullptr);
  EXPECT_STREQ(ts->Attribute("name"), "darwin & co");
  EXPECT_EQ(ts->IntAttribute("tests", -1), 3);
  EXPECT_EQ(ts->IntAttribute("failures", -1), 1);
  EXPECT_EQ(ts->IntAttribute("errors", -1), 1);
  EXPECT_DOUBLE_EQ(ts->DoubleAttribute("time", -1), 2.0);

  std::vector<const tinyxml2::XMLElement*> cases;
  for (auto* c = ts->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    EXPECT_STREQ(c->Name(), "testcase");
    cases.push_back(c);
  }
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_STREQ(cases[0]->Attribute("name"), "walks");
  EXPECT_STREQ(cases[1]->Attribute("name"), "stands");
  EXPECT_STREQ(cases[2]->Attribute("name"), "crashes");
  EXPECT_DOUBLE_EQ(cases[0]->DoubleAttribute("time", -1), 0.25);
  EXPECT_DOUBLE_EQ(cases[1]->DoubleAttribute("time", -1), 1.5);
  EXPECT_DOUBLE_EQ(cases[2]->DoubleAttribute("time", -1), 0.0);

  EXPECT_EQ(cases[0]->FirstChildElement(), nullptr);  // passed: nothing inside

  const auto* failure = cases[1]->FirstChildElement("failure");
  ASSERT_NE(failure, nullptr);
  EXPECT_EQ(failure->NextSiblingElement(), nullptr);  // one <failure> for both assertions
  EXPECT_STREQ(failure->Attribute("message"), report.cases[1].failures[0].c_str());
  ASSERT_NE(failure->GetText(), nullptr);
  EXPECT_THAT(failure->GetText(), AllOf(HasSubstr(report.cases[1].failures[0]),
                                        HasSubstr(report.cases[1].failures[1])));
  EXPECT_EQ(cases[1]->FirstChildElement("error"), nullptr);

  const auto* error = cases[2]->FirstChildElement("error");
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(cases[2]->FirstChildElement("failure"), nullptr);
  // the control character is replaced, the rest arrives as written
  EXPECT_STREQ(error->Attribute("message"),
               "the run failed: component 'a' <broke>  (log: run.log)");
  ASSERT_NE(error->GetText(), nullptr);
  EXPECT_THAT(error->GetText(), HasSubstr("component 'a' <broke>"));
}

TEST_F(suite_runner, junit_unwritable_file_throws) {
  suite_spec suite;
  suite.name = "s";
  write("a_file", "");
  EXPECT_THROW(write_junit(scratch.path() / "a_file" / "junit.xml", suite, three_cases()),
               std::runtime_error);
}

// ---- run_suite ----

TEST_F(suite_runner, a_filter_matching_no_case_is_an_error) {
  write("s.xml", "<suite><case name='one' system='x.xml'><never signal='a.b'/></case></suite>");
  const suite_spec s = parse_suite_file(suite_file());
  run_settings settings;
  settings.stride = k_cli;
  settings.output_dir = scratch.path() / "out";
  settings.filter = "two*";
  try {
    run_suite(s, settings);
    FAIL() << "no error";
  } catch (const cosim::validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("no case matches --filter 'two*'"));
    EXPECT_THAT(e.what(), HasSubstr(suite_file().string()));
  }
  EXPECT_FALSE(fs::exists(scratch.path() / "out" / "one"));  // nothing ran
}

#ifdef STRIDE_SUITE_HAVE_TEST_FMU

const fs::path k_pair = fs::path(STRIDE_ORCHESTRATOR_DATA_DIR) / "stride_test_pair.xml";

// a.y = gain * 1, a.counter counts steps of 0.01 s, a.integral = t, b.integral = a.y * t
std::string e2e_suite() {
  return "<suite name='e2e'>\n"  // 1
         "  <case name='passes' system='" +
         k_pair.string() +
         "' stop='0.5' interval='0.1'>\n"
         "    <set variable='a.gain' value='4'/>\n"                            // 3
         "    <bounds signal='a.y' min='4' max='4'/>\n"                        // 4
         "    <final signal='a.counter' value='50'/>\n"                        // 5
         "    <never signal='a.n'/>\n"                                         // 6
         "    <eventually signal='a.active'/>\n"                               // 7
         "    <mean signal='a.y' min='4' max='4'/>\n"                          // 8
         "    <rate signal='a.integral' min='0.999' max='1.001'/>\n"           // 9
         "    <speed x='a.integral' y='b.integral' min='4.12' max='4.13'/>\n"  // 10
         "    <reference file='ref.csv' absolute='1e-9'/>\n"                   // 11
         "  </case>\n"
         "  <case name='fails' system='" +
         k_pair.string() +
         "' stop='0.2' interval='0.1'>\n"
         "    <bounds signal='a.y' max='2.5'/>\n"        // 14
         "    <never signal='a.n'/>\n"                   // 15
         "    <final signal='a.counter' value='19'/>\n"  // 16
         "  </case>\n"
         "  <case name='breaks' system='" +
         k_pair.string() +
         "' stop='0.2'>\n"
         "    <set variable='a.fail_at_step' value='2'/>\n"
         "    <never signal='a.n'/>\n"
         "  </case>\n"
         "  <case name='cannot_load' system='" +
         (k_data / "unloadable.xml").string() +
         "'>\n"
         "    <never signal='a.n'/>\n"
         "  </case>\n"
         "</suite>\n";
}

class suite_runner_e2e : public suite_runner {
 protected:
  suite_spec suite;
  run_settings settings;
  void SetUp() override {
    // reference points between the recorded ones (every 0.1 s): the run is interpolated
    write("ref.csv", "time,a.integral\n0.05,0.05\n0.25,0.25\n0.5,0.5\n");
    write("s.xml", e2e_suite());
    suite = parse_suite_file(suite_file());
    check_suite(suite, builtin_assertions());
    settings.stride = k_cli;
    settings.output_dir = scratch.path() / "out";
  }
};

TEST_F(suite_runner_e2e, runs_every_case_and_reports_pass_fail_and_error) {
  settings.jobs = 2;
  std::FILE* progress = std::tmpfile();
  ASSERT_NE(progress, nullptr);
  settings.progress = progress;
  const suite_report r = run_suite(suite, settings);

  ASSERT_EQ(r.cases.size(), 4u);  // in the suite's order, whatever finished first
  EXPECT_EQ(r.cases[0].name, "passes");
  EXPECT_EQ(r.cases[1].name, "fails");
  EXPECT_EQ(r.cases[2].name, "breaks");
  EXPECT_EQ(r.cases[3].name, "cannot_load");

  EXPECT_EQ(r.cases[0].status, case_status::passed)
      << ::testing::PrintToString(r.cases[0].failures) << r.cases[0].error;
  EXPECT_TRUE(r.cases[0].failures.empty());
  EXPECT_EQ(r.cases[0].dir, settings.output_dir / "passes");
  // the case recorded what its assertions name, nothing else
  const recorded_signals rec = read_recorded_signals(r.cases[0].dir / "results.csv");
  EXPECT_THAT(rec.names, ::testing::UnorderedElementsAre("a.y", "a.counter", "a.n", "a.active",
                                                         "a.integral", "b.integral"));
  EXPECT_EQ(rec.time.size(), 6u);  // 0, 0.1, ..., 0.5

  EXPECT_EQ(r.cases[1].status, case_status::failed);
  ASSERT_EQ(r.cases[1].failures.size(), 2u);
  EXPECT_THAT(r.cases[1].failures[0],
              StartsWith(at_line(14) + "bounds: a.y = 3 at t = 0 s, not at most 2.5 (3 of 3"));
  EXPECT_THAT(r.cases[1].failures[1],
              StartsWith(at_line(16) + "final: final a.counter = 20 at t = 0.2 s, not within "
                                       "[19, 19]"));

  EXPECT_EQ(r.cases[2].status, case_status::error);
  EXPECT_THAT(r.cases[2].error,
              AllOf(StartsWith("the run failed: "), HasSubstr("fmi2DoStep"),
                    HasSubstr((settings.output_dir / "breaks" / "run.log").string())));
  EXPECT_EQ(r.cases[3].status, case_status::error);
  EXPECT_THAT(r.cases[3].error, HasSubstr("no_such_component_fmu"));

  EXPECT_EQ(r.count(case_status::passed), 1u);
  EXPECT_EQ(r.count(case_status::failed), 1u);
  EXPECT_EQ(r.count(case_status::error), 2u);
  EXPECT_THAT(lines_of(format_summary(r)).back(),
              StartsWith("1 passed, 3 failed (2 could not run)"));

  // one progress line per finished case
  std::rewind(progress);
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, progress) != nullptr) text += buf;
  std::fclose(progress);
  const auto lines = lines_of(text);
  ASSERT_EQ(lines.size(), 4u) << text;
  EXPECT_EQ(std::count_if(lines.begin(), lines.end(),
                          [](const std::string& l) { return l.rfind("ERROR", 0) == 0; }),
            2);
}

TEST_F(suite_runner_e2e, the_filter_chooses_cases) {
  settings.filter = "*s";  // passes, fails, breaks
  const suite_report r = run_suite(suite, settings);
  ASSERT_EQ(r.cases.size(), 3u);
  EXPECT_EQ(r.cases[0].name, "passes");
  EXPECT_EQ(r.cases[1].name, "fails");
  EXPECT_EQ(r.cases[2].name, "breaks");
  EXPECT_FALSE(fs::exists(settings.output_dir / "cannot_load"));
}

TEST_F(suite_runner_e2e, a_reference_that_differs_fails_naming_the_point) {
  write("ref.csv", "time,a.integral\n0.05,0.05\n0.25,0.3\n0.5,0.5\n");
  settings.filter = "passes";
  const suite_report r = run_suite(suite, settings);
  ASSERT_EQ(r.cases.size(), 1u);
  EXPECT_EQ(r.cases[0].status, case_status::failed);
  ASSERT_EQ(r.cases[0].failures.size(), 1u);
  EXPECT_THAT(r.cases[0].failures[0],
              AllOf(StartsWith(at_line(11) + "reference: a.integral differs from the reference"),
                    HasSubstr("at t = 0.25 s (run 0.25, reference 0.3"),
                    HasSubstr("1 of 3 points outside")));
}

#endif  // STRIDE_SUITE_HAVE_TEST_FMU

}  // namespace
}  // namespace stride::suite
