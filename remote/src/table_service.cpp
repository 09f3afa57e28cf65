#include <algorithm>
#include <atomic>
#include <cstring>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include "stride/remote/shared_table.hpp"
#include "table_journal.hpp"
#include "table_wire.hpp"

namespace stride::remote {

namespace {

bool same_update(const table_update& a, const table_update& b) {
  return a.agent == b.agent && a.entries == b.entries &&
         a.increments.size() == b.increments.size() &&
         std::memcmp(a.increments.data(), b.increments.data(),
                     a.increments.size() * sizeof(double)) == 0;
}

// adds one agent's update to a table
void apply(table_snapshot& t, const table_update& u) {
  for (std::size_t i = 0; i < u.entries.size(); ++i) t.values[u.entries[i]] += u.increments[i];
  t.updates += 1;
}

}  // namespace

struct table_service::impl {
  table_endpoint where;
  dds::entity participant;
  table_wire::topics topics;
  dds::entity publisher, subscriber, writer, reader, waitset;
  std::atomic<bool> stopping{false};
  std::thread thread;

  std::mutex drops_mutex;
  std::vector<int> drops;  // agents lost, for the service thread to leave out

  mutable std::mutex mutex;  // guards what follows
  table_snapshot table;
  std::vector<double> initial;
  std::string error;

  // merge bookkeeping (service thread only)
  std::vector<std::deque<table_update>> pending;  // synchronous: per agent, rounds not merged
  std::vector<std::int64_t> last_round;           // per agent: the newest round received
  std::vector<bool> ended;                        // per agent: its last update was received
  std::vector<std::int64_t> end_round;            // per agent: the round of its last update

  // every merged round (synchronous): the tables of rounds that rejoined agents walk again
  std::vector<journal_round> merged;
  table_snapshot answered;  // the table of the round last answered, to go on from

  // journal and resume (synchronous only)
  journal_writer journal;
  journal_contents replay;  // the interrupted run's rounds, while resuming and to verify
  bool resuming = false;
  std::vector<std::optional<table_update>> announced;  // per agent, while resuming
  std::vector<table_update> held;                      // updates that came before all announced

  impl(const table_endpoint& w, const table_journal& j)
      : where(w),
        participant(table_wire::participant(w)),
        topics(participant.get()),
        pending(static_cast<std::size_t>(w.agents)),
        last_round(static_cast<std::size_t>(w.agents), 0),
        ended(static_cast<std::size_t>(w.agents), false),
        end_round(static_cast<std::size_t>(w.agents), 0),
        announced(static_cast<std::size_t>(w.agents)) {
    if (!j.file.empty()) {
      if (!w.synchronous) {
        throw std::runtime_error("shared table " + w.table +
                                 ": only synchronous rounds are journaled (an asynchronous run "
                                 "cannot be repeated, so it cannot be resumed)");
      }
      std::uint64_t keep = 0;
      if (j.resume) {
        replay = read_journal(j.file);
        keep = journal_valid_size(j.file);
        if (replay.has_header && replay.agents != w.agents) {
          throw std::runtime_error(j.file.string() + ": the journal is of " +
                                   std::to_string(replay.agents) + " agents, the run has " +
                                   std::to_string(w.agents));
        }
        resuming = true;
      }
      journal = journal_writer(j.file, keep);
    }
    const std::string part = table_wire::partition(w);
    publisher = dds::make_publisher(participant.get(), part);
    subscriber = dds::make_subscriber(participant.get(), part);
    dds_qos_t* qos = table_wire::state_qos();
    writer =
        dds::entity(dds::check(dds_create_writer(publisher.get(), topics.state.get(), qos, nullptr),
                               "table state writer"));
    dds_delete_qos(qos);
    qos = table_wire::update_qos();
    reader = dds::entity(
        dds::check(dds_create_reader(subscriber.get(), topics.update.get(), qos, nullptr),
                   "table update reader"));
    dds_delete_qos(qos);
    dds::check(dds_set_status_mask(reader.get(), DDS_DATA_AVAILABLE_STATUS), "table reader mask");
    waitset = dds::entity(dds::check(dds_create_waitset(participant.get()), "table waitset"));
    dds::check(dds_waitset_attach(waitset.get(), reader.get(), reader.get()), "table waitset");
    thread = std::thread([this] { serve(); });
  }

  ~impl() {
    stopping = true;
    dds_waitset_set_trigger(waitset.get(), true);
    if (thread.joinable()) thread.join();
  }

  void serve() {
    while (!stopping) {
      dds_attach_t hit = 0;
      dds_waitset_wait(waitset.get(), &hit, 1, DDS_MSECS(100));
      if (stopping) break;
      dds_waitset_set_trigger(waitset.get(), false);
      // updates that arrived before an agent was lost count: take them first
      std::vector<table_update> arrived;
      dds::take_all<stride_table_update>(
          reader.get(), [&](const stride_table_update& u, const dds_sample_info_t&) {
            table_update c;
            c.agent = u.agent;
            c.round = u.round;
            c.entries.assign(u.entries._buffer, u.entries._buffer + u.entries._length);
            c.increments.assign(u.increments._buffer, u.increments._buffer + u.increments._length);
            c.initial.assign(u.initial._buffer, u.initial._buffer + u.initial._length);
            c.last = u.last;
            c.resumed = u.resumed;
            arrived.push_back(std::move(c));
          });
      for (auto& u : arrived) handle(std::move(u));
      std::vector<int> lost;
      {
        std::lock_guard lock(drops_mutex);
        lost.swap(drops);
      }
      for (const int agent : lost) leave_out(agent);
    }
  }

  bool failed() const {
    std::lock_guard lock(mutex);
    return !error.empty();
  }

  void handle(table_update u) {
    if (failed()) return;
    try {
      if (u.resumed) {
        if (resuming) {
          announce(std::move(u));
        } else {
          rejoin(std::move(u));
        }
      } else if (resuming) {
        held.push_back(std::move(u));
      } else {
        accept(std::move(u));
      }
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }

  void fail(const std::string& why) {
    std::lock_guard lock(mutex);
    if (!error.empty()) return;
    error = why;
    publish_locked();
  }

  // a lost agent: the rounds it sent are merged, later rounds go on without it
  void leave_out(int agent) {
    if (agent < 1 || agent > where.agents || failed()) return;
    const auto a = static_cast<std::size_t>(agent - 1);
    if (ended[a]) return;
    ended[a] = true;
    end_round[a] = last_round[a];
    if (where.synchronous) {
      merge_complete_rounds();
      std::lock_guard lock(mutex);
      if (all_ended() && !table.final && nothing_pending()) {  // the others were done
        table.final = true;
        publish_locked();
      }
    } else {
      std::lock_guard lock(mutex);
      table.final = all_ended();
      publish_locked();
    }
  }

  std::size_t index_of(const table_update& u) const {
    if (u.agent < 1 || u.agent > where.agents) {
      throw std::runtime_error("agent " + std::to_string(u.agent) + " is not in 1.." +
                               std::to_string(where.agents));
    }
    return static_cast<std::size_t>(u.agent - 1);
  }

  // the initial table: the first agent's; every other agent must bring the same
  void take_initial(const table_update& u) {
    const std::string from = "agent " + std::to_string(u.agent);
    if (u.initial.empty()) throw std::runtime_error(from + ": no initial table");
    std::lock_guard lock(mutex);
    if (initial.empty()) {
      initial = u.initial;
      table.values = u.initial;
      if (journal.active()) journal.header(where.agents, initial);
    } else if (u.initial.size() != initial.size() ||
               std::memcmp(u.initial.data(), initial.data(), initial.size() * sizeof(double)) !=
                   0) {
      throw std::runtime_error(from + "'s initial table differs from the first agent's (" +
                               std::to_string(u.initial.size()) + " vs " +
                               std::to_string(initial.size()) + " entries, or other values)");
    }
  }

  // checks an update against what came before; merges or queues it
  void accept(table_update u) {
    const auto a = index_of(u);
    const std::string from = "agent " + std::to_string(u.agent);
    if (where.synchronous && u.round >= 1 && u.round <= last_round[a]) {
      repeated(u);
      return;
    }
    if (ended[a]) {
      throw std::runtime_error(from + " sent round " + std::to_string(u.round) + " after its last");
    }
    if (u.round != last_round[a] + 1) {
      throw std::runtime_error(from + " sent round " + std::to_string(u.round) + " after round " +
                               std::to_string(last_round[a]));
    }
    if (u.entries.size() != u.increments.size()) {
      throw std::runtime_error(from + ": entries and increments differ in length");
    }
    if (u.round == 1) take_initial(u);
    {
      std::lock_guard lock(mutex);
      for (const auto e : u.entries) {
        if (e >= table.values.size()) {
          throw std::runtime_error(from + ": entry " + std::to_string(e) + " is outside the " +
                                   std::to_string(table.values.size()) + "-entry table");
        }
      }
    }
    last_round[a] = u.round;
    if (u.last) {
      ended[a] = true;
      end_round[a] = u.round;
    }
    if (!where.synchronous) {
      std::lock_guard lock(mutex);
      apply_locked(u);
      table.final = all_ended();
      publish_locked();
      return;
    }
    pending[a].push_back(std::move(u));
    merge_complete_rounds();
  }

  // an agent whose copy continues from an earlier state (a standby worker took over): it says
  // after which round; rounds it sends again are answered from the merged ones
  void rejoin(table_update u) {
    const auto a = index_of(u);
    const std::string from = "agent " + std::to_string(u.agent);
    if (!where.synchronous) {
      throw std::runtime_error(from + " rejoins, but an asynchronous table cannot be walked again");
    }
    if (ended[a] && end_round[a] < u.round) {
      throw std::runtime_error(from + " rejoins after round " + std::to_string(u.round) +
                               ", but it was left out after round " + std::to_string(end_round[a]));
    }
    take_initial(u);
    if (u.round > last_round[a] + 1) {
      throw std::runtime_error(from + " rejoins after round " + std::to_string(u.round) +
                               ", but its last round here is " + std::to_string(last_round[a]));
    }
    u.resumed = false;
    if (u.round >= 1) accept(std::move(u));  // new when it was lost on the way, else repeated
  }

  // a round an agent sent before: it must be what it sent then; counted once, answered with the
  // table of that round once merged (the broadcast answers it otherwise)
  void repeated(const table_update& u) {
    const auto a = index_of(u);
    const table_update* first = nullptr;
    if (u.round <= table.round) {
      const auto& round = merged[static_cast<std::size_t>(u.round - 1)].updates;
      const auto it = std::find_if(round.begin(), round.end(),
                                   [&](const table_update& m) { return m.agent == u.agent; });
      if (it != round.end()) first = &*it;
    } else {
      for (const auto& p : pending[a]) {
        if (p.round == u.round) first = &p;
      }
    }
    const std::string what =
        "agent " + std::to_string(u.agent) + " sent round " + std::to_string(u.round) + " again";
    if (first == nullptr) throw std::runtime_error(what + ", but it was never received");
    if (!same_update(*first, u)) {
      throw std::runtime_error(what + ", different from the first time (not deterministic?)");
    }
    if (u.round <= table.round) answer(u.agent, u.round);
  }

  // publishes the table of merged round `round` to agent `agent` alone
  void answer(int agent, std::int64_t round) {
    std::lock_guard lock(mutex);
    if (answered.round > round || answered.values.empty()) {
      answered = table_snapshot{};
      answered.values = initial;
    }
    for (std::int64_t r = answered.round + 1; r <= round; ++r) {
      for (const auto& up : merged[static_cast<std::size_t>(r - 1)].updates) apply(answered, up);
      answered.round = r;
    }
    write_locked(agent, answered);
  }

  // a resumed agent says where it continues; once all have, the table is rebuilt to the oldest
  // such round and the rounds of agents that are further on come from the journal
  void announce(table_update u) {
    const auto a = index_of(u);
    if (!resuming) {
      throw std::runtime_error("agent " + std::to_string(u.agent) +
                               " resumes, but this run is not a resumed one");
    }
    take_initial(u);
    announced[a] = std::move(u);
    for (const auto& x : announced) {
      if (!x) return;
    }
    std::int64_t oldest = announced[0]->round;
    for (const auto& x : announced) oldest = std::min(oldest, x->round);
    const auto journaled = static_cast<std::int64_t>(replay.rounds.size());
    {
      std::lock_guard lock(mutex);
      for (std::int64_t r = 1; r <= oldest; ++r) {
        if (r > journaled) {
          throw std::runtime_error("the journal ends at round " + std::to_string(journaled) +
                                   ", but every agent resumed after round " +
                                   std::to_string(oldest));
        }
        for (const auto& up : replay.rounds[static_cast<std::size_t>(r - 1)].updates) {
          apply_locked(up);
        }
        merged.push_back(replay.rounds[static_cast<std::size_t>(r - 1)]);
      }
      table.round = oldest;
      publish_locked();
    }
    for (std::size_t k = 0; k < announced.size(); ++k) {
      const table_update& x = *announced[k];
      for (std::int64_t r = oldest + 1; r <= x.round; ++r) {
        table_update up;
        if (r <= journaled) {
          const auto& round = replay.rounds[static_cast<std::size_t>(r - 1)].updates;
          const auto it = std::find_if(round.begin(), round.end(),
                                       [&](const table_update& j) { return j.agent == x.agent; });
          if (it == round.end()) {
            throw std::runtime_error("agent " + std::to_string(x.agent) + " resumed after round " +
                                     std::to_string(x.round) + ", but round " + std::to_string(r) +
                                     " of the journal has no update of it");
          }
          up = *it;
        } else if (r == x.round) {
          up = x;  // sent before the interruption, never merged
          up.resumed = false;
        } else {
          throw std::runtime_error("the journal ends at round " + std::to_string(journaled) +
                                   ", but agent " + std::to_string(x.agent) +
                                   " resumed after round " + std::to_string(x.round));
        }
        up.last = false;
        pending[k].push_back(std::move(up));
      }
      last_round[k] = x.round;
      if (x.last) {  // it had finished
        ended[k] = true;
        end_round[k] = x.round;
      }
    }
    resuming = false;
    announced.assign(announced.size(), std::nullopt);
    merge_complete_rounds();
    {
      std::lock_guard lock(mutex);
      if (all_ended() && !table.final && nothing_pending()) {  // every agent had finished
        table.final = true;
        publish_locked();
      }
    }
    std::vector<table_update> later;
    later.swap(held);
    for (auto& h : later) accept(std::move(h));
  }

  bool nothing_pending() const {
    for (const auto& q : pending) {
      if (!q.empty()) return false;
    }
    return true;
  }

  bool all_ended() const {
    for (const bool e : ended) {
      if (!e) return false;
    }
    return true;
  }

  // synchronous: merges every round all agents still in it have sent, in agent order
  void merge_complete_rounds() {
    for (;;) {
      const std::int64_t next = table.round + 1;
      bool complete = true, anyone = false;
      for (std::size_t a = 0; a < pending.size(); ++a) {
        const bool in_round = !ended[a] || end_round[a] >= next;
        if (!in_round) continue;
        anyone = true;
        if (pending[a].empty() || pending[a].front().round != next) complete = false;
      }
      if (!complete || !anyone) return;
      journal_round round;
      round.round = next;
      for (auto& q : pending) {
        if (q.empty() || q.front().round != next) continue;
        round.updates.push_back(std::move(q.front()));
        q.pop_front();
      }
      record(round);
      std::lock_guard lock(mutex);
      for (const auto& u : round.updates) apply_locked(u);
      merged.push_back(std::move(round));
      table.round = next;
      table.final = all_ended() && nothing_pending();
      publish_locked();
    }
  }

  // a round the interrupted run merged must come out the same; later rounds are journaled
  void record(const journal_round& round) {
    const auto journaled = static_cast<std::int64_t>(replay.rounds.size());
    if (round.round <= journaled) {
      const auto& before = replay.rounds[static_cast<std::size_t>(round.round - 1)].updates;
      bool same = before.size() == round.updates.size();
      for (std::size_t i = 0; same && i < before.size(); ++i) {
        same = same_update(before[i], round.updates[i]);
      }
      if (!same) {
        throw std::runtime_error("round " + std::to_string(round.round) +
                                 " differs from the journal of the interrupted run: the agents "
                                 "did not repeat what they did (not deterministic?)");
      }
      return;
    }
    if (journal.active()) journal.round(round);
  }

  void apply_locked(const table_update& u) { apply(table, u); }

  void publish_locked() { write_locked(0, table); }

  void write_locked(int to, const table_snapshot& t) {
    stride_table_table_state s{};
    s.agent = to;
    s.table = const_cast<char*>(where.table.c_str());
    s.round = t.round;
    s.updates = t.updates;
    table_wire::borrow(s.values, std::span<const double>(t.values));
    s.final = t.final;
    s.error = const_cast<char*>(error.c_str());
    dds_write(writer.get(), &s);
  }
};

table_service::table_service(const table_endpoint& where, const table_journal& journal)
    : impl_(std::make_unique<impl>(where, journal)) {}

table_service::~table_service() = default;

void table_service::abandon(const std::string& why) {
  impl_->fail(why);
}

void table_service::leave_out(int agent) {
  {
    std::lock_guard lock(impl_->drops_mutex);
    impl_->drops.push_back(agent);
  }
  dds_waitset_set_trigger(impl_->waitset.get(), true);
}

const table_endpoint& table_service::endpoint() const {
  return impl_->where;
}

table_snapshot table_service::current() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->table;
}

std::string table_service::error() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->error;
}

}  // namespace stride::remote
