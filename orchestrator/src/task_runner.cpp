#include "task_runner.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace stride::cosim {

namespace {

// how long an idle worker polls for new tasks before it sleeps
constexpr std::chrono::microseconds k_spin_time{1000};

// polls `done` for up to k_spin_time
template <class F>
void spin_until(F done) {
  const auto until = std::chrono::steady_clock::now() + k_spin_time;
  // plain loads, no pause instruction: a virtual CPU that pauses in a loop may be descheduled
  for (int i = 0; !done(); ++i) {
    if ((i & 63) == 0 && std::chrono::steady_clock::now() > until) return;
  }
}

}  // namespace

task_runner::task_runner(int threads, std::size_t max_tasks) : claims_(max_tasks) {
  for (int i = 1; i < threads; ++i) {
    workers_.emplace_back([this, i] { worker_loop(static_cast<std::size_t>(i)); });
  }
}

task_runner::~task_runner() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (auto& w : workers_) w.join();
}

bool task_runner::take(std::size_t& task) {
  if (ready_.empty()) return false;
  task = ready_.back();
  ready_.pop_back();
  ready_count_.store(ready_.size(), std::memory_order_relaxed);
  return true;
}

void task_runner::finish(std::size_t task, bool release_successors) {
  for (std::size_t s : plan_->successors[task]) {
    if (!release_successors) blocked_[s] = true;
    if (--waiting_for_[s] > 0) continue;
    if (blocked_[s]) {
      finish(s, false);  // skipped: holds back its own successors too
    } else {
      ready_.push_back(s);
    }
  }
  ready_count_.store(ready_.size(), std::memory_order_relaxed);
  --unfinished_;
  unfinished_count_.store(unfinished_, std::memory_order_release);
}

void task_runner::execute(std::size_t task) {
  bool released = false;
  std::exception_ptr failure;
  if (!failed_.load(std::memory_order_relaxed)) {
    try {
      released = (*work_)(task);
    } catch (...) {
      failure = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  std::unique_lock lock(mutex_);
  if (failure && !error_) error_ = failure;
  finish(task, released && !error_);
  const bool notify = !ready_.empty() || unfinished_ == 0;
  lock.unlock();
  if (notify) changed_.notify_all();
}

bool task_runner::claim(std::size_t task, std::uint64_t generation) {
  // generations only grow: a thread that comes late, when its generation is over, finds every
  // task claimed by it or a later one and claims nothing
  std::uint64_t seen = claims_[task].generation.load(std::memory_order_relaxed);
  while (seen < generation) {
    if (claims_[task].generation.compare_exchange_weak(seen, generation,
                                                       std::memory_order_acq_rel)) {
      return true;
    }
  }
  return false;
}

void task_runner::run_claimed(std::size_t task, const std::function<bool(std::size_t)>& work) {
  if (!failed_.load(std::memory_order_relaxed)) {
    try {
      work(task);  // nothing waits for it: what it returns does not matter
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  if (unfinished_count_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
    std::lock_guard lock(mutex_);  // the caller may be asleep on changed_
    changed_.notify_all();
  }
}

void task_runner::run_independent(std::size_t index, std::uint64_t generation, std::size_t tasks,
                                  const std::function<bool(std::size_t)>& work) {
  const std::size_t threads = workers_.size() + 1;
  for (std::size_t t = index; t < tasks; t += threads) {
    if (claim(t, generation)) run_claimed(t, work);
  }
  // the others' tasks, last first: their home threads take theirs in ascending order
  for (std::size_t t = tasks; t-- > 0;) {
    if (t % threads != index && claim(t, generation)) run_claimed(t, work);
  }
}

void task_runner::run(const step_plan& plan, const std::function<bool(std::size_t)>& work) {
  if (plan.tasks.size() > claims_.size()) {
    throw std::logic_error("task_runner: a plan of " + std::to_string(plan.tasks.size()) +
                           " tasks, made for at most " + std::to_string(claims_.size()));
  }
  std::unique_lock lock(mutex_);
  plan_ = &plan;
  work_ = &work;
  error_ = nullptr;
  failed_.store(false, std::memory_order_relaxed);
  independent_ = std::all_of(plan.predecessor_count.begin(), plan.predecessor_count.end(),
                             [](int n) { return n == 0; });
  if (independent_) {
    // each thread takes its own share; no lock per task
    const std::uint64_t generation = generation_.load(std::memory_order_relaxed) + 1;
    unfinished_count_.store(plan.tasks.size(), std::memory_order_relaxed);
    generation_.store(generation, std::memory_order_release);
    lock.unlock();
    changed_.notify_all();
    run_independent(0, generation, plan.tasks.size(), work);
    spin_until([this] { return unfinished_count_.load(std::memory_order_acquire) == 0; });
    lock.lock();
    changed_.wait(lock, [this] { return unfinished_count_.load(std::memory_order_acquire) == 0; });
    plan_ = nullptr;
    work_ = nullptr;
    if (error_) std::rethrow_exception(error_);
    return;
  }
  waiting_for_ = plan.predecessor_count;
  blocked_.assign(plan.tasks.size(), false);
  ready_.clear();
  // pushed in reverse so that the calling thread takes the first task in stepping order
  for (std::size_t t = plan.tasks.size(); t-- > 0;) {
    if (waiting_for_[t] == 0) ready_.push_back(t);
  }
  unfinished_ = plan.tasks.size();
  unfinished_count_.store(unfinished_, std::memory_order_relaxed);
  ready_count_.store(ready_.size(), std::memory_order_relaxed);
  lock.unlock();
  changed_.notify_all();

  lock.lock();
  while (unfinished_ > 0) {
    std::size_t task = 0;
    if (take(task)) {
      lock.unlock();
      execute(task);
      lock.lock();
    } else {
      // the others are busy: poll a little before sleeping
      lock.unlock();
      spin_until([this] {
        return unfinished_count_.load(std::memory_order_acquire) == 0 ||
               ready_count_.load(std::memory_order_relaxed) > 0;
      });
      lock.lock();
      changed_.wait(lock, [this] { return unfinished_ == 0 || !ready_.empty(); });
    }
  }
  plan_ = nullptr;
  work_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

void task_runner::worker_loop(std::size_t index) {
  std::uint64_t seen = 0;  // the last generation of independent tasks this thread ran
  for (;;) {
    // poll a little before sleeping
    spin_until([&] {
      return ready_count_.load(std::memory_order_relaxed) > 0 ||
             generation_.load(std::memory_order_acquire) != seen;
    });
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] {
      return stopping_ || !ready_.empty() || generation_.load(std::memory_order_acquire) != seen;
    });
    if (stopping_) return;
    if (generation_.load(std::memory_order_acquire) != seen) {
      // the run of this generation, read under the lock; it may be over already
      seen = generation_.load(std::memory_order_acquire);
      const bool current = independent_ && plan_ != nullptr;
      const std::size_t tasks = current ? plan_->tasks.size() : 0;
      const auto* work = work_;
      lock.unlock();
      if (current) run_independent(index, seen, tasks, *work);
      continue;
    }
    std::size_t task = 0;
    if (!take(task)) continue;
    lock.unlock();
    execute(task);
  }
}

}  // namespace stride::cosim
