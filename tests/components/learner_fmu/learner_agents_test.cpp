// Several learners sharing V (docs/swarm.md) in the real closed loop (demo system: gait.fmu +
// robot.fmu + learner.fmu), agents on threads of this process, the shared table over Cyclone
// DDS on loopback: one synchronous agent learns exactly as an unshared learner; synchronous
// runs are deterministic, and resumed after SIGKILL equal to uninterrupted ones; asynchronous
// runs merge every update.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "../../orchestrator/process.hpp"
#include "stride/cosim/run.hpp"
#include "stride/cosim/run_agents.hpp"
#include "stride/remote/shared_table.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;

const fs::path k_demo = fs::path(STRIDE_SOURCE_DIR) / "models" / "experiments" / "demo.xml";
constexpr int k_domain = 81;  // the other DDS tests use other domains

std::string read_all(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  EXPECT_TRUE(in.good()) << f;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

run_options quiet_options(const fs::path& out, int total_steps) {
  run_options o;
  o.output_dir = out;
  o.progress = false;
  o.build.log = stderr_log_sink(log_level::warning);
  o.overrides = {"learner.total_steps=" + std::to_string(total_steps),
                 "learner.steps_per_episode=4", "learner.footsteps_per_step=2",
                 "learner.snapshot_steps=5,12"};
  return o;
}

struct agents_run {
  agents_report report;
  remote::table_snapshot table;
};

agents_run run_with_agents(const fs::path& out, int agents, bool synchronous, int total_steps) {
  remote::table_endpoint where;
  where.domain = k_domain;
  where.table = remote::unique_table_name("learner-test");
  where.agents = agents;
  where.synchronous = synchronous;
  remote::table_service service(where);
  system_structure system = parse_system_file(k_demo);
  system.agents.synchronous = synchronous;
  agents_options a;
  a.count = agents;
  a.shared_table = where.str();
  a.abandon = [&service](const std::string& why) { service.abandon(why); };
  agents_run r;
  r.report = run_agents(system, quiet_options(out, total_steps), a);
  r.table = service.current();
  return r;
}

TEST(learner_agents, one_synchronous_agent_learns_exactly_as_an_unshared_learner) {
  temp_dir scratch("stride-agents-");
  run_system(parse_system_file(k_demo), quiet_options(scratch.path() / "alone", 12));
  const agents_run shared = run_with_agents(scratch.path() / "shared", 1, true, 12);
  EXPECT_EQ(shared.table.updates, 12);
  EXPECT_TRUE(shared.table.final);
  for (const char* file : {"v_table.csv", "v_snapshot_5.csv", "v_snapshot_12.csv", "steps.csv",
                           "episodes.csv", "paths.csv", "best.txt", "results.csv"}) {
    EXPECT_EQ(read_all(scratch.path() / "shared" / "agent1" / file),
              read_all(scratch.path() / "alone" / file))
        << file;
  }
  // an agent's checkpoint also holds its part of the shared table (docs/swarm.md, "Resume")
  EXPECT_TRUE(fs::exists(scratch.path() / "shared" / "agent1" / "checkpoint.bin"));
}

TEST(learner_agents, synchronous_rounds_are_deterministic_and_agents_explore_apart) {
  temp_dir scratch("stride-agents-");
  const agents_run a = run_with_agents(scratch.path() / "a", 2, true, 12);
  const agents_run b = run_with_agents(scratch.path() / "b", 2, true, 12);
  EXPECT_EQ(a.table.updates, 12);  // 6 rounds of 2 agents
  EXPECT_EQ(a.table.values, b.table.values);
  for (const char* file : {"agent1/v_table.csv", "agent1/v_snapshot_5.csv", "agent1/steps.csv",
                           "agent2/steps.csv", "agent2/episodes.csv"}) {
    EXPECT_EQ(read_all(scratch.path() / "a" / file), read_all(scratch.path() / "b" / file)) << file;
  }
  // agent 2 has a seed stream of its own: it starts elsewhere than agent 1
  EXPECT_NE(read_all(scratch.path() / "a/agent1/steps.csv"),
            read_all(scratch.path() / "a/agent2/steps.csv"));
  // agent 1 writes the shared V; the other agents only their own logs
  EXPECT_FALSE(fs::exists(scratch.path() / "a/agent2/v_table.csv"));
  const std::string manifest = read_all(scratch.path() / "a" / "manifest.json");
  EXPECT_THAT(manifest, ::testing::HasSubstr("\"agents\": 2"));
  EXPECT_THAT(manifest, ::testing::HasSubstr("\"status\": \"ok\""));
}

TEST(learner_agents, asynchronous_agents_merge_every_update_into_the_final_table) {
  temp_dir scratch("stride-agents-");
  const agents_run a = run_with_agents(scratch.path() / "a", 2, false, 12);
  EXPECT_EQ(a.table.updates, 12);
  EXPECT_TRUE(a.table.final);
  // agent 1 wrote the final table: 455 states + header
  const std::string v = read_all(scratch.path() / "a/agent1/v_table.csv");
  EXPECT_EQ(std::count(v.begin(), v.end(), '\n'), 456);
}

// the CLI: --agents runs the demo's agents; a run of agents cannot be resumed yet
TEST(learner_agents, stride_run_with_agents_on_the_command_line) {
  temp_dir scratch("stride-agents-");
  const fs::path out = scratch.path() / "run";
  const auto r = test::run_command(
      std::string(STRIDE_CLI) + " run " + test::quoted(k_demo) + " --agents 2 --no-plots" +
          " --set learner.total_steps=8 --set learner.steps_per_episode=4" +
          " --set learner.footsteps_per_step=2 -o " + test::quoted(out),
      scratch.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, ::testing::HasSubstr("2 of 2 agents finished"));
  EXPECT_THAT(r.out, ::testing::HasSubstr("the shared table merged 8 updates"));
  EXPECT_TRUE(fs::exists(out / "agent1" / "v_table.csv"));
  EXPECT_TRUE(fs::exists(out / "agent2" / "steps.csv"));
  // the service's table: one line per state
  const std::string table = read_all(out / "shared_table.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 456);
}

// `${agent}` and `${shared_table}` are substituted by validate as by a run of one
TEST(learner_agents, validate_takes_an_experiment_with_agent_placeholders) {
  temp_dir scratch("stride-agents-");
  const auto r = test::run_command(
      std::string(STRIDE_CLI) + " validate " + test::quoted(k_demo) + " --quiet", scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// SIGKILL in the middle of a synchronous run of 2 agents, wherever it then is; `stride run
// --resume` continues every agent from its last checkpoint and the table from its journal: the
// result is byte for byte the uninterrupted run's
TEST(learner_agents, a_synchronous_run_killed_and_resumed_equals_the_uninterrupted_one) {
  temp_dir scratch("stride-agents-");
  const std::vector<std::string> args = {STRIDE_CLI,
                                         "run",
                                         k_demo.string(),
                                         "--agents",
                                         "2",
                                         "--no-plots",
                                         "--quiet",
                                         "--set",
                                         "learner.total_steps=400",
                                         "--set",
                                         "learner.steps_per_episode=4",
                                         "--set",
                                         "learner.footsteps_per_step=2",
                                         "--set",
                                         "learner.snapshot_steps=10,200",
                                         "--output"};
  const auto with_output = [&](const fs::path& out) {
    std::vector<std::string> a = args;
    a.push_back(out.string());
    return a;
  };
  const fs::path whole = scratch.path() / "whole", cut = scratch.path() / "cut";
  const pid_t w = test::spawn(with_output(whole), scratch.path() / "whole.log");
  int status = 0;
  ASSERT_EQ(::waitpid(w, &status, 0), w);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << read_all(scratch.path() / "whole.log");

  const pid_t c = test::spawn(with_output(cut), scratch.path() / "cut.log");
  // both agents have a checkpoint: kill soon after
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!(fs::exists(cut / "agent1" / "checkpoint.bin") &&
           fs::exists(cut / "agent2" / "checkpoint.bin")) &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ::kill(c, SIGKILL);
  ASSERT_EQ(::waitpid(c, &status, 0), c);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed: make it longer";

  const auto resumed = test::run_command(
      std::string(STRIDE_CLI) + " run --resume " + test::quoted(cut) + " --no-plots",
      scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.out, ::testing::HasSubstr("2 agents (synchronous rounds), resuming"));
  for (const char* file :
       {"agent1/v_table.csv", "agent1/v_snapshot_10.csv", "agent1/v_snapshot_200.csv",
        "agent1/best.txt", "agent1/steps.csv", "agent1/episodes.csv", "agent1/paths.csv",
        "agent2/steps.csv", "agent2/episodes.csv", "agent2/paths.csv", "shared_table.csv"}) {
    EXPECT_EQ(read_all(cut / file), read_all(whole / file)) << file;
  }
}

TEST(learner_agents, resuming_needs_the_journal_and_the_same_agents) {
  temp_dir scratch("stride-agents-");
  const fs::path out = scratch.path() / "run";
  const std::string run = std::string(STRIDE_CLI) + " run " + test::quoted(k_demo) +
                          " --agents 2 --no-plots --quiet --set learner.total_steps=8" +
                          " --set learner.footsteps_per_step=2 -o " + test::quoted(out);
  ASSERT_EQ(test::run_command(run, scratch.path()).exit_code, 0);
  const auto other = test::run_command(
      std::string(STRIDE_CLI) + " run --resume " + test::quoted(out) + " --agents 3",
      scratch.path());
  EXPECT_NE(other.exit_code, 0);
  EXPECT_THAT(other.err, ::testing::HasSubstr("--agents 3: the run in"));
  // as a run killed before its end leaves it (no manifest: a finished run is not resumed)
  fs::remove(out / "manifest.json");
  fs::remove(out / "shared_table.journal");
  const auto no_journal = test::run_command(
      std::string(STRIDE_CLI) + " run --resume " + test::quoted(out), scratch.path());
  EXPECT_NE(no_journal.exit_code, 0);
  EXPECT_THAT(no_journal.err, ::testing::HasSubstr("shared_table.journal is missing"));
  // periodic checkpoints of the whole system are not how agents are resumed
  const auto periodic = test::run_command(run + "-periodic --checkpoint-every 10", scratch.path());
  EXPECT_NE(periodic.exit_code, 0);
  EXPECT_THAT(periodic.err, ::testing::HasSubstr("--checkpoint-every: a run of agents is resumed "
                                                 "from its shared table's journal"));
}

}  // namespace
}  // namespace stride::cosim
