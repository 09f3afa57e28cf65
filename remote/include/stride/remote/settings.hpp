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
  /// A DDS Security identity: a folder `stride security add` made (KEYSTORE/NAME). Empty: the
  /// environment variable STRIDE_SECURITY when it is set, else no security (docs/distributed.md).
  std::filesystem::path security;
};

/// The environment variable that names the identity of every DDS participant of a process.
inline constexpr const char* k_security_env = "STRIDE_SECURITY";

/// The identity the participants of `settings` use: its own, else $STRIDE_SECURITY, else none
/// (empty).
std::filesystem::path effective_identity(const dds_settings& settings);

/// Deletes every DDS entity of the process, domains included, and waits for DDS's threads to end.
/// A process that used DDS calls it before it exits: a security handshake still running on a DDS
/// thread would otherwise meet OpenSSL's clean-up at exit.
void close_dds();

/// A check of an identity (its folder) before a participant on `domain` uses it; throws saying
/// what is wrong. The CLI sets the keystore's (certificate times, CA, domains); without one only
/// the files are checked (FMUs do not link OpenSSL for it).
using identity_check = void (*)(const std::filesystem::path& identity, int domain);
void set_identity_check(identity_check check);

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
  /// a reply the network held up this long (beyond the worker's own time) is a stall: logged
  /// and counted; far above a repaired packet loss (tens of ms), far below the lease (1 s)
  std::chrono::milliseconds stall{200};
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_SETTINGS_HPP
