// The thread pool of the fixed-step algorithm: every task once per run, predecessors first,
// independent tasks on their home threads, failures passed to the caller.
#include "task_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace stride::cosim {
namespace {

step_plan independent_plan(std::size_t tasks) {
  step_plan p;
  p.tasks.resize(tasks);
  p.successors.resize(tasks);
  p.predecessor_count.assign(tasks, 0);
  return p;
}

// waits until `count` reaches `target`, at most a few seconds; false when it never did
bool await(const std::atomic<int>& count, int target) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (count.load() < target) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::yield();
  }
  return true;
}

TEST(task_runner, runs_every_independent_task_once_per_run) {
  for (int threads : {2, 3, 4}) {
    for (std::size_t tasks : {1u, 2u, 5u, 8u}) {
      task_runner runner(threads, tasks);
      const step_plan plan = independent_plan(tasks);
      std::vector<std::atomic<int>> runs(tasks);
      for (int r = 0; r < 2000; ++r) {
        runner.run(plan, [&](std::size_t t) {
          ++runs[t];
          return true;
        });
      }
      for (std::size_t t = 0; t < tasks; ++t) {
        EXPECT_EQ(runs[t].load(), 2000) << threads << " threads, task " << t << " of " << tasks;
      }
    }
  }
}

TEST(task_runner, independent_tasks_stay_on_their_home_threads) {
  // homes: tasks 0 and 2 the calling thread, 1 and 3 the worker. Tasks 0 and 1 each wait until
  // the other has started, then tasks 2 and 3 likewise: each pair holds both threads, so a thread
  // that took a task of the other's home before its own would show on the wrong thread (or leave
  // a pair waiting for ever)
  task_runner runner(2, 4);
  const step_plan plan = independent_plan(4);
  const auto caller = std::this_thread::get_id();
  std::thread::id worker;
  for (int r = 0; r < 200; ++r) {
    std::atomic<int> started[2] = {};
    std::thread::id ran_on[4];
    bool met[4] = {};
    runner.run(plan, [&](std::size_t t) {
      ran_on[t] = std::this_thread::get_id();
      ++started[t / 2];
      met[t] = await(started[t / 2], 2);
      return true;
    });
    for (bool m : met) ASSERT_TRUE(m) << "a pair of tasks never ran together, run " << r;
    if (r == 0) worker = ran_on[1];
    ASSERT_NE(worker, caller);
    EXPECT_EQ(ran_on[0], caller) << "run " << r;
    EXPECT_EQ(ran_on[2], caller) << "run " << r;
    EXPECT_EQ(ran_on[1], worker) << "run " << r;
    EXPECT_EQ(ran_on[3], worker) << "run " << r;
  }
}

TEST(task_runner, a_task_runs_after_its_predecessors_and_not_after_a_refusal) {
  // 0 → 2, 1 → 2, 2 → 3; task 1 refuses in odd runs: 2 and 3 are then skipped
  step_plan plan = independent_plan(4);
  plan.successors = {{2}, {2}, {3}, {}};
  plan.predecessor_count = {0, 0, 2, 1};
  task_runner runner(3, 4);
  for (int r = 0; r < 500; ++r) {
    std::atomic<int> done[4] = {};
    bool order_kept = true;
    runner.run(plan, [&](std::size_t t) {
      if (t == 2 && (done[0] == 0 || done[1] == 0)) order_kept = false;
      if (t == 3 && done[2] == 0) order_kept = false;
      ++done[t];
      return !(t == 1 && r % 2 == 1);
    });
    EXPECT_TRUE(order_kept) << "run " << r;
    EXPECT_EQ(done[0].load(), 1);
    EXPECT_EQ(done[1].load(), 1);
    EXPECT_EQ(done[2].load(), r % 2 == 0 ? 1 : 0) << "run " << r;
    EXPECT_EQ(done[3].load(), r % 2 == 0 ? 1 : 0) << "run " << r;
  }
}

TEST(task_runner, a_failing_task_reaches_the_caller_and_the_next_run_works) {
  task_runner runner(2, 3);
  const step_plan plan = independent_plan(3);
  EXPECT_THROW(runner.run(plan,
                          [](std::size_t t) -> bool {
                            if (t == 1) throw std::runtime_error("task 1 failed");
                            return true;
                          }),
               std::runtime_error);
  std::atomic<int> runs{0};
  runner.run(plan, [&](std::size_t) {
    ++runs;
    return true;
  });
  EXPECT_EQ(runs.load(), 3);
}

TEST(task_runner, refuses_a_plan_larger_than_it_was_made_for) {
  task_runner runner(2, 2);
  EXPECT_THROW(runner.run(independent_plan(3), [](std::size_t) { return true; }), std::logic_error);
}

}  // namespace
}  // namespace stride::cosim
