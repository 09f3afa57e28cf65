// Saved states as bytes (a run's checkpoint file): fixed-width integers and doubles in host byte
// order, lengths before lists and strings. A checkpoint is read back on the machine kind that
// wrote it.
#ifndef STRIDE_COSIM_STATE_BYTES_HPP
#define STRIDE_COSIM_STATE_BYTES_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

class byte_writer {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  void put_size(std::size_t n) { put(static_cast<std::uint64_t>(n)); }
  void put_bytes(std::span<const std::byte> b) {
    put_size(b.size());
    bytes_.insert(bytes_.end(), b.begin(), b.end());
  }
  void put_string(const std::string& s) { put_bytes(std::as_bytes(std::span(s.data(), s.size()))); }
  void put_block(const value_block& b) {
    put_size(b.reals.size());
    for (double v : b.reals) put(v);
    put_size(b.integers.size());
    for (int v : b.integers) put(static_cast<std::int32_t>(v));
    put_size(b.booleans.size());
    for (bool v : b.booleans) put(static_cast<std::uint8_t>(v ? 1 : 0));
    put_size(b.strings.size());
    for (const auto& s : b.strings) put_string(s);
  }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  std::vector<std::byte> bytes_;
};

/// Reads what byte_writer wrote; \throws validation_error naming `what` when the bytes end early.
class byte_reader {
 public:
  byte_reader(std::span<const std::byte> bytes, std::string what)
      : bytes_(bytes), what_(std::move(what)) {}
  template <class T>
  requires std::is_trivially_copyable_v<T> T get() {
    T v;
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  std::size_t get_size() {
    const auto n = get<std::uint64_t>();
    if (n > bytes_.size() - pos_) fail();  // no list is longer than what is left
    return static_cast<std::size_t>(n);
  }
  std::span<const std::byte> get_bytes() { return take(get_size()); }
  std::string get_string() {
    const auto b = get_bytes();
    return std::string(reinterpret_cast<const char*>(b.data()), b.size());
  }
  value_block get_block() {
    value_block b;
    b.reals.resize(get_size());
    for (double& v : b.reals) v = get<double>();
    b.integers.resize(get_size());
    for (int& v : b.integers) v = get<std::int32_t>();
    const std::size_t nb = get_size();
    for (std::size_t i = 0; i < nb; ++i) b.booleans.push_back(get<std::uint8_t>() != 0);
    b.strings.resize(get_size());
    for (auto& s : b.strings) s = get_string();
    return b;
  }
  bool at_end() const { return pos_ == bytes_.size(); }
  [[noreturn]] void fail() const { throw validation_error(what_ + ": damaged or truncated"); }

 private:
  std::span<const std::byte> take(std::size_t n) {
    if (n > bytes_.size() - pos_) fail();
    const auto out = bytes_.subspan(pos_, n);
    pos_ += n;
    return out;
  }
  std::span<const std::byte> bytes_;
  std::size_t pos_ = 0;
  std::string what_;
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_STATE_BYTES_HPP
