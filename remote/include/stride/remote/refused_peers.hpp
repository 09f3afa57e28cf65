// One log line per peer whose DDS Security handshake fails, where Cyclone repeats its own message
// about twice a second for as long as the peer is there.
#ifndef STRIDE_REMOTE_REFUSED_PEERS_HPP
#define STRIDE_REMOTE_REFUSED_PEERS_HPP

#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <string_view>

namespace stride::remote {

class refused_peer_log {
 public:
  /// Takes over Cyclone's log sink for the lifetime of this object: handshake failures go to
  /// `log` once per peer and reason, everything else to stderr as before.
  explicit refused_peer_log(std::function<void(const std::string&)> log);
  ~refused_peer_log();
  refused_peer_log(const refused_peer_log&) = delete;
  refused_peer_log& operator=(const refused_peer_log&) = delete;

  /// The line for one Cyclone log message, "" when it is no handshake failure or was said.
  std::string refusal(std::string_view message);

 private:
  std::function<void(const std::string&)> log_;
  std::mutex mutex_;
  std::set<std::string> seen_;
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REFUSED_PEERS_HPP
