// `stride test` end to end: exit status, errors with file and line, --filter, --junit, --quiet.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <algorithm>
#include <fstream>

#include "../orchestrator/process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::suite {
namespace {

namespace fs = std::filesystem;
using cosim::test::quoted;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const std::string k_cli = STRIDE_CLI;

std::size_t line_count(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

class suite_cli : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-suite-cli-"};
  fs::path suite = scratch.path() / "s.xml";
  fs::path out = scratch.path() / "out";

  void write_suite(const std::string& text) { std::ofstream(suite, std::ios::binary) << text; }
  cosim::test::process_result stride_test(const std::string& args = "") {
    return cosim::test::run_command(
        "'" + k_cli + "' test " + quoted(suite) + " --output " + quoted(out) + " " + args,
        scratch.path());
  }
  std::string at_line(int line) const { return suite.string() + ":" + std::to_string(line) + ": "; }
};

TEST_F(suite_cli, malformed_suite_fails_with_file_and_line) {
  write_suite(
      "<suite>\n  <case name='a' system='x.xml'>\n    <never signal='a.b'>\n  </case>\n"
      "</suite>\n");
  const auto r = stride_test();
  EXPECT_EQ(r.exit_code, 1);
  // tinyxml2 names the element left open
  EXPECT_THAT(r.err, StartsWith("stride: error: " + at_line(3) + "malformed XML"));
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(out));  // nothing ran
}

TEST_F(suite_cli, unknown_assertion_fails_with_file_and_line_before_anything_runs) {
  write_suite(
      "<suite>\n"
      "  <case name='a' system='" +
      (k_data / "unloadable.xml").string() +
      "'>\n"
      "    <never signal='a.b'/>\n"
      "    <sometimes signal='a.b'/>\n"
      "  </case>\n"
      "</suite>\n");
  const auto r = stride_test();
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("stride: error: " + at_line(4) + "unknown assertion <sometimes>"));
  // the study's kinds are known to the CLI
  EXPECT_THAT(r.err, AllOf(HasSubstr("best_state"), HasSubstr("value_at")));
  EXPECT_FALSE(fs::exists(out / "a"));
}

TEST_F(suite_cli, a_filter_matching_nothing_is_an_error) {
  write_suite("<suite><case name='a' system='" + (k_data / "unloadable.xml").string() +
              "'><never signal='a.b'/></case></suite>");
  const auto r = stride_test("--filter 'zz*'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("no case matches --filter 'zz*'"));
  EXPECT_THAT(r.out, Not(HasSubstr("passed")));
}

TEST_F(suite_cli, a_missing_system_file_stops_the_suite_before_it_runs) {
  write_suite(
      "<suite>\n"
      "  <case name='no_system_file' system='no_such_system.xml'>\n"
      "    <never signal='a.b'/>\n"
      "  </case>\n"
      "</suite>\n");
  const auto r = stride_test("");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr(at_line(2) + "system file "));
  EXPECT_FALSE(fs::exists(out));  // nothing ran
}

TEST_F(suite_cli, a_case_whose_system_cannot_load_is_an_error_never_a_pass) {
  write_suite(
      "<suite name='broken'>\n"
      "  <case name='cannot_load' system='" +
      (k_data / "unloadable.xml").string() +
      "'>\n"
      "    <never signal='a.b'/>\n"
      "  </case>\n"
      "  <case name='cannot_load_either' system='" +
      (k_data / "unloadable.xml").string() +
      "'>\n"
      "    <never signal='a.b'/>\n"
      "  </case>\n"
      "</suite>\n");
  const fs::path junit = scratch.path() / "junit.xml";
  const auto r = stride_test("--junit " + quoted(junit));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("ERROR cannot_load"));
  EXPECT_THAT(r.out, HasSubstr("ERROR cannot_load_either"));
  EXPECT_THAT(r.out, HasSubstr("no_such_component_fmu"));  // the run's own error, in the summary
  EXPECT_THAT(r.out, HasSubstr("\n0 passed, 2 failed (2 could not run) in "));
  EXPECT_TRUE(fs::exists(out / "cannot_load" / "run.log"));

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(junit.c_str()), tinyxml2::XML_SUCCESS);
  const auto* ts = doc.RootElement()->FirstChildElement("testsuite");
  ASSERT_NE(ts, nullptr);
  EXPECT_STREQ(ts->Attribute("name"), "broken");
  EXPECT_EQ(ts->IntAttribute("tests", -1), 2);
  EXPECT_EQ(ts->IntAttribute("errors", -1), 2);
  EXPECT_EQ(ts->IntAttribute("failures", -1), 0);
  const auto* c = ts->FirstChildElement("testcase");
  ASSERT_NE(c, nullptr);
  EXPECT_NE(c->FirstChildElement("error"), nullptr);
}

#ifdef STRIDE_SUITE_HAVE_TEST_FMU

const fs::path k_pair = fs::path(STRIDE_ORCHESTRATOR_DATA_DIR) / "stride_test_pair.xml";

std::string pair_case(const std::string& name, const std::string& assertions) {
  return "  <case name='" + name + "' system='" + k_pair.string() +
         "' stop='0.2' interval='0.05'>\n" + assertions + "  </case>\n";
}

TEST_F(suite_cli, a_passing_suite_exits_zero_and_writes_junit) {
  write_suite("<suite name='small'>\n" +
              pair_case("gain",
                        "    <set variable='a.gain' value='2'/>\n"
                        "    <bounds signal='a.y' min='2' max='2'/>\n") +
              pair_case("counts",
                        "    <final signal='a.counter' value='20'/>\n"
                        "    <never signal='a.n'/>\n") +
              "</suite>\n");
  const fs::path junit = scratch.path() / "reports" / "junit.xml";
  const auto r = stride_test("--jobs 2 --junit " + quoted(junit));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, AllOf(HasSubstr("PASS  gain"), HasSubstr("PASS  counts")));
  EXPECT_THAT(r.out, HasSubstr("\n2 passed, 0 failed in "));
  EXPECT_TRUE(fs::exists(out / "gain" / "results.csv"));

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(junit.c_str()), tinyxml2::XML_SUCCESS);
  const auto* ts = doc.RootElement()->FirstChildElement("testsuite");
  ASSERT_NE(ts, nullptr);
  EXPECT_EQ(ts->IntAttribute("tests", -1), 2);
  EXPECT_EQ(ts->IntAttribute("failures", -1), 0);
  EXPECT_EQ(ts->IntAttribute("errors", -1), 0);

  // --quiet: the closing line only
  const auto q = stride_test("--quiet");
  EXPECT_EQ(q.exit_code, 0) << q.err;
  EXPECT_THAT(q.out, StartsWith("2 passed, 0 failed in "));
  EXPECT_EQ(line_count(q.out), 1u) << q.out;
}

TEST_F(suite_cli, a_failing_assertion_fails_the_suite_and_is_listed) {
  write_suite("<suite name='small'>\n" +
              pair_case("gain", "    <bounds signal='a.y' min='3' max='3'/>\n") +
              pair_case("counts", "    <final signal='a.counter' value='21'/>\n") + "</suite>\n");
  auto r = stride_test();
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_THAT(r.out, HasSubstr("FAIL  counts"));
  EXPECT_THAT(r.out, HasSubstr(at_line(6) + "final: final a.counter = 20 at t = 0.2 s"));
  EXPECT_THAT(r.out, HasSubstr("\n1 passed, 1 failed in "));
  // the filter leaves the failing case out
  r = stride_test("--filter gain");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("\n1 passed, 0 failed in "));
}

#endif  // STRIDE_SUITE_HAVE_TEST_FMU

}  // namespace
}  // namespace stride::suite
