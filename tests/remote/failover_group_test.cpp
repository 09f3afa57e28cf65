// A step group whose members have standby workers, with in-process stand-ins for the instances
// (fake_cluster.hpp): the group steps as one unit, and when its worker is lost every member moves
// to the standby and the group goes on there with exactly the outputs it would have had. The real
// thing (worker processes, SIGKILL) is in failover_run_test.cpp.
#include "failover_group.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fake_cluster.hpp"

namespace stride::remote {
namespace {

using test::accumulator;
using test::fake_cluster;
using test::k_dt;
using test::log_capture;
using ::testing::AllOf;
using ::testing::HasSubstr;

const cosim::variable_refs k_refs{{0}, {}, {}, {}};

// a feeds b: b's input is a's output of the same macro step (b steps after a)
cosim::group_layout layout() {
  cosim::group_layout l;
  l.order = {0, 1};
  l.multiples = {1, 1};
  l.base_step = k_dt;
  l.links = {{0, 0, 1, 0, cosim::variable_type::real, false}};
  return l;
}

class failover_group_test : public ::testing::Test {
 protected:
  fake_cluster cluster;
  log_capture log;
  std::shared_ptr<standby_pool> pool;
  std::vector<std::unique_ptr<failover_component>> members;
  std::map<int, std::string> kills;  // step → the worker that dies before it
  int groups_built = 0;

  std::unique_ptr<failover_group> make(std::vector<std::string> standby, int every) {
    pool = std::make_shared<standby_pool>(std::move(standby));
    for (const char* name : {"a", "b"}) {
      auto factory = [this, name](const std::string& worker) -> std::unique_ptr<cosim::component> {
        cluster.check(worker);
        return std::make_unique<accumulator>(cluster, worker, name);
      };
      members.push_back(std::make_unique<failover_component>(factory("w1"), "w1", factory, pool,
                                                             every, log.sink()));
    }
    auto on_worker = [this](const std::vector<cosim::component*>& instances,
                            const std::string&) -> std::unique_ptr<cosim::step_group> {
      ++groups_built;
      return std::make_unique<cosim::local_step_group>(instances);
    };
    return std::make_unique<failover_group>(
        std::vector<failover_component*>{members[0].get(), members[1].get()}, on_worker, pool);
  }

  // a run of the group: both members' outputs after each step
  std::vector<std::pair<double, double>> run(std::vector<cosim::component*> parts,
                                             cosim::step_group& group, int steps) {
    for (auto* c : parts) {
      c->setup(cosim::time_point{}, std::nullopt);
      c->set_values(k_refs, {{0.5}, {}, {}, {}});
      c->expose(k_refs, k_refs);
      c->enter_initialization();
      c->exit_initialization();
    }
    group.arrange(layout());
    const cosim::member_cache start{cosim::time_point{}, {{0.0}, {}, {}, {}}, {{0.0}, {}, {}, {}}};
    const std::vector<cosim::member_cache> caches{start, start};
    group.prepare(caches);
    std::vector<std::pair<double, double>> ys;
    for (int k = 0; k < steps; ++k) {
      if (const auto it = kills.find(k); it != kills.end()) cluster.dead.insert(it->second);
      // b's input slot is fed by the link; the value here must not matter
      const cosim::value_block in_a{{0.1 * k}, {}, {}, {}}, in_b{{-99.0}, {}, {}, {}};
      cosim::value_block out_a{{0.0}, {}, {}, {}}, out_b{{0.0}, {}, {}, {}};
      const std::vector<const cosim::value_block*> inputs{&in_a, &in_b};
      const std::vector<cosim::value_block*> outputs{&out_a, &out_b};
      EXPECT_EQ(group.step(cosim::time_point{} + k * k_dt, k, inputs, outputs), std::nullopt);
      ys.emplace_back(out_a.reals.at(0), out_b.reals.at(0));
    }
    return ys;
  }
  std::vector<std::pair<double, double>> undisturbed(int steps) {
    fake_cluster alone;
    accumulator a(alone, "w1", "a"), b(alone, "w1", "b");
    cosim::local_step_group group({&a, &b});
    const auto saved = kills;
    kills.clear();
    auto ys = run({&a, &b}, group, steps);
    kills = saved;
    return ys;
  }
  std::vector<std::pair<double, double>> run_members(cosim::step_group& group, int steps) {
    return run({members[0].get(), members[1].get()}, group, steps);
  }
};

TEST_F(failover_group_test, without_a_loss_it_steps_as_one_group_and_takes_images) {
  auto group = make({"s1"}, 10);
  EXPECT_EQ(run_members(*group, 30), undisturbed(30));
  EXPECT_EQ(groups_built, 1);
  EXPECT_EQ(cluster.images, 2 * 3);
  EXPECT_TRUE(log.lines.empty()) << log.all();
}

TEST_F(failover_group_test, a_lost_worker_moves_every_member_and_changes_no_output) {
  kills = {{37, "w1"}};
  auto group = make({"s1"}, 10);
  EXPECT_EQ(run_members(*group, 60), undisturbed(60));
  EXPECT_EQ(members[0]->worker(), "s1");
  EXPECT_EQ(members[1]->worker(), "s1");
  EXPECT_EQ(cluster.instances, 4);
  EXPECT_EQ(groups_built, 2);
  ASSERT_EQ(log.lines.size(), 2u) << log.all();
  // b replays the inputs it had on the worker, a's outputs through the link included
  for (const char* name : {"a", "b"}) {
    EXPECT_THAT(log.all(), HasSubstr(std::string(name) +
                                     " [failover] worker 'w1' is lost after t = 0.37 s: continues "
                                     "on standby worker 's1' (from its last state image, 7 steps"));
  }
}

TEST_F(failover_group_test, a_worker_lost_when_an_image_is_taken_is_taken_over) {
  cluster.dies_at_image = "w1";  // the first image, after step 10
  auto group = make({"s1"}, 10);
  EXPECT_EQ(run_members(*group, 25), undisturbed(25));
  EXPECT_EQ(members[0]->worker(), "s1");
  EXPECT_EQ(members[1]->worker(), "s1");
  EXPECT_THAT(log.all(), HasSubstr("(from the start, 10 steps replayed"));
}

TEST_F(failover_group_test, two_losses_in_a_row_use_two_standbys) {
  kills = {{13, "w1"}, {41, "s1"}};
  auto group = make({"s1", "s2"}, 10);
  EXPECT_EQ(run_members(*group, 60), undisturbed(60));
  EXPECT_EQ(members[1]->worker(), "s2");
  EXPECT_EQ(groups_built, 3);
}

// the algorithm calls a member alone too (values, images): a member that fails over there takes
// the others with it before the group steps again
TEST_F(failover_group_test, a_member_that_moved_alone_is_followed_by_the_others) {
  auto group = make({"s1"}, 10);
  const auto reference = undisturbed(20);
  auto first = run_members(*group, 12);
  cluster.dead.insert("w1");
  cosim::value_block y;
  members[1]->get_values(k_refs, y);  // b notices the loss and moves alone
  EXPECT_EQ(members[1]->worker(), "s1");
  EXPECT_EQ(members[0]->worker(), "w1");
  for (int k = 12; k < 20; ++k) {
    const cosim::value_block in_a{{0.1 * k}, {}, {}, {}}, in_b{{-99.0}, {}, {}, {}};
    cosim::value_block out_a{{0.0}, {}, {}, {}}, out_b{{0.0}, {}, {}, {}};
    const std::vector<const cosim::value_block*> inputs{&in_a, &in_b};
    const std::vector<cosim::value_block*> outputs{&out_a, &out_b};
    group->step(cosim::time_point{} + k * k_dt, k, inputs, outputs);
    first.emplace_back(out_a.reals.at(0), out_b.reals.at(0));
  }
  EXPECT_EQ(first, reference);
  EXPECT_EQ(members[0]->worker(), "s1");
  EXPECT_THAT(log.all(), AllOf(HasSubstr("a [failover]"), HasSubstr("b [failover]")));
}

TEST_F(failover_group_test, with_no_standby_left_the_step_ends_with_the_loss) {
  kills = {{5, "w1"}, {9, "s1"}};
  auto group = make({"s1"}, 10);
  test::expect_loss_with_no_standby_left([&] { run_members(*group, 20); }, "s1");
}

}  // namespace
}  // namespace stride::remote
