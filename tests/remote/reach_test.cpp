// Which DDS configurations let other hosts reach a worker: only those that keep every interface
// and peer on loopback do not.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "stride/remote/reach.hpp"

namespace stride::remote {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class reach : public ::testing::Test {
 protected:
  void SetUp() override {
    ::unsetenv("CYCLONEDDS_URI");
    dir_ = fs::temp_directory_path() /
           ("stride-reach-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    ::unsetenv("CYCLONEDDS_URI");
    fs::remove_all(dir_);
  }

  dds_settings config(const std::string& general, const std::string& peers = "") {
    const fs::path file = dir_ / "dds.xml";
    std::ofstream(file) << "<CycloneDDS xmlns=\"https://cdds.io/config\"><Domain Id=\"any\">"
                        << "<General>" << general << "</General><Discovery><Peers>" << peers
                        << "</Peers></Discovery></Domain></CycloneDDS>";
    dds_settings s;
    s.config_file = file;
    return s;
  }

  fs::path dir_;
};

TEST_F(reach, the_shipped_loopback_configuration_stays_on_this_machine) {
  EXPECT_EQ(reach_beyond_loopback(dds_settings{}), "");
}

TEST_F(reach, a_configuration_on_loopback_with_local_peers_stays) {
  EXPECT_EQ(reach_beyond_loopback(
                config("<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>",
                       "<Peer address=\"localhost\"/>")),
            "");
  EXPECT_EQ(reach_beyond_loopback(config("<NetworkInterfaceAddress>lo</NetworkInterfaceAddress>")),
            "");
}

TEST_F(reach, a_network_interface_or_a_far_peer_reaches_beyond) {
  EXPECT_THAT(
      reach_beyond_loopback(config("<Interfaces><NetworkInterface name=\"eth0\"/></Interfaces>")),
      HasSubstr("network interface 'eth0'"));
  EXPECT_THAT(reach_beyond_loopback(
                  config("<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>",
                         "<Peer address=\"10.0.0.2\"/>")),
              HasSubstr("peer '10.0.0.2'"));
}

TEST_F(reach, no_interface_or_autodetermine_reaches_beyond) {
  EXPECT_THAT(reach_beyond_loopback(config("<AllowMulticast>false</AllowMulticast>")),
              HasSubstr("does not restrict DDS to the loopback interface"));
  EXPECT_THAT(reach_beyond_loopback(
                  config("<Interfaces><NetworkInterface autodetermine=\"true\"/></Interfaces>")),
              HasSubstr("does not restrict"));
}

TEST_F(reach, variables_are_expanded_as_cyclone_does) {
  ::setenv("STRIDE_REACH_TEST_IFACE", "lo", 1);
  EXPECT_EQ(
      reach_beyond_loopback(config(
          "<Interfaces><NetworkInterface name=\"${STRIDE_REACH_TEST_IFACE}\"/></Interfaces>")),
      "");
  ::setenv("STRIDE_REACH_TEST_IFACE", "eth1", 1);
  EXPECT_THAT(
      reach_beyond_loopback(config(
          "<Interfaces><NetworkInterface name=\"${STRIDE_REACH_TEST_IFACE}\"/></Interfaces>")),
      HasSubstr("'eth1'"));
  ::unsetenv("STRIDE_REACH_TEST_IFACE");
}

TEST_F(reach, cyclonedds_uri_inline_or_file_is_read_when_no_file_is_given) {
  ::setenv("CYCLONEDDS_URI",
           "<General><Interfaces><NetworkInterface name=\"eth0\"/>"
           "</Interfaces></General>",
           1);
  EXPECT_THAT(reach_beyond_loopback(dds_settings{}), HasSubstr("CYCLONEDDS_URI"));
  const dds_settings local =
      config("<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>");
  ::setenv("CYCLONEDDS_URI", ("file://" + local.config_file.string()).c_str(), 1);
  EXPECT_EQ(reach_beyond_loopback(dds_settings{}), "");
}

TEST_F(reach, an_unreadable_configuration_is_taken_to_reach_beyond) {
  dds_settings s;
  s.config_file = dir_ / "missing.xml";
  EXPECT_THAT(reach_beyond_loopback(s), HasSubstr("cannot be read"));
  std::ofstream(dir_ / "bad.xml") << "<CycloneDDS><General>";
  s.config_file = dir_ / "bad.xml";
  EXPECT_THAT(reach_beyond_loopback(s), HasSubstr("cannot be read"));
}

}  // namespace
}  // namespace stride::remote
