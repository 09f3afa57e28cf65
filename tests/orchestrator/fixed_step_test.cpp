// The fixed-step master algorithm, driven through an execution with mock components.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "execution_fixtures.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {
namespace {

using namespace test;
using ::testing::HasSubstr;

// A → B → C, declared in reverse so the order must come from the graph

struct chain {
  std::shared_ptr<call_log> log = std::make_shared<call_log>();
  execution algo;
  observed_variable a, b, c;

  explicit chain(algorithm_kind kind, int threads = 1)
      : algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, kind, threads), time_point{},
             quiet_log()) {
    algo.add_component(latch("C", log));
    algo.add_component(latch("B", log));
    algo.add_component(counter("A", log));
    algo.connect(var(algo, "A", "y"), var(algo, "B", "u"));
    algo.connect(var(algo, "B", "y"), var(algo, "C", "u"));
    a = algo.observe(var(algo, "A", "y"));
    b = algo.observe(var(algo, "B", "y"));
    c = algo.observe(var(algo, "C", "y"));
    algo.initialize(std::nullopt);
  }
};

TEST(cosim_algorithm, gauss_seidel_steps_a_chain_in_dependency_order) {
  chain ch(algorithm_kind::gauss_seidel);
  EXPECT_EQ(ch.algo.order(), (std::vector<std::size_t>{2, 1, 0}));  // A, B, C
  for (int k = 0; k < 5; ++k) ASSERT_FALSE(ch.algo.step().terminated);
  // each component sees its upstream's value of the same macro step
  EXPECT_EQ(ch.algo.real_value(ch.a), 5.0);
  EXPECT_EQ(ch.algo.real_value(ch.b), 5.0);
  EXPECT_EQ(ch.algo.real_value(ch.c), 5.0);
  std::vector<std::string> steps;
  for (const auto& e : ch.log->entries) {
    if (e.find("do_step@0") != std::string::npos) steps.push_back(e.substr(0, 1));
  }
  EXPECT_EQ(steps, (std::vector<std::string>{"A", "B", "C"}));
}

TEST(cosim_algorithm, jacobi_delays_every_connection_by_one_step) {
  chain ch(algorithm_kind::jacobi);
  EXPECT_EQ(ch.algo.order(), (std::vector<std::size_t>{0, 1, 2}));  // declaration order
  for (int k = 0; k < 5; ++k) ch.algo.step();
  EXPECT_EQ(ch.algo.real_value(ch.a), 5.0);
  EXPECT_EQ(ch.algo.real_value(ch.b), 4.0);
  EXPECT_EQ(ch.algo.real_value(ch.c), 3.0);
}

TEST(cosim_algorithm, delayed_connection_reads_the_previous_communication_point) {
  auto log = std::make_shared<call_log>();
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  algo.add_component(counter("A", log));
  algo.add_component(latch("B", log));
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"), {true, "here"});
  const auto b = algo.observe(var(algo, "B", "y"));
  algo.initialize(std::nullopt);
  for (int k = 0; k < 3; ++k) algo.step();
  EXPECT_EQ(algo.real_value(b), 2.0);
}

// B latches A's y through factor 2, offset 1: after k steps A.y = k (Gauss-Seidel: B reads it
// in the same macro step), so B.u = 2k + 1 and B.y = 2k + 1
TEST(cosim_algorithm, a_transforming_connection_delivers_factor_times_value_plus_offset) {
  auto log = std::make_shared<call_log>();
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  algo.add_component(counter("A", log));
  algo.add_component(latch("B", log));
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"), {false, "here", 2.0, 1.0});
  const auto u = algo.observe(var(algo, "B", "u"));
  const auto y = algo.observe(var(algo, "B", "y"));
  algo.initialize(std::nullopt);
  EXPECT_EQ(algo.real_value(u), 1.0);  // 2 * 0 + 1 at initialization
  for (int k = 0; k < 3; ++k) algo.step();
  EXPECT_EQ(algo.real_value(u), 7.0);
  EXPECT_EQ(algo.real_value(y), 7.0);
}

// 1 * x + 0 would turn -0.0 into +0.0: an untransformed connection does no arithmetic at all
TEST(cosim_algorithm, an_untransformed_connection_passes_the_value_bit_for_bit) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  auto a = std::make_unique<mock_component>("A");
  a->real("y", causality::output);
  a->on_update = [](mock_component& self) { self.r("y") = -0.0; };
  algo.add_component(std::move(a));
  algo.add_component(latch("B", {}));
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"), {false, "here", 1.0, 0.0});
  const auto u = algo.observe(var(algo, "B", "u"));
  algo.initialize(std::nullopt);
  algo.step();
  EXPECT_TRUE(std::signbit(algo.real_value(u)));
}

TEST(cosim_algorithm, a_transformation_that_overflows_stops_the_run_naming_the_connection) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  algo.add_component(counter("A", {}));
  algo.add_component(latch("B", {}));
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"), {false, "t.ssd:9", 1e308, 0.0});
  algo.initialize(std::nullopt);
  try {
    for (int k = 0; k < 3; ++k) algo.step();  // 1e308 × 2 overflows
    ADD_FAILURE() << "an infinity reached B";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("t.ssd:9: connection A.y -> B.u: 1e+308 * 2 + 0 is not a "
                                    "finite number"));
  }
}

TEST(cosim_algorithm, only_real_connections_transform) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  for (const char* name : {"A", "B"}) {
    auto m = std::make_unique<mock_component>(name);
    m->add("n", variable_type::integer, causality::output);
    m->add("k", variable_type::integer, causality::input);
    algo.add_component(std::move(m));
  }
  algo.connect(var(algo, "A", "n"), var(algo, "B", "k"), {false, "t.ssd:4", 1.0, 1.0});
  try {
    algo.initialize(std::nullopt);
    ADD_FAILURE() << "an Integer connection transformed";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("t.ssd:4: connection A.n -> B.k: a linear transformation "
                                    "(factor, offset) applies to Real variables only"));
  }
}

// C is declared before its producer P and feeds P back through a delay. Gauss-Seidel must step P
// first (the delay imposes no order): C then reads P's value of the same macro step and P reads
// C's value of the previous communication point, so after k steps P.y = C.y = k. Stepped in
// declaration order, C would lag P by one step and P would climb at half the rate.
TEST(cosim_algorithm, a_consumer_declared_first_still_reads_its_producer_of_the_same_step) {
  auto log = std::make_shared<call_log>();
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  algo.add_component(latch("C", log));
  auto p = std::make_unique<mock_component>("P", log);
  p->real("u", causality::input);
  p->real("y", causality::output);
  p->on_step = [](mock_component& self, time_point, duration) {
    self.r("y") = self.r("u") + 1;  // latched: no feedthrough
    return step_result::complete;
  };
  algo.add_component(std::move(p));
  algo.connect(var(algo, "P", "y"), var(algo, "C", "u"));
  algo.connect(var(algo, "C", "y"), var(algo, "P", "u"), {true, "back edge"});
  const auto c = algo.observe(var(algo, "C", "y"));
  const auto py = algo.observe(var(algo, "P", "y"));
  algo.initialize(std::nullopt);
  EXPECT_EQ(algo.order(), (std::vector<std::size_t>{1, 0}));
  for (int k = 0; k < 4; ++k) algo.step();
  EXPECT_EQ(algo.real_value(py), 4.0);
  EXPECT_EQ(algo.real_value(c), 4.0);
}

TEST(cosim_algorithm, decimation_steps_slow_components_with_a_multiple_of_the_base_step) {
  auto log = std::make_shared<call_log>();
  execution algo(std::make_unique<fixed_step_algorithm>(100 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  auto fast = counter("fast", log);
  auto slow = counter("slow", log);
  auto* fast_ptr = fast.get();
  auto* slow_ptr = slow.get();
  algo.add_component(std::move(fast), 1);
  algo.add_component(std::move(slow), 3);
  const auto y = algo.observe(var(algo, "slow", "y"));
  algo.initialize(time_point(700 * k_ms));
  // a slow component whose last step ends after the stop time is told the later time
  EXPECT_EQ(*slow_ptr->setup_stop, time_point(900 * k_ms));
  EXPECT_EQ(*fast_ptr->setup_stop, time_point(700 * k_ms));
  std::vector<double> seen;
  for (int k = 0; k < 7; ++k) {
    algo.step();
    seen.push_back(algo.real_value(y));
  }
  EXPECT_EQ(fast_ptr->step_times.size(), 7u);
  ASSERT_EQ(slow_ptr->step_times.size(), 3u);
  EXPECT_EQ(slow_ptr->step_times[1], time_point(300 * k_ms));
  EXPECT_EQ(slow_ptr->step_sizes[0], 300 * k_ms);
  // the slow output becomes visible when global time reaches the slow component's time
  EXPECT_EQ(seen, (std::vector<double>{0, 0, 1, 1, 1, 2, 2}));
}

TEST(cosim_algorithm, decimated_consumer_sees_the_value_at_its_step_start) {
  auto log = std::make_shared<call_log>();
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  algo.add_component(counter("A", log), 1);
  auto b = latch("B", log);
  auto* b_ptr = b.get();
  algo.add_component(std::move(b), 2);
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"));
  algo.initialize(std::nullopt);
  std::vector<double> latched;
  for (int k = 0; k < 6; ++k) {
    algo.step();
    latched.push_back(b_ptr->r("y"));
  }
  // B steps at k = 0, 2, 4 and reads A at the end of the macro step (Gauss-Seidel)
  EXPECT_EQ(latched, (std::vector<double>{1, 1, 3, 3, 5, 5}));
}

TEST(cosim_algorithm, initialization_propagates_feedthrough_chains_in_order) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  auto src = std::make_unique<mock_component>("src");
  src->real("p", causality::parameter);
  src->real("y", causality::output);
  src->on_update = [](mock_component& s) { s.r("y") = s.r("p"); };
  auto twice = [](const std::string& name) {
    auto m = std::make_unique<mock_component>(name);
    m->real("u", causality::input);
    m->real("y", causality::output, std::vector<std::string>{"u"});
    m->on_update = [](mock_component& s) { s.r("y") = 2 * s.r("u"); };
    return m;
  };
  algo.add_component(twice("second"));
  algo.add_component(twice("first"));
  algo.add_component(std::move(src));
  algo.connect(var(algo, "src", "y"), var(algo, "first", "u"));
  algo.connect(var(algo, "first", "y"), var(algo, "second", "u"));
  algo.set_start_value(var(algo, "src", "p"), 1.5);
  const auto out = algo.observe(var(algo, "second", "y"));
  algo.initialize(std::nullopt);
  EXPECT_EQ(algo.real_value(out), 6.0);
}

TEST(cosim_algorithm, exchanges_every_type) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  auto a = std::make_unique<mock_component>("a");
  a->add("i", variable_type::integer, causality::output);
  a->add("b", variable_type::boolean, causality::output);
  a->add("s", variable_type::string, causality::output);
  a->on_step = [](mock_component& self, time_point, duration) {
    self.i("i") += 7;
    self.b("b") = !self.b("b");
    self.s("s") += "x";
    return step_result::complete;
  };
  auto b = std::make_unique<mock_component>("b");
  b->add("i", variable_type::integer, causality::input);
  b->add("b", variable_type::boolean, causality::input);
  b->add("s", variable_type::string, causality::input);
  auto* b_ptr = b.get();
  algo.add_component(std::move(a));
  algo.add_component(std::move(b));
  for (const char* v : {"i", "b", "s"}) algo.connect(var(algo, "a", v), var(algo, "b", v));
  algo.initialize(std::nullopt);
  algo.step();
  algo.step();
  EXPECT_EQ(b_ptr->i("i"), 14);
  EXPECT_EQ(b_ptr->b("b"), false);
  EXPECT_EQ(b_ptr->s("s"), "xx");
}

TEST(cosim_algorithm, integer_time_is_exact_after_a_million_steps) {
  execution algo(
      std::make_unique<fixed_step_algorithm>(duration(100'000'000), algorithm_kind::gauss_seidel),
      time_point{}, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  auto* mp = m.get();
  algo.add_component(std::move(m));
  algo.initialize(std::nullopt);
  double naive = 0.0;
  for (int k = 0; k < 1'000'000; ++k) {
    algo.step();
    naive += 0.1;
  }
  EXPECT_EQ(algo.current_time().time_since_epoch().count(), 100'000'000'000'000);
  EXPECT_EQ(to_seconds(algo.current_time()), 100000.0);
  EXPECT_EQ(to_seconds(mp->step_times.back()), 99999.9);
  EXPECT_EQ(to_seconds(mp->step_times[3]), 0.3);
  EXPECT_NE(naive, 100000.0);  // what accumulating doubles would have produced
}

// Two independent chains (A → B and C → D, D with multiple 2) plus delayed cross connections
// B → C and D → A: every component's values, after every step, for a thread count.
std::vector<std::vector<double>> run_two_chains(algorithm_kind kind, int threads) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, kind, threads), time_point{},
               quiet_log());
  // y = 3·u + (steps so far), so any wrong read shows in the values
  const auto mixer = [](const std::string& name) {
    auto m = std::make_unique<mock_component>(name);
    m->real("u", causality::input);
    m->real("y", causality::output);
    m->on_step = [](mock_component& self, time_point, duration) {
      self.r("y") = 3 * self.r("u") + static_cast<double>(self.step_times.size());
      return step_result::complete;
    };
    return m;
  };
  for (const char* name : {"A", "B", "C"}) ex.add_component(mixer(name));
  ex.add_component(mixer("D"), 2);
  ex.connect(var(ex, "A", "y"), var(ex, "B", "u"));
  ex.connect(var(ex, "C", "y"), var(ex, "D", "u"));
  ex.connect(var(ex, "B", "y"), var(ex, "C", "u"), {true, {}});
  ex.connect(var(ex, "D", "y"), var(ex, "A", "u"), {true, {}});
  std::vector<observed_variable> ys;
  for (const char* name : {"A", "B", "C", "D"}) ys.push_back(ex.observe(var(ex, name, "y")));
  ex.initialize(std::nullopt);
  std::vector<std::vector<double>> seen;
  for (int k = 0; k < 40; ++k) {
    ex.step();
    seen.emplace_back();
    for (const auto& y : ys) seen.back().push_back(ex.real_value(y));
  }
  return seen;
}

TEST(cosim_algorithm, any_thread_count_gives_the_sequential_values) {
  for (const auto kind : {algorithm_kind::gauss_seidel, algorithm_kind::jacobi}) {
    const auto sequential = run_two_chains(kind, 1);
    EXPECT_NE(sequential.back()[0], sequential.back()[2]);  // the chains differ
    for (int threads : {2, 3, 4}) {
      EXPECT_EQ(run_two_chains(kind, threads), sequential)
          << to_string(kind) << ", " << threads << " threads";
    }
  }
}

TEST(cosim_algorithm, independent_components_step_on_several_threads) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, 2),
               time_point{}, quiet_log());
  // each waits until both are inside a step at the same time (or gives up after a while)
  auto inside = std::make_shared<std::atomic<int>>(0);
  auto met = std::make_shared<std::atomic<bool>>(false);
  for (const char* name : {"left", "right"}) {
    auto m = std::make_unique<mock_component>(name);
    m->on_step = [inside, met](mock_component&, time_point, duration) {
      ++*inside;
      for (int i = 0; i < 2'000'000 && inside->load() < 2; ++i) std::this_thread::yield();
      if (inside->load() == 2) *met = true;
      return step_result::complete;
    };
    ex.add_component(std::move(m));
  }
  ex.initialize(std::nullopt);
  ex.step();
  EXPECT_TRUE(*met) << "the two independent components never stepped at the same time";
}

TEST(cosim_algorithm, a_termination_stops_its_chain_and_the_others_complete_the_step) {
  for (int threads : {1, 2}) {
    auto log = std::make_shared<call_log>();
    execution ex(
        std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, threads),
        time_point{}, quiet_log());
    auto stopper = counter("stopper", log);
    stopper->on_step = [](mock_component& self, time_point, duration) {
      self.r("y") += 1;
      return self.r("y") >= 3 ? step_result::terminate : step_result::complete;
    };
    ex.add_component(std::move(stopper));
    auto after = latch("after", log);
    auto* after_ptr = after.get();
    ex.add_component(std::move(after));
    auto other = counter("other", log);
    auto* other_ptr = other.get();
    ex.add_component(std::move(other));
    ex.connect(var(ex, "stopper", "y"), var(ex, "after", "u"));
    const auto r = ex.simulate_until(time_point(std::chrono::seconds(1)));
    EXPECT_EQ(r.terminated_by, "stopper");
    EXPECT_EQ(r.steps, 2);
    EXPECT_EQ(after_ptr->step_times.size(), 2u) << threads;  // held back in the last step
    EXPECT_EQ(other_ptr->step_times.size(), 3u) << threads;  // independent: completed it
  }
}

TEST(cosim_algorithm, one_step_call_per_component_per_communication_step) {
  chain ch(algorithm_kind::gauss_seidel);
  std::vector<mock_component*> mocks;
  for (std::size_t i = 0; i < 3; ++i) {
    mocks.push_back(dynamic_cast<mock_component*>(&ch.algo.component_at(i)));
  }
  std::vector<int> sets, gets;
  for (auto* m : mocks) {
    sets.push_back(m->set_calls);
    gets.push_back(m->get_calls);
  }
  for (int k = 0; k < 10; ++k) ch.algo.step();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(mocks[i]->step_calls, 10) << mocks[i]->name();
    EXPECT_EQ(mocks[i]->set_calls, sets[i]) << mocks[i]->name();  // nothing besides the step
    EXPECT_EQ(mocks[i]->get_calls, gets[i]) << mocks[i]->name();
  }
}

}  // namespace
}  // namespace stride::cosim
