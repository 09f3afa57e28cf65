// Cyclone's repeated handshake failures become one line per peer and reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stride/remote/refused_peers.hpp"

namespace stride::remote {
namespace {

const std::string k_failure =
    "fsm: Begin handshake reply failed: Certificate not valid: error: unable to get local "
    "issuer certificate; subject: /O=Stride keystore 1a2b3c4d/CN=intruder(code: 200)\n";

TEST(refused_peer_log, a_handshake_failure_is_said_once_per_peer_and_reason) {
  std::vector<std::string> lines;
  refused_peer_log log([&](const std::string& l) { lines.push_back(l); });
  EXPECT_EQ(log.refusal(k_failure),
            "refused peer /O=Stride keystore 1a2b3c4d/CN=intruder: unable to get local issuer "
            "certificate (DDS Security handshake)");
  EXPECT_EQ(log.refusal(k_failure), "");  // Cyclone repeats it about twice a second
  std::string expired = k_failure;
  expired.replace(expired.find("unable to get local issuer certificate"), 38,
                  "certificate has expired");
  EXPECT_THAT(log.refusal(expired), ::testing::HasSubstr("certificate has expired"));
  ASSERT_EQ(lines.size(), 2u);
}

TEST(refused_peer_log, other_messages_are_not_refusals) {
  std::vector<std::string> lines;
  refused_peer_log log([&](const std::string& l) { lines.push_back(l); });
  EXPECT_EQ(log.refusal("config: //CycloneDDS/Domain/General: deprecated element"), "");
  EXPECT_EQ(log.refusal("handshake with a peer completed"), "");
  EXPECT_TRUE(lines.empty());
}

}  // namespace
}  // namespace stride::remote
