// Which authentication plugin a secure participant is given: Stride's wrapper, which reports the
// handshakes, when it can be loaded; Cyclone's own otherwise, whose log messages then stay.
#include "dds_security.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "stride/cosim/archive.hpp"

namespace stride::remote::dds {
namespace {

namespace fs = std::filesystem;

void ignore(void*, stride_handshake_event, std::int64_t, const char*, const char*, const char*) {}

// the authentication plugin a participant made with `identity` would load
std::string auth_plugin_of(const fs::path& identity) {
  dds_qos_t* qos = dds_create_qos();
  add_security(qos, identity);
  char* path = nullptr;
  std::string out = dds_qget_prop(qos, "dds.sec.auth.library.path", &path) ? path : "";
  dds_free(path);
  dds_delete_qos(qos);
  return out;
}

TEST(dds_security, a_wrapper_that_cannot_be_loaded_leaves_cyclones_plugin_in_charge) {
  // one process, one wrapper: the broken one first, then the real one
  const cosim::temp_dir scratch{"stride-dds-security-"};
  const fs::path broken = scratch.path() / "libstride_dds_auth.so";
  std::ofstream(broken) << "not a shared library";
  const fs::path identity = scratch.path() / "w1";  // only its file names are read here

  ASSERT_TRUE(watch_handshakes_through(broken, &ignore, nullptr));
  EXPECT_EQ(auth_plugin_of(identity), plugin_path("dds_security_auth"));
  EXPECT_FALSE(handshakes_watched());  // Cyclone's handshake messages are not held back
  EXPECT_EQ(auth_plugin_of(identity), plugin_path("dds_security_auth"));  // not tried again

  ASSERT_TRUE(watch_handshakes_through(STRIDE_AUTH_WATCH_LIBRARY, &ignore, nullptr));
  EXPECT_EQ(auth_plugin_of(identity), STRIDE_AUTH_WATCH_LIBRARY);
  EXPECT_TRUE(handshakes_watched());
  stop_watching_handshakes();
}

}  // namespace
}  // namespace stride::remote::dds
