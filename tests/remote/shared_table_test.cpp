// The shared table over real Cyclone DDS (loopback, in one process): the merge order of
// synchronous rounds, asynchronous merging, the final table, refused updates, agents that rejoin
// from an earlier state, and abandoning.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <span>
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

// Agent 1 adds r to entry 0 in round r, agent 2 adds 10 r to entry 1.
std::vector<double> increment(int agent, std::int64_t round) {
  return {static_cast<double>(round) * (agent == 1 ? 1.0 : 10.0)};
}
const std::vector<std::uint32_t> k_entry1 = {1};
const std::vector<std::uint32_t>& entry_of(int agent) {
  return agent == 1 ? k_entry0 : k_entry1;
}
const std::vector<double> k_zeros = {0.0, 0.0};

void send_round(table_client& c, int agent, std::int64_t round) {
  c.send(round, entry_of(agent), increment(agent, round),
         round == 1 ? std::span<const double>(k_zeros) : std::span<const double>());
}

// A copy of agent 1 made anew from its state after round 2 (its worker was lost) walks rounds 3
// and 4 again: each wait gives the table of that round, not the newest, and nothing counts twice.
TEST(shared_table, a_rejoined_agent_meets_the_tables_of_the_rounds_it_walks_again) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  std::vector<table_snapshot> seen(5);
  for (std::int64_t r = 1; r <= 4; ++r) {
    send_round(a1, 1, r);
    send_round(a2, 2, r);
    seen[static_cast<std::size_t>(r)] = a1.wait_round(r, 10s);
  }
  EXPECT_EQ(seen[4].values, (std::vector<double>{10.0, 100.0}));
  table_client copy(where, 1);
  copy.resume(2, k_entry0, increment(1, 2), k_zeros, false);
  for (std::int64_t r = 2; r <= 4; ++r) {
    if (r > 2) send_round(copy, 1, r);
    const table_snapshot& t = copy.wait_round(r, 10s);
    EXPECT_EQ(t.round, r);
    EXPECT_EQ(t.updates, 2 * r);
    EXPECT_EQ(t.values, seen[static_cast<std::size_t>(r)].values) << "round " << r;
  }
  EXPECT_EQ(service.current().updates, 8);
  EXPECT_EQ(service.current().values, seen[4].values);
  // and it goes on with the others
  send_round(copy, 1, 5);
  send_round(a2, 2, 5);
  EXPECT_EQ(copy.wait_round(5, 10s).values, (std::vector<double>{15.0, 150.0}));
  EXPECT_EQ(service.error(), "");
}

// The copy's state may be older than a round the service holds but has not merged, or newer than
// what reached the service (the lost worker's last update never arrived).
TEST(shared_table, a_rejoined_agent_fits_rounds_not_merged_and_rounds_never_received) {
  const table_endpoint where = endpoint(2, true);
  table_service service(where);
  table_client a1(where, 1), a2(where, 2);
  send_round(a1, 1, 1);
  send_round(a2, 2, 1);
  send_round(a1, 1, 2);  // agent 2 has not sent round 2: not merged
  ASSERT_EQ(a1.wait_round(1, 10s).round, 1);
  table_client copy(where, 1);
  copy.resume(1, k_entry0, increment(1, 1), k_zeros, false);
  EXPECT_EQ(copy.wait_round(1, 10s).values, (std::vector<double>{1.0, 10.0}));
  send_round(copy, 1, 2);  // the same again: waits like the first
  EXPECT_THROW(copy.wait_round(2, 300ms), std::runtime_error);
  send_round(a2, 2, 2);
  EXPECT_EQ(copy.wait_round(2, 10s).values, (std::vector<double>{3.0, 30.0}));
  // a second copy resumes after round 3, which the service never received: it is new
  table_client later(where, 1);
  later.resume(3, k_entry0, increment(1, 3), k_zeros, false);
  send_round(a2, 2, 3);
  const table_snapshot& t = later.wait_round(3, 10s);
  EXPECT_EQ(t.values, (std::vector<double>{6.0, 60.0}));
  EXPECT_EQ(t.updates, 6);
  EXPECT_EQ(service.error(), "");
}

TEST(shared_table, a_round_sent_again_otherwise_stops_the_service) {
  const table_endpoint where = endpoint(1, true);
  table_service service(where);
  table_client a1(where, 1);
  send_round(a1, 1, 1);
  send_round(a1, 1, 2);
  ASSERT_EQ(a1.wait_round(2, 10s).round, 2);
  table_client copy(where, 1);
  copy.resume(1, k_entry0, increment(1, 1), k_zeros, false);
  copy.send(2, k_entry0, std::vector<double>{2.5});
  const auto until = std::chrono::steady_clock::now() + 10s;
  while (service.error().empty() && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_THAT(service.error(), HasSubstr("agent 1 sent round 2 again, different from the first "
                                         "time"));
  EXPECT_THROW(copy.wait_round(3, 10s), std::runtime_error);  // the agent hears of it
  // a copy further on than anything the service has
  const table_endpoint other = endpoint(1, true);
  table_service fresh(other);
  table_client ahead(other, 1);
  ahead.resume(5, k_entry0, increment(1, 5), k_zeros, false);
  EXPECT_THROW(ahead.wait_round(5, 10s), std::runtime_error);
  EXPECT_THAT(fresh.error(), HasSubstr("agent 1 rejoins after round 5, but its last round here "
                                       "is 0"));
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
