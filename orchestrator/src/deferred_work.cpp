#include "stride/cosim/deferred_work.hpp"

#include <algorithm>
#include <vector>

namespace stride::cosim {

namespace detail {

// One thread's work, oldest first. Work still left when the thread ends forgets the list.
struct work_list {
  std::vector<deferred_work*> items;  // in the order of their tickets
  unsigned long long next_ticket = 1;

  work_list() = default;
  work_list(const work_list&) = delete;
  work_list& operator=(const work_list&) = delete;
  ~work_list() {
    for (deferred_work* w : items) w->left_in_ = nullptr;
  }
};

}  // namespace detail

namespace {

detail::work_list& this_threads_work() {
  thread_local detail::work_list list;
  return list;
}

}  // namespace

void defer_work(deferred_work& w) {
  if (w.left_in_ != nullptr) return;
  detail::work_list& list = this_threads_work();
  list.items.push_back(&w);
  w.left_in_ = &list;
  w.ticket_ = list.next_ticket++;
}

void withdraw_work(deferred_work& w) noexcept {
  if (w.left_in_ == nullptr) return;
  auto& items = w.left_in_->items;
  items.erase(std::remove(items.begin(), items.end(), &w), items.end());
  w.left_in_ = nullptr;
}

void run_deferred_work() noexcept {
  detail::work_list& list = this_threads_work();
  auto& items = list.items;
  // each is taken off before it runs, which may leave or withdraw other work; what is left from
  // now on has a later ticket and waits
  const unsigned long long last = list.next_ticket - 1;
  while (!items.empty() && items.front()->ticket_ <= last) {
    deferred_work* w = items.front();
    items.erase(items.begin());
    w->left_in_ = nullptr;
    w->do_deferred_work();
  }
}

}  // namespace stride::cosim
