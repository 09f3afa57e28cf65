#include "task_runner.hpp"

#include <chrono>

namespace stride::cosim {

namespace {

// how long an idle worker polls for new tasks before it sleeps
constexpr std::chrono::microseconds k_spin_time{50};

void cpu_relax() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

}  // namespace

task_runner::task_runner(int threads) {
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
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

void task_runner::run(const step_plan& plan, const std::function<bool(std::size_t)>& work) {
  std::unique_lock lock(mutex_);
  plan_ = &plan;
  work_ = &work;
  error_ = nullptr;
  failed_.store(false, std::memory_order_relaxed);
  waiting_for_ = plan.predecessor_count;
  blocked_.assign(plan.tasks.size(), false);
  ready_.clear();
  // pushed in reverse so that the calling thread takes the first task in stepping order
  for (std::size_t t = plan.tasks.size(); t-- > 0;) {
    if (waiting_for_[t] == 0) ready_.push_back(t);
  }
  unfinished_ = plan.tasks.size();
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
      changed_.wait(lock, [this] { return unfinished_ == 0 || !ready_.empty(); });
    }
  }
  plan_ = nullptr;
  work_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

void task_runner::worker_loop() {
  for (;;) {
    // poll a little before sleeping
    const auto spin_until = std::chrono::steady_clock::now() + k_spin_time;
    for (int i = 0; ready_count_.load(std::memory_order_relaxed) == 0; ++i) {
      cpu_relax();
      if ((i & 63) == 0 && std::chrono::steady_clock::now() > spin_until) break;
    }
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return stopping_ || !ready_.empty(); });
    if (stopping_) return;
    std::size_t task = 0;
    if (!take(task)) continue;
    lock.unlock();
    execute(task);
  }
}

}  // namespace stride::cosim
