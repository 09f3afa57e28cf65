// Validation of connections and the stepping order, through an execution with mock components.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "execution_fixtures.hpp"
#include "stride/cosim/connection_graph.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {
namespace {

using namespace test;
using ::testing::HasSubstr;

struct two_components {
  execution algo{std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log()};
  two_components() {
    for (const char* name : {"a", "b"}) {
      auto m = std::make_unique<mock_component>(name);
      m->real("u", causality::input);
      m->real("v", causality::input);
      m->real("y", causality::output, std::vector<std::string>{"u"});  // feedthrough from u
      m->real("z", causality::output);                                 // none
      m->add("n", variable_type::integer, causality::output);
      m->add("p", variable_type::real, causality::parameter);
      algo.add_component(std::move(m));
    }
  }
  variable_id v(const std::string& comp, const std::string& name) const {
    return var(algo, comp, name);
  }
};

std::string freeze_error(execution& algo) {
  try {
    algo.freeze();
  } catch (const validation_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(cosim_validation, connection_must_go_from_output_to_input) {
  two_components s;
  s.algo.connect(s.v("a", "u"), s.v("b", "u"), {false, "sys.xml:7"});
  EXPECT_THAT(freeze_error(s.algo),
              HasSubstr("sys.xml:7: connection a.u -> b.u: source a.u is input"));
}

TEST(cosim_validation, connection_must_end_at_an_input_or_parameter) {
  two_components s;
  s.algo.connect(s.v("a", "y"), s.v("b", "z"), {false, "sys.xml:8"});
  EXPECT_THAT(freeze_error(s.algo), HasSubstr("target b.z is output"));
}

TEST(cosim_validation, types_must_match) {
  two_components s;
  s.algo.connect(s.v("a", "n"), s.v("b", "u"), {false, "sys.xml:9"});
  EXPECT_THAT(freeze_error(s.algo),
              HasSubstr("sys.xml:9: connection a.n -> b.u: type mismatch, a.n is Integer but b.u "
                        "is Real"));
}

TEST(cosim_validation, an_input_is_driven_once) {
  two_components s;
  s.algo.connect(s.v("a", "y"), s.v("b", "u"), {false, "sys.xml:3"});
  s.algo.connect(s.v("a", "z"), s.v("b", "u"), {false, "sys.xml:4"});
  EXPECT_THAT(freeze_error(s.algo),
              HasSubstr("sys.xml:4: input b.u is driven twice: by a.y (sys.xml:3) and by a.z"));
}

TEST(cosim_validation, algebraic_loop_is_spelled_out) {
  two_components s;
  s.algo.connect(s.v("a", "y"), s.v("b", "u"), {false, "sys.xml:3"});
  s.algo.connect(s.v("b", "y"), s.v("a", "u"), {false, "sys.xml:4"});
  const std::string message = freeze_error(s.algo);
  EXPECT_THAT(message, HasSubstr("algebraic loop"));
  EXPECT_THAT(message, HasSubstr("a.y -> b.u => b.y -> a.u => a.y"));
  EXPECT_THAT(message, HasSubstr("sys.xml:3, sys.xml:4"));
}

TEST(cosim_validation, loop_without_feedthrough_is_fine_and_keeps_declaration_order) {
  two_components s;
  s.algo.connect(s.v("a", "z"), s.v("b", "u"));
  s.algo.connect(s.v("b", "y"), s.v("a", "u"));  // b.y depends on b.u, but a.z not on a.u
  EXPECT_EQ(freeze_error(s.algo), "no error");
  EXPECT_EQ(s.algo.order(), (std::vector<std::size_t>{0, 1}));
}

TEST(cosim_validation, a_delay_breaks_an_algebraic_loop) {
  two_components s;
  s.algo.connect(s.v("a", "y"), s.v("b", "u"));
  s.algo.connect(s.v("b", "y"), s.v("a", "u"), {true, {}});
  EXPECT_EQ(freeze_error(s.algo), "no error");
  EXPECT_EQ(s.algo.order(), (std::vector<std::size_t>{0, 1}));
}

// the consumer is declared before its producer and feeds it back through a delay: the delayed
// edge must not constrain the order, so the producer steps first although declared second
TEST(cosim_validation, a_delayed_back_edge_lets_a_later_declared_producer_step_first) {
  two_components s;
  s.algo.connect(s.v("b", "y"), s.v("a", "u"));
  s.algo.connect(s.v("a", "y"), s.v("b", "u"), {true, {}});
  EXPECT_EQ(freeze_error(s.algo), "no error");
  EXPECT_EQ(s.algo.order(), (std::vector<std::size_t>{1, 0}));
}

TEST(cosim_validation, jacobi_has_no_algebraic_loops) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::jacobi),
                 time_point{}, quiet_log());
  for (const char* name : {"a", "b"}) {
    auto m = std::make_unique<mock_component>(name);
    m->real("u", causality::input);
    m->real("y", causality::output, std::nullopt);  // depends on everything
    algo.add_component(std::move(m));
  }
  algo.connect(var(algo, "a", "y"), var(algo, "b", "u"));
  algo.connect(var(algo, "b", "y"), var(algo, "a", "u"));
  EXPECT_EQ(freeze_error(algo), "no error");
}

TEST(cosim_validation, self_loop_through_feedthrough) {
  two_components s;
  s.algo.connect(s.v("a", "y"), s.v("a", "u"));
  EXPECT_THAT(freeze_error(s.algo), HasSubstr("a.y -> a.u => a.y"));
}

TEST(cosim_validation, unit_mismatch_is_a_warning) {
  std::vector<std::string> warnings;
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{},
                 [&](log_level l, std::string_view, std::string_view, std::string_view m) {
                   if (l == log_level::warning) warnings.emplace_back(m);
                 });
  auto a = std::make_unique<mock_component>("a");
  a->add("y", variable_type::real, causality::output, std::vector<std::string>{}, "mm");
  auto b = std::make_unique<mock_component>("b");
  b->add("u", variable_type::real, causality::input, std::nullopt, "m");
  algo.add_component(std::move(a));
  algo.add_component(std::move(b));
  algo.connect(var(algo, "a", "y"), var(algo, "b", "u"));
  EXPECT_EQ(freeze_error(algo), "no error");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("unit mismatch, 'mm' -> 'm'"));
}

TEST(cosim_validation, start_values_only_for_parameters_and_inputs) {
  two_components s;
  EXPECT_THROW(s.algo.set_start_value(s.v("a", "y"), 1.0), validation_error);
  EXPECT_THROW(s.algo.set_start_value(s.v("a", "n"), 1), validation_error);
  EXPECT_THROW(s.algo.set_start_value(s.v("a", "p"), std::string("x")), validation_error);
  EXPECT_NO_THROW(s.algo.set_start_value(s.v("a", "p"), 2.0));
  EXPECT_NO_THROW(s.algo.set_start_value(s.v("a", "u"), 2.0));
}

// the connection sets its target at initialization: a value given to it would be lost silently
TEST(cosim_validation, a_value_for_a_variable_a_connection_drives_is_refused_naming_both) {
  two_components s;
  s.algo.set_start_value(s.v("b", "u"), 2.0, "--set b.u=2");
  s.algo.set_start_value(s.v("b", "v"), 3.0, "sys.xml:4");  // not driven: fine
  s.algo.connect(s.v("a", "z"), s.v("b", "u"), {true, "sys.xml:9"});
  EXPECT_EQ(freeze_error(s.algo),
            "--set b.u=2: b.u is given a value, but the connection a.z -> b.u (sys.xml:9) drives "
            "it and would overwrite it: remove the value or the connection");
  two_components parameter;
  parameter.algo.set_start_value(parameter.v("b", "p"), 2.0, "sys.xml:5");
  parameter.algo.connect(parameter.v("a", "z"), parameter.v("b", "p"), {false, "sys.xml:10"});
  EXPECT_THAT(freeze_error(parameter.algo),
              HasSubstr("sys.xml:5: b.p is given a value, but the connection a.z -> b.p "
                        "(sys.xml:10) drives it"));
}

TEST(cosim_validation, frozen_topology_cannot_change) {
  two_components s;
  s.algo.freeze();
  EXPECT_THROW(s.algo.add_component(std::make_unique<mock_component>("c")), validation_error);
  EXPECT_THROW(s.algo.connect(s.v("a", "y"), s.v("b", "u")), validation_error);
}

TEST(cosim_validation, duplicate_component_names_and_bad_multiples) {
  execution algo(std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel),
                 time_point{}, quiet_log());
  algo.add_component(std::make_unique<mock_component>("a"));
  EXPECT_THROW(algo.add_component(std::make_unique<mock_component>("a")), validation_error);
  EXPECT_THROW(algo.add_component(std::make_unique<mock_component>("b"), 0), validation_error);
}

// The documented tie-break: among components free to step, the lowest declaration index goes
// first, and a feedback group ranks by its first member (expected orders worked out by hand).
TEST(cosim_step_plan, ties_go_to_the_lowest_declaration_index) {
  // 3 -> 0; 2 <-> 4 a cycle without feedthrough; 1 and 5 alone
  std::vector<connection> c = {{{3, 0}, {0, 0}, {}}, {{2, 0}, {4, 0}, {}}, {{4, 0}, {2, 1}, {}}};
  // free at the start: 1, {2,4}, 3, 5 -> 1; then {2,4}; then 3, which frees 0 (0 < 5); then 5
  EXPECT_EQ(gauss_seidel_order(6, c), (std::vector<std::size_t>{1, 2, 4, 3, 0, 5}));
  // with 3 -> 0 delayed nothing holds 0 back: declaration order, the group's members together
  // at the place of its first member
  c[0].options.delayed = true;
  EXPECT_EQ(gauss_seidel_order(6, c), (std::vector<std::size_t>{0, 1, 2, 4, 3, 5}));
}

TEST(cosim_step_plan, independent_chains_become_tasks_and_chains_merge) {
  // 0 → 1 → 2, 3 → 4, 5 alone; 2 → 3 delayed (no same-step dependency)
  std::vector<connection> c = {{{0, 0}, {1, 0}, {}},
                               {{1, 0}, {2, 0}, {}},
                               {{3, 0}, {4, 0}, {}},
                               {{2, 0}, {3, 0}, {true, {}}}};
  const auto order = gauss_seidel_order(6, c);
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  const step_plan plan = plan_steps(order, c, false);
  EXPECT_EQ(plan.tasks, (std::vector<std::vector<std::size_t>>{{0, 1, 2}, {3, 4}, {5}}));
  EXPECT_EQ(plan.predecessor_count, (std::vector<int>{0, 0, 0}));
}

TEST(cosim_step_plan, a_join_keeps_its_predecessors_and_a_cycle_stays_one_task) {
  // 0 → 2 ← 1: 2 waits for both; 3 ⇄ 4 (a feedback cycle without feedthrough) is one group
  std::vector<connection> c = {
      {{0, 0}, {2, 0}, {}}, {{1, 0}, {2, 1}, {}}, {{3, 0}, {4, 0}, {}}, {{4, 0}, {3, 1}, {}}};
  const auto order = gauss_seidel_order(5, c);
  const step_plan plan = plan_steps(order, c, false);
  ASSERT_EQ(plan.tasks.size(), 4u);
  EXPECT_EQ(plan.tasks[0], (std::vector<std::size_t>{0}));
  EXPECT_EQ(plan.tasks[1], (std::vector<std::size_t>{1}));
  EXPECT_EQ(plan.tasks[2], (std::vector<std::size_t>{2}));
  EXPECT_EQ(plan.tasks[3], (std::vector<std::size_t>{3, 4}));
  EXPECT_EQ(plan.predecessor_count, (std::vector<int>{0, 0, 2, 0}));
  EXPECT_EQ(plan.successors[0], (std::vector<std::size_t>{2}));
  // Jacobi: every component on its own
  EXPECT_EQ(plan_steps({0, 1, 2, 3, 4}, c, true).tasks.size(), 5u);
}

}  // namespace
}  // namespace stride::cosim
