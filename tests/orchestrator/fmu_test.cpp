// FMU-level tests with the bundled stride_test.fmu: import, every value type across
// connections, FMU-requested stop, errors, wrong GUID, the CLI end to end.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/observers.hpp"
#include "stride/cosim/run.hpp"
#include "stride/cosim/run_agents.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/fmi2/fmi2_api.h"
#include "zip_writer.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path k_fmu = fs::path(STRIDE_FMU_DIR) / "stride_test.fmu";
const fs::path k_data = STRIDE_TEST_DATA_DIR;
const std::string k_cli = STRIDE_CLI;

struct captured_log {
  std::vector<std::string> lines;
  log_sink sink() {
    return [this](log_level level, std::string_view source, std::string_view,
                  std::string_view message) {
      lines.push_back(std::string(to_string(level)) + " " + std::string(source) + ": " +
                      std::string(message));
    };
  }
};

std::vector<std::string> read_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// column `name` of the last row of a results CSV
std::string last_value(const fs::path& csv, const std::string& name) {
  const auto rows = read_lines(csv);
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    cells.push_back(cell);
    return cells;
  };
  const auto header = split(rows.front());
  const auto last = split(rows.back());
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return last.at(i);
  }
  return "<no column " + name + ">";
}

class cosim_fmu_test : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-fmu-test-"};
  captured_log log;

  run_options options(const std::string& out) {
    run_options o;
    o.output_dir = scratch.path() / out;
    o.progress = false;
    o.build.log = log.sink();
    o.build.import.extract_root = scratch.path() / "extract";
    fs::create_directories(o.build.import.extract_root);
    return o;
  }
};

TEST_F(cosim_fmu_test, imports_and_runs_one_instance_directly) {
  fmu_import_options io;
  io.extract_root = scratch.path();
  auto f = fmu::load(k_fmu, io);
  const auto& md = f->model_description();
  EXPECT_EQ(md.co_simulation->model_identifier, "stride_test");
  EXPECT_EQ(*md.default_experiment.step_size, 0.01);
  const auto y = *md.index_of("y");
  const auto u = *md.index_of("u");
  const auto integral = *md.index_of("integral");
  EXPECT_TRUE(md.has_feedthrough(y, u));
  EXPECT_FALSE(md.has_feedthrough(integral, u));
  EXPECT_EQ(md.variables[*md.index_of("gain")].variability, variability::tunable);
  EXPECT_EQ(f->resource_uri().rfind("file://" + scratch.path().string(), 0), 0u);

  auto c = f->instantiate("one", {log.sink(), false});
  c->setup(time_point{}, time_point(std::chrono::seconds(1)));
  c->enter_initialization();
  const value_reference u_vr = md.variables[u].reference;
  const value_reference y_vr = md.variables[y].reference;
  variable_refs u_refs, y_refs;
  u_refs.reals = {u_vr};
  y_refs.reals = {y_vr};
  value_block three, out;
  three.reals = {3.0};
  c->set_values(u_refs, three);
  c->get_values(y_refs, out);
  EXPECT_EQ(out.reals, std::vector<double>{6.0});  // gain 2 * u 3
  c->exit_initialization();
  c->expose(u_refs, y_refs);
  three.reals = {4.0};
  EXPECT_EQ(c->step(time_point{}, duration(10'000'000), three, out), step_result::complete);
  EXPECT_EQ(out.reals, std::vector<double>{8.0});  // the output after the step, with u = 4
  c->terminate();
  const fs::path extracted = f->extracted_dir();
  EXPECT_TRUE(fs::exists(extracted));
  c.reset();
  f.reset();
  EXPECT_FALSE(fs::exists(extracted));  // RAII cleanup
}

void ignore_fmu_log(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {
}

// The same inputs given to two instances: to one as batches through the component interface,
// to the other one variable at a time through the typed fmi2Set*/fmi2Get* of the binary.
TEST_F(cosim_fmu_test, a_batched_exchange_equals_individual_typed_calls) {
  auto f = fmu::load(k_fmu);
  const auto& md = f->model_description();
  const auto ref = [&](const char* name) { return md.find(name)->reference; };
  variable_refs in, out;
  in.reals = {ref("u"), ref("vec_in[1]"), ref("vec_in[2]"), ref("vec_in[3]")};
  in.integers = {ref("n")};
  in.booleans = {ref("enable")};
  in.strings = {ref("suffix")};
  out.reals = {ref("y"), ref("integral"), ref("vec_out[1]"), ref("vec_out[3]")};
  out.integers = {ref("counter")};
  out.booleans = {ref("active")};
  out.strings = {ref("echo")};
  const auto inputs_at = [](int k) {
    value_block v;
    v.reals = {0.5 * k, -1.0 * k, 2.0, k * k * 0.25};
    v.integers = {k};
    v.booleans = {k % 2 == 1};
    v.strings = {"s" + std::to_string(k)};
    return v;
  };

  // batched: one step call per communication step
  auto batched = f->instantiate("batched", {log.sink(), false});
  batched->setup(time_point{}, std::nullopt);
  batched->expose(in, out);
  batched->enter_initialization();
  batched->exit_initialization();
  std::vector<value_block> batched_outputs;
  for (int k = 0; k < 5; ++k) {
    value_block o;
    o.resize_for(out);
    ASSERT_EQ(batched->step(time_point{} + k * duration(10'000'000), duration(10'000'000),
                            inputs_at(k), o),
              step_result::complete);
    batched_outputs.push_back(o);
  }

  // individual: the raw FMI functions of the same binary, one value reference per call
  void* lib = dlopen((f->extracted_dir() / "binaries/linux64/stride_test.so").c_str(),
                     RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(lib, nullptr);
#define STRIDE_GET(name) \
  [[maybe_unused]] auto* name = reinterpret_cast<name##TYPE*>(dlsym(lib, #name));
  STRIDE_FMI2_CS_FUNCTIONS(STRIDE_GET)
#undef STRIDE_GET
  fmi2CallbackFunctions cb{ignore_fmu_log, calloc, free, nullptr, nullptr};
  fmi2Component c = fmi2Instantiate("typed", fmi2CoSimulation, md.guid.c_str(),
                                    f->resource_uri().c_str(), &cb, fmi2False, fmi2False);
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
  ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
  for (int k = 0; k < 5; ++k) {
    const value_block v = inputs_at(k);
    for (std::size_t i = 0; i < in.reals.size(); ++i) fmi2SetReal(c, &in.reals[i], 1, &v.reals[i]);
    fmi2SetInteger(c, &in.integers[0], 1, &v.integers[0]);
    const fmi2Boolean b = v.booleans[0] ? fmi2True : fmi2False;
    fmi2SetBoolean(c, &in.booleans[0], 1, &b);
    const fmi2String str = v.strings[0].c_str();
    fmi2SetString(c, &in.strings[0], 1, &str);
    ASSERT_EQ(fmi2DoStep(c, 0.01 * k, 0.01, fmi2True), fmi2OK);
    const value_block& o = batched_outputs[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < out.reals.size(); ++i) {
      double x = 0;
      fmi2GetReal(c, &out.reals[i], 1, &x);
      EXPECT_EQ(x, o.reals[i]) << "step " << k << ", real " << i;
    }
    int n = 0;
    fmi2GetInteger(c, &out.integers[0], 1, &n);
    EXPECT_EQ(n, o.integers[0]);
    fmi2Boolean active = fmi2False;
    fmi2GetBoolean(c, &out.booleans[0], 1, &active);
    EXPECT_EQ(active != fmi2False, o.booleans[0]);
    fmi2String echo = nullptr;
    fmi2GetString(c, &out.strings[0], 1, &echo);
    EXPECT_EQ(std::string(echo), o.strings[0]);
  }
  EXPECT_EQ(batched_outputs[4].strings[0], "strides4");  // label + the last step's suffix
  EXPECT_EQ(batched_outputs[4].integers[0], 15);         // Σ (1 + n) over five steps
  fmi2Terminate(c);
  fmi2FreeInstance(c);
  dlclose(lib);
}

TEST_F(cosim_fmu_test, every_value_type_crosses_connections) {
  auto o = options("pair");
  const auto report = run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
  EXPECT_EQ(report.result.steps, 100);
  EXPECT_EQ(report.result.end_time, time_point(std::chrono::seconds(1)));
  const auto csv = report.results_file;
  EXPECT_EQ(last_value(csv, "time"), "1");
  EXPECT_EQ(last_value(csv, "a.y"), "3");  // gain 3 * u 1
  EXPECT_EQ(last_value(csv, "b.y"), "6");  // gain 2 * a.y
  EXPECT_EQ(last_value(csv, "a.counter"), "100");
  EXPECT_EQ(last_value(csv, "b.echo"), "stridehello");  // b.label + a.echo
  EXPECT_EQ(last_value(csv, "b.active"), "1");
  EXPECT_EQ(last_value(csv, "b.vec_out[3]"), "12");                  // 2 * 2 * 3
  EXPECT_NEAR(std::stod(last_value(csv, "b.integral")), 3.0, 1e-9);  // b.u = 3 for 1 s
  // b.n = a.counter: b counts 1 + a.counter per step = 100 + (1 + ... + 100)
  EXPECT_EQ(last_value(csv, "b.counter"), std::to_string(100 + 100 * 101 / 2));
  const auto manifest = read_text(report.manifest_file);
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"ok\""));
  EXPECT_THAT(manifest, HasSubstr("stride_test.fmu"));
  EXPECT_TRUE(fs::is_empty(o.build.import.extract_root));
}

TEST_F(cosim_fmu_test, fmu_requested_stop_ends_the_run_cleanly) {
  auto o = options("stop");
  o.overrides = {"a.stop_after_steps=5"};
  const auto report = run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
  EXPECT_TRUE(report.result.terminated_by_component);
  EXPECT_EQ(report.result.terminated_by, "a");
  EXPECT_EQ(report.result.end_time, time_point(std::chrono::milliseconds(40)));
  EXPECT_EQ(read_lines(report.results_file).size(), 1u + 5u);  // header, t = 0 .. 0.04
  EXPECT_THAT(read_text(report.manifest_file),
              HasSubstr("\"ended_by\": \"component a requested termination\""));
  EXPECT_THAT(read_text(report.manifest_file),
              HasSubstr("\"stop_reason\": {\"kind\": \"component\", \"component\": \"a\", "
                        "\"time\": 0.04}"));
}

TEST_F(cosim_fmu_test, a_stop_condition_ends_the_run_and_the_manifest_names_it) {
  auto o = options("condition");
  o.stop_when = {"b.count*"};  // b.counter = 1 + a.counter each step: non-zero after the first
  const auto report = run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
  EXPECT_EQ(report.result.stopped_by, "b.counter");
  EXPECT_EQ(report.result.steps, 1);
  EXPECT_EQ(end_reason(report.result), "b.counter");
  EXPECT_THAT(read_text(report.manifest_file),
              HasSubstr("\"stop_reason\": {\"kind\": \"condition\", \"variable\": "
                        "\"b.counter\", \"time\": 0.01}"));
  EXPECT_EQ(read_lines(report.results_file).size(), 1u + 2u);  // header, t = 0, 0.01
}

TEST_F(cosim_fmu_test, fmu_error_names_component_function_and_time_and_keeps_results) {
  auto o = options("fail");
  o.overrides = {"a.fail_at_step=3"};
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'a': fmi2DoStep returned fmi2Error"));
    EXPECT_THAT(e.what(), HasSubstr("t = 0.02 s"));
  }
  EXPECT_EQ(read_lines(o.output_dir / "results.csv").size(), 1u + 3u);  // t = 0, 0.01, 0.02
  const auto manifest = read_text(o.output_dir / "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"error\""));
  // the FMU's own message reached the log, prefixed with the instance name
  bool logged = false;
  for (const auto& l : log.lines) logged = logged || l.find("error a: ") == 0;
  EXPECT_TRUE(logged);
  EXPECT_TRUE(fs::is_empty(o.build.import.extract_root));
}

// a.vec_out[2] = 2 * a.vec_in[2] overflows to infinity in the first step: the run ends naming
// the output, before b or the results see it
TEST_F(cosim_fmu_test, a_non_finite_output_ends_the_run_naming_the_variable) {
  auto o = options("overflow");
  o.overrides = {"a.vec_in[2]=1e308"};
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'a': fmi2GetReal gave a.vec_out[2] = inf, not a "
                                    "finite number"));
    EXPECT_THAT(e.what(), HasSubstr("t = 0 s"));
  }
  const auto rows = read_lines(o.output_dir / "results.csv");
  ASSERT_EQ(rows.size(), 1u + 1u);  // header, t = 0
  EXPECT_THAT(rows[1], Not(HasSubstr("inf")));
}

TEST_F(cosim_fmu_test, wrong_guid_is_refused_at_instantiation) {
  auto entries = test::read_zip(k_fmu);
  for (auto& e : entries) {
    if (e.name != "modelDescription.xml") continue;
    const auto at = e.content.find("guid=\"");
    ASSERT_NE(at, std::string::npos);
    e.content.replace(at + 6, 1, "0");  // change the first GUID character
    if (e.content[at + 6] == '0') e.content[at + 6] = '1';
  }
  const fs::path bad = scratch.path() / "bad_guid.fmu";
  test::write_zip(bad, entries);
  auto f = fmu::load(bad);
  EXPECT_THROW(f->instantiate("x", {log.sink(), false}), component_error);
}

TEST_F(cosim_fmu_test, missing_symbol_is_named) {
  // an FMU whose binary is some other shared library: libzip exports no fmi2 functions
  auto entries = test::read_zip(k_fmu);
  const fs::path bad = scratch.path() / "no_symbols.fmu";
  std::string libc;
  for (const char* candidate :
       {"/lib/x86_64-linux-gnu/libzip.so.4", "/usr/lib/x86_64-linux-gnu/libzip.so.4"}) {
    if (fs::exists(candidate)) {
      libc = read_text(candidate);
      break;
    }
  }
  if (libc.empty()) GTEST_SKIP() << "no shared library to plant";
  for (auto& e : entries) {
    if (e.name.ends_with(".so")) e.content = libc;
  }
  test::write_zip(bad, entries);
  try {
    fmu::load(bad);
    FAIL();
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("does not export fmi2"));
  }
}

TEST_F(cosim_fmu_test, cli_run_writes_the_output_folder) {
  const fs::path out = scratch.path() / "cli";
  const auto r = test::run_command(
      "'" + k_cli + "' run " + quoted(k_data / "stride_test_pair.xml") + " --output " +
          quoted(out) + " --set a.gain=4 --set b.label=x --stop-time 0.5 --quiet",
      scratch.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(last_value(out / "results.csv", "time"), "0.5");
  EXPECT_EQ(last_value(out / "results.csv", "a.y"), "4");
  EXPECT_EQ(last_value(out / "results.csv", "b.echo"), "xhello");
  const auto copy = parse_system_file(out / "system.xml");
  EXPECT_EQ(*copy.stop, time_point(std::chrono::milliseconds(500)));
  EXPECT_TRUE(fs::exists(out / "manifest.json"));
}

// FMI 2.0 allows fmi2Terminate only after initialization: when b fails during the initial
// exchange, a (still in initialization mode) is freed without it
TEST_F(cosim_fmu_test, an_initialization_failure_terminates_no_instance_in_initialization_mode) {
  const std::string long_label(60,
                               'x');  // a.echo = label + suffix: 70 characters, b.suffix holds 63
  const auto r =
      test::run_command("'" + k_cli + "' run " + quoted(k_data / "stride_test_pair.xml") +
                            " --output " + quoted(scratch.path() / "init-fail") +
                            " --set a.label=" + long_label + " --set a.suffix=abcdefghij --quiet",
                        scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("component 'b': fmi2SetString returned fmi2Error (initialization"));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("fmi2Terminate"))) << r.err;
}

// SIGINT or SIGTERM end the run between two steps: whole rows, a manifest that says so, the
// signal's exit status; the unpacked FMUs are removed
TEST_F(cosim_fmu_test, a_run_stopped_by_a_signal_keeps_its_results_and_says_so) {
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path out = scratch.path() / ("signal-" + std::to_string(signal));
    const pid_t pid =
        test::spawn({k_cli, "run", (k_data / "stride_test_pair.xml").string(), "--stop-time",
                     "1000000", "--record-interval", "1", "--quiet", "--output", out.string()},
                    scratch.path() / "run.log");
    ASSERT_GT(pid, 0);
    // wait until it is stepping and recording
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!(fs::exists(out / "results.csv") && fs::file_size(out / "results.csv") > 2000) &&
           std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(pid, signal);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    std::ifstream log(scratch.path() / "run.log");
    std::stringstream text;
    text << log.rdbuf();
    EXPECT_THAT(text.str(), HasSubstr(signal == SIGINT ? "stride: interrupted by SIGINT at t = "
                                                       : "stride: interrupted by SIGTERM at t = "));
    std::ifstream manifest(out / "manifest.json");
    std::stringstream m;
    m << manifest.rdbuf();
    EXPECT_THAT(m.str(), HasSubstr("\"status\": \"interrupted\""));
    EXPECT_THAT(m.str(), HasSubstr("\"ended_by\": \"interrupted\""));
    // every row whole: as many fields as the header
    std::ifstream csv(out / "results.csv");
    std::string line;
    std::getline(csv, line);
    const auto fields = std::count(line.begin(), line.end(), ',');
    int rows = 0;
    while (std::getline(csv, line)) {
      EXPECT_EQ(std::count(line.begin(), line.end(), ','), fields) << line;
      ++rows;
    }
    EXPECT_GT(rows, 3);
  }
}

// the times of a results CSV, row by row
std::vector<double> result_times(const fs::path& csv) {
  std::vector<double> times;
  const auto rows = read_lines(csv);
  for (std::size_t i = 1; i < rows.size(); ++i) times.push_back(std::stod(rows[i]));
  return times;
}

// every file below `dir` with its content
std::map<std::string, std::string> folder_contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_text(e.path());
  }
  return files;
}

// SIGINT or SIGTERM, then `stride run --resume`: the run goes on from where it stopped, and its
// results are those of the run that was never stopped; a finished run is left as it is
TEST_F(cosim_fmu_test, a_run_stopped_by_a_signal_and_resumed_equals_the_uninterrupted_run) {
  const fs::path system = k_data / "stride_test_counting.xml";
  // a million steps: long enough to be stopped while stepping (the results are flushed every
  // 64 KiB, after a few per cent of the run), short enough for a sanitizer build
  const std::vector<std::string> run = {
      k_cli, "run", system.string(), "--stop-time", "10000", "--record-interval", "0.5", "--quiet"};
  const fs::path full = scratch.path() / "full";
  {
    std::string command;
    for (const auto& a : run) command += test::quoted(fs::path(a)) + " ";
    const auto r = test::run_command(command + "--output " + quoted(full), scratch.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::vector<double> full_times = result_times(full / "results.csv");
  ASSERT_EQ(full_times.size(), 20001u);  // 0, 0.5, ..., 10000
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path out = scratch.path() / ("stopped-" + std::to_string(signal));
    auto args = run;
    args.insert(args.end(), {"--output", out.string()});
    const pid_t pid = test::spawn(args, scratch.path() / "run.log");
    ASSERT_GT(pid, 0);
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!(fs::exists(out / "results.csv") && fs::file_size(out / "results.csv") > 2000) &&
           std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ::kill(pid, signal);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 128 + signal)
        << "the run was not stopped by the signal: " << read_text(scratch.path() / "run.log");

    // the manifest says when; the rows end there; the checkpoint is there
    const std::string manifest = read_text(out / "manifest.json");
    EXPECT_THAT(manifest, HasSubstr("\"status\": \"interrupted\""));
    const auto at = manifest.find("\"interrupted_at\": ");
    ASSERT_NE(at, std::string::npos) << manifest;
    const double stopped_at = std::stod(manifest.substr(at + 18));
    EXPECT_GT(stopped_at, 0.0);
    EXPECT_LT(stopped_at, 10000.0);
    EXPECT_THAT(manifest, HasSubstr("\"checkpoint\": \"checkpoint.stride\""));
    EXPECT_TRUE(fs::exists(checkpoint_file(out)));
    const std::vector<double> first_part = result_times(out / "results.csv");
    ASSERT_FALSE(first_part.empty());
    EXPECT_LE(first_part.back(), stopped_at);
    EXPECT_LT(first_part.size(), full_times.size());

    const auto r = test::run_command("'" + k_cli + "' run --resume " + quoted(out) + " --quiet",
                                     scratch.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // one series: the same rows as the run that was never stopped, times strictly increasing
    const std::vector<double> times = result_times(out / "results.csv");
    ASSERT_EQ(times.size(), full_times.size());
    for (std::size_t i = 1; i < times.size(); ++i) ASSERT_LT(times[i - 1], times[i]) << i;
    EXPECT_EQ(read_text(out / "results.csv"), read_text(full / "results.csv"));
    EXPECT_FALSE(fs::exists(out / "results-resumed.csv"));
    EXPECT_FALSE(fs::exists(checkpoint_file(out)));  // finished: nothing to resume from
    const std::string resumed = read_text(out / "manifest.json");
    EXPECT_THAT(resumed, HasSubstr("\"status\": \"ok\""));
    EXPECT_THAT(resumed, HasSubstr("\"resumed_at\": "));
    EXPECT_THAT(resumed, HasSubstr("\"end_time\": 10000,"));

    // resuming the finished run says so and changes nothing
    const auto before = folder_contents(out);
    const auto again = test::run_command("'" + k_cli + "' run --resume " + quoted(out) + " --quiet",
                                         scratch.path());
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_THAT(again.out, HasSubstr("the run has finished"));
    EXPECT_THAT(again.out, HasSubstr("nothing to resume"));
    EXPECT_EQ(folder_contents(out), before);
  }
}

// --checkpoint-every: a run killed outright (SIGKILL, no chance to save) goes on from its last
// periodic checkpoint, and the results are still those of the run that was never stopped
TEST_F(cosim_fmu_test, a_killed_run_resumes_from_its_last_periodic_checkpoint) {
  const fs::path system = k_data / "stride_test_counting.xml";
  const std::string run = "'" + k_cli + "' run " + quoted(system) +
                          " --stop-time 10000 --record-interval 0.5 --quiet --output ";
  const fs::path full = scratch.path() / "full";
  const auto r = test::run_command(run + quoted(full), scratch.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(checkpoint_file(full)));  // none without the option

  const fs::path out = scratch.path() / "killed";
  const pid_t pid =
      test::spawn({k_cli, "run", system.string(), "--stop-time", "10000", "--record-interval",
                   "0.5", "--quiet", "--checkpoint-every", "250", "--output", out.string()},
                  scratch.path() / "killed.log");
  ASSERT_GT(pid, 0);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(checkpoint_file(out)) && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status))
      << "the run ended before it was killed: " << read_text(scratch.path() / "killed.log");
  ASSERT_TRUE(fs::exists(checkpoint_file(out)));
  const auto resumed =
      test::run_command("'" + k_cli + "' run --resume " + quoted(out) + " --quiet", scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_text(out / "results.csv"), read_text(full / "results.csv"));
  EXPECT_THAT(read_text(out / "manifest.json"), HasSubstr("\"resumed_at\": "));
  EXPECT_FALSE(fs::exists(checkpoint_file(out)));  // finished: nothing to resume from

  for (const char* bad : {"0", "-5", "soon"}) {
    const auto b = test::run_command(
        run + quoted(scratch.path() / "bad") + " --checkpoint-every " + bad, scratch.path());
    EXPECT_NE(b.exit_code, 0) << bad;
    EXPECT_THAT(b.err, HasSubstr("--checkpoint-every")) << bad;
  }
}

#ifdef STRIDE_MINI_FMU
// a component that cannot save its state (canGetAndSetFMUstate false): the interrupted run says
// so and leaves no checkpoint; without ${resume} in the system nothing can be resumed, and the
// attempt changes nothing
TEST_F(cosim_fmu_test, a_run_whose_state_cannot_be_saved_leaves_no_checkpoint) {
  const fs::path system = scratch.path() / "mini.xml";
  std::ofstream(system) << "<?xml version=\"1.0\"?>\n<system name=\"mini\" version=\"1\">\n"
                           "  <simulation start=\"0\" stop=\"100000\" step=\"0.01\"/>\n"
                           "  <component name=\"m\" fmu=\"" STRIDE_MINI_FMU
                           "\"/>\n"
                           "  <record interval=\"0.5\" file=\"results.csv\"/>\n</system>\n";
  const fs::path out = scratch.path() / "mini";
  const pid_t pid =
      test::spawn({k_cli, "run", system.string(), "--quiet", "--output", out.string()},
                  scratch.path() / "run.log");
  ASSERT_GT(pid, 0);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!(fs::exists(out / "results.csv") && fs::file_size(out / "results.csv") > 2000) &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << read_text(scratch.path() / "run.log");
  EXPECT_THAT(read_text(scratch.path() / "run.log"), HasSubstr("no checkpoint to resume from"));
  EXPECT_FALSE(fs::exists(checkpoint_file(out)));
  const std::string manifest = read_text(out / "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"interrupted_at\": "));
  EXPECT_THAT(manifest, ::testing::Not(HasSubstr("\"checkpoint\"")));

  const auto before = folder_contents(out);
  const auto r =
      test::run_command("'" + k_cli + "' run --resume " + quoted(out) + " --quiet", scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("holds no checkpoint of an interrupted run"));
  EXPECT_EQ(folder_contents(out), before);

  // periodic checkpoints: the first attempt says why there are none, and the run goes on
  const auto periodic = test::run_command("'" + k_cli + "' run " + quoted(system) +
                                              " --stop-time 10 --checkpoint-every 1 --output " +
                                              quoted(scratch.path() / "periodic"),
                                          scratch.path());
  EXPECT_EQ(periodic.exit_code, 0) << periodic.err;
  const std::string warning = "no more checkpoints (--checkpoint-every): ";
  EXPECT_THAT(periodic.err, HasSubstr(warning));
  EXPECT_EQ(periodic.err.find(warning), periodic.err.rfind(warning));  // said once
  EXPECT_FALSE(fs::exists(checkpoint_file(scratch.path() / "periodic")));
}
#endif

// validate checks what run checks before its first step
TEST_F(cosim_fmu_test, validate_refuses_what_run_would_refuse_before_stepping) {
  auto r = test::run_command("'" + k_cli + "' validate " + quoted(k_data / "stride_test_pair.xml") +
                                 " --set b.stop_after_steps=-1",
                             scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(
      r.err,
      HasSubstr("--set b.stop_after_steps=-1: b.stop_after_steps = -1 is below its minimum 0"));
  const fs::path system = scratch.path() / "record.xml";
  std::ofstream(system) << "<system name='r'>\n<simulation stop='1' step='0.01'/>\n"
                           "<component name='a' fmu='stride_test'/>\n"
                           "<record><signal name='a.nothing'/></record>\n</system>\n";
  r = test::run_command("'" + k_cli + "' validate " + quoted(system), scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("record.xml:4: record signal 'a.nothing' matches no variable"));
  r = test::run_command("'" + k_cli + "' validate " + quoted(k_data / "stride_test_pair.xml"),
                        scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(cosim_fmu_test, cli_run_error_is_one_line_and_non_zero) {
  const fs::path out = scratch.path() / "cli-fail";
  const auto r =
      test::run_command("'" + k_cli + "' run " + quoted(k_data / "stride_test_pair.xml") +
                            " --output " + quoted(out) + " --set a.fail_at_step=2 --quiet",
                        scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  const auto last_line_start = r.err.rfind("stride: error: ");
  ASSERT_NE(last_line_start, std::string::npos) << r.err;
  EXPECT_THAT(r.err.substr(last_line_start),
              HasSubstr("component 'a': fmi2DoStep returned fmi2Error (step at t = 0.01 s)"));
  EXPECT_TRUE(fs::exists(out / "results.csv"));
}

TEST_F(cosim_fmu_test, cli_validate_and_inspect) {
  auto r = test::run_command("'" + k_cli + "' validate " + quoted(k_fmu), scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("OK"));
  r = test::run_command("'" + k_cli + "' validate " + quoted(k_data / "stride_test_pair.xml"),
                        scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("2 components"));
  r = test::run_command("'" + k_cli + "' inspect " + quoted(k_fmu), scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::ContainsRegex("gain +parameter +tunable +Real +2"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("y +output +continuous +Real"));
}

TEST_F(cosim_fmu_test, loop_through_feedthrough_outputs_is_found_from_model_structure) {
  system_structure s;
  s.stop = time_point(std::chrono::seconds(1));
  s.base_step = duration(10'000'000);
  s.add_component("a", "stride_test");
  s.add_component("b", "stride_test");
  s.connect("a.y", "b.u");
  s.connect("b.y", "a.u");
  build_options o;
  o.log = log.sink();
  try {
    build_system(s, o);
    FAIL();
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("a.y -> b.u => b.y -> a.u => a.y"));
  }
  s.connections[1].delayed = true;
  EXPECT_NO_THROW(build_system(s, o));
  s.connections[1].from = "b.integral";  // no feedthrough: fine
  s.connections[1].to = "a.u";
  s.connections[1].delayed = false;
  EXPECT_NO_THROW(build_system(s, o));
}

// Agents (stride/cosim/run_agents.hpp): the system run as separate runs at once, each with its
// ${agent}; a plain run has ${agent} = 1 and an empty ${shared_table}.
TEST_F(cosim_fmu_test, agents_are_separate_runs_with_their_own_number) {
  auto o = options("agents");
  o.overrides = {"a.offset=${agent}", "a.label=table=${shared_table};"};
  agents_options a;
  a.count = 3;
  a.shared_table = "T";
  int abandoned = 0;
  a.abandon = [&](const std::string&) { ++abandoned; };
  const agents_report r = run_agents(parse_system_file(k_data / "stride_test_pair.xml"), o, a);
  ASSERT_EQ(r.agents.size(), 3u);
  for (int k = 1; k <= 3; ++k) {
    const fs::path dir = o.output_dir / ("agent" + std::to_string(k));
    EXPECT_EQ(r.agents[static_cast<std::size_t>(k - 1)].output_dir, dir);
    EXPECT_EQ(last_value(dir / "results.csv", "a.y"), std::to_string(3 + k));  // 3 * 1 + k
    EXPECT_EQ(last_value(dir / "results.csv", "b.echo"), "stridetable=T;");    // b.label + a.echo
    EXPECT_THAT(read_text(dir / "manifest.json"), HasSubstr("\"status\": \"ok\""));
  }
  EXPECT_EQ(abandoned, 0);
  const std::string manifest = read_text(o.output_dir / "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"agents\": 3"));
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"ok\""));
  EXPECT_THAT(read_text(o.output_dir / "system.xml"), HasSubstr("<agents count=\"3\""));

  auto plain = options("plain");
  plain.overrides = {"a.label=${agent}|${shared_table}|"};
  const auto report = run_system(parse_system_file(k_data / "stride_test_pair.xml"), plain);
  EXPECT_EQ(last_value(report.results_file, "b.echo"), "stride1||");
}

TEST_F(cosim_fmu_test, a_failing_agent_is_lost_and_the_others_go_on) {
  auto o = options("agents");
  o.overrides = {"a.offset=${agent}000"};  // agent 2's 2000 is out of range (-1000..1000)
  agents_options a;
  a.count = 2;
  std::vector<std::pair<int, std::string>> lost;
  std::mutex m;
  a.lost = [&](int agent, const std::string& why) {
    std::lock_guard lock(m);
    lost.emplace_back(agent, why);
  };
  const agents_report r = run_agents(parse_system_file(k_data / "stride_test_pair.xml"), o, a);
  EXPECT_EQ(r.lost(), 1u);
  EXPECT_TRUE(r.errors[0].empty());
  EXPECT_THAT(r.errors[1], HasSubstr("a.offset = 2000 is above its maximum 1000"));
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].first, 2);
  EXPECT_EQ(r.agents[0].result.steps, 100);  // agent 1 ran to its stop time
  const std::string manifest = read_text(o.output_dir / "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"partial\""));
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"lost\", \"error\": "));

  // every agent failing fails the run
  auto all = options("all");
  all.overrides = {"a.offset=${agent}0000"};
  EXPECT_THROW(run_agents(parse_system_file(k_data / "stride_test_pair.xml"), all, a), error);
  EXPECT_THAT(read_text(all.output_dir / "manifest.json"), HasSubstr("\"status\": \"error\""));
}

TEST_F(cosim_fmu_test, start_values_outside_the_declared_range_are_refused_by_name) {
  auto o = options("range");
  o.overrides = {"a.gain=2e6"};
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("--set a.gain=2e6: a.gain = 2e+06 is above its maximum 1000000"));
  }
  o.overrides = {"a.offset=-1000.5"};
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("a.offset = -1000.5 is below its minimum -1000"));
  }
  o.overrides = {"a.offset=-1000"};  // the bound itself is inside
  EXPECT_NO_THROW(run_system(parse_system_file(k_data / "stride_test_pair.xml"), o));
}

TEST_F(cosim_fmu_test, an_earlier_run_is_not_overwritten) {
  auto o = options("twice");
  run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
  const std::string first = read_text(o.output_dir / "manifest.json");
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), o);
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("holds an earlier run (its system.xml)"));
  }
  EXPECT_EQ(read_text(o.output_dir / "manifest.json"), first);
  agents_options a;
  a.count = 2;
  EXPECT_THROW(run_agents(parse_system_file(k_data / "stride_test_pair.xml"), o, a),
               validation_error);
  EXPECT_FALSE(fs::exists(o.output_dir / "agent1"));
  // nor is anything else: a folder is written into only when it is empty, or when forced
  auto other = options("other");
  fs::create_directories(other.output_dir);
  std::ofstream(other.output_dir / "notes.txt") << "mine\n";
  try {
    run_system(parse_system_file(k_data / "stride_test_pair.xml"), other);
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(" is not empty (it holds notes.txt)"));
  }
  EXPECT_THROW(run_agents(parse_system_file(k_data / "stride_test_pair.xml"), other, a),
               validation_error);
  EXPECT_FALSE(fs::exists(other.output_dir / "system.xml"));
  other.force_output = true;
  EXPECT_NO_THROW(run_system(parse_system_file(k_data / "stride_test_pair.xml"), other));
  EXPECT_EQ(read_text(other.output_dir / "notes.txt"), "mine\n");
  auto empty = options("empty");
  fs::create_directories(empty.output_dir);
  EXPECT_NO_THROW(run_system(parse_system_file(k_data / "stride_test_pair.xml"), empty));
}

TEST_F(cosim_fmu_test, a_system_with_agents_is_not_run_as_one) {
  system_structure s = parse_system_file(k_data / "stride_test_pair.xml");
  s.agents.count = 2;
  try {
    run_system(s, options("one"));
    ADD_FAILURE() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("has <agents>: run it with run_agents"));
  }
  auto o = options("resume");
  o.resume_dir = scratch.path() / "no-such-run";
  agents_options a;
  a.count = 2;
  EXPECT_THROW(run_agents(s, o, a), validation_error);
}

}  // namespace
}  // namespace stride::cosim
