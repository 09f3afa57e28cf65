// The handshake events of the wrapper plugin become one line per refused peer, on either side of
// the handshake.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stride/remote/refused_peers.hpp"

namespace stride::remote {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using clock = refused_peer_log::clock;

const std::string k_intruder = "/O=Stride keystore 1a2b3c4d/CN=intruder";
const std::string k_other_ca = "/O=Stride keystore 1a2b3c4d/CN=Stride CA";

struct refused_peers : ::testing::Test {
  std::vector<std::string> lines;
  refused_peer_log log{[this](const std::string& l) { lines.push_back(l); },
                       std::chrono::seconds(3)};
};

TEST_F(refused_peers, a_refused_certificate_is_said_once_with_the_reason) {
  // as Cyclone's plugin says it: the subject of the certificate it refused is in the reason
  const std::string reason =
      "Certificate not valid: error: unable to get local issuer certificate; subject: " +
      k_intruder;
  log.on_event(handshake_event::failed, 7, "participant 01", "", reason);
  log.on_event(handshake_event::failed, 7, "participant 01", "", reason);  // asked again
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "refused peer " + k_intruder +
                          ": unable to get local issuer certificate (DDS Security handshake)");
  log.on_event(handshake_event::failed, 8, k_intruder, k_other_ca, "certificate has expired");
  ASSERT_EQ(lines.size(), 2u);  // another participant of the same identity is another peer
  EXPECT_THAT(lines[1], HasSubstr("certificate has expired"));
}

TEST_F(refused_peers, a_peer_that_answers_is_not_refused) {
  log.on_event(handshake_event::requested, 3, k_intruder, k_other_ca, "");
  log.on_event(handshake_event::authenticated, 3, k_intruder, k_other_ca, "");
  log.check_unanswered(clock::now() + std::chrono::seconds(60));
  log.on_event(handshake_event::ended, 3, "", "", "");
  EXPECT_TRUE(lines.empty());
}

TEST_F(refused_peers, a_peer_that_does_not_answer_in_time_is_said_with_its_ca) {
  log.on_event(handshake_event::requested, 4, k_intruder, k_other_ca, "");
  log.check_unanswered(clock::now() + std::chrono::seconds(1));
  EXPECT_TRUE(lines.empty());  // still within the time it has to answer
  log.check_unanswered(clock::now() + std::chrono::seconds(4));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_THAT(lines[0], AllOf(HasSubstr("refused peer " + k_intruder + " (its CA: " + k_other_ca +
                                        "): it did not answer"),
                              HasSubstr("does not trust this identity")));
  log.check_unanswered(clock::now() + std::chrono::seconds(8));
  log.on_event(handshake_event::ended, 4, "", "", "");
  EXPECT_EQ(lines.size(), 1u);
}

TEST_F(refused_peers, a_peer_that_leaves_after_its_time_to_answer_is_said_at_once) {
  refused_peer_log quick([this](const std::string& l) { lines.push_back(l); },
                         std::chrono::milliseconds(50));
  // Cyclone 0.10's identity tokens name no certificate: the participant is named instead
  quick.on_event(handshake_event::requested, 5, "participant 0a0b0c0d:01020304:05060708:000001c1",
                 "", "");
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  quick.on_event(handshake_event::ended, 5, "", "", "");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_THAT(lines[0], HasSubstr("refused peer participant 0a0b0c0d:01020304:05060708:000001c1: "
                                  "it did not answer"));
}

TEST_F(refused_peers, a_peer_that_leaves_within_its_time_to_answer_is_not_said) {
  log.on_event(handshake_event::requested, 5, k_intruder, "", "");
  log.on_event(handshake_event::ended, 5, "", "", "");
  EXPECT_TRUE(lines.empty());
}

TEST_F(refused_peers, a_peer_whose_time_to_answer_passed_is_said_when_the_process_ends) {
  {
    refused_peer_log ending([this](const std::string& l) { lines.push_back(l); },
                            std::chrono::milliseconds(50));
    ending.on_event(handshake_event::requested, 9, k_intruder, "", "");
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
  }  // (the timer looks every 250 ms: this end comes before it)
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_THAT(lines[0], HasSubstr("refused peer " + k_intruder + ": it did not answer"));
}

TEST_F(refused_peers, a_peer_asked_just_now_is_not_said_when_the_process_ends) {
  {
    refused_peer_log ending([this](const std::string& l) { lines.push_back(l); });
    ending.on_event(handshake_event::requested, 9, k_intruder, "", "");
  }
  EXPECT_TRUE(lines.empty());
}

TEST_F(refused_peers, the_timer_says_an_unanswered_peer_by_itself) {
  refused_peer_log quick([this](const std::string& l) { lines.push_back(l); },
                         std::chrono::milliseconds(1));
  quick.on_event(handshake_event::requested, 6, k_intruder, k_other_ca, "");
  for (int i = 0; i < 400 && lines.empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(lines.size(), 1u);
}

}  // namespace
}  // namespace stride::remote
