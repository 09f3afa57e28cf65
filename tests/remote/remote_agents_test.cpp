// Agents on `stride worker` processes (docs/swarm.md): real workers on loopback, real
// `stride run --agents`, the demo's closed loop with a shared V. Synchronous agents on workers
// learn exactly what agents on threads learn; a worker killed in the middle of the run loses
// its agent, and the others finish, or with a standby worker the agent goes on there and the
// table is the same. Sweep points on workers too.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "../orchestrator/process.hpp"
#include "stride/cosim/archive.hpp"
#include "worker_process.hpp"

namespace stride::remote::test {
namespace {

namespace fs = std::filesystem;
using cosim::test::quoted;
using cosim::test::run_command;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;

const std::string k_cli = STRIDE_CLI;
const fs::path k_demo = fs::path(STRIDE_SOURCE_DIR) / "models" / "experiments" / "demo.xml";

std::string read(const fs::path& file) {
  return cosim::test::read_file(file);
}

class remote_agents : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-remote-agents-"};

  // the demo with <agents>, `attrs` added to it
  fs::path demo_with_agents(const std::string& attrs) {
    std::string xml = read(k_demo);
    // <agents> follows <simulation>
    const auto simulation = xml.find("<simulation ");
    EXPECT_NE(simulation, std::string::npos);
    const auto at = xml.find("/>", simulation) + 2;
    xml.insert(at, "\n  <agents " + attrs + "/>");
    const fs::path f = scratch.path() / "agents.xml";
    std::ofstream(f, std::ios::binary) << xml;
    return f;
  }
  cosim::test::process_result run(const fs::path& system, const std::string& out,
                                  const std::string& args) {
    return run_command("'" + k_cli + "' run " + quoted(system) + " --no-plots --output " +
                           quoted(scratch.path() / out) +
                           " --set learner.steps_per_episode=4"
                           " --set learner.footsteps_per_step=2 " +
                           args,
                       scratch.path());
  }
  std::string file(const std::string& out, const std::string& name) {
    return read(scratch.path() / out / name);
  }
  worker_process start_worker(const std::string& name, int domain) {
    return worker_process(k_cli, name, domain, scratch.path() / (name + ".log"));
  }
};

TEST_F(remote_agents, synchronous_agents_on_workers_learn_what_agents_on_threads_learn) {
  auto w1 = start_worker("w1", 82);
  auto w2 = start_worker("w2", 82);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  const auto threads = run(k_demo, "threads", "--agents 2 --set learner.total_steps=12");
  ASSERT_EQ(threads.exit_code, 0) << threads.err;
  const auto workers = run(demo_with_agents("count=\"2\" workers=\"w1 w2\""), "workers",
                           "--domain 82 --set learner.total_steps=12");
  ASSERT_EQ(workers.exit_code, 0) << workers.err;
  for (const char* f : {"agent1/v_table.csv", "agent1/steps.csv", "agent2/steps.csv",
                        "agent2/results.csv", "shared_table.csv"}) {
    EXPECT_EQ(file("workers", f), file("threads", f)) << f;
  }
  EXPECT_THAT(file("workers", "manifest.json"), HasSubstr("\"where\": \"worker w2\""));
  EXPECT_THAT(w1.output(), HasSubstr("loaded learner"));
  EXPECT_THAT(w2.output(), HasSubstr("loaded learner"));
}

TEST_F(remote_agents, a_killed_worker_loses_its_agent_and_the_others_finish) {
  auto w1 = start_worker("w1", 83);
  auto w2 = start_worker("w2", 83);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  const fs::path system = demo_with_agents("count=\"2\" workers=\"w1 w2\"");
  std::thread killer([&] {
    // kill w2 once agent 2 has learned a few steps: in the middle of the run
    const fs::path steps = scratch.path() / "run" / "agent2" / "steps.csv";
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < until) {
      const std::string text = read(steps);
      if (std::count(text.begin(), text.end(), '\n') > 3) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    w2.stop(SIGKILL);
  });
  const auto r = run(system, "run", "--domain 83 --set learner.total_steps=60");
  killer.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("agent 2 is lost"));
  EXPECT_THAT(r.out, HasSubstr("1 of 2 agents finished"));
  const std::string manifest = file("run", "manifest.json");
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"partial\""));
  EXPECT_THAT(manifest, HasSubstr("\"status\": \"lost\""));
  // agent 1 walked its whole share and wrote the final table; no value was corrupted
  const std::string steps = file("run", "agent1/steps.csv");
  EXPECT_EQ(std::count(steps.begin(), steps.end(), '\n'), 31);
  std::istringstream table(file("run", "shared_table.csv"));
  std::string line;
  std::getline(table, line);
  int rows = 0;
  while (std::getline(table, line)) {
    const double v = std::stod(line.substr(line.find(',') + 1));
    EXPECT_TRUE(std::isfinite(v)) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 455);
  EXPECT_EQ(read(scratch.path() / "run/agent1/v_table.csv").empty(), false);
}

// The same kill with a standby worker (docs/failover.md): agent 2's loop goes on on s1 from its
// last state image, re-walks the rounds since then against the tables merged then, and the run
// learns exactly what the undisturbed one learns.
TEST_F(remote_agents, a_killed_agents_worker_fails_over_and_the_shared_table_is_unchanged) {
  const std::string steps = "--set learner.total_steps=40";
  const auto undisturbed = run(k_demo, "threads", "--agents 2 " + steps);
  ASSERT_EQ(undisturbed.exit_code, 0) << undisturbed.err;
  auto w1 = start_worker("w1", 170);
  auto w2 = start_worker("w2", 170);
  auto s1 = start_worker("s1", 170);
  ASSERT_TRUE(w1.ready() && w2.ready() && s1.ready()) << w1.output() << w2.output();
  std::thread killer([&] {
    // in the middle of agent 2's share (20 steps), between two of its state images
    const fs::path log = scratch.path() / "run" / "agent2" / "steps.csv";
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < until) {
      const std::string text = read(log);
      if (std::count(text.begin(), text.end(), '\n') > 8) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    w2.stop(SIGKILL);
  });
  const auto r = run(demo_with_agents("count=\"2\" workers=\"w1 w2\""), "run",
                     "--domain 170 --standby s1 --snapshot-every 250 " + steps);
  killer.join();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("worker 'w2' is lost after t = "));
  EXPECT_THAT(r.out, HasSubstr("2 of 2 agents finished"));
  // the rounds walked again were counted once
  const auto merged = [](const std::string& out) {
    const auto at = out.find("merged ");
    return out.substr(at, out.find('\n', at) - at);
  };
  EXPECT_EQ(merged(r.out), merged(undisturbed.out));
  for (const char* f : {"shared_table.csv", "agent1/v_table.csv", "agent1/steps.csv",
                        "agent2/steps.csv", "agent2/episodes.csv", "agent2/results.csv"}) {
    EXPECT_EQ(file("run", f), file("threads", f)) << f;
  }
  EXPECT_THAT(file("run", "agent2/manifest.json"), ContainsRegex("\"failovers\": 1[,}]"));
  EXPECT_THAT(s1.output(), HasSubstr("loaded learner"));
}

// `stride sweep --workers`: the points run in turn on the workers, with the files of points
// run in process
TEST_F(remote_agents, sweep_points_on_workers_equal_points_in_process) {
  auto w1 = start_worker("w1", 84);
  auto w2 = start_worker("w2", 84);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  const fs::path pair =
      fs::path(STRIDE_SOURCE_DIR) / "tests/orchestrator/data/stride_test_pair.xml";
  const auto sweep = [&](const std::string& out, const std::string& args) {
    return run_command("'" + k_cli + "' sweep " + quoted(pair) +
                           " --grid a.gain=1:4:1 --jobs 2 --quiet -o " +
                           quoted(scratch.path() / out) + " " + args,
                       scratch.path());
  };
  const auto local = sweep("local", "");
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const auto remote = sweep("remote", "--workers w1,w2 --domain 84");
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_EQ(file("remote", "sweep.csv"), file("local", "sweep.csv"));
  for (const char* point : {"1", "2", "3", "4"}) {
    const std::string results = std::string("points/") + point + "/results.csv";
    EXPECT_GT(file("local", results).size(), 1000u);
    EXPECT_EQ(file("remote", results), file("local", results)) << point;
  }
  // each worker ran two of the four points
  const auto runs = [](const std::string& log) {
    std::size_t n = 0;
    for (auto at = log.find(" begins"); at != std::string::npos; at = log.find(" begins", at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(runs(w1.output()), 2u);
  EXPECT_EQ(runs(w2.output()), 2u);
}

}  // namespace
}  // namespace stride::remote::test
