// Where remote components are looked for: the DDS domain and its configuration.
#ifndef STRIDE_REMOTE_SETTINGS_HPP
#define STRIDE_REMOTE_SETTINGS_HPP

#include <chrono>
#include <filesystem>

namespace stride::remote {

/// The DDS domain of a run and its workers.
struct dds_settings {
  int domain = 0;
  /// A Cyclone DDS configuration file. Empty: CYCLONEDDS_URI when it is set, else the shipped
  /// loopback configuration (this machine only, no multicast).
  std::filesystem::path config_file;
};

/// The shipped loopback configuration (remote/config/loopback.xml), as text.
const char* loopback_config();

/// How long the orchestrator waits.
struct timeouts {
  /// for a worker to appear on the domain and for the request path to it to open
  std::chrono::milliseconds connect{10000};
  /// how often a caller waiting for a reply checks that the worker is still alive
  std::chrono::milliseconds poll{100};
  /// how long a caller watches for its reply before it sleeps (BENCHMARKS.md: waking a sleeping
  /// thread costs about as much as the round trip itself)
  std::chrono::microseconds spin{500};
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_SETTINGS_HPP
