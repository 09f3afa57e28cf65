// `stride run` conveniences through the built CLI on pairs of the stride_test FMU: --record and
// its alias --signals, --stop-when and the stop reason in the summary and manifest, the refusal
// of a non-empty output folder (and --force), values for inputs a connection drives.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const std::string k_cli = STRIDE_CLI;
const fs::path k_pair = k_data / "stride_test_pair.xml";

std::string read(const fs::path& file) {
  return test::read_file(file);
}

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

std::size_t line_count(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

class run_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-run-test-"};
  // in the scratch folder: relative --output folders land there
  test::process_result stride(const std::string& args) {
    return run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                       scratch.path());
  }
  // `stride run` of the pair, stop time 0.1 s
  test::process_result run_pair(const std::string& args) {
    return stride("run " + quoted(k_pair) + " --stop-time 0.1 " + args);
  }
  fs::path out(const std::string& name) const { return scratch.path() / name; }
};

TEST_F(run_cli, help_documents_the_options) {
  const auto r = stride("run --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--record", "--signals", "--record-interval", "--stop-time",
                             "--stop-when", "--force", "--output"}) {
    EXPECT_THAT(r.out, HasSubstr(option));
  }
}

TEST_F(run_cli, record_takes_comma_separated_patterns_and_may_be_repeated) {
  auto r = run_pair("--quiet -o one --record 'a.y,b.c*' --record b.echo --record-interval 0.05");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(first_line(out("one") / "results.csv"), "time,a.y,b.counter,b.echo");
  EXPECT_EQ(line_count(read(out("one") / "results.csv")), 1u + 3u);  // t = 0, 0.05, 0.1
  // --signals is the same option; space-separated patterns too
  r = run_pair("--quiet -o two --signals 'a.y b.counter'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(first_line(out("two") / "results.csv"), "time,a.y,b.counter");
}

TEST_F(run_cli, a_record_pattern_that_matches_nothing_is_named_and_nothing_is_written) {
  auto r = run_pair("--quiet -o bad --record 'a.y,robot.base_*'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("stride: error: --record: record signal 'robot.base_*' matches "
                                "no variable"));
  EXPECT_EQ(line_count(r.err), 1u);
  EXPECT_FALSE(fs::exists(out("bad")));
  r = run_pair("--quiet -o empty --record ','");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--record: no signal pattern given"));
}

TEST_F(run_cli, a_stop_condition_ends_the_run_and_the_summary_and_manifest_say_why_and_when) {
  // a.counter counts steps: non-zero after the first one
  auto r = run_pair("-o cond --stop-when a.counter");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("stopped: a.counter at t = 0.01 s after 1 steps ("));
  const std::string manifest = read(out("cond") / "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"ended_by\": \"a.counter\""));
  EXPECT_THAT(manifest, HasSubstr("\"stop_reason\": {\"kind\": \"condition\", \"variable\": "
                                  "\"a.counter\", \"time\": 0.01}"));
  // a Boolean that is false all along: the stop time ends the run
  r = run_pair("-o never --set a.enable=false --stop-when a.active");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("finished at t = 0.1 s after 10 steps"));
  EXPECT_THAT(read(out("never") / "manifest.json"),
              HasSubstr("\"stop_reason\": {\"kind\": \"stop_time\", \"time\": 0.1}"));
}

TEST_F(run_cli, a_component_that_ends_the_run_is_named_with_the_time) {
  const auto r = run_pair("-o comp --set a.stop_after_steps=4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("stopped: component a requested termination at t = 0.03 s"));
  EXPECT_THAT(read(out("comp") / "manifest.json"),
              HasSubstr("\"stop_reason\": {\"kind\": \"component\", \"component\": \"a\", "
                        "\"time\": 0.03}"));
}

TEST_F(run_cli, stop_when_names_a_pattern_that_is_no_condition) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"a.nothing", "--stop-when 'a.nothing': names no variable"},
      {"a.u", "--stop-when 'a.u': a.u is input; a stop condition needs an output"},
      {"a.gain", "--stop-when 'a.gain': a.gain is parameter; a stop condition needs an output"},
      {"a.echo", "--stop-when 'a.echo': a.echo is a String output"},
      {"'b.s*'", "--stop-when 'b.s*': matches no Boolean, Integer or Real output"},
  };
  for (const auto& [pattern, message] : cases) {
    const auto r = run_pair("--quiet -o stop --stop-when " + pattern);
    EXPECT_EQ(r.exit_code, 1) << pattern;
    EXPECT_THAT(r.err, StartsWith("stride: error: " + message)) << pattern;
    EXPECT_EQ(line_count(r.err), 1u) << r.err;
  }
  EXPECT_FALSE(fs::exists(out("stop")));  // refused before anything was written
}

TEST_F(run_cli, a_non_empty_output_folder_is_refused_unless_forced) {
  fs::create_directories(out("mine"));
  std::ofstream(out("mine") / "notes.txt") << "keep\n";
  auto r = run_pair("--quiet -o mine");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("stride: error: output folder mine is not empty (it holds "
                                "notes.txt): "));
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(std::distance(fs::directory_iterator(out("mine")), fs::directory_iterator()), 1);
  // an empty folder is fine
  fs::create_directories(out("empty"));
  EXPECT_EQ(run_pair("--quiet -o empty").exit_code, 0);
  // an earlier run: refused, named as such, and kept
  const std::string manifest = read(out("empty") / "manifest.json");
  r = run_pair("--quiet -o empty");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("holds an earlier run (its system.xml)"));
  EXPECT_EQ(read(out("empty") / "manifest.json"), manifest);
  // --force writes into both
  r = run_pair("--quiet -o mine --force");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out("mine") / "results.csv"));
  EXPECT_EQ(read(out("mine") / "notes.txt"), "keep\n");
  EXPECT_EQ(run_pair("--quiet -o empty --force --set a.offset=7").exit_code, 0);
  EXPECT_THAT(read(out("empty") / "manifest.json"), HasSubstr("\"a.offset\": \"7\""));
  // a file is no folder
  std::ofstream(out("file")) << "x";
  r = run_pair("--quiet -o file");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("output folder file is a file"));
}

TEST_F(run_cli, a_sweep_refuses_a_non_empty_folder_that_holds_no_sweep) {
  fs::create_directories(out("mine"));
  std::ofstream(out("mine") / "notes.txt") << "keep\n";
  const auto r = stride("sweep " + quoted(k_pair) + " --grid a.gain=1:2:1 --quiet -o mine");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--output mine is not empty and holds no sweep"));
  EXPECT_FALSE(fs::exists(out("mine") / "points"));
}

TEST_F(run_cli, a_value_for_an_input_a_connection_drives_is_refused_by_run_and_validate) {
  // stride_test_pair.xml: <connection from="a.y" to="b.u"/> on line 14
  const std::string connection = "the connection a.y -> b.u (" + k_pair.string() + ":14) drives it";
  auto r = run_pair("--quiet -o set --set b.u=5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err,
              StartsWith("stride: error: --set b.u=5: b.u is given a value, but " + connection));
  EXPECT_FALSE(fs::exists(out("set")));
  r = stride("validate " + quoted(k_pair) + " --set b.u=5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err,
              StartsWith("stride: error: --set b.u=5: b.u is given a value, but " + connection));
  // the same value in the system file: named by its line
  std::string xml = read(k_pair);
  const std::string b = "<component name=\"b\" fmu=\"stride_test\"/>";
  const auto at = xml.find(b);
  ASSERT_NE(at, std::string::npos);
  xml.replace(at, b.size(),
              "<component name=\"b\" fmu=\"stride_test\"><parameter name=\"u\" "
              "value=\"5\"/></component>");
  const fs::path system = out("driven.xml");
  std::ofstream(system) << xml;
  r = stride("validate " + quoted(system));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr(system.string() +
                               ":13: b.u is given a value, but the connection a.y -> "
                               "b.u (" +
                               system.string() + ":14) drives it"));
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
}

}  // namespace
}  // namespace stride::cosim
