// The failover layer on its own: in-process stand-ins for instances on workers, which fail with
// worker_lost when their worker is "killed". The real thing (worker processes, SIGKILL) is in
// failover_run_test.cpp.
#include "failover_component.hpp"

#include "fake_cluster.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace stride::remote {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

using test::accumulator;
using test::fake_cluster;
using test::k_dt;
using test::log_capture;

class failover : public ::testing::Test {
 protected:
  fake_cluster cluster;
  log_capture log;
  // kill: worker → the step before which it dies
  std::map<int, std::string> kills;

  std::unique_ptr<failover_component> make(std::vector<std::string> standby, int every) {
    auto factory = [this](const std::string& worker) -> std::unique_ptr<cosim::component> {
      cluster.check(worker);
      if (cluster.refusing.contains(worker)) {
        throw cosim::component_error("worker '" + worker + "' refuses the archive");
      }
      return std::make_unique<accumulator>(cluster, worker);
    };
    return std::make_unique<failover_component>(factory("w1"), "w1", factory,
                                                std::make_shared<standby_pool>(std::move(standby)),
                                                every, log.sink());
  }
  // a whole run of `steps` steps: the outputs after each
  std::vector<double> run(cosim::component& c, int steps) {
    const cosim::variable_refs refs{{0}, {}, {}, {}};
    c.setup(cosim::time_point{}, std::nullopt);
    c.set_values(refs, {{0.5}, {}, {}, {}});
    c.expose(refs, refs);
    c.enter_initialization();
    c.exit_initialization();
    std::vector<double> ys;
    for (int k = 0; k < steps; ++k) {
      if (const auto it = kills.find(k); it != kills.end()) cluster.dead.insert(it->second);
      if (k == steps / 2) c.set_values(refs, {{0.25}, {}, {}, {}});  // a parameter changed mid-run
      cosim::value_block out;
      c.step(cosim::time_point{} + k * k_dt, k_dt, {{0.1 * k}, {}, {}, {}}, out);
      ys.push_back(out.reals.at(0));
    }
    c.terminate();
    return ys;
  }
  std::vector<double> undisturbed(int steps) {
    fake_cluster alone;
    accumulator a(alone, "w1");
    auto saved = kills;
    kills.clear();
    auto ys = run(a, steps);
    kills = saved;
    return ys;
  }
};

TEST_F(failover, a_lost_worker_changes_no_output_and_is_logged_once) {
  kills = {{37, "w1"}};
  auto c = make({"s1"}, 10);
  EXPECT_EQ(run(*c, 60), undisturbed(60));
  EXPECT_EQ(c->worker(), "s1");
  EXPECT_EQ(cluster.instances, 2);
  ASSERT_EQ(log.lines.size(), 1u) << log.all();
  EXPECT_THAT(log.lines[0],
              AllOf(HasSubstr("acc [failover] worker 'w1' is lost after t = 0.37 s"),
                    HasSubstr("continues on standby worker 's1' (from its last state image, "
                              "7 steps replayed in ")));
}

TEST_F(failover, images_are_taken_every_n_steps) {
  auto c = make({"s1"}, 10);
  run(*c, 60);
  EXPECT_EQ(cluster.images, 6);
}

TEST_F(failover, before_the_first_image_the_instance_is_rebuilt_from_the_start) {
  kills = {{4, "w1"}};
  auto c = make({"s1"}, 10);
  EXPECT_EQ(run(*c, 20), undisturbed(20));
  EXPECT_THAT(log.all(), HasSubstr("(from the start, 4 steps replayed"));
}

TEST_F(failover, two_losses_in_a_row_use_two_standbys) {
  kills = {{13, "w1"}, {41, "s1"}};
  auto c = make({"s1", "s2"}, 10);
  EXPECT_EQ(run(*c, 60), undisturbed(60));
  EXPECT_EQ(c->worker(), "s2");
  EXPECT_EQ(log.lines.size(), 2u) << log.all();
  EXPECT_THAT(log.all(), AllOf(HasSubstr("worker 'w1' is lost"), HasSubstr("worker 's1' is lost"),
                               HasSubstr("continues on standby worker 's2'")));
}

TEST_F(failover, a_standby_lost_during_the_replay_is_replaced_by_the_next) {
  kills = {{25, "w1"}};
  cluster.dead.insert("s1");  // gone before it was needed
  auto c = make({"s1", "s2"}, 10);
  EXPECT_EQ(run(*c, 40), undisturbed(40));
  EXPECT_EQ(c->worker(), "s2");
  EXPECT_THAT(log.all(), HasSubstr("worker 'w1' is lost after t = 0.25 s (and so is standby "
                                   "worker 's1'): continues on standby worker 's2'"));
}

TEST_F(failover, a_standby_that_refuses_is_skipped_with_a_warning) {
  kills = {{25, "w1"}};
  cluster.refusing.insert("s1");
  auto c = make({"s1", "s2"}, 10);
  EXPECT_EQ(run(*c, 40), undisturbed(40));
  EXPECT_EQ(c->worker(), "s2");
  EXPECT_THAT(log.all(), HasSubstr("standby worker 's1' cannot take over: worker 's1' refuses"));
}

TEST_F(failover, with_no_standby_left_the_run_ends_with_the_loss) {
  kills = {{10, "w1"}, {20, "s1"}};
  auto c = make({"s1"}, 10);
  test::expect_loss_with_no_standby_left([&] { run(*c, 40); }, "s1");
}

TEST_F(failover, a_loss_during_initialization_is_taken_over) {
  cluster.dead.clear();
  auto c = make({"s1"}, 10);
  const cosim::variable_refs refs{{0}, {}, {}, {}};
  c->setup(cosim::time_point{}, std::nullopt);
  c->set_values(refs, {{0.5}, {}, {}, {}});
  c->expose(refs, refs);
  c->enter_initialization();
  cluster.dead.insert("w1");
  c->exit_initialization();  // replays setup, the value, expose and enter first
  cosim::value_block out;
  c->step(cosim::time_point{}, k_dt, {{1.0}, {}, {}, {}}, out);
  EXPECT_DOUBLE_EQ(out.reals.at(0), 1.5 * 0.01);
  EXPECT_EQ(c->worker(), "s1");
  EXPECT_THAT(log.all(), Not(HasSubstr("after t =")));  // no step had been made
}

TEST_F(failover, the_orchestrators_own_restore_is_where_a_replay_starts) {
  auto c = make({"s1"}, 1000);
  const cosim::variable_refs refs{{0}, {}, {}, {}};
  c->setup(cosim::time_point{}, std::nullopt);
  c->set_values(refs, {{1.0}, {}, {}, {}});
  c->expose(refs, refs);
  c->enter_initialization();
  c->exit_initialization();
  cosim::value_block out;
  for (int k = 0; k < 5; ++k)
    c->step(cosim::time_point{} + k * k_dt, k_dt, {{0.0}, {}, {}, {}}, out);
  const std::vector<std::byte> image = c->save_state();  // y = 0.05
  for (int k = 5; k < 9; ++k)
    c->step(cosim::time_point{} + k * k_dt, k_dt, {{0.0}, {}, {}, {}}, out);
  c->restore_state(image);  // back to y = 0.05, as a resumed run does
  cluster.dead.insert("w1");
  c->step(cosim::time_point{} + 5 * k_dt, k_dt, {{0.0}, {}, {}, {}}, out);
  EXPECT_DOUBLE_EQ(out.reals.at(0), 0.06);
  EXPECT_THAT(log.all(), HasSubstr("from its last state image, 0 steps replayed"));
}

TEST_F(failover, a_worker_lost_before_the_run_is_replaced_at_once) {
  cluster.dead.insert("w1");
  auto factory = [this](const std::string& worker) -> std::unique_ptr<cosim::component> {
    cluster.check(worker);
    return std::make_unique<accumulator>(cluster, worker);
  };
  auto c = failover_component::start("w1", factory,
                                     std::make_shared<standby_pool>(std::vector<std::string>{"s1"}),
                                     10, log.sink());
  EXPECT_EQ(c->worker(), "s1");
  EXPECT_THAT(log.all(), HasSubstr("acc [failover] worker 'w1' was lost before the run: starts "
                                   "on standby worker 's1'"));
  EXPECT_EQ(run(*c, 20), undisturbed(20));
  cluster.dead.insert("s1");
  try {
    failover_component::start(
        "s1", factory, std::make_shared<standby_pool>(std::vector<std::string>{}), 10, log.sink());
    FAIL() << "no standby";
  } catch (const worker_lost&) {
    FAIL() << "a run that cannot start is no loss to take over";
  } catch (const cosim::component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("worker 's1' is gone; no standby worker is left"));
  }
}

TEST(standby_pool, the_components_of_one_lost_worker_move_to_one_standby) {
  standby_pool pool({"s1", "s2"});
  EXPECT_EQ(pool.replacement_for("w1"), "s1");
  EXPECT_EQ(pool.replacement_for("w1"), "s1");
  EXPECT_EQ(pool.replacement_for("w2"), "s2");
  EXPECT_EQ(pool.replacement_for("s1"), std::nullopt);
  EXPECT_EQ(pool.failovers(), 2);
  pool.discard("s1");
  EXPECT_EQ(pool.replacement_for("w1"), std::nullopt);  // s1 refused, s2 is taken
}

}  // namespace
}  // namespace stride::remote
