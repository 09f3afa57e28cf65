// The master algorithm and the execution, driven with mock components (no FMUs).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mock_component.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/observers.hpp"

namespace stride::cosim {
namespace {

using test::call_log;
using test::mock_component;
using ::testing::HasSubstr;

constexpr duration k_ms{1'000'000};

log_sink quiet_log() {
  return [](log_level, std::string_view, std::string_view, std::string_view) {};
}

// y = number of completed steps (no feedthrough)
std::unique_ptr<mock_component> counter(const std::string& name, std::shared_ptr<call_log> log) {
  auto m = std::make_unique<mock_component>(name, std::move(log));
  m->real("y", causality::output);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("y") += 1;
    return step_result::complete;
  };
  return m;
}

// y = the value of u when the step started (latched in the step: no feedthrough)
std::unique_ptr<mock_component> latch(const std::string& name, std::shared_ptr<call_log> log) {
  auto m = std::make_unique<mock_component>(name, std::move(log));
  m->real("u", causality::input);
  m->real("y", causality::output);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("y") = self.r("u");
    return step_result::complete;
  };
  return m;
}

variable_id var(const fixed_step_algorithm& a, const std::string& comp, const std::string& v) {
  const auto c = *a.find_component(comp);
  return {c, *a.component_at(c).model_description().index_of(v)};
}

// A → B → C, declared in reverse so the order must come from the graph
struct chain {
  std::shared_ptr<call_log> log = std::make_shared<call_log>();
  fixed_step_algorithm algo;
  observed_variable a, b, c;

  explicit chain(algorithm_kind kind) : algo(10 * k_ms, kind, quiet_log()) {
    algo.add_component(latch("C", log));
    algo.add_component(latch("B", log));
    algo.add_component(counter("A", log));
    algo.connect(var(algo, "A", "y"), var(algo, "B", "u"));
    algo.connect(var(algo, "B", "y"), var(algo, "C", "u"));
    a = algo.observe(var(algo, "A", "y"));
    b = algo.observe(var(algo, "B", "y"));
    c = algo.observe(var(algo, "C", "y"));
    algo.initialize(time_point{}, std::nullopt);
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
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  algo.add_component(counter("A", log));
  algo.add_component(latch("B", log));
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"), {true, "here"});
  const auto b = algo.observe(var(algo, "B", "y"));
  algo.initialize(time_point{}, std::nullopt);
  for (int k = 0; k < 3; ++k) algo.step();
  EXPECT_EQ(algo.real_value(b), 2.0);
}

TEST(cosim_algorithm, decimation_steps_slow_components_with_a_multiple_of_the_base_step) {
  auto log = std::make_shared<call_log>();
  fixed_step_algorithm algo(100 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  auto fast = counter("fast", log);
  auto slow = counter("slow", log);
  auto* fast_ptr = fast.get();
  auto* slow_ptr = slow.get();
  algo.add_component(std::move(fast), 1);
  algo.add_component(std::move(slow), 3);
  const auto y = algo.observe(var(algo, "slow", "y"));
  algo.initialize(time_point{}, time_point(700 * k_ms));
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
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  algo.add_component(counter("A", log), 1);
  auto b = latch("B", log);
  auto* b_ptr = b.get();
  algo.add_component(std::move(b), 2);
  algo.connect(var(algo, "A", "y"), var(algo, "B", "u"));
  algo.initialize(time_point{}, std::nullopt);
  std::vector<double> latched;
  for (int k = 0; k < 6; ++k) {
    algo.step();
    latched.push_back(b_ptr->r("y"));
  }
  // B steps at k = 0, 2, 4 and reads A at the end of the macro step (Gauss-Seidel)
  EXPECT_EQ(latched, (std::vector<double>{1, 1, 3, 3, 5, 5}));
}

TEST(cosim_algorithm, initialization_propagates_feedthrough_chains_in_order) {
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
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
  algo.initialize(time_point{}, std::nullopt);
  EXPECT_EQ(algo.real_value(out), 6.0);
}

TEST(cosim_algorithm, exchanges_every_type) {
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
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
  algo.initialize(time_point{}, std::nullopt);
  algo.step();
  algo.step();
  EXPECT_EQ(b_ptr->i("i"), 14);
  EXPECT_EQ(b_ptr->b("b"), false);
  EXPECT_EQ(b_ptr->s("s"), "xx");
}

TEST(cosim_algorithm, integer_time_is_exact_after_a_million_steps) {
  fixed_step_algorithm algo(duration(100'000'000), algorithm_kind::gauss_seidel, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  auto* mp = m.get();
  algo.add_component(std::move(m));
  algo.initialize(time_point{}, std::nullopt);
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

TEST(cosim_execution, component_requested_stop_ends_the_run_cleanly) {
  auto algo =
      std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  auto m = counter("stopper", {});
  auto* mp = m.get();
  m->on_step = [](mock_component& self, time_point, duration) {
    if (self.r("y") >= 4) return step_result::terminate;
    self.r("y") += 1;
    return step_result::complete;
  };
  algo->add_component(std::move(m));
  execution ex(std::move(algo), time_point{});
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  EXPECT_TRUE(result.terminated_by_component);
  EXPECT_EQ(result.terminated_by, "stopper");
  EXPECT_EQ(result.end_time, time_point(40 * k_ms));
  EXPECT_EQ(result.steps, 4);
  EXPECT_TRUE(ex.ended());
  EXPECT_TRUE(mp->terminated);
}

TEST(cosim_execution, component_error_names_component_and_time_and_flushes_results) {
  temp_dir dir("stride-test-");
  auto algo =
      std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  auto m = counter("broken", {});
  m->on_step = [](mock_component& self, time_point, duration) -> step_result {
    if (self.r("y") >= 3) throw std::runtime_error("doStep failed");
    self.r("y") += 1;
    return step_result::complete;
  };
  algo->add_component(std::move(m));
  execution ex(std::move(algo), time_point{});
  const auto csv = dir.path() / "out.csv";
  ex.add_observer(std::make_shared<csv_recorder>(csv, std::vector<variable_id>{}));
  try {
    ex.simulate_until(time_point(std::chrono::seconds(1)));
    FAIL() << "no error";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'broken'"));
    EXPECT_THAT(e.what(), HasSubstr("doStep failed"));
    EXPECT_THAT(e.what(), HasSubstr("t = 0.03 s"));
  }
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "time,broken.y\n0,0\n0.01,1\n0.02,2\n0.03,3\n");
}

TEST(cosim_observers, csv_recorder_writes_full_names_and_every_type) {
  temp_dir dir("stride-test-");
  auto algo =
      std::make_unique<fixed_step_algorithm>(250 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  auto m = std::make_unique<mock_component>("m");
  m->real("x", causality::output);
  m->add("n", variable_type::integer, causality::output);
  m->add("flag", variable_type::boolean, causality::output);
  m->add("label", variable_type::string, causality::output);
  m->add("p", variable_type::real, causality::parameter);
  m->on_step = [](mock_component& self, time_point, duration) {
    self.r("x") += 0.1;
    self.i("n") -= 1;
    self.b("flag") = true;
    self.s("label") = "a,\"b\"";
    return step_result::complete;
  };
  algo->add_component(std::move(m));
  execution ex(std::move(algo), time_point{});
  const auto csv = dir.path() / "sub" / "r.csv";
  ex.add_observer(csv_recorder::from_patterns(csv, ex.algorithm(), {"m.*"}, 500 * k_ms));
  const auto result = ex.simulate_until(time_point(std::chrono::seconds(1)));
  ex.end();
  EXPECT_EQ(result.steps, 4);
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  // the parameter is not matched by a wildcard; rows every 0.5 s
  EXPECT_EQ(text.str(),
            "time,m.x,m.n,m.flag,m.label\n"
            "0,0,0,0,\"\"\n"
            "0.5,0.2,-2,1,\"a,\"\"b\"\"\"\n"
            "1,0.4,-4,1,\"a,\"\"b\"\"\"\n");
}

TEST(cosim_observers, recording_interval_must_be_a_multiple_of_the_base_step) {
  auto algo =
      std::make_unique<fixed_step_algorithm>(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  algo->add_component(counter("a", {}));
  execution ex(std::move(algo), time_point{});
  temp_dir dir("stride-test-");
  EXPECT_THROW(ex.add_observer(std::make_shared<csv_recorder>(
                   dir.path() / "x.csv", std::vector<variable_id>{}, 15 * k_ms)),
               validation_error);
}

TEST(cosim_observers, glob_match) {
  EXPECT_TRUE(glob_match("robot.*", "robot.base_x"));
  EXPECT_TRUE(glob_match("*.fallen", "robot.fallen"));
  EXPECT_TRUE(glob_match("gait.joint_angle[?]", "gait.joint_angle[3]"));
  EXPECT_FALSE(glob_match("gait.joint_angle[?]", "gait.joint_angle[13]"));
  EXPECT_TRUE(glob_match("*a*b*", "xxaxxbxx"));
  EXPECT_FALSE(glob_match("robot.*", "gait.x"));
}

TEST(cosim_observers, progress_line_shows_time_rtf_and_eta) {
  progress_display p(time_point(std::chrono::seconds(60)), stderr, false);
  const std::string line = p.format(time_point(std::chrono::seconds(30)), 10.0);
  EXPECT_THAT(line, HasSubstr("t = 30.000 / 60.000 s (50.0%)"));
  EXPECT_THAT(line, HasSubstr("RTF 3.00x"));
  EXPECT_THAT(line, HasSubstr("ETA 10 s"));
}

// ---- validation ----

struct two_components {
  fixed_step_algorithm algo{10 * k_ms, algorithm_kind::gauss_seidel, quiet_log()};
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

std::string freeze_error(fixed_step_algorithm& algo) {
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

TEST(cosim_validation, jacobi_has_no_algebraic_loops) {
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::jacobi, quiet_log());
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
  fixed_step_algorithm algo(
      10 * k_ms, algorithm_kind::gauss_seidel,
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

TEST(cosim_validation, frozen_topology_cannot_change) {
  two_components s;
  s.algo.freeze();
  EXPECT_THROW(s.algo.add_component(std::make_unique<mock_component>("c")), validation_error);
  EXPECT_THROW(s.algo.connect(s.v("a", "y"), s.v("b", "u")), validation_error);
}

TEST(cosim_validation, duplicate_component_names_and_bad_multiples) {
  fixed_step_algorithm algo(10 * k_ms, algorithm_kind::gauss_seidel, quiet_log());
  algo.add_component(std::make_unique<mock_component>("a"));
  EXPECT_THROW(algo.add_component(std::make_unique<mock_component>("a")), validation_error);
  EXPECT_THROW(algo.add_component(std::make_unique<mock_component>("b"), 0), validation_error);
}

// ---- time ----

TEST(cosim_time, parse_duration_is_exact) {
  EXPECT_EQ(parse_duration("0.008").count(), 8'000'000);
  EXPECT_EQ(parse_duration("60").count(), 60'000'000'000);
  EXPECT_EQ(parse_duration("1e-3").count(), 1'000'000);
  EXPECT_EQ(parse_duration("2.5E+1").count(), 25'000'000'000);
  EXPECT_EQ(parse_duration("-0.5").count(), -500'000'000);
  EXPECT_EQ(parse_duration("0.000000001").count(), 1);
  EXPECT_EQ(parse_duration("0").count(), 0);
  EXPECT_EQ(parse_duration(".25").count(), 250'000'000);
  EXPECT_THROW(parse_duration("0.0000000001"), std::invalid_argument);
  EXPECT_THROW(parse_duration("abc"), std::invalid_argument);
  EXPECT_THROW(parse_duration("1s"), std::invalid_argument);
  EXPECT_THROW(parse_duration(""), std::invalid_argument);
  EXPECT_THROW(parse_duration("1e30"), std::out_of_range);
}

TEST(cosim_time, format_seconds_round_trips) {
  for (const char* s : {"0", "0.008", "60", "-1.5", "99999.9", "0.000000001"}) {
    EXPECT_EQ(format_seconds(parse_duration(s)), s);
  }
  EXPECT_EQ(duration_from_seconds(0.008).count(), 8'000'000);
}

TEST(cosim_scalar, parse_and_format) {
  EXPECT_EQ(std::get<double>(parse_scalar(variable_type::real, "1.5")), 1.5);
  EXPECT_EQ(std::get<int>(parse_scalar(variable_type::integer, "-3")), -3);
  EXPECT_EQ(std::get<bool>(parse_scalar(variable_type::boolean, "true")), true);
  EXPECT_EQ(std::get<bool>(parse_scalar(variable_type::boolean, "0")), false);
  EXPECT_EQ(std::get<std::string>(parse_scalar(variable_type::string, "a b")), "a b");
  EXPECT_THROW(parse_scalar(variable_type::real, "abc"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::integer, "1.5"), std::invalid_argument);
  EXPECT_THROW(parse_scalar(variable_type::boolean, "yes"), std::invalid_argument);
  EXPECT_EQ(format_scalar(0.1), "0.1");
}

}  // namespace
}  // namespace stride::cosim
