// Runs the tasks of a step_plan on a fixed set of threads, each task after its predecessors.
// The calling thread works too. Idle threads (workers between runs, the caller waiting for the
// last task) spin briefly before they sleep: macro steps follow each other within microseconds,
// and waking a sleeping thread costs tens of them.
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
  /// Starts `threads` − 1 workers.
  explicit task_runner(int threads);
  ~task_runner();
  task_runner(const task_runner&) = delete;
  task_runner& operator=(const task_runner&) = delete;

  /// Runs work(task) for every task of `plan` whose predecessors all ran and returned true;
  /// a task whose work returns false (or whose predecessor was skipped) holds back its
  /// successors. Returns when every task has run or been skipped; rethrows the first exception
  /// of a work call after that (tasks not yet started are then skipped).
  /// A plan whose tasks depend on nothing runs without a lock per task: a shared counter hands
  /// out the tasks.
  void run(const step_plan& plan, const std::function<bool(std::size_t)>& work);

 private:
  void worker_loop();
  // takes tasks of the plan of `generation` (without dependencies) until none is left
  void run_independent(std::uint64_t generation, std::size_t tasks,
                       const std::function<bool(std::size_t)>& work);
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
  std::atomic<std::uint64_t> ticket_{0};
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_TASK_RUNNER_HPP
