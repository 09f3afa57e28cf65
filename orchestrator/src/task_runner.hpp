// Runs the tasks of a step_plan on a fixed set of threads, each task after its predecessors.
// The calling thread works too. Idle threads (workers between runs, the caller waiting for the
// last task) spin briefly before they sleep: macro steps follow each other within microseconds,
// and waking a sleeping thread costs tens of them. Independent tasks each have a home thread
// that runs them step after step, so a component's memory stays in one core's cache; a thread
// that has finished its own takes the others' that have not started.
#ifndef STRIDE_COSIM_TASK_RUNNER_HPP
#define STRIDE_COSIM_TASK_RUNNER_HPP

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "stride/cosim/connection_graph.hpp"

namespace stride::cosim {

class task_runner {
 public:
  /// Starts `threads` − 1 workers, for plans of at most `max_tasks` tasks.
  task_runner(int threads, std::size_t max_tasks);
  ~task_runner();
  task_runner(const task_runner&) = delete;
  task_runner& operator=(const task_runner&) = delete;

  /// Runs work(task) for every task of `plan` whose predecessors all ran and returned true;
  /// a task whose work returns false (or whose predecessor was skipped) holds back its
  /// successors. Returns when every task has run or been skipped; rethrows the first exception
  /// of a work call after that (tasks not yet started are then skipped).
  /// A plan whose tasks depend on nothing runs without a lock per task: task t is claimed with
  /// one atomic exchange, first by its home thread (t modulo the thread count).
  void run(const step_plan& plan, const std::function<bool(std::size_t)>& work);

 private:
  void worker_loop(std::size_t index);
  // thread `index` takes tasks of the plan of `generation` (without dependencies): its own,
  // then those of the others that nobody has claimed
  void run_independent(std::size_t index, std::uint64_t generation, std::size_t tasks,
                       const std::function<bool(std::size_t)>& work);
  bool claim(std::size_t task, std::uint64_t generation);
  void run_claimed(std::size_t task, const std::function<bool(std::size_t)>& work);
  // takes a ready task, or returns false when none is ready; with the lock held
  bool take(std::size_t& task);
  void finish(std::size_t task, bool release_successors);
  void execute(std::size_t task);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable changed_;  // a task became ready, all finished, or stopping
  // the current run, guarded by mutex_
  const step_plan* plan_ = nullptr;
  const std::function<bool(std::size_t)>* work_ = nullptr;
  std::vector<int> waiting_for_;  // per task: predecessors not yet finished
  std::vector<bool> blocked_;     // per task: a predecessor did not release it
  std::vector<std::size_t> ready_;
  std::size_t unfinished_ = 0;
  std::exception_ptr error_;
  bool stopping_ = false;
  std::atomic<std::size_t> ready_count_{0};       // read without the lock by spinning workers
  std::atomic<bool> failed_{false};               // a work call threw: start no more tasks
  std::atomic<std::size_t> unfinished_count_{0};  // unfinished_, for the caller's spin
  // plans without dependencies: a new run is announced by a new generation
  bool independent_ = false;
  std::atomic<std::uint64_t> generation_{0};
  // per task the generation that last claimed it, one cache line each: home threads claim
  // their own tasks without touching a line that another thread writes
  struct alignas(64) claim_slot {
    std::atomic<std::uint64_t> generation{0};
  };
  std::vector<claim_slot> claims_;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_TASK_RUNNER_HPP
