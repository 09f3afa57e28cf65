// Saved states of executions and runs as bytes (stride/common/bytes.hpp), with value blocks.
#ifndef STRIDE_COSIM_STATE_BYTES_HPP
#define STRIDE_COSIM_STATE_BYTES_HPP

#include <cstdint>
#include <string>

#include "stride/common/bytes.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

using byte_writer = common::byte_writer;

/// \throws validation_error "<what>: damaged or truncated" when the bytes end early.
class byte_reader : public common::byte_reader<validation_error> {
 public:
  byte_reader(std::span<const std::byte> bytes, const std::string& what)
      : common::byte_reader<validation_error>(bytes, what + ": damaged or truncated") {}
};

inline void put_block(byte_writer& w, const value_block& b) {
  w.put_size(b.reals.size());
  for (double v : b.reals) w.put(v);
  w.put_size(b.integers.size());
  for (int v : b.integers) w.put(static_cast<std::int32_t>(v));
  w.put_size(b.booleans.size());
  for (bool v : b.booleans) w.put(static_cast<std::uint8_t>(v ? 1 : 0));
  w.put_size(b.strings.size());
  for (const auto& s : b.strings) w.put_string(s);
}

inline value_block get_block(byte_reader& r) {
  value_block b;
  b.reals.resize(r.get_size(sizeof(double)));
  for (double& v : b.reals) v = r.get<double>();
  b.integers.resize(r.get_size(sizeof(std::int32_t)));
  for (int& v : b.integers) v = r.get<std::int32_t>();
  const std::size_t nb = r.get_size(sizeof(std::uint8_t));
  for (std::size_t i = 0; i < nb; ++i) b.booleans.push_back(r.get<std::uint8_t>() != 0);
  b.strings.resize(r.get_size(sizeof(std::uint64_t)));
  for (auto& s : b.strings) s = r.get_string();
  return b;
}

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_STATE_BYTES_HPP
