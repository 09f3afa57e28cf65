// The protocol's vocabulary: operations, reply statuses, partition names, and the conversion of
// value batches to and from the wire types. A wire struct written here borrows the memory of the
// C++ values it was filled from (nothing is copied before DDS serialises it).
#ifndef STRIDE_REMOTE_PROTOCOL_HPP
#define STRIDE_REMOTE_PROTOCOL_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "dds.hpp"
#include "stride/cosim/component.hpp"
#include "stride_remote.h"

namespace stride::remote {

/// What a request asks of the worker.
enum class op : std::int32_t {
  hello = 0,    ///< handshake: answered once both directions of the run's path are matched
  load = 1,     ///< text: content hash; blob: the FMU archive or empty ("do you have it?")
  instantiate,  ///< component: instance name; text: content hash
  setup,        ///< t_ns: start; dt_ns: stop or -1
  set_values,   ///< data: values; more: their references
  get_values,   ///< data: references; reply data: values
  expose,       ///< data: input references; more: output references
  enter_initialization,
  exit_initialization,
  step,           ///< t_ns, dt_ns; data: input values; reply data: output values
  save_state,     ///< reply blob: the state
  restore_state,  ///< blob: the state
  terminate,
  free_instance,  ///< the instance goes away
  end_run,        ///< every instance of the run goes away
  group_setup,    ///< component: group name; members, order, links: where they stand and how
                  ///< they step (again after every restore)
  group_step,     ///< component: group name; t_ns, dt_ns (base step), index; members: inputs;
                  ///< reply outputs per member, ended
};

/// How a request went.
enum class status : std::int32_t {
  ok = 0,
  terminate = 1,     ///< step: the component asks to end the simulation
  need_archive = 2,  ///< load without archive: the worker has no FMU with that hash
  error = 3,         ///< message says why
};

std::string to_string(op o);

/// Partition of a worker's requests, and of a run's replies.
std::string worker_partition(const std::string& worker);
std::string run_partition(const std::string& run);

/// Lowercase hex SHA-256 of `bytes`: the name an FMU archive is cached under.
std::string content_hash(std::span<const std::byte> bytes);

/// Keeps what a wire `values` struct points into alive (booleans and string pointers need their
/// own arrays).
struct wire_storage {
  std::unique_ptr<bool[]> booleans;
  std::vector<char*> strings;
};

/// Fills `out` with the references of `refs` (values empty).
void put_refs(const cosim::variable_refs& refs, stride_remote_values& out);
/// Fills `out` with the values of `v` (references empty).
void put_values(const cosim::value_block& v, stride_remote_values& out, wire_storage& storage);
/// Reads references; every value list must be empty. \throws std::runtime_error
cosim::variable_refs get_refs(const stride_remote_values& in);
/// Reads values. \throws std::runtime_error when the sizes are not those of `expected`.
void get_values(const stride_remote_values& in, const cosim::variable_refs& expected,
                cosim::value_block& out);

/// Reads values of any sizes.
void copy_values(const stride_remote_values& in, cosim::value_block& out);

/// Whether `v` holds as many values of each type as `refs` has references.
bool fits(const cosim::value_block& v, const cosim::variable_refs& refs);
/// Whether `a` and `b` hold as many values of each type.
bool same_shape(const cosim::value_block& a, const cosim::value_block& b);

/// Borrows `bytes` into a wire octet sequence.
void put_blob(std::span<const std::byte> bytes, dds_sequence_octet& out);
std::vector<std::byte> get_blob(const dds_sequence_octet& in);

/// The three topics of the protocol on one participant.
struct topics {
  dds::entity worker_info;
  dds::entity request;
  dds::entity reply;
  explicit topics(dds_entity_t participant);
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_PROTOCOL_HPP
