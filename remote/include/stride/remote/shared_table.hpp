// A table of doubles shared by several agents over Cyclone DDS (docs/swarm.md). Each agent keeps a
// replica; after each of its rounds it sends the increments it applied, and the service merges
// them and publishes the table:
//   synchronous   round r is merged once every agent has sent it, in agent order (1, 2, ...):
//                 the result depends only on what the agents send, never on timing;
//   asynchronous  every update is merged when it arrives.
// Only round traffic crosses between agents. The header names no DDS type: components link the
// client without seeing DDS.
#ifndef STRIDE_REMOTE_SHARED_TABLE_HPP
#define STRIDE_REMOTE_SHARED_TABLE_HPP

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stride::remote {

/// Where a shared table is and how it merges, as one text for a component parameter:
/// `dds;domain=0;table=NAME;agents=N;mode=synchronous[;config=FILE]`.
struct table_endpoint {
  int domain = 0;
  std::string table;  ///< unique per run: also the DDS partition
  int agents = 1;
  bool synchronous = true;
  std::filesystem::path config_file;  ///< empty: CYCLONEDDS_URI, else the loopback configuration

  std::string str() const;
  /// \throws std::invalid_argument naming the part that is wrong
  static table_endpoint parse(std::string_view text);
};

/// The merged table as the service published it.
struct table_snapshot {
  std::int64_t round = 0;    ///< synchronous: rounds merged
  std::int64_t updates = 0;  ///< updates merged in all
  std::vector<double> values;
  bool final = false;
};

/// One agent's end.
class table_client {
 public:
  /// Joins the table as agent `agent` (1..agents) and waits up to `connect` for the service.
  table_client(const table_endpoint& where, int agent,
               std::chrono::milliseconds connect = std::chrono::seconds(10));
  ~table_client();
  table_client(const table_client&) = delete;
  table_client& operator=(const table_client&) = delete;

  /// Sends the increments of round `round` (1, 2, ... in order); `initial` only with round 1.
  void send(std::int64_t round, std::span<const std::uint32_t> entries,
            std::span<const double> increments, std::span<const double> initial = {},
            bool last = false);
  /// A resumed agent (docs/swarm.md): it continues after round `round` (0: from the start), whose
  /// update `entries`/`increments` it sent before the interruption (`last`: its final one).
  /// Sent instead of round 1. The same in a running table rejoins it (an agent's copy restored
  /// from an earlier state, docs/failover.md): rounds it sends again are checked against the
  /// first time, counted once, and answered with the table merged then.
  void resume(std::int64_t round, std::span<const std::uint32_t> entries,
              std::span<const double> increments, std::span<const double> initial, bool last);
  /// Synchronous: waits until round `round` is merged (round 0: returns at once with nothing
  /// merged); after resume(), the table of exactly that round. Asynchronous: the newest table the
  /// service published, without waiting. `timeout` bounds the wait. \throws std::runtime_error on
  /// timeout or a service error.
  const table_snapshot& wait_round(std::int64_t round, std::chrono::milliseconds timeout);
  /// Waits for the final table (after every agent's last update).
  const table_snapshot& wait_final(std::chrono::milliseconds timeout);

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

/// Where a synchronous service keeps its journal of merged rounds, and whether it continues one.
struct table_journal {
  std::filesystem::path file;  ///< empty: none (the run cannot be resumed)
  /// Continue the interrupted run of `file`: the table is rebuilt from it to the oldest round an
  /// agent resumes after, the rounds of agents that are further on are replayed from it, and
  /// every round merged again must equal the journal's (a resumed run is bit-identical).
  bool resume = false;
};

/// The service: merges the agents' updates and publishes the table, on its own thread.
class table_service {
 public:
  /// Starts serving `where.table` for `where.agents` agents. \throws std::runtime_error for a
  /// journal that cannot be read or written (naming the file).
  explicit table_service(const table_endpoint& where, const table_journal& journal = {});
  ~table_service();
  table_service(const table_service&) = delete;
  table_service& operator=(const table_service&) = delete;

  const table_endpoint& endpoint() const;
  /// The table as merged so far.
  table_snapshot current() const;
  /// The first refused update ("" if none): the service stops merging then.
  std::string error() const;
  /// Stops merging and tells every agent why (they fail at their next wait instead of waiting
  /// for an agent that is gone).
  void abandon(const std::string& why);
  /// Goes on without agent `agent` (lost): the rounds it sent are merged, later ones are merged
  /// without waiting for it, and the final table comes when the others are done.
  void leave_out(int agent);

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

/// A table name no other run on the domain uses (host, process, time, counter).
std::string unique_table_name(std::string_view prefix);

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_SHARED_TABLE_HPP
