// Failover end to end: the walk with the robot on a real `stride worker` that is killed (SIGKILL)
// while the run goes on; standby workers take over and the results equal the in-process walk byte
// for byte. Each test has its own DDS domain.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <regex>
#include <string>
#include <thread>

#include "../orchestrator/fake_fmu.hpp"
#include "../orchestrator/process.hpp"
#include "stride/cosim/archive.hpp"
#include "worker_process.hpp"

namespace stride::remote::test {
namespace {

namespace fs = std::filesystem;
using cosim::test::quoted;
using cosim::test::read_file;
using cosim::test::run_command;
using ::testing::AllOf;
using ::testing::ContainsRegex;
using ::testing::HasSubstr;

const std::string k_cli = STRIDE_CLI;
const fs::path k_source = STRIDE_SOURCE_DIR;
const fs::path k_walk_on_worker = k_source / "models/distributed/walk-robot-on-worker.xml";
const fs::path k_walk_on_one_worker = k_source / "models/distributed/walk-on-one-worker.xml";

class failover_run : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-failover-"};

  worker_process start_worker(const std::string& name, int domain) {
    return worker_process(k_cli, name, domain, scratch.path() / (name + ".log"));
  }
  std::string in_process_walk() {
    const auto local = run_command("'" + k_cli + "' run " + quoted(k_source / "models/walk.xml") +
                                       " --quiet --output " + quoted(scratch.path() / "local"),
                                   scratch.path());
    EXPECT_EQ(local.exit_code, 0) << local.err;
    return read_file(scratch.path() / "local/results.csv");
  }
  pid_t start_run(int domain, const std::vector<std::string>& extra,
                  const fs::path& system = k_walk_on_worker) {
    std::vector<std::string> args{k_cli,
                                  "run",
                                  system.string(),
                                  "--domain",
                                  std::to_string(domain),
                                  "--output",
                                  (scratch.path() / "remote").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return cosim::test::spawn(args, scratch.path() / "remote.log");
  }
  // waits until the run's results hold `bytes`; false when the run ended first
  bool wait_for_results(std::uintmax_t bytes, pid_t run) {
    const fs::path csv = scratch.path() / "remote/results.csv";
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < until) {
      std::error_code ec;
      if (fs::file_size(csv, ec) >= bytes && !ec) return true;
      if (::waitpid(run, nullptr, WNOHANG) == run) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }
  int wait_exit(pid_t run) {
    int status = 0;
    ::waitpid(run, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  std::string run_log() { return read_file(scratch.path() / "remote.log"); }
};

// a point in the results at a random fraction within [low, high] of `size` (the seed is shown)
std::uintmax_t random_point(std::size_t size, double low, double high, unsigned seed) {
  std::mt19937 rng(seed);
  return static_cast<std::uintmax_t>(static_cast<double>(size) *
                                     std::uniform_real_distribution<double>(low, high)(rng));
}

TEST_F(failover_run, a_worker_killed_mid_walk_is_replaced_and_the_csv_is_unchanged) {
  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("kill point seed " + std::to_string(seed));
  const std::string local = in_process_walk();
  ASSERT_GT(local.size(), 100000u);
  auto w1 = start_worker("w1", 150);
  auto s1 = start_worker("s1", 150);
  ASSERT_TRUE(w1.ready() && s1.ready()) << w1.output() << s1.output();
  const pid_t run = start_run(150, {"--quiet", "--standby", "s1"});
  ASSERT_GT(run, 0);
  ASSERT_TRUE(wait_for_results(random_point(local.size(), 0.1, 0.6, seed), run)) << run_log();
  EXPECT_EQ(w1.stop(SIGKILL), 128 + SIGKILL);
  ASSERT_EQ(wait_exit(run), 0) << run_log();
  EXPECT_THAT(run_log(), AllOf(HasSubstr("worker 'w1' is lost after t = "),
                               HasSubstr("continues on standby worker 's1'")));
  EXPECT_EQ(read_file(scratch.path() / "remote/results.csv"), local);  // byte for byte
  EXPECT_THAT(read_file(scratch.path() / "remote/manifest.json"),
              AllOf(HasSubstr("\"status\": \"ok\""), ContainsRegex("\"failovers\": 1[,}]")));
  EXPECT_THAT(s1.output(), HasSubstr("loaded robot"));
}

// gait and robot on one worker step there as one group, also with a standby: the group moves
// to the standby as a whole, its members each replaying what they stepped with
TEST_F(failover_run, a_step_group_whose_worker_is_killed_moves_to_the_standby_as_a_group) {
  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("kill point seed " + std::to_string(seed));
  const std::string local = in_process_walk();
  auto w1 = start_worker("w1", 175);
  auto s1 = start_worker("s1", 175);
  ASSERT_TRUE(w1.ready() && s1.ready()) << w1.output() << s1.output();
  const pid_t run = start_run(175, {"--quiet", "--standby", "s1"}, k_walk_on_one_worker);
  ASSERT_GT(run, 0);
  const std::uintmax_t kill_point = random_point(local.size(), 0.1, 0.6, seed);
  ASSERT_TRUE(wait_for_results(kill_point, run)) << run_log();
  EXPECT_EQ(w1.stop(SIGKILL), 128 + SIGKILL);
  ASSERT_EQ(wait_exit(run), 0) << run_log();
  for (const std::string member : {"gait", "robot"}) {
    EXPECT_THAT(run_log(),
                ContainsRegex("\\[" + member +
                              "\\] warning \\(failover\\): worker 'w1' is lost after t = "
                              "[0-9.]+ s: continues on standby worker 's1'"));
  }
  EXPECT_EQ(read_file(scratch.path() / "remote/results.csv"), local);
  EXPECT_THAT(read_file(scratch.path() / "remote/manifest.json"),
              ContainsRegex("\"failovers\": 1[,}]"));
  // one request per macro step on the standby, not one per member: at most the steps left after
  // the kill, the replays (up to 100 steps each) and the images, where two members stepping
  // apart would need twice the steps left
  ASSERT_TRUE(s1.wait_for(" requests)")) << s1.output();
  const std::string out = s1.output();
  std::smatch count;
  ASSERT_TRUE(std::regex_search(out, count, std::regex("; ([0-9]+) requests\\)"))) << out;
  const long requests = std::stol(count[1].str());
  const double steps_left =
      7500.0 * (1.0 - static_cast<double>(kill_point) / static_cast<double>(local.size()));
  EXPECT_LT(requests, 1.3 * steps_left + 300) << out;
}

TEST_F(failover_run, two_kills_in_a_row_with_two_standbys_leave_the_csv_unchanged) {
  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("kill point seed " + std::to_string(seed));
  const std::string local = in_process_walk();
  auto w1 = start_worker("w1", 151);
  auto s1 = start_worker("s1", 151);
  auto s2 = start_worker("s2", 151);
  ASSERT_TRUE(w1.ready() && s1.ready() && s2.ready());
  // the standbys as the system file names them
  std::string xml = read_file(k_walk_on_worker);
  const std::string sim = "<simulation ";
  xml.insert(xml.find("\n", xml.find(sim)) + 1, "  <failover standby=\"s1 s2\"/>\n");
  const fs::path system = scratch.path() / "walk-failover.xml";
  std::ofstream(system) << xml;
  std::vector<std::string> args{
      k_cli, "run",     system.string(), "--domain",
      "151", "--quiet", "--output",      (scratch.path() / "remote").string()};
  const pid_t run = cosim::test::spawn(args, scratch.path() / "remote.log");
  ASSERT_GT(run, 0);
  ASSERT_TRUE(wait_for_results(random_point(local.size(), 0.05, 0.3, seed), run)) << run_log();
  EXPECT_EQ(w1.stop(SIGKILL), 128 + SIGKILL);
  // the second kill once the first standby has taken over and stepped on
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (run_log().find("continues on standby worker 's1'") == std::string::npos &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(wait_for_results(random_point(local.size(), 0.4, 0.6, seed + 1), run)) << run_log();
  EXPECT_EQ(s1.stop(SIGKILL), 128 + SIGKILL);
  ASSERT_EQ(wait_exit(run), 0) << run_log();
  EXPECT_THAT(run_log(), AllOf(HasSubstr("worker 'w1' is lost"), HasSubstr("worker 's1' is lost"),
                               HasSubstr("continues on standby worker 's2'")));
  EXPECT_EQ(read_file(scratch.path() / "remote/results.csv"), local);
  EXPECT_THAT(read_file(scratch.path() / "remote/manifest.json"),
              ContainsRegex("\"failovers\": 2[,}]"));
  // the system as run keeps its standbys
  EXPECT_THAT(read_file(scratch.path() / "remote/system.xml"), HasSubstr("standby=\"s1 s2\""));
}

TEST_F(failover_run, with_no_standby_left_the_run_stops_with_the_results_so_far) {
  const std::string local = in_process_walk();
  auto w1 = start_worker("w1", 152);
  auto s1 = start_worker("s1", 152);
  ASSERT_TRUE(w1.ready() && s1.ready());
  const pid_t run = start_run(
      152, {"--quiet", "--standby", "s1", "--snapshot-every", "50", "--worker-timeout", "2"});
  ASSERT_TRUE(wait_for_results(local.size() / 5, run)) << run_log();
  EXPECT_EQ(w1.stop(SIGKILL), 128 + SIGKILL);
  EXPECT_EQ(s1.stop(SIGKILL), 128 + SIGKILL);
  EXPECT_EQ(wait_exit(run), 1);
  EXPECT_THAT(run_log(),
              AllOf(HasSubstr("worker 'w1' is gone"), HasSubstr("no standby worker is left")));
  const std::string partial = read_file(scratch.path() / "remote/results.csv");
  ASSERT_FALSE(partial.empty());
  EXPECT_EQ(partial, local.substr(0, partial.size()));
  EXPECT_THAT(read_file(scratch.path() / "remote/manifest.json"),
              HasSubstr("\"status\": \"error\""));
}

TEST_F(failover_run, bad_failover_settings_are_refused_with_the_reason) {
  const auto no_standby = run_command(
      "'" + k_cli + "' run " + quoted(k_walk_on_worker) + " --snapshot-every 10 --domain 152",
      scratch.path());
  EXPECT_NE(no_standby.exit_code, 0);
  EXPECT_THAT(no_standby.err, HasSubstr("--snapshot-every: no standby worker"));
  std::string xml = read_file(k_walk_on_worker);
  {
    std::string asynchronous = xml;
    asynchronous.insert(asynchronous.find("\n", asynchronous.find("<simulation ")) + 1,
                        "  <agents count=\"2\" mode=\"asynchronous\"/>\n");
    const fs::path system = scratch.path() / "asynchronous.xml";
    std::ofstream(system) << asynchronous;
    const auto agents = run_command(
        "'" + k_cli + "' run " + quoted(system) + " --standby s1 --domain 152", scratch.path());
    EXPECT_NE(agents.exit_code, 0);
    EXPECT_THAT(agents.err, HasSubstr("standby workers (<failover>, --standby) need synchronous "
                                      "agents"));
  }
  xml.insert(xml.find("\n", xml.find("<simulation ")) + 1, "  <failover standby=\" \"/>\n");
  const fs::path system = scratch.path() / "empty-standby.xml";
  std::ofstream(system) << xml;
  const auto empty = run_command("'" + k_cli + "' validate " + quoted(system), scratch.path());
  EXPECT_NE(empty.exit_code, 0);
  EXPECT_THAT(empty.err, AllOf(HasSubstr("empty-standby.xml:7"), HasSubstr("names no worker")));
}

// the shipped loopback configuration with Cyclone DDS dropping `per_mille` of the packets each
// process sends (its test option Internal/Test/XmitLossiness)
fs::path lossy_config(const fs::path& dir, int per_mille) {
  std::string xml = read_file(k_source / "remote/config/loopback.xml");
  const auto at = xml.find("</Internal>");
  if (at == std::string::npos) return {};
  xml.insert(
      at, "  <Test><XmitLossiness>" + std::to_string(per_mille) + "</XmitLossiness></Test>\n    ");
  const fs::path file = dir / ("lossy-" + std::to_string(per_mille) + ".xml");
  std::ofstream(file) << xml;
  return file;
}

TEST_F(failover_run, packets_lost_on_the_way_change_nothing) {
  const fs::path lossy = lossy_config(scratch.path(), 50);  // 5 %
  ASSERT_FALSE(lossy.empty());
  auto w1 =
      worker_process(k_cli, "w1", 153, scratch.path() / "w1.log", {"--dds-config", lossy.string()});
  ASSERT_TRUE(w1.ready()) << w1.output();
  const auto local =
      run_command("'" + k_cli + "' run " + quoted(k_source / "models/walk.xml") +
                      " --quiet --stop-time 2 --output " + quoted(scratch.path() / "local"),
                  scratch.path());
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const auto remote =
      run_command("'" + k_cli + "' run " + quoted(k_walk_on_worker) +
                      " --stop-time 2 --domain 153 --standby s1 --dds-config " + quoted(lossy) +
                      " --output " + quoted(scratch.path() / "remote"),
                  scratch.path());
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_THAT(remote.err, ::testing::Not(HasSubstr("is lost")));  // reliable delivery, no failover
  EXPECT_EQ(read_file(scratch.path() / "remote/results.csv"),
            read_file(scratch.path() / "local/results.csv"));
  // the control: with every packet dropped the worker is never reached, so the option works
  const fs::path dead = lossy_config(scratch.path(), 1000);
  const auto cut_off = run_command("'" + k_cli + "' run " + quoted(k_walk_on_worker) +
                                       " --stop-time 2 --domain 153 --worker-timeout 1 "
                                       "--dds-config " +
                                       quoted(dead) + " --output " + quoted(scratch.path() / "cut"),
                                   scratch.path());
  EXPECT_NE(cut_off.exit_code, 0);
  EXPECT_THAT(cut_off.err, HasSubstr("worker 'w1' did not appear"));
}

// The orchestrator itself killed (SIGKILL) mid-walk, with --checkpoint-every: `--resume`
// continues from its last checkpoint on the same worker, and the CSV equals the in-process walk.
TEST_F(failover_run, a_killed_orchestrator_resumes_from_its_periodic_checkpoint) {
  const std::string local = in_process_walk();
  auto w1 = start_worker("w1", 172);
  ASSERT_TRUE(w1.ready()) << w1.output();
  const fs::path out = scratch.path() / "remote";
  const pid_t run = start_run(172, {"--quiet", "--checkpoint-every", "5"});
  ASSERT_GT(run, 0);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < until &&
         !(fs::exists(out / "checkpoint.stride") && fs::file_size(out / "results.csv") > 150000)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(run, SIGKILL);
  ASSERT_EQ(wait_exit(run), 128 + SIGKILL) << run_log();
  ASSERT_TRUE(fs::exists(out / "checkpoint.stride"));
  const auto resumed = run_command(
      "'" + k_cli + "' run --resume " + quoted(out) + " --quiet --domain 172", scratch.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(out / "results.csv"), local);  // byte for byte
}

// A reply the network holds up beyond --stall is a stall: one log line each, counted in the
// manifest. With --stall 0 every reply is one, which shows the lines and the count agree; a
// clean loopback run has none at the default (the netns test makes a real one).
TEST_F(failover_run, replies_held_up_by_the_network_are_logged_and_counted_as_stalls) {
  auto w1 = start_worker("w1", 171);
  ASSERT_TRUE(w1.ready()) << w1.output();
  const auto every = run_command("'" + k_cli + "' run " + quoted(k_walk_on_worker) +
                                     " --stop-time 0.2 --domain 171 --stall 0 --output " +
                                     quoted(scratch.path() / "every"),
                                 scratch.path());
  ASSERT_EQ(every.exit_code, 0) << every.err;
  const std::string line = "the network held up the reply of worker 'w1' to '";
  std::size_t lines = 0;
  for (auto at = every.err.find(line); at != std::string::npos; at = every.err.find(line, at + 1)) {
    ++lines;
  }
  EXPECT_GE(lines, 25u);  // 25 steps, and the calls before them
  EXPECT_THAT(every.err, HasSubstr("[robot] warning (network): " + line + "step' for "));
  EXPECT_THAT(read_file(scratch.path() / "every/manifest.json"),
              HasSubstr("\"stalls\": " + std::to_string(lines) + "}"));
  const auto bad =
      run_command("'" + k_cli + "' run " + quoted(k_walk_on_worker) + " --domain 171 --stall -1",
                  scratch.path());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_THAT(bad.err, HasSubstr("--stall"));
}

TEST_F(failover_run, an_fmu_that_cannot_save_its_state_is_refused_before_the_run) {
  cosim::test::write_fake_fmu(scratch.path() / "fake.fmu", {{"y", "output", "Real", ""}});
  const fs::path system = scratch.path() / "fake.xml";
  std::ofstream(system) << "<system name=\"fake\">\n  <simulation stop=\"1\" step=\"0.01\"/>\n"
                           "  <component name=\"f\" fmu=\"fake.fmu\" worker=\"w1\"/>\n</system>\n";
  const auto refused = run_command("'" + k_cli + "' run " + quoted(system) +
                                       " --standby s1 --domain 152 --worker-timeout 1 --output " +
                                       quoted(scratch.path() / "out"),
                                   scratch.path());
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_THAT(refused.err, AllOf(HasSubstr("fake.xml:3: component 'f' on worker 'w1'"),
                                 HasSubstr("cannot fail over to a standby worker"),
                                 HasSubstr("canGetAndSetFMUstate")));
}

}  // namespace
}  // namespace stride::remote::test
