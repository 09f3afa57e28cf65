// Deferred work: left on a thread, done by that thread's next run, once, oldest first.
#include "stride/cosim/deferred_work.hpp"

#include <gtest/gtest.h>

#include <future>
#include <string>
#include <thread>

namespace stride::cosim {
namespace {

// appends its name to a shared log when done; may leave another piece of work while it runs
class named_work : public deferred_work {
 public:
  named_work(std::string name, std::string& log) : name_(std::move(name)), log_(log) {}
  ~named_work() { withdraw_work(*this); }
  void do_deferred_work() noexcept override {
    log_ += name_;
    if (then_ != nullptr) defer_work(*then_);
  }
  named_work* then_ = nullptr;

 private:
  std::string name_;
  std::string& log_;
};

TEST(deferred_work, work_left_is_done_once_oldest_first) {
  std::string log;
  named_work a("a", log), b("b", log);
  defer_work(b);
  defer_work(a);
  defer_work(b);  // already left: stays where it was
  run_deferred_work();
  EXPECT_EQ(log, "ba");
  run_deferred_work();
  EXPECT_EQ(log, "ba");
  defer_work(a);  // done work may be left again
  run_deferred_work();
  EXPECT_EQ(log, "baa");
}

TEST(deferred_work, withdrawn_work_is_not_done) {
  std::string log;
  named_work a("a", log), b("b", log);
  defer_work(a);
  defer_work(b);
  withdraw_work(a);
  withdraw_work(a);  // twice is harmless
  run_deferred_work();
  EXPECT_EQ(log, "b");
  {
    named_work gone("x", log);
    defer_work(gone);
  }  // withdrawn as it goes
  run_deferred_work();
  EXPECT_EQ(log, "b");
}

TEST(deferred_work, work_left_while_running_waits_for_the_next_run) {
  std::string log;
  named_work a("a", log), b("b", log);
  a.then_ = &b;
  b.then_ = &a;  // would never end if each run did all it found
  defer_work(a);
  run_deferred_work();
  EXPECT_EQ(log, "a");
  run_deferred_work();
  EXPECT_EQ(log, "ab");
  withdraw_work(a);
  withdraw_work(b);
}

TEST(deferred_work, each_thread_does_only_its_own_work) {
  std::string mine, theirs;
  named_work here("h", mine), there("t", theirs), left_behind("l", theirs);
  defer_work(here);
  std::thread other([&] {
    defer_work(there);
    run_deferred_work();  // not `here`
    defer_work(left_behind);
  });  // ends with `left_behind` still left on it
  other.join();
  EXPECT_EQ(theirs, "t");
  EXPECT_TRUE(mine.empty());
  run_deferred_work();
  EXPECT_EQ(mine, "h");
  EXPECT_EQ(theirs, "t");
  // the thread that held it is gone: it can be left here now, and is done here
  defer_work(left_behind);
  run_deferred_work();
  EXPECT_EQ(theirs, "tl");
}

TEST(deferred_work, work_left_on_another_thread_can_be_withdrawn_from_this_one) {
  std::string log;
  named_work w("w", log);
  std::promise<void> left, withdrawn;
  std::thread other([&] {
    defer_work(w);
    left.set_value();
    withdrawn.get_future().wait();
    run_deferred_work();
  });
  left.get_future().wait();
  withdraw_work(w);
  withdrawn.set_value();
  other.join();
  EXPECT_TRUE(log.empty());
  // a thread that ends with work left forgets it: withdrawing it then is harmless
  std::thread([&] { defer_work(w); }).join();
  withdraw_work(w);
  run_deferred_work();
  EXPECT_TRUE(log.empty());
}

}  // namespace
}  // namespace stride::cosim
