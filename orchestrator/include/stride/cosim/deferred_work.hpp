// Work a thread may do while it would otherwise only wait. An observer leaves work here (the CSV
// recorder leaves the formatting of its latest row); a component that waits for the reply of a
// worker does it meanwhile, on the same thread. Whatever is left is done by its owner later.
#ifndef STRIDE_COSIM_DEFERRED_WORK_HPP
#define STRIDE_COSIM_DEFERRED_WORK_HPP

namespace stride::cosim {

namespace detail {
struct work_list;
}

/// A piece of work that can wait until its thread has nothing better to do.
class deferred_work {
 public:
  /// Does the work. Must not throw: it runs inside someone else's wait (keep an error for later).
  virtual void do_deferred_work() noexcept = 0;

 protected:
  deferred_work() = default;
  deferred_work(const deferred_work&) = delete;
  deferred_work& operator=(const deferred_work&) = delete;
  ~deferred_work() = default;

 private:
  friend void defer_work(deferred_work& w);
  friend void withdraw_work(deferred_work& w) noexcept;
  friend void run_deferred_work() noexcept;
  friend struct detail::work_list;
  detail::work_list* left_in_ = nullptr;  // the list of the thread it was left on
  unsigned long long ticket_ = 0;         // its place in that list's order
};

/// Leaves `w` to this thread's next run_deferred_work(); leaving it twice leaves it once.
void defer_work(deferred_work& w);
/// Takes `w` back, unless it is done already; from any thread, so long as the one it was left on
/// does not run its work meanwhile (its owner calls this before it is destroyed).
void withdraw_work(deferred_work& w) noexcept;
/// Does and forgets the work left on this thread, oldest first; work left meanwhile (by the work
/// itself) waits for the next call.
void run_deferred_work() noexcept;

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_DEFERRED_WORK_HPP
