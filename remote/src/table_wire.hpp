// What the shared table's client and service agree on: topics, QoS, partition, and filling wire
// sequences from C++ memory without copying.
#ifndef STRIDE_REMOTE_TABLE_WIRE_HPP
#define STRIDE_REMOTE_TABLE_WIRE_HPP

#include <span>
#include <string>

#include "dds.hpp"
#include "stride/remote/shared_table.hpp"
#include "stride_table.h"

namespace stride::remote::table_wire {

/// The participant for an endpoint (its domain and configuration).
dds::entity participant(const table_endpoint& where);

struct topics {
  dds::entity update;
  dds::entity state;
  explicit topics(dds_entity_t participant);
};

/// Updates: reliable, every one kept until delivered.
dds_qos_t* update_qos();
/// Table states: reliable, the newest kept for readers that match late.
dds_qos_t* state_qos();

inline std::string partition(const table_endpoint& where) {
  return "stride.table." + where.table;
}

/// Points a wire sequence at `data` (DDS serialises it before the call that writes returns).
template <class Seq, class T>
void borrow(Seq& seq, std::span<const T> data) {
  seq._buffer = const_cast<T*>(data.data());
  seq._length = seq._maximum = static_cast<std::uint32_t>(data.size());
  seq._release = false;
}

}  // namespace stride::remote::table_wire

#endif  // STRIDE_REMOTE_TABLE_WIRE_HPP
