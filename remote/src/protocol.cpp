#include "protocol.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace stride::remote {

std::string to_string(op o) {
  switch (o) {
    case op::hello:
      return "hello";
    case op::load:
      return "load";
    case op::instantiate:
      return "instantiate";
    case op::setup:
      return "setup";
    case op::set_values:
      return "set_values";
    case op::get_values:
      return "get_values";
    case op::expose:
      return "expose";
    case op::enter_initialization:
      return "enter_initialization";
    case op::exit_initialization:
      return "exit_initialization";
    case op::step:
      return "step";
    case op::save_state:
      return "save_state";
    case op::restore_state:
      return "restore_state";
    case op::terminate:
      return "terminate";
    case op::free_instance:
      return "free_instance";
    case op::end_run:
      return "end_run";
    case op::group_setup:
      return "group_setup";
    case op::group_step:
      return "group_step";
  }
  return "operation " + std::to_string(static_cast<int>(o));
}

std::string worker_partition(const std::string& worker) {
  return "stride.worker." + worker;
}

std::string run_partition(const std::string& run) {
  return "stride.run." + run;
}

std::string content_hash(std::span<const std::byte> bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 failed");
  }
  static constexpr char k_hex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) {
    out += k_hex[digest[i] >> 4];
    out += k_hex[digest[i] & 15];
  }
  return out;
}

namespace {

template <class Seq, class T>
void borrow(Seq& seq, const T* data, std::size_t n) {
  seq._maximum = seq._length = static_cast<std::uint32_t>(n);
  seq._buffer = const_cast<T*>(data);
  seq._release = false;
}

template <class Seq>
std::vector<cosim::value_reference> refs_of(const Seq& seq) {
  return {seq._buffer, seq._buffer + seq._length};
}

void expect_size(std::uint32_t got, std::size_t want, const char* what) {
  if (got != want) {
    throw std::runtime_error(std::string("protocol: ") + std::to_string(got) + " " + what +
                             " where " + std::to_string(want) + " were expected");
  }
}

}  // namespace

void put_refs(const cosim::variable_refs& refs, stride_remote_values& out) {
  out = {};
  borrow(out.real_refs, refs.reals.data(), refs.reals.size());
  borrow(out.integer_refs, refs.integers.data(), refs.integers.size());
  borrow(out.boolean_refs, refs.booleans.data(), refs.booleans.size());
  borrow(out.string_refs, refs.strings.data(), refs.strings.size());
}

void put_values(const cosim::value_block& v, stride_remote_values& out, wire_storage& storage) {
  out = {};
  borrow(out.reals, v.reals.data(), v.reals.size());
  static_assert(sizeof(int) == sizeof(std::int32_t));
  borrow(out.integers, reinterpret_cast<const std::int32_t*>(v.integers.data()), v.integers.size());
  storage.booleans = std::make_unique<bool[]>(v.booleans.size());
  for (std::size_t i = 0; i < v.booleans.size(); ++i) storage.booleans[i] = v.booleans[i];
  borrow(out.booleans, storage.booleans.get(), v.booleans.size());
  storage.strings.clear();
  for (const auto& s : v.strings) storage.strings.push_back(const_cast<char*>(s.c_str()));
  borrow(out.strings, storage.strings.data(), storage.strings.size());
}

cosim::variable_refs get_refs(const stride_remote_values& in) {
  if (in.reals._length + in.integers._length + in.booleans._length + in.strings._length != 0) {
    throw std::runtime_error("protocol: values where only references were expected");
  }
  cosim::variable_refs r;
  r.reals = refs_of(in.real_refs);
  r.integers = refs_of(in.integer_refs);
  r.booleans = refs_of(in.boolean_refs);
  r.strings = refs_of(in.string_refs);
  return r;
}

void get_values(const stride_remote_values& in, const cosim::variable_refs& expected,
                cosim::value_block& out) {
  expect_size(in.reals._length, expected.reals.size(), "reals");
  expect_size(in.integers._length, expected.integers.size(), "integers");
  expect_size(in.booleans._length, expected.booleans.size(), "booleans");
  expect_size(in.strings._length, expected.strings.size(), "strings");
  copy_values(in, out);
}

void copy_values(const stride_remote_values& in, cosim::value_block& out) {
  out.reals.assign(in.reals._buffer, in.reals._buffer + in.reals._length);
  out.integers.assign(in.integers._buffer, in.integers._buffer + in.integers._length);
  out.booleans.assign(in.booleans._buffer, in.booleans._buffer + in.booleans._length);
  out.strings.resize(in.strings._length);
  for (std::uint32_t i = 0; i < in.strings._length; ++i) {
    out.strings[i] = in.strings._buffer[i] != nullptr ? in.strings._buffer[i] : "";
  }
}

bool fits(const cosim::value_block& v, const cosim::variable_refs& refs) {
  return v.reals.size() == refs.reals.size() && v.integers.size() == refs.integers.size() &&
         v.booleans.size() == refs.booleans.size() && v.strings.size() == refs.strings.size();
}

bool same_shape(const cosim::value_block& a, const cosim::value_block& b) {
  return a.reals.size() == b.reals.size() && a.integers.size() == b.integers.size() &&
         a.booleans.size() == b.booleans.size() && a.strings.size() == b.strings.size();
}

void put_blob(std::span<const std::byte> bytes, dds_sequence_octet& out) {
  borrow(out, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

std::vector<std::byte> get_blob(const dds_sequence_octet& in) {
  const auto* p = reinterpret_cast<const std::byte*>(in._buffer);
  return {p, p + in._length};
}

topics::topics(dds_entity_t participant) {
  dds_qos_t* qos = dds::reliable_qos();
  request = dds::entity(dds::check(dds_create_topic(participant, &stride_remote_request_desc,
                                                    "stride_remote_request", qos, nullptr),
                                   "topic stride_remote_request"));
  reply = dds::entity(dds::check(
      dds_create_topic(participant, &stride_remote_reply_desc, "stride_remote_reply", qos, nullptr),
      "topic stride_remote_reply"));
  dds_delete_qos(qos);
  qos = dds::announcement_qos(std::chrono::milliseconds(0));
  worker_info =
      dds::entity(dds::check(dds_create_topic(participant, &stride_remote_worker_info_desc,
                                              "stride_remote_worker_info", qos, nullptr),
                             "topic stride_remote_worker_info"));
  dds_delete_qos(qos);
}

}  // namespace stride::remote
