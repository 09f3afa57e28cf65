// Components on worker processes, end to end: real `stride worker` processes, real `stride run`,
// Cyclone DDS on the loopback interface. Each test has its own DDS domain, so that tests running
// at the same time never see each other's workers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
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
using ::testing::AllOf;
using ::testing::HasSubstr;

const std::string k_cli = STRIDE_CLI;
const fs::path k_source = STRIDE_SOURCE_DIR;

std::string read(const fs::path& file) {
  return cosim::test::read_file(file);
}

// replaces every `from` in `text` by `to`; the test fails if there is none
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class remote_run : public ::testing::Test {
 protected:
  cosim::temp_dir scratch{"stride-remote-"};

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path f = scratch.path() / name;
    std::ofstream(f, std::ios::binary) << text;
    return f;
  }
  // the stride_test pair (two instances, every type across a connection) with `steps` steps of
  // 10 ms, `a_attrs` and `b_attrs` added to the components' elements
  fs::path pair(const std::string& name, int steps, const std::string& a_attrs,
                const std::string& b_attrs) {
    std::string xml = read(k_source / "tests/orchestrator/data/stride_test_pair.xml");
    xml = replaced(xml, "stop=\"1\"", "stop=\"" + std::to_string(steps / 100.0) + "\"");
    xml = replaced(xml, "<component name=\"a\" fmu=\"stride_test\"",
                   "<component name=\"a\" fmu=\"stride_test\" " + a_attrs);
    xml = replaced(xml, "<component name=\"b\" fmu=\"stride_test\"",
                   "<component name=\"b\" fmu=\"stride_test\" " + b_attrs);
    return write(name, xml);
  }
  worker_process start_worker(const std::string& name, int domain) {
    return worker_process(k_cli, name, domain, scratch.path() / (name + ".log"));
  }
  cosim::test::process_result run(const fs::path& system, const std::string& out,
                                  const std::string& args) {
    return run_command("'" + k_cli + "' run " + quoted(system) + " --quiet --output " +
                           quoted(scratch.path() / out) + " " + args,
                       scratch.path());
  }
  std::string results(const std::string& out) { return read(scratch.path() / out / "results.csv"); }
  // the worker w1 on `domain` serves a fresh run: b placed on it gives the in-process CSV
  void expect_next_run_served(int domain, int steps) {
    ASSERT_EQ(run(pair("local.xml", steps, "", ""), "local", "").exit_code, 0);
    const auto next = run(pair("next.xml", steps, "", "worker=\"w1\""), "next",
                          "--domain " + std::to_string(domain));
    ASSERT_EQ(next.exit_code, 0) << next.err;
    EXPECT_EQ(results("next"), results("local"));
  }
};

TEST_F(remote_run, a_component_on_a_worker_gives_the_same_csv_as_in_process) {
  auto w = start_worker("w1", 61);
  ASSERT_TRUE(w.ready()) << w.output();
  const auto local = run(pair("local.xml", 300, "", ""), "local", "");
  ASSERT_EQ(local.exit_code, 0) << local.err;
  const auto remote = run(pair("remote.xml", 300, "", "worker=\"w1\""), "remote", "--domain 61");
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_GT(results("local").size(), 1000u);
  EXPECT_EQ(results("remote"), results("local"));  // byte for byte
  EXPECT_THAT(w.output(), AllOf(HasSubstr("loaded stride_test"), HasSubstr(" begins"),
                                HasSubstr("ends (its orchestrator said so; ")));
}

TEST_F(remote_run, components_on_two_workers_give_the_same_csv) {
  auto w1 = start_worker("w1", 62);
  auto w2 = start_worker("w2", 62);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  ASSERT_EQ(run(pair("local.xml", 200, "", ""), "local", "").exit_code, 0);
  const auto remote =
      run(pair("remote.xml", 200, "worker=\"w1\"", "worker=\"w2\""), "remote", "--domain 62");
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_EQ(results("remote"), results("local"));
  EXPECT_THAT(w1.output(), HasSubstr("loaded stride_test"));
  EXPECT_THAT(w2.output(), HasSubstr("loaded stride_test"));
}

TEST_F(remote_run, the_archive_is_shipped_once_per_worker_and_kept_for_the_next_run) {
  auto w = start_worker("w1", 63);
  ASSERT_TRUE(w.ready()) << w.output();
  // both instances on one worker: one archive
  const fs::path both = pair("both.xml", 50, "worker=\"w1\"", "worker=\"w1\"");
  ASSERT_EQ(run(both, "first", "--domain 63").exit_code, 0);
  ASSERT_EQ(run(both, "second", "--domain 63").exit_code, 0);
  EXPECT_EQ(results("first"), results("second"));
  const std::string log = w.output();
  const auto loads = [&] {
    std::size_t n = 0;
    for (auto at = log.find("loaded stride_test"); at != std::string::npos;
         at = log.find("loaded stride_test", at + 1)) {
      ++n;
    }
    return n;
  }();
  EXPECT_EQ(loads, 1u) << log;
}

TEST_F(remote_run, an_error_on_the_worker_names_worker_component_and_time) {
  auto w = start_worker("w1", 64);
  ASSERT_TRUE(w.ready()) << w.output();
  const auto r = run(pair("failing.xml", 100, "worker=\"w1\"", ""), "failing",
                     "--domain 64 --set a.fail_at_step=7");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, AllOf(HasSubstr("component 'a' on worker 'w1'"),
                           HasSubstr("step 7 fails on request"), HasSubstr("t = 0.06 s")));
  // the steps before are recorded: rows for t = 0 .. 0.06
  EXPECT_THAT(results("failing"), HasSubstr("\n0.06,"));

  // the worker outlives the failed run and serves the next one
  expect_next_run_served(64, 100);
}

TEST_F(remote_run, a_component_that_ends_the_run_on_a_worker_ends_it_here) {
  auto w = start_worker("w1", 65);
  ASSERT_TRUE(w.ready()) << w.output();
  ASSERT_EQ(run(pair("local.xml", 100, "", ""), "local", "--set b.stop_after_steps=12").exit_code,
            0);
  const auto r = run(pair("remote.xml", 100, "", "worker=\"w1\""), "remote",
                     "--domain 65 --set b.stop_after_steps=12");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(results("remote"), results("local"));
}

// the number of requests a worker served for its only run, from its "run … ends" line
std::uint64_t requests_served(const std::string& log) {
  const auto end = log.find(" requests)");
  if (end == std::string::npos) return 0;
  const auto start = log.rfind(' ', end - 1);
  return std::stoull(log.substr(start + 1, end - start - 1));
}

TEST_F(remote_run, connected_components_on_one_worker_step_together_in_one_request_per_step) {
  auto w1 = start_worker("w1", 74);
  auto w2 = start_worker("w2", 74);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  ASSERT_EQ(run(pair("local.xml", 300, "", ""), "local", "").exit_code, 0);
  // a → b on one worker: one group
  const auto grouped = run_command(
      "'" + k_cli + "' run " + quoted(pair("grouped.xml", 300, "worker=\"w1\"", "worker=\"w1\"")) +
          " --domain 74 --output " + quoted(scratch.path() / "grouped"),
      scratch.path());
  ASSERT_EQ(grouped.exit_code, 0) << grouped.err;
  EXPECT_THAT(grouped.err, HasSubstr("a, b step together on worker 'w1'"));
  EXPECT_EQ(results("grouped"), results("local"));
  // the same pair over two workers: a request per component and step
  const auto split =
      run(pair("split.xml", 300, "worker=\"w1\"", "worker=\"w2\""), "split", "--domain 74");
  ASSERT_EQ(split.exit_code, 0) << split.err;
  EXPECT_EQ(results("split"), results("local"));
  w1.stop(SIGTERM);
  w2.stop(SIGTERM);
  const std::string log1 = w1.output();
  const auto first_run_end = log1.find(" requests)");
  ASSERT_NE(first_run_end, std::string::npos) << log1;
  const std::uint64_t grouped_requests = requests_served(log1.substr(0, first_run_end + 10));
  const std::uint64_t split_requests = requests_served(w2.output());
  EXPECT_GE(grouped_requests, 300u);
  EXPECT_LT(grouped_requests, 300u + 40u) << log1;  // 300 steps, a few for loading and setup
  EXPECT_GE(split_requests, 300u);                  // b alone on w2, stepped every step
}

TEST_F(remote_run, a_member_of_a_group_that_fails_or_ends_the_run_is_named) {
  auto w = start_worker("w1", 75);
  ASSERT_TRUE(w.ready()) << w.output();
  const std::string both = "worker=\"w1\"";
  const auto failed =
      run(pair("failing.xml", 100, both, both), "failing", "--domain 75 --set a.fail_at_step=7");
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_THAT(failed.err,
              AllOf(HasSubstr("step group a+b on worker 'w1'"), HasSubstr("component 'a'"),
                    HasSubstr("step 7 fails on request"), HasSubstr("t = 0.06 s")));
  ASSERT_EQ(run(pair("local.xml", 100, "", ""), "local", "--set b.stop_after_steps=12").exit_code,
            0);
  const auto ended =
      run(pair("ends.xml", 100, both, both), "ends", "--domain 75 --set b.stop_after_steps=12");
  ASSERT_EQ(ended.exit_code, 0) << ended.err;
  EXPECT_EQ(results("ends"), results("local"));
}

TEST_F(remote_run, a_missing_worker_is_a_timeout_error) {
  const auto r = run(pair("remote.xml", 10, "", "worker=\"nobody\""), "remote",
                     "--domain 66 --worker-timeout 0.5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err,
              AllOf(HasSubstr("remote.xml:"), HasSubstr("component 'b'"),
                    HasSubstr("worker 'nobody' did not appear on DDS domain 66 within 0.5 s"),
                    HasSubstr("stride worker --name nobody --domain 66")));
}

TEST_F(remote_run, two_runs_at_once_on_one_domain_do_not_mix) {
  auto w = start_worker("w1", 67);
  ASSERT_TRUE(w.ready()) << w.output();
  // different parameters, so that crossed replies would show
  ASSERT_EQ(run(pair("l1.xml", 400, "", ""), "l1", "--set a.gain=2").exit_code, 0);
  ASSERT_EQ(run(pair("l2.xml", 400, "", ""), "l2", "--set a.gain=5").exit_code, 0);
  ASSERT_NE(results("l1"), results("l2"));
  const fs::path sys = pair("remote.xml", 400, "", "worker=\"w1\"");
  cosim::test::process_result r1, r2;
  std::thread t1([&] { r1 = run(sys, "r1", "--domain 67 --set a.gain=2"); });
  std::thread t2([&] { r2 = run(sys, "r2", "--domain 67 --set a.gain=5"); });
  t1.join();
  t2.join();
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_EQ(results("r1"), results("l1"));
  EXPECT_EQ(results("r2"), results("l2"));
}

TEST_F(remote_run, a_worker_drops_the_run_of_an_orchestrator_that_died) {
  auto w = start_worker("w1", 68);
  ASSERT_TRUE(w.ready()) << w.output();
  const fs::path sys = pair("long.xml", 100000, "", "worker=\"w1\"");
  const pid_t run_pid = spawn({k_cli, "run", sys.string(), "--quiet", "--domain", "68", "--output",
                               (scratch.path() / "long").string()},
                              scratch.path() / "long.log");
  ASSERT_GT(run_pid, 0);
  ASSERT_TRUE(w.wait_for(" begins"));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(run_pid, SIGKILL);
  ::waitpid(run_pid, nullptr, 0);
  EXPECT_TRUE(w.wait_for("ends (its orchestrator is gone; ")) << w.output();
  // and serves the next run
  expect_next_run_served(68, 50);
}

TEST_F(remote_run, a_second_worker_of_the_same_name_is_refused) {
  auto w = start_worker("w1", 69);
  ASSERT_TRUE(w.ready()) << w.output();
  auto twin = start_worker("w1", 69);
  EXPECT_EQ(twin.wait_exit(), 1);
  EXPECT_THAT(twin.output(), HasSubstr("a worker named 'w1' is already on DDS domain 69"));
}

TEST_F(remote_run, workers_are_listed_and_stop_cleanly_on_sigterm) {
  auto w1 = start_worker("alpha", 70);
  auto w2 = start_worker("beta", 70);
  ASSERT_TRUE(w1.ready() && w2.ready());
  const auto list = run_command("'" + k_cli + "' workers --domain 70", scratch.path());
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_THAT(list.out, AllOf(HasSubstr("alpha"), HasSubstr("beta")));
  EXPECT_EQ(w1.stop(SIGTERM), 0);
  EXPECT_THAT(w1.output(), HasSubstr("worker stopped"));
  const auto after = run_command("'" + k_cli + "' workers --domain 70", scratch.path());
  EXPECT_THAT(after.out, AllOf(HasSubstr("beta"), ::testing::Not(HasSubstr("alpha"))));
  EXPECT_EQ(w2.stop(SIGINT), 0);
}

TEST_F(remote_run, validate_and_inspect_say_where_each_component_runs_without_a_worker) {
  const fs::path system = pair("placed.xml", 10, "", "worker=\"w9\"");
  const auto validated = run_command("'" + k_cli + "' validate " + quoted(system), scratch.path());
  ASSERT_EQ(validated.exit_code, 0) << validated.err;
  EXPECT_THAT(validated.out, AllOf(HasSubstr("OK"), HasSubstr("placement:")));
  EXPECT_THAT(validated.out, ::testing::ContainsRegex("a +this process"));
  EXPECT_THAT(validated.out, ::testing::ContainsRegex("b +worker w9"));
  EXPECT_THAT(validated.out, ::testing::Not(HasSubstr("step together")));
  const auto both = run_command(
      "'" + k_cli + "' validate " + quoted(pair("both.xml", 10, "worker=\"w9\"", "worker=\"w9\"")),
      scratch.path());
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_THAT(both.out, HasSubstr("a, b step together on worker w9"));
  const auto inspected = run_command("'" + k_cli + "' inspect " + quoted(system), scratch.path());
  ASSERT_EQ(inspected.exit_code, 0) << inspected.err;
  EXPECT_THAT(inspected.out, ::testing::ContainsRegex("b +worker w9 +stride_test"));
  EXPECT_THAT(inspected.out, HasSubstr("2 components"));
}

#ifdef STRIDE_REMOTE_HAVE_WALK
// the DARwIn-OP walk with the robot on a worker: the plant is the heavy component
TEST_F(remote_run, the_walk_with_the_robot_on_a_worker_equals_the_walk_in_process) {
  auto w = start_worker("w1", 71);
  ASSERT_TRUE(w.ready()) << w.output();
  ASSERT_EQ(run(k_source / "models/walk.xml", "local", "--stop-time 10").exit_code, 0);
  const auto remote = run(k_source / "models/distributed/walk-robot-on-worker.xml", "remote",
                          "--stop-time 10 --domain 71");
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_EQ(results("remote"), results("local"));
}

// group placement: the gait generator and the robot step together on the worker
TEST_F(remote_run, the_walk_with_gait_and_robot_on_one_worker_equals_the_walk_in_process) {
  auto w = start_worker("w1", 76);
  ASSERT_TRUE(w.ready()) << w.output();
  ASSERT_EQ(run(k_source / "models/walk.xml", "local", "--stop-time 10").exit_code, 0);
  const auto remote = run_command(
      "'" + k_cli + "' run " + quoted(k_source / "models/distributed/walk-on-one-worker.xml") +
          " --stop-time 10 --domain 76 --output " + quoted(scratch.path() / "remote"),
      scratch.path());
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_THAT(remote.err, HasSubstr("gait, robot step together on worker 'w1'"));
  EXPECT_EQ(results("remote"), results("local"));
}

// four independent walkers, their robots spread over two workers and stepped concurrently
TEST_F(remote_run, walkers_on_two_workers_equal_the_walkers_in_process) {
  auto w1 = start_worker("w1", 73);
  auto w2 = start_worker("w2", 73);
  ASSERT_TRUE(w1.ready() && w2.ready()) << w1.output() << w2.output();
  ASSERT_EQ(run(k_source / "models/walkers.xml", "local", "--stop-time 4").exit_code, 0);
  const auto remote = run(k_source / "models/distributed/walkers-on-two-workers.xml", "remote",
                          "--stop-time 4 --domain 73 --threads 2");
  ASSERT_EQ(remote.exit_code, 0) << remote.err;
  EXPECT_EQ(results("remote"), results("local"));
  for (auto* w : {&w1, &w2}) {
    const std::string log = w->output();
    EXPECT_EQ(log.find("loaded robot"), log.rfind("loaded robot")) << log;  // one archive each
    EXPECT_NE(log.find("loaded robot"), std::string::npos) << log;
  }
}

TEST_F(remote_run, a_killed_worker_stops_the_run_with_an_error_and_the_results_so_far) {
  auto w = start_worker("w1", 72);
  ASSERT_TRUE(w.ready()) << w.output();
  ASSERT_EQ(run(k_source / "models/walk.xml", "local", "").exit_code, 0);
  const fs::path out = scratch.path() / "remote";
  const pid_t run_pid =
      spawn({k_cli, "run", (k_source / "models/distributed/walk-robot-on-worker.xml").string(),
             "--quiet", "--domain", "72", "--output", out.string()},
            scratch.path() / "remote.log");
  ASSERT_GT(run_pid, 0);
  // kill it once the walk is under way
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!(fs::exists(out / "results.csv") && fs::file_size(out / "results.csv") > 100000) &&
         std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(w.stop(SIGKILL), 128 + SIGKILL);
  const auto killed = std::chrono::steady_clock::now();
  int status = 0;
  ::waitpid(run_pid, &status, 0);
  // the worker's DDS liveliness lease is 1 s; the bound is 2 s from kill to the end
  EXPECT_LT(std::chrono::steady_clock::now() - killed, std::chrono::seconds(2));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_THAT(read(scratch.path() / "remote.log"),
              AllOf(HasSubstr("component 'robot' on worker 'w1'"), HasSubstr("worker 'w1' is gone"),
                    HasSubstr("(step at t = ")));
  // what was recorded is there, complete rows, equal to the same rows in process
  const std::string partial = results("remote");
  const std::string full = results("local");
  ASSERT_GT(partial.size(), 100000u);
  ASSERT_LT(partial.size(), full.size());
  ASSERT_EQ(partial.back(), '\n');
  EXPECT_EQ(partial, full.substr(0, partial.size()));
}
#endif

}  // namespace
}  // namespace stride::remote::test
