// The shared table over real Cyclone DDS (loopback, in one process): the merge order of
// synchronous rounds, asynchronous merging, the final table, refused updates and abandoning.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

#include "stride/remote/shared_table.hpp"

namespace stride::remote {
namespace {

using namespace std::chrono_literals;
using ::testing::HasSubstr;

constexpr int k_domain = 80;  // the other DDS tests use other domains

table_endpoint endpoint(int agents, bool synchronous) {
  table_endpoint e;
  e.domain = k_domain;
  e.table = unique_table_name("test");
  e.agents = agents;
  e.synchronous = synchronous;
  return e;
}

const std::vector<std::uint32_t> k_entry0 = {0};

TEST(table_endpoint, round_trips_through_its_text) {
  table_endpoint e = endpoint(3, false);
  e.config_file = "/etc/dds.xml";
  const table_endpoint back = table_endpoint::parse(e.str());
  EXPECT_EQ(back.domain, e.domain);
  EXPECT_EQ(back.table, e.table);
  EXPECT_EQ(back.agents, 3);
  EXPECT_FALSE(back.synchronous);
  EXPECT_EQ(back.config_file, e.config_file);
}

TEST(table_endpoint, names_what_is_wrong) {
  const auto message = [](const char* text) {
    try {
      table_endpoint::parse(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message("tcp;table=a"), HasSubstr("does not start with 'dds;'"));
  EXPECT_THAT(message("dds;domain=0"), HasSubstr("has no table="));
  EXPECT_THAT(message("dds;table=a;agents=0"), HasSubstr("agents '0'"));
  EXPECT_THAT(message("dds;table=a;domain=231"), HasSubstr("domain '231'"));
  EXPECT_THAT(message("dds;table=a;mode=sometimes"), HasSubstr("mode 'sometimes'"));
  EXPECT_THAT(message("dds;table=a;colour=red"), HasSubstr("unknown key 'colour'"));
  EXPECT_THAT(message("dds;table=a;agents"), HasSubstr("is not key=value"));
}

// Floating-point addition is not associative: 1e16 + 1 + 1 differs from 1 + 1 + 1e16. Agent 2
// sends first, but a synchronous round adds agent 1's increment first.
TEST(shared_table, a_synchronous_round_merges_in_agent_order_whatever_arrives_first) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  const std::vector<double> initial = {1.0, 5.0};
  const std::vector<double> big = {1e16}, one = {1.0};
  a2.send(1, k_entry0, one, initial);
  // agent 1 has not sent: round 1 is not merged
  EXPECT_THROW(a2.wait_round(1, 300ms), std::runtime_error);
  a1.send(1, k_entry0, big, initial);
  const table_snapshot& t = a2.wait_round(1, 10s);
  EXPECT_EQ(t.round, 1);
  EXPECT_EQ(t.updates, 2);
  ASSERT_EQ(t.values.size(), 2u);
  EXPECT_EQ(t.values[0], (1.0 + 1e16) + 1.0);
  EXPECT_NE(t.values[0], (1.0 + 1.0) + 1e16);
  EXPECT_EQ(t.values[1], 5.0);
  EXPECT_EQ(a1.wait_round(1, 10s).values, t.values);
  EXPECT_EQ(a1.wait_round(0, 10s).values.size(), 0u);  // round 0: nothing to wait for
}

TEST(shared_table, the_final_table_comes_after_every_agents_last_round) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  const std::vector<double> initial = {0.0};
  const std::vector<double> inc = {0.5};
  a1.send(1, k_entry0, inc, initial);
  a2.send(1, k_entry0, inc, initial);
  a1.send(2, k_entry0, inc, {}, true);
  EXPECT_THROW(a1.wait_final(300ms), std::runtime_error);
  a2.send(2, k_entry0, inc, {}, true);
  const table_snapshot& t = a1.wait_final(10s);
  EXPECT_TRUE(t.final);
  EXPECT_EQ(t.round, 2);
  EXPECT_EQ(t.values, std::vector<double>{2.0});
  EXPECT_EQ(service.current().values, t.values);
}

TEST(shared_table, asynchronous_updates_are_merged_as_they_arrive) {
  const table_endpoint where = endpoint(2, false);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  const std::vector<double> initial = {0.0, 0.0};
  const std::vector<double> inc = {1.0};
  const std::vector<std::uint32_t> entry1 = {1};
  a1.send(1, k_entry0, inc, initial);
  a1.send(2, k_entry0, inc, {}, true);
  // no waiting for agent 2: both of agent 1's updates are merged
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (a1.wait_round(2, 0ms).updates < 2 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_EQ(a1.wait_round(2, 0ms).values, (std::vector<double>{2.0, 0.0}));
  a2.send(1, entry1, inc, initial, true);
  const table_snapshot& t = a2.wait_final(10s);
  EXPECT_EQ(t.updates, 3);
  EXPECT_EQ(t.values, (std::vector<double>{2.0, 1.0}));
}

TEST(shared_table, refused_updates_stop_the_service_and_reach_every_agent) {
  const std::vector<double> initial = {0.0};
  const std::vector<double> inc = {1.0};
  {
    const table_endpoint where = endpoint(2, true);
    table_service service(where);
    table_client a1(where, 1), a2(where, 2);
    a1.send(1, k_entry0, inc, initial);
    a2.send(1, k_entry0, inc, std::vector<double>{3.0});  // another initial table
    try {
      a1.wait_round(1, 10s);
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("agent 2's initial table differs"));
    }
    EXPECT_THAT(service.error(), HasSubstr("initial table differs"));
  }
  {
    const table_endpoint where = endpoint(1, true);
    table_service service(where);
    table_client a1(where, 1);
    a1.send(2, k_entry0, inc, initial);  // round 1 skipped
    EXPECT_THROW(a1.wait_round(2, 10s), std::runtime_error);
    EXPECT_THAT(service.error(), HasSubstr("agent 1 sent round 2 after round 0"));
  }
  {
    const table_endpoint where = endpoint(1, true);
    table_service service(where);
    table_client a1(where, 1);
    const std::vector<std::uint32_t> outside = {7};
    a1.send(1, outside, inc, initial);
    EXPECT_THROW(a1.wait_round(1, 10s), std::runtime_error);
    EXPECT_THAT(service.error(), HasSubstr("entry 7 is outside the 1-entry table"));
  }
  EXPECT_THROW(table_client(endpoint(2, true), 3), std::invalid_argument);
}

TEST(shared_table, a_lost_agent_is_left_out_of_later_rounds) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  const std::vector<double> initial = {0.0};
  a1.send(1, k_entry0, std::vector<double>{1.0}, initial);
  a2.send(1, k_entry0, std::vector<double>{2.0}, initial);
  a1.send(2, k_entry0, std::vector<double>{4.0}, {}, true);
  EXPECT_EQ(a1.wait_round(1, 10s).values, std::vector<double>{3.0});
  EXPECT_THROW(a1.wait_round(2, 300ms), std::runtime_error);  // waits for agent 2
  service.leave_out(2);
  // agent 2's round 1 counts; round 2 and the final table come without it
  const table_snapshot& t = a1.wait_final(10s);
  EXPECT_EQ(t.round, 2);
  EXPECT_EQ(t.updates, 3);
  EXPECT_EQ(t.values, std::vector<double>{7.0});
}

TEST(shared_table, abandoning_releases_waiting_agents_at_once) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1);
  a1.send(1, k_entry0, std::vector<double>{1.0}, std::vector<double>{0.0});
  std::thread stopper([&] {
    std::this_thread::sleep_for(200ms);
    service.abandon("agent 2 failed: gone");
  });
  const auto start = std::chrono::steady_clock::now();
  try {
    a1.wait_round(1, 60s);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("agent 2 failed: gone"));
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, 30s);
  stopper.join();
}

TEST(shared_table, a_client_without_a_service_gives_up_with_a_clear_error) {
  try {
    table_client lonely(endpoint(1, true), 1, 300ms);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("no service answered"));
  }
}

}  // namespace
}  // namespace stride::remote
