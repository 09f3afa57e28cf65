#include <optional>
#include <stdexcept>
#include <thread>

#include "stride/remote/shared_table.hpp"
#include "table_wire.hpp"

namespace stride::remote {

struct table_client::impl {
  table_endpoint where;
  int agent = 0;
  dds::entity participant;
  table_wire::topics topics;
  dds::entity publisher, subscriber, writer, reader, waitset;
  table_snapshot newest;                 // the newest table for every agent
  std::optional<table_snapshot> answer;  // the newest answer to this agent's repeated round
  bool rejoined = false;  // walks rounds again: a round's table is that round's, never a later one
  table_snapshot empty;   // round 0: nothing merged yet

  impl(const table_endpoint& w, int a)
      : where(w), agent(a), participant(table_wire::participant(w)), topics(participant.get()) {
    const std::string part = table_wire::partition(w);
    publisher = dds::make_publisher(participant.get(), part);
    subscriber = dds::make_subscriber(participant.get(), part);
    dds_qos_t* qos = table_wire::update_qos();
    writer = dds::entity(
        dds::check(dds_create_writer(publisher.get(), topics.update.get(), qos, nullptr),
                   "table update writer"));
    dds_delete_qos(qos);
    qos = table_wire::state_qos();
    reader = dds::entity(
        dds::check(dds_create_reader(subscriber.get(), topics.state.get(), qos, nullptr),
                   "table state reader"));
    dds_delete_qos(qos);
    dds::check(dds_set_status_mask(reader.get(), DDS_DATA_AVAILABLE_STATUS), "table reader mask");
    waitset = dds::entity(dds::check(dds_create_waitset(participant.get()), "table waitset"));
    dds::check(dds_waitset_attach(waitset.get(), reader.get(), reader.get()), "table waitset");
  }

  // takes what arrived; keeps the newest table
  void drain() {
    std::string error;  // thrown after the samples are returned to DDS
    dds::take_all<stride_table_table_state>(
        reader.get(), [&](const stride_table_table_state& s, const dds_sample_info_t&) {
          if (s.agent != 0) {
            if (s.agent == agent) answer = snapshot_of(s);
            return;
          }
          if (s.error != nullptr && s.error[0] != '\0') {
            error = s.error;
            return;
          }
          if (s.updates < newest.updates && !s.final) return;
          newest = snapshot_of(s);
        });
    if (!error.empty()) {
      throw std::runtime_error("shared table " + where.table + ": the service stopped: " + error);
    }
  }

  static table_snapshot snapshot_of(const stride_table_table_state& s) {
    table_snapshot t;
    t.round = s.round;
    t.updates = s.updates;
    t.final = s.final;
    t.values.assign(s.values._buffer, s.values._buffer + s.values._length);
    return t;
  }

  // the table of synchronous round `round`, if it is here
  const table_snapshot* table_of(std::int64_t round) const {
    if (answer && answer->round == round) return &*answer;
    if (rejoined) return newest.round == round ? &newest : nullptr;
    return newest.round >= round || newest.final ? &newest : nullptr;
  }

  // `found` returns the table waited for, or null
  template <class Found>
  const table_snapshot& wait(Found found, std::chrono::milliseconds timeout,
                             const std::string& what) {
    const auto until = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      drain();
      if (const table_snapshot* t = found()) return *t;
      const auto now = std::chrono::steady_clock::now();
      if (now >= until) {
        throw std::runtime_error("shared table " + where.table + ": agent " +
                                 std::to_string(agent) + " waited " +
                                 std::to_string(timeout.count() / 1000) + " s for " + what +
                                 " (newest merged round " + std::to_string(newest.round) + ")");
      }
      const auto left = std::chrono::duration_cast<std::chrono::nanoseconds>(until - now);
      dds_attach_t hit = 0;
      dds_waitset_wait(waitset.get(), &hit, 1,
                       std::min<std::int64_t>(left.count(), DDS_MSECS(100)));
    }
  }
};

table_client::table_client(const table_endpoint& where, int agent,
                           std::chrono::milliseconds connect) {
  if (agent < 1 || agent > where.agents) {
    throw std::invalid_argument("shared table " + where.table + ": agent " + std::to_string(agent) +
                                " is not in 1.." + std::to_string(where.agents));
  }
  impl_ = std::make_unique<impl>(where, agent);
  if (!dds::wait_for_reader(impl_->writer.get(), connect)) {
    throw std::runtime_error("shared table " + where.table + ": no service answered within " +
                             std::to_string(connect.count() / 1000) + " s on DDS domain " +
                             std::to_string(where.domain));
  }
}

table_client::~table_client() = default;

namespace {

void write_update(dds_entity_t writer, const table_endpoint& where, int agent, std::int64_t round,
                  std::span<const std::uint32_t> entries, std::span<const double> increments,
                  std::span<const double> initial, bool last, bool resumed) {
  if (entries.size() != increments.size()) {
    throw std::invalid_argument("shared table: entries and increments differ in length");
  }
  stride_table_update u{};
  u.table = const_cast<char*>(where.table.c_str());
  u.agent = agent;
  u.round = round;
  table_wire::borrow(u.entries, entries);
  table_wire::borrow(u.increments, increments);
  table_wire::borrow(u.initial, initial);
  u.last = last;
  u.resumed = resumed;
  dds::check(dds_write(writer, &u), "shared table " + where.table + ": agent " +
                                        std::to_string(agent) + " sending round " +
                                        std::to_string(round));
}

}  // namespace

void table_client::send(std::int64_t round, std::span<const std::uint32_t> entries,
                        std::span<const double> increments, std::span<const double> initial,
                        bool last) {
  write_update(impl_->writer.get(), impl_->where, impl_->agent, round, entries, increments, initial,
               last, false);
}

void table_client::resume(std::int64_t round, std::span<const std::uint32_t> entries,
                          std::span<const double> increments, std::span<const double> initial,
                          bool last) {
  impl_->rejoined = true;
  write_update(impl_->writer.get(), impl_->where, impl_->agent, round, entries, increments, initial,
               last, true);
}

const table_snapshot& table_client::wait_round(std::int64_t round,
                                               std::chrono::milliseconds timeout) {
  if (!impl_->where.synchronous) {
    impl_->drain();
    return impl_->newest;
  }
  if (round <= 0) return impl_->empty;
  return impl_->wait([&] { return impl_->table_of(round); }, timeout,
                     "round " + std::to_string(round));
}

const table_snapshot& table_client::wait_final(std::chrono::milliseconds timeout) {
  return impl_->wait([&] { return impl_->newest.final ? &impl_->newest : nullptr; }, timeout,
                     "the final table");
}

}  // namespace stride::remote
