// One log line per peer that DDS Security keeps out, on whichever side of the handshake this
// process is: the side that answers a handshake checks the other's certificate and may refuse it;
// the side that asked learns nothing from a peer that refuses, it just gets no answer.
#ifndef STRIDE_REMOTE_REFUSED_PEERS_HPP
#define STRIDE_REMOTE_REFUSED_PEERS_HPP

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <thread>

namespace stride::remote {

enum class handshake_event { requested, authenticated, failed, ended };

class refused_peer_log {
 public:
  using clock = std::chrono::steady_clock;

  /// Watches the handshakes of the participants this process creates from now on (through the
  /// wrapper plugin libstride_dds_auth) and sends each refusal to `log`, once per peer. Cyclone's
  /// own handshake messages, repeated while a refused peer is there, no longer reach stderr.
  /// `answer_within`: how long a peer asked for a handshake may leave it unanswered (the default
  /// covers one resend of a lost request, which Cyclone makes after 1 s); it is said when that
  /// time has passed, or later when it leaves or this process ends.
  explicit refused_peer_log(std::function<void(const std::string&)> log,
                            std::chrono::milliseconds answer_within = std::chrono::seconds(2));
  ~refused_peer_log();
  refused_peer_log(const refused_peer_log&) = delete;
  refused_peer_log& operator=(const refused_peer_log&) = delete;

  /// One step of the handshake with `peer` (the plugin's handle of its identity).
  void on_event(handshake_event event, std::int64_t peer, std::string_view subject,
                std::string_view ca_subject, std::string_view detail);

  /// Says the peers asked before `now - answer_within` that have not answered.
  void check_unanswered(clock::time_point now);

 private:
  struct asked {
    std::string subject;
    std::string ca_subject;
    clock::time_point since;
  };
  void start_timer();                                    // with mutex_ held
  void say(std::int64_t peer, const std::string& line);  // with mutex_ held
  void unanswered(std::int64_t peer, const asked& a);    // with mutex_ held
  void say_unanswered(clock::time_point asked_before);   // with mutex_ held

  std::function<void(const std::string&)> log_;
  std::chrono::milliseconds answer_within_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool watching_ = false;
  std::map<std::int64_t, asked> asked_;  // peers whose answer is awaited
  std::set<std::int64_t> said_;          // peers refused and said
  std::thread timer_;                    // from the first handshake this process asks for
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REFUSED_PEERS_HPP
