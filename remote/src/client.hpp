// The orchestrator's end of the protocol: one per run. It finds workers on the domain, sends
// requests and hands each caller its reply (callers on several threads may wait at once). A
// worker whose liveliness lapses fails the calls waiting on it instead of leaving them hanging.
#ifndef STRIDE_REMOTE_CLIENT_HPP
#define STRIDE_REMOTE_CLIENT_HPP

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dds.hpp"
#include "protocol.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/log.hpp"
#include "stride/remote/settings.hpp"

namespace stride::remote {

/// A call that failed because its worker is gone (its liveliness lapsed): the call was not
/// answered, and another worker may take over (failover_component.hpp).
class worker_lost : public cosim::component_error {
 public:
  using cosim::component_error::component_error;
};

/// A reply, copied out of DDS.
struct reply_data {
  status result = status::ok;
  std::string message;
  cosim::value_block values;
  std::vector<std::byte> blob;
  struct log_line {
    cosim::log_level level;
    std::string source;  ///< the instance that logged it
    std::string category;
    std::string message;
  };
  std::vector<log_line> log;                ///< what the component logged meanwhile
  std::vector<cosim::value_block> outputs;  ///< group step: per member
  int ended = -1;                           ///< group step: the member that ended the run
  std::chrono::nanoseconds busy{0};         ///< the worker's time serving the request
  std::chrono::nanoseconds network{0};      ///< the rest of the round trip
};

class client {
 public:
  client(const dds_settings& settings, const timeouts& limits);
  /// Tells every connected worker that the run is over (its instances go away).
  ~client();
  client(const client&) = delete;
  client& operator=(const client&) = delete;

  const std::string& run_id() const noexcept { return run_; }
  /// Replies held up by the network (stalls shorter than the lease) so far.
  long stalls() const noexcept { return stalls_.load(); }
  int domain() const noexcept { return settings_.domain; }

  /// Waits for `worker` to be announced and its request path to open; returns the writer to
  /// address it with. Connecting twice returns the same writer.
  /// \throws std::runtime_error naming the worker and the domain on timeout.
  dds_entity_t connect(const std::string& worker);

  /// Sends `r` (its run and sequence number are filled in here) and waits for the reply.
  /// \throws worker_lost when the worker's liveliness lapses meanwhile.
  reply_data call(dds_entity_t writer, const std::string& worker, stride_remote_request& r);

  /// call() on behalf of a component or group (`who`, e.g. "component 'x' on worker 'w'"): the
  /// reply's log lines go to `forward`; a lost worker or an error reply becomes a
  /// cosim::component_error starting with `who` and the operation (a worker_lost for the former).
  /// A reply the network held up for `timeouts::stall` or longer is a stall: counted, and a
  /// warning (source "") goes to `forward`.
  reply_data call_for(const std::string& who, dds_entity_t writer, const std::string& worker,
                      stride_remote_request& r,
                      const std::function<void(const reply_data::log_line&)>& forward);

 private:
  // writes `r` with this run's id and a fresh sequence number; returns the number
  std::uint64_t send(dds_entity_t writer, const std::string& worker, stride_remote_request& r);
  // waits for the reply to `seq` (`seen`: arrivals_ before sending); nullopt at `until`.
  // \throws worker_lost when the worker's liveliness lapses meanwhile.
  std::optional<reply_data> wait_reply(std::uint64_t seq, std::uint64_t seen,
                                       const std::string& worker,
                                       std::optional<std::chrono::steady_clock::time_point> until);

  // the writer handle of the worker's live announcement, 0 when it has none
  dds_instance_handle_t announcement_of(const std::string& worker);
  bool alive(const std::string& worker);
  void take_replies();  // DDS's receive thread, when replies arrive

  dds_settings settings_;
  timeouts limits_;
  std::string run_;
  dds::entity participant_;
  topics topics_;
  dds::entity announcements_;  // reader of worker_info
  dds::entity reply_subscriber_;
  dds::entity replies_;                                                 // reader
  std::map<std::string, std::pair<dds::entity, dds::entity>> workers_;  // publisher, writer

  std::atomic<std::uint64_t> next_seq_{0};
  std::mutex mutex_;
  std::condition_variable arrived_cv_;
  std::map<std::uint64_t, reply_data> arrived_;
  std::set<std::uint64_t> abandoned_;       // requests no longer waited for (unanswered hellos)
  std::atomic<std::uint64_t> arrivals_{0};  // batches of replies taken so far
  std::atomic<long> stalls_{0};
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_CLIENT_HPP
