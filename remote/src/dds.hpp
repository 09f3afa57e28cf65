// A thin C++ layer over Cyclone DDS's C API (Debian ships no C++ binding): entities that delete
// themselves, the domain set up from the project's configuration, the QoS the protocols use, and
// typed take of the generated wire types. Position independent: FMUs link it too.
#ifndef STRIDE_REMOTE_DDS_HPP
#define STRIDE_REMOTE_DDS_HPP

#include <dds/dds.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>

#include "stride/remote/settings.hpp"

namespace stride::remote::dds {

/// A DDS entity deleted (with its children) when this goes away, unless it is borrowed.
class entity {
 public:
  entity() = default;
  explicit entity(dds_entity_t e) : e_(e) {}
  /// An entity someone else deletes (the process's shared participant).
  static entity borrowed(dds_entity_t e) {
    entity b(e);
    b.owned_ = false;
    return b;
  }
  ~entity() { reset(); }
  entity(const entity&) = delete;
  entity& operator=(const entity&) = delete;
  entity(entity&& o) noexcept : e_(std::exchange(o.e_, 0)), owned_(std::exchange(o.owned_, true)) {}
  entity& operator=(entity&& o) noexcept {
    if (this != &o) {
      reset();
      e_ = std::exchange(o.e_, 0);
      owned_ = std::exchange(o.owned_, true);
    }
    return *this;
  }
  dds_entity_t get() const noexcept { return e_; }
  explicit operator bool() const noexcept { return e_ > 0; }
  void reset() noexcept {
    if (e_ > 0 && owned_) dds_delete(e_);
    e_ = 0;
    owned_ = true;
  }

 private:
  dds_entity_t e_ = 0;
  bool owned_ = true;
};

/// Throws std::runtime_error with `what` and DDS's text for `rc` when `rc` is negative.
dds_return_t check(dds_return_t rc, const std::string& what);

/// The participant of this process on the settings' domain, borrowed: every caller in the
/// process shares one (FMUs that link this layer included), and it lives until close_dds(). Its
/// users delete the entities they make under it. The first call in a process sets the domain up
/// (the configuration file, else CYCLONEDDS_URI, else the loopback configuration) and creates the
/// participant with the process's security identity; later calls with another configuration or
/// identity for the same domain are an error.
entity make_participant(const dds_settings& settings);

/// QoS of the request and reply paths: reliable, every sample kept until delivered.
dds_qos_t* reliable_qos();
/// QoS of worker announcements: reliable, the last one kept for late joiners; `lease` > 0 makes
/// the writer's liveliness automatic with that lease.
dds_qos_t* announcement_qos(std::chrono::milliseconds lease);

/// A publisher or subscriber limited to one partition.
entity make_publisher(dds_entity_t participant, const std::string& partition);
entity make_subscriber(dds_entity_t participant, const std::string& partition);

/// Waits until `writer` has at least one matched reader. Returns false on timeout.
bool wait_for_reader(dds_entity_t writer, std::chrono::milliseconds timeout);

/// Takes every available sample of `reader` and calls `f(sample, info)` for each valid one.
template <class T, class F>
void take_all(dds_entity_t reader, F&& f) {
  constexpr std::size_t k_batch = 16;
  void* samples[k_batch] = {};
  dds_sample_info_t infos[k_batch];
  for (;;) {
    const dds_return_t n = dds_take(reader, samples, infos, k_batch, k_batch);
    if (n <= 0) return;
    for (dds_return_t i = 0; i < n; ++i) {
      if (infos[i].valid_data) f(*static_cast<const T*>(samples[i]), infos[i]);
    }
    dds_return_loan(reader, samples, n);
    if (static_cast<std::size_t>(n) < k_batch) return;
  }
}

/// Reads (without taking) every sample of `reader`, valid or not: instance states included.
template <class T, class F>
void read_all(dds_entity_t reader, F&& f) {
  constexpr std::size_t k_batch = 64;
  void* samples[k_batch] = {};
  dds_sample_info_t infos[k_batch];
  const dds_return_t n = dds_read(reader, samples, infos, k_batch, k_batch);
  if (n <= 0) return;
  for (dds_return_t i = 0; i < n; ++i) f(*static_cast<const T*>(samples[i]), infos[i]);
  dds_return_loan(reader, samples, n);
}

}  // namespace stride::remote::dds

#endif  // STRIDE_REMOTE_DDS_HPP
