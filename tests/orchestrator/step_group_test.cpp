// Step groups: components stepped as one unit give exactly the values they give stepped one by
// one, in any algorithm, with decimation, delays and threads; the grouping rules of the builder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "execution_fixtures.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/step_group.hpp"
#include "stride/cosim/system_builder.hpp"

namespace stride::cosim::test {
namespace {

using ::testing::HasSubstr;

// y = 3·u + v/2 + t: stateless, so that only the algorithm's and the group's caches carry the
// past
std::unique_ptr<mock_component> mixer(const std::string& name) {
  auto m = std::make_unique<mock_component>(name);
  m->real("u", causality::input);
  m->real("v", causality::input);
  m->real("y", causality::output);
  m->on_step = [](mock_component& self, time_point t, duration) {
    self.r("y") = 3 * self.r("u") + self.r("v") / 2 + to_seconds(t);
    return step_result::complete;
  };
  return m;
}

// counts the calls and passes them on to a local group
class counting_group final : public step_group {
 public:
  explicit counting_group(std::vector<component*> members) : local_(std::move(members)) {}
  void arrange(group_layout layout) override {
    layout_ = layout;
    local_.arrange(std::move(layout));
  }
  void prepare(std::span<const member_cache> members) override {
    ++prepares;
    local_.prepare(members);
  }
  std::optional<std::size_t> step(time_point t, std::int64_t index,
                                  std::span<const value_block* const> inputs,
                                  std::span<value_block* const> outputs) override {
    ++steps;
    return local_.step(t, index, inputs, outputs);
  }
  int prepares = 0;
  int steps = 0;
  group_layout layout_;

 private:
  local_step_group local_;
};

// A → B → C → D → E in one step (D every second base step), E → A and D → C delayed (to C's
// second input); groups {A, B} and {C, D} when `grouped`. Every component's y after every step.
struct five {
  execution ex;
  std::vector<observed_variable> ys;
  std::vector<counting_group*> groups;

  five(algorithm_kind kind, int threads, bool grouped)
      : ex(std::make_unique<fixed_step_algorithm>(10 * k_ms, kind, threads), time_point{},
           quiet_log()) {
    for (const char* name : {"A", "B", "C", "D", "E"}) {
      ex.add_component(mixer(name), std::string(name) == "D" ? 2 : 1);
    }
    ex.connect(var(ex, "A", "y"), var(ex, "B", "u"));
    ex.connect(var(ex, "B", "y"), var(ex, "C", "u"));
    ex.connect(var(ex, "C", "y"), var(ex, "D", "u"));
    ex.connect(var(ex, "D", "y"), var(ex, "E", "u"));
    ex.connect(var(ex, "E", "y"), var(ex, "A", "u"), {true, {}});
    ex.connect(var(ex, "D", "y"), var(ex, "C", "v"), {true, {}});
    if (grouped) {
      for (const auto& pair : {std::vector<std::size_t>{0, 1}, std::vector<std::size_t>{2, 3}}) {
        auto g = std::make_unique<counting_group>(
            std::vector<component*>{&ex.component_at(pair[0]), &ex.component_at(pair[1])});
        groups.push_back(g.get());
        ex.add_group(pair, std::move(g));
      }
    }
    for (const char* name : {"A", "B", "C", "D", "E"}) ys.push_back(ex.observe(var(ex, name, "y")));
    ex.initialize(std::nullopt);
  }
  std::vector<std::vector<double>> run(int steps) {
    std::vector<std::vector<double>> seen;
    for (int k = 0; k < steps; ++k) {
      ex.step();
      seen.emplace_back();
      for (const auto& y : ys) seen.back().push_back(ex.real_value(y));
    }
    return seen;
  }
};

TEST(cosim_step_group, grouped_components_give_the_values_they_give_one_by_one) {
  for (const auto kind : {algorithm_kind::gauss_seidel, algorithm_kind::jacobi}) {
    const auto alone = five(kind, 1, false).run(30);
    EXPECT_NE(alone[29][0], alone[29][4]);
    for (int threads : {1, 2}) {
      five grouped(kind, threads, true);
      EXPECT_EQ(grouped.run(30), alone) << to_string(kind) << ", " << threads << " threads";
      for (const auto* g : grouped.groups) {
        EXPECT_EQ(g->steps, 30);
        EXPECT_EQ(g->prepares, 1);
      }
      // each member stepped inside its group, D every second step
      EXPECT_EQ(dynamic_cast<mock_component&>(grouped.ex.component_at(1)).step_calls, 30);
      EXPECT_EQ(dynamic_cast<mock_component&>(grouped.ex.component_at(3)).step_calls, 15);
    }
  }
}

TEST(cosim_step_group, the_group_gets_its_order_multiples_and_links) {
  five f(algorithm_kind::gauss_seidel, 1, true);
  const group_layout& cd = f.groups[1]->layout_;
  EXPECT_EQ(cd.order, (std::vector<std::size_t>{0, 1}));  // C before D
  EXPECT_EQ(cd.multiples, (std::vector<int>{1, 2}));
  EXPECT_EQ(cd.base_step, 10 * k_ms);
  ASSERT_EQ(cd.links.size(), 2u);  // C.y → D.u and D.y → C.v; D.y → E.u leaves the group
  EXPECT_EQ(cd.links[0].from, 0u);
  EXPECT_EQ(cd.links[0].to, 1u);
  EXPECT_FALSE(cd.links[0].previous);
  EXPECT_EQ(cd.links[1].from, 1u);
  EXPECT_TRUE(cd.links[1].previous);
  five j(algorithm_kind::jacobi, 1, true);
  EXPECT_TRUE(j.groups[0]->layout_.links.at(0).previous);  // Jacobi reads the previous point
}

TEST(cosim_step_group, a_member_ending_the_run_holds_back_the_members_after_it) {
  for (int threads : {1, 2}) {
    execution ex(
        std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, threads),
        time_point{}, quiet_log());
    auto stopper = counter("stopper", nullptr);
    stopper->on_step = [](mock_component& self, time_point, duration) {
      self.r("y") += 1;
      return self.r("y") >= 3 ? step_result::terminate : step_result::complete;
    };
    ex.add_component(std::move(stopper));
    auto after = latch("after", nullptr);
    auto* after_ptr = after.get();
    ex.add_component(std::move(after));
    auto other = counter("other", nullptr);
    auto* other_ptr = other.get();
    ex.add_component(std::move(other));
    ex.connect(var(ex, "stopper", "y"), var(ex, "after", "u"));
    ex.add_group({0, 1}, std::make_unique<local_step_group>(
                             std::vector<component*>{&ex.component_at(0), &ex.component_at(1)}));
    const auto r = ex.simulate_until(time_point(std::chrono::seconds(1)));
    EXPECT_EQ(r.terminated_by, "stopper");
    EXPECT_EQ(r.steps, 2);
    EXPECT_EQ(after_ptr->step_times.size(), 2u) << threads;  // held back in the last step
    EXPECT_EQ(other_ptr->step_times.size(), 3u) << threads;  // outside the group: completed it
  }
}

TEST(cosim_step_group, a_restore_hands_the_group_the_restored_caches) {
  // the algorithm alone: the mocks keep no state, the algorithm and the group do
  fixed_step_algorithm algo(10 * k_ms);
  std::vector<std::unique_ptr<mock_component>> parts;
  for (const char* name : {"A", "B"}) parts.push_back(mixer(name));
  system_wiring w;
  for (auto& p : parts) w.components.push_back(p.get());
  w.step_multiples = {1, 1};
  w.starts.resize(2);
  const auto y = *parts[0]->model_description().index_of("y");
  const auto u = *parts[0]->model_description().index_of("u");
  w.connections.push_back({{0, y}, {1, u}, {}});
  w.connections.push_back({{1, y}, {0, u}, {true, {}}});
  counting_group group({parts[0].get(), parts[1].get()});
  w.groups.push_back({{0, 1}, &group});
  const auto order = algo.stepping_order(w);
  algo.setup(w, order);
  const auto b = algo.observe({1, y});
  algo.initialize(time_point{}, std::nullopt);
  for (int k = 0; k < 5; ++k) algo.step(time_point(k * 10 * k_ms));
  const std::any saved = algo.save_state();
  std::vector<double> first, again;
  for (int k = 5; k < 10; ++k) {
    algo.step(time_point(k * 10 * k_ms));
    first.push_back(algo.real_value(b));
  }
  algo.restore_state(saved);
  for (int k = 5; k < 10; ++k) {
    algo.step(time_point(k * 10 * k_ms));
    again.push_back(algo.real_value(b));
  }
  EXPECT_EQ(again, first);
  EXPECT_EQ(group.prepares, 2);
}

TEST(cosim_step_group, groups_are_refused_for_overlaps_and_misuse) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  for (const char* name : {"A", "B", "C"}) ex.add_component(mixer(name));
  const auto group_of = [&](std::vector<std::size_t> m) {
    std::vector<component*> parts;
    for (std::size_t i : m) parts.push_back(&ex.component_at(i));
    return std::make_unique<local_step_group>(parts);
  };
  EXPECT_THROW(ex.add_group({0}, group_of({0})), validation_error);
  EXPECT_THROW(ex.add_group({0, 7}, group_of({0})), validation_error);
  ex.add_group({0, 1}, group_of({0, 1}));
  try {
    ex.add_group({1, 2}, group_of({1, 2}));
    ADD_FAILURE() << "overlapping groups accepted";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'B' is already in a step group"));
  }
}

// the builder's rule: connected components on one worker, unless a same-step cycle runs through
// a component elsewhere
TEST(cosim_step_group, worker_groups_are_connected_sets_off_same_step_cycles) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  for (const char* name : {"A", "B", "X", "C", "D", "E"}) ex.add_component(mixer(name));
  // A → X → B with A, B on w1: A and B are not connected to each other: no group
  ex.connect(var(ex, "A", "y"), var(ex, "X", "u"));
  ex.connect(var(ex, "X", "y"), var(ex, "B", "u"));
  // C → D on w2, D → E here, E → C delayed: no same-step cycle, a group
  ex.connect(var(ex, "C", "y"), var(ex, "D", "u"));
  ex.connect(var(ex, "D", "y"), var(ex, "E", "u"));
  ex.connect(var(ex, "E", "y"), var(ex, "C", "u"), {true, {}});
  const std::vector<std::string> workers{"w1", "w1", "", "w2", "w2", ""};
  EXPECT_EQ(worker_groups(ex, workers, algorithm_kind::gauss_seidel),
            (std::vector<std::vector<std::size_t>>{{3, 4}}));
  // B → A too: now A, B are connected, but X lies on A → X → B → A within the step
  ex.connect(var(ex, "B", "y"), var(ex, "A", "u"), {true, {}});
  EXPECT_EQ(worker_groups(ex, workers, algorithm_kind::gauss_seidel),
            (std::vector<std::vector<std::size_t>>{{3, 4}}))
      << "A and B are connected now, but A → X → B runs through X within the step";
  execution loop(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  for (const char* name : {"A", "B", "X"}) loop.add_component(mixer(name));
  loop.connect(var(loop, "A", "y"), var(loop, "B", "u"));
  loop.connect(var(loop, "B", "y"), var(loop, "X", "u"));
  loop.connect(var(loop, "X", "y"), var(loop, "A", "u"));
  const std::vector<std::string> two{"w", "w", ""};
  EXPECT_TRUE(worker_groups(loop, two, algorithm_kind::gauss_seidel).empty());
  EXPECT_EQ(worker_groups(loop, two, algorithm_kind::jacobi),
            (std::vector<std::vector<std::size_t>>{{0, 1}}));  // Jacobi: no same-step values
}

// a group's links carry values as they are: members joined by a transforming connection step
// through the algorithm, which applies factor and offset
TEST(cosim_step_group, a_transforming_connection_keeps_its_ends_out_of_a_group) {
  execution ex(std::make_unique<fixed_step_algorithm>(10 * k_ms), time_point{}, quiet_log());
  for (const char* name : {"A", "B", "C", "D"}) ex.add_component(mixer(name));
  ex.connect(var(ex, "A", "y"), var(ex, "B", "u"), {false, {}, 2.0, 0.0});
  ex.connect(var(ex, "C", "y"), var(ex, "D", "u"), {false, {}, 1.0, 0.0});
  const std::vector<std::string> workers{"w", "w", "w", "w"};
  EXPECT_EQ(worker_groups(ex, workers, algorithm_kind::gauss_seidel),
            (std::vector<std::vector<std::size_t>>{{2, 3}}));
}

}  // namespace
}  // namespace stride::cosim::test
