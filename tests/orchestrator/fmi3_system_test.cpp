// A system of FMI 2.0 and FMI 3.0 FMUs run by the orchestrator (data/fmi3_mixed.xml): the
// connected values flow both ways, with the test FMUs' relations as the oracle.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "../remote/worker_process.hpp"
#include "fmi3_fixture.hpp"
#include "process.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/run.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;

#ifdef STRIDE_HAVE_TEST_FMU

// The last row of a results CSV by column name (no quoted commas in this system's values).
std::map<std::string, std::string> last_row(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (const char c : line) {
      if (c == ',') {
        cells.push_back(cell);
        cell.clear();
      } else if (c != '"') {
        cell += c;
      }
    }
    cells.push_back(cell);
    return cells;
  };
  const auto header = split(lines.front());
  const auto last = split(lines.back());
  std::map<std::string, std::string> row;
  for (std::size_t i = 0; i < header.size() && i < last.size(); ++i) row[header[i]] = last[i];
  return row;
}

class fmi3_system_test : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-fmi3-system-test-"};

  run_options options() {
    run_options o;
    o.output_dir = scratch.path() / "out";
    o.progress = false;
    o.build.log = [](log_level, std::string_view, std::string_view, std::string_view) {};
    o.build.import.extract_root = scratch.path() / "extract";
    fs::create_directories(o.build.import.extract_root);
    o.build.fmu_search_path = {STRIDE_FMU_DIR, test::k_fmi3_kinds.parent_path()};
    return o;
  }
};

TEST_F(fmi3_system_test, values_flow_between_fmi2_and_fmi3_components) {
  const auto report =
      run_system(parse_system_file(fs::path(STRIDE_TEST_DATA_DIR) / "fmi3_mixed.xml"), options());
  EXPECT_EQ(report.result.steps, 10);
  auto row = last_row(report.results_file);
  // 2.0 -> 3.0: a.y = 3 * 1 is a Float64 input, k.f64_out = gain 10 * 3 + steps
  EXPECT_EQ(row.at("k.steps"), "10");
  EXPECT_EQ(std::stod(row.at("k.f64_out")), 10 * 3 + 10);
  // Integer -> Int64 (Gauss-Seidel: k reads a's counter after a's step)
  EXPECT_EQ(std::stoi(row.at("k.i64_out")), std::stoi(row.at("a.counter")) + 1);
  EXPECT_EQ(row.at("k.b_out"), "0");         // !a.active, a.enable defaults to true
  EXPECT_EQ(row.at("k.s_out"), "stride!");   // a.echo = label "stride" + suffix ""
  EXPECT_EQ(row.at("k.bin_out"), "10ff00");  // the parameter's bytes reversed
  EXPECT_EQ(row.at("k.i8_aout[2]"), "9");    // parameter 7 + 2
  // 2.0 array elements into a 3.0 Float32 array: a.vec_out = 2 * (1, 2, 3), plus (1, 2, 3)
  EXPECT_EQ(std::stod(row.at("k.f32_aout[1]")), 2 + 1);
  EXPECT_EQ(std::stod(row.at("k.f32_aout[3]")), 6 + 3);
  // 3.0 -> 2.0: b.enable = k.b_out, b.echo = label + k.s_out, b.vec_out = 2 * k.f64_aout
  EXPECT_EQ(row.at("b.active"), "0");
  EXPECT_EQ(row.at("b.echo"), "stridestride!");
  EXPECT_EQ(std::stod(row.at("b.vec_out[2]")), 2 * (20 + 2));
  // UInt16 -> Integer: k.u16_out = 2 + 1 each step, and b counts 1 + n per step
  EXPECT_EQ(row.at("k.u16_out"), "3");
  EXPECT_EQ(row.at("b.counter"), std::to_string(10 * (1 + 3)));
}

// A checkpoint of the whole mixed system (the 3.0 component through fmi3GetFMUState and its
// serialization) continues exactly as the run that was never restored.
TEST_F(fmi3_system_test, a_checkpoint_of_the_mixed_system_resumes_identically) {
  auto built = build_system(parse_system_file(fs::path(STRIDE_TEST_DATA_DIR) / "fmi3_mixed.xml"),
                            options().build);
  auto& ex = *built.execution;
  const auto var = [&](const std::string& comp, const std::string& name) {
    const std::size_t c = *ex.find_component(comp);
    return ex.observe({c, *ex.component_at(c).model_description().index_of(name)});
  };
  const auto f64_out = var("k", "f64_out");
  const auto i64_out = var("k", "i64_out");
  const auto b_counter = var("b", "counter");
  const auto b_vec = var("b", "vec_out[3]");
  const auto s_out = var("k", "s_out");
  ex.initialize(built.stop);
  const auto values = [&] {
    return std::tuple(ex.real_value(f64_out), ex.integer_value(i64_out),
                      ex.integer_value(b_counter), ex.real_value(b_vec), ex.string_value(s_out));
  };
  for (int i = 0; i < 3; ++i) ex.step();
  const auto checkpoint = ex.save_state_bytes();
  std::vector<decltype(values())> first;
  for (int i = 0; i < 4; ++i) {
    ex.step();
    first.push_back(values());
  }
  ex.restore_state_bytes(checkpoint);
  for (int i = 0; i < 4; ++i) {
    ex.step();
    EXPECT_EQ(values(), first[i]) << i;
  }
  EXPECT_EQ(std::get<0>(first.back()), 10 * 3 + 7);  // gain * a.y + the 3.0 FMU's own steps
}

// The same system with the FMI 3.0 component on a `stride worker` (DDS domain 120): the archive
// is shipped to the worker and the results are those of the run in one process.
TEST_F(fmi3_system_test, the_fmi3_component_on_a_worker_gives_the_same_csv) {
  const std::string cli = STRIDE_CLI;
  const std::string env = "STRIDE_FMU_PATH=" + test::quoted(test::k_fmi3_kinds.parent_path()) + " ";
  const fs::path local_system = fs::path(STRIDE_TEST_DATA_DIR) / "fmi3_mixed.xml";
  const fs::path remote_system = scratch.path() / "remote.xml";
  std::ofstream(remote_system) << test::replaced(test::read_whole(local_system),
                                                 "<component name=\"k\" fmu=\"fmi3_kinds\"",
                                                 "<component name=\"k\" fmu=\"fmi3_kinds\" "
                                                 "worker=\"w1\"");
  const auto run = [&](const fs::path& system, const std::string& out, const std::string& args) {
    return test::run_command(env + "'" + cli + "' run " + test::quoted(system) +
                                 " --quiet --output " + test::quoted(scratch.path() / out) + " " +
                                 args,
                             scratch.path());
  };
  const auto local = run(local_system, "local", "");
  ASSERT_EQ(local.exit_code, 0) << local.err;
  remote::test::worker_process worker(cli, "w1", 120, scratch.path() / "w1.log");
  ASSERT_TRUE(worker.ready()) << worker.output();
  const auto remote = run(remote_system, "remote", "--domain 120");
  ASSERT_EQ(remote.exit_code, 0) << remote.err << worker.output();
  const std::string csv = test::read_whole(scratch.path() / "local" / "results.csv");
  EXPECT_NE(csv.find("k.f32_aout[3]"), std::string::npos);
  EXPECT_EQ(test::read_whole(scratch.path() / "remote" / "results.csv"), csv);
  EXPECT_EQ(last_row(scratch.path() / "remote" / "results.csv").at("b.echo"), "stridestride!");
}

#endif

}  // namespace
}  // namespace stride::cosim
