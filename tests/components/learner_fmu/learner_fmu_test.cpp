// learner.fmu imported by libstride and driven by a scripted fake plant (a mock component in the
// master algorithm): it must find the known optimum of a synthetic speed map, reproduce its V
// table from the seed, and report bad settings naming the parameter.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../../orchestrator/mock_component.hpp"
#include "raw_fmu.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/run.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::mock_component;
using ::testing::HasSubstr;

const fs::path k_learner_fmu = fs::path(STRIDE_FMU_DIR) / "learner.fmu";

// A plant with a synthetic speed map over (period_time, swing_right_left): one footstep every
// period/2 ms, speed peaking at (600 ms, 25 mm); with swing 35 mm it falls after one footstep.
// Any change of `reset` puts it back at the origin.
std::unique_ptr<mock_component> make_plant() {
  auto p = std::make_unique<mock_component>("plant");
  p->real("period_time", causality::input);
  p->real("swing_right_left", causality::input);
  p->add("reset", variable_type::integer, causality::input);
  p->real("base_x", causality::output);
  p->real("base_y", causality::output);
  p->add("fallen", variable_type::boolean, causality::output);
  p->add("footsteps", variable_type::integer, causality::output);
  p->real("phase", causality::local);
  p->add("applied_reset", variable_type::integer, causality::local);
  p->on_step = [](mock_component& m, time_point, duration dt) {
    if (m.i("reset") != m.i("applied_reset")) {
      m.i("applied_reset") = m.i("reset");
      m.r("base_x") = 0;
      m.i("footsteps") = 0;
      m.b("fallen") = false;
      m.r("phase") = 0;
    }
    const double period = m.r("period_time"), swing = m.r("swing_right_left");
    const double h = to_seconds(dt);
    const double speed = 0.25 - 0.1 * std::pow((period - 600) / 150, 2) -
                         0.1 * std::pow((swing - 25) / 10, 2);  // m/s
    m.r("phase") += h;
    if (m.r("phase") >= period / 2000) {
      m.r("phase") -= period / 2000;
      m.i("footsteps") += 1;
      if (swing >= 35) m.b("fallen") = true;
    }
    if (!m.b("fallen")) m.r("base_x") += speed * h;
    return step_result::complete;
  };
  return p;
}

struct learner_run {
  std::vector<double> values;  // the V table as the learner wrote it (v_table.csv, V column)
  std::string best;
  std::string log;
  int rl_steps = 0;
};

std::string read_all(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

learner_run run_with_plant(const fs::path& out, int seed, int total_steps) {
  auto f = fmu::load(k_learner_fmu);
  instance_options io;
  auto log = std::make_shared<std::string>();
  io.log = [log](log_level, std::string_view, std::string_view, std::string_view m) {
    *log += std::string(m) + "\n";
  };
  execution algo(std::make_unique<fixed_step_algorithm>(parse_duration("0.02")));
  const auto plant = algo.add_component(make_plant());
  const auto learner = algo.add_component(f->instantiate("learner", io));
  auto var = [&](std::size_t c, const std::string& name) {
    const auto index = algo.component_at(c).model_description().index_of(name);
    if (!index) throw std::runtime_error("no variable " + name);
    return variable_id{c, *index};
  };
  algo.connect(var(plant, "base_x"), var(learner, "base_x"));
  algo.connect(var(plant, "base_y"), var(learner, "base_y"));
  algo.connect(var(plant, "fallen"), var(learner, "fallen"));
  algo.connect(var(plant, "footsteps"), var(learner, "footsteps"));
  algo.connect(var(learner, "value[1]"), var(plant, "period_time"));
  algo.connect(var(learner, "value[2]"), var(plant, "swing_right_left"));
  algo.connect(var(learner, "reset_robot"), var(plant, "reset"));
  algo.set_start_value(var(learner, "grid"),
                       std::string("period_time:450:750:50,swing_right_left:15:35:5"));
  algo.set_start_value(var(learner, "seed"), seed);
  algo.set_start_value(var(learner, "total_steps"), total_steps);
  algo.set_start_value(var(learner, "steps_per_episode"), 20);
  algo.set_start_value(var(learner, "footsteps_per_step"), 1);
  algo.set_start_value(var(learner, "settle_footsteps"), 0);
  algo.set_start_value(var(learner, "output_dir"), out.string());
  algo.set_start_value(var(learner, "progress_interval"), 0.0);
  algo.initialize(std::nullopt);
  learner_run r;
  for (int i = 0; i < 10'000'000; ++i) {
    const auto outcome = algo.step();
    if (outcome.terminated) break;
  }
  algo.end();
  std::istringstream table(read_all(out / "v_table.csv"));
  std::string line;
  std::getline(table, line);
  while (std::getline(table, line)) r.values.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  r.best = read_all(out / "best.txt");
  r.log = *log;
  std::istringstream steps(read_all(out / "steps.csv"));
  while (std::getline(steps, line)) ++r.rl_steps;
  --r.rl_steps;  // header
  return r;
}

TEST(learner_fmu, finds_the_optimum_of_a_synthetic_speed_map) {
  temp_dir scratch("stride-learner-fmu-");
  const auto r = run_with_plant(scratch.path() / "a", 1, 3000);
  EXPECT_EQ(r.rl_steps, 3000);
  ASSERT_EQ(r.values.size(), 35u);
  EXPECT_THAT(r.best, HasSubstr("best state: period_time = 600, swing_right_left = 25"));
  EXPECT_FALSE(fs::exists(scratch.path() / "a" / "config.ini"));  // the gait's business
  // the falling row (swing 35) ends up far below the rest
  for (int p = 0; p < 7; ++p) {
    EXPECT_LT(r.values[static_cast<std::size_t>(4 * 7 + p)], 0.0) << p;
  }
  EXPECT_THAT(r.log, HasSubstr("RL step 3000/3000"));
}

TEST(learner_fmu, same_seed_gives_a_bit_identical_value_table) {
  temp_dir scratch("stride-learner-fmu-");
  const auto a = run_with_plant(scratch.path() / "a", 7, 600);
  const auto b = run_with_plant(scratch.path() / "b", 7, 600);
  const auto c = run_with_plant(scratch.path() / "c", 8, 600);
  EXPECT_EQ(read_all(scratch.path() / "a" / "v_table.csv"),
            read_all(scratch.path() / "b" / "v_table.csv"));
  EXPECT_EQ(read_all(scratch.path() / "a" / "episodes.csv"),
            read_all(scratch.path() / "b" / "episodes.csv"));
  EXPECT_NE(read_all(scratch.path() / "a" / "v_table.csv"),
            read_all(scratch.path() / "c" / "v_table.csv"));
}

std::string initialization_error(const std::string& var, scalar_value value) {
  auto f = fmu::load(k_learner_fmu);
  instance_options io;
  auto log = std::make_shared<std::string>();
  io.log = [log](log_level, std::string_view, std::string_view, std::string_view m) {
    *log += std::string(m) + "\n";
  };
  auto c = f->instantiate("learner", io);
  const auto& md = c->model_description();
  const auto* v = md.find(var);
  if (v == nullptr) return "no variable " + var;
  try {
    c->setup(time_point{}, std::nullopt);
    variable_refs refs;
    value_block in;
    if (auto* s = std::get_if<std::string>(&value)) {
      refs.strings = {v->reference};
      in.strings = {*s};
    } else if (auto* i = std::get_if<int>(&value)) {
      refs.integers = {v->reference};
      in.integers = {*i};
    } else if (auto* d = std::get_if<double>(&value)) {
      refs.reals = {v->reference};
      in.reals = {*d};
    }
    c->set_values(refs, in);
    c->enter_initialization();
    c->exit_initialization();
  } catch (const std::exception& e) {
    return *log + e.what();
  }
  return "(no error)";
}

TEST(learner_fmu, bad_settings_fail_initialization_naming_the_parameter) {
  EXPECT_THAT(initialization_error("grid", std::string("period_time:450:960")),
              HasSubstr("grid dimension 'period_time:450:960': expected name:min:max:step"));
  EXPECT_THAT(initialization_error("grid", std::string("period_time:960:450:15")),
              HasSubstr("max < min"));
  // the learner knows no gait: what its values mean is checked by the study (tests/study)
  EXPECT_EQ(initialization_error("grid", std::string("period_time:-15:960:15")), "(no error)");
  EXPECT_THAT(initialization_error("eval_point", std::string("600,abc")),
              HasSubstr("eval_point: 'abc' is not a finite number"));
  EXPECT_THAT(initialization_error("snapshot_steps", std::string("1000,-5")),
              HasSubstr("snapshot_steps: '-5'"));
  EXPECT_THAT(initialization_error("output_dir", std::string("${output_dir}")),
              HasSubstr("unsubstituted"));
  EXPECT_THAT(initialization_error("alpha", 1.5), HasSubstr("alpha"));
  EXPECT_THAT(initialization_error("resume", std::string("/no/such/dir/checkpoint.bin")),
              HasSubstr("(no error)"));  // no checkpoint yet: a fresh start, with a warning
}

TEST(learner_fmu, placeholders_are_substituted_and_unknown_ones_rejected) {
  system_structure s;
  auto& c = s.add_component("learner", "learner");
  s.set("learner.output_dir", "${output_dir}/P1");
  s.set("learner.resume", "${resume}");
  EXPECT_EQ(substitute_placeholders(s, "/runs/a", ""), 1u);
  EXPECT_EQ(c.parameters[0].value, "/runs/a/P1");
  EXPECT_EQ(c.parameters[1].value, "");
  s.set("learner.resume", "${resume}");
  substitute_placeholders(s, "/runs/a", "/runs/a");
  EXPECT_EQ(c.parameters[1].value, "/runs/a");
  s.set("learner.grid", "${grid}");
  EXPECT_THROW(substitute_placeholders(s, "/x", ""), validation_error);
}

TEST(learner_fmu, protocols_give_their_documented_settings_and_explicit_sets_win) {
  stride::test::raw_fmu f(k_learner_fmu);
  // values are readable from initialization mode on
  const auto enter_initialization = [&f](fmi2Component c) {
    ASSERT_EQ(f.fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
    ASSERT_EQ(f.fmi2EnterInitializationMode(c), fmi2OK) << f.last_message();
  };
  fmi2Component paper = f.instantiate("paper");  // the default
  enter_initialization(paper);
  EXPECT_EQ(f.real(paper, "lambda"), 0.05);
  EXPECT_EQ(f.real(paper, "negative_reward"), -400.0);
  EXPECT_EQ(f.integer(paper, "steps_per_episode"), 40);
  EXPECT_EQ(f.integer(paper, "settle_footsteps"), 1);
  EXPECT_EQ(f.real(paper, "speed_cap"), 0.0);
  EXPECT_TRUE(f.boolean(paper, "balance"));

  fmi2Component authors = f.instantiate("authors");
  ASSERT_EQ(f.set_real(authors, "alpha", 0.2), fmi2OK);
  ASSERT_EQ(f.set_string(authors, "protocol", "authors-code"), fmi2OK);
  ASSERT_EQ(f.set_integer(authors, "max_falls", 5), fmi2OK);
  enter_initialization(authors);
  EXPECT_EQ(f.real(authors, "lambda"), 0.3);
  EXPECT_EQ(f.real(authors, "negative_reward"), -200.0);
  EXPECT_EQ(f.integer(authors, "steps_per_episode"), 30);
  EXPECT_EQ(f.integer(authors, "settle_footsteps"), 0);
  EXPECT_EQ(f.real(authors, "speed_cap"), 30.0);
  EXPECT_EQ(f.real(authors, "capped_reward"), 50.0);
  EXPECT_EQ(f.real(authors, "k1"), std::pow(10.0, 1e-6) / 3);
  EXPECT_FALSE(f.boolean(authors, "balance"));
  EXPECT_EQ(f.real(authors, "alpha"), 0.2);  // set explicitly, before or after: kept
  EXPECT_EQ(f.integer(authors, "max_falls"), 5);

  fmi2Component bad = f.instantiate("bad");
  EXPECT_EQ(f.set_string(bad, "protocol", "webots"), fmi2Error);
  EXPECT_TRUE(f.logged("protocol 'webots' is not a learner protocol (paper, authors-code)"))
      << f.last_message();
}

}  // namespace
}  // namespace stride::cosim
