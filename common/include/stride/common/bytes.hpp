// Saved states and checkpoints as bytes: numbers (fixed-width integers, IEEE doubles) in
// little-endian byte order whatever the host's, lengths (64-bit) before byte strings. So what one
// machine writes any other reads (docs/checkpoint-format.md).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace stride::common {

/// A number or an enumeration: what byte_writer and byte_reader encode.
template <class T>
concept encodable_number = std::is_arithmetic_v<T> || std::is_enum_v<T>;

/// `v`'s bytes, least significant first.
template <encodable_number T>
std::array<std::byte, sizeof(T)> little_endian_bytes(T v) {
  auto raw = std::bit_cast<std::array<std::byte, sizeof(T)>>(v);
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
  return raw;
}

class byte_writer {
 public:
  template <encodable_number T>
  void put(const T& v) {
    const auto raw = little_endian_bytes(v);
    bytes_.insert(bytes_.end(), raw.begin(), raw.end());
  }
  void put_size(std::size_t n) { put(static_cast<std::uint64_t>(n)); }
  void put_bytes(std::span<const std::byte> b) {
    put_size(b.size());
    bytes_.insert(bytes_.end(), b.begin(), b.end());
  }
  void put_string(const std::string& s) { put_bytes(std::as_bytes(std::span(s.data(), s.size()))); }
  /// Bytes as they are, no length before them (the reader knows how many).
  void put_raw(std::span<const std::byte> b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
  const std::vector<std::byte>& bytes() const noexcept { return bytes_; }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  std::vector<std::byte> bytes_;
};

/// Reads what byte_writer wrote. When the bytes end early it throws `Error(message)`, so each
/// user reports damage in its own error type and words.
template <class Error>
class byte_reader {
 public:
  byte_reader(std::span<const std::byte> bytes, std::string message)
      : bytes_(bytes), message_(std::move(message)) {}
  template <encodable_number T>
  T get() {
    std::array<std::byte, sizeof(T)> raw;
    std::memcpy(raw.data(), take(sizeof(T)).data(), sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
    return std::bit_cast<T>(raw);
  }
  /// A length; never more than `item_size`-byte items can follow in what is left.
  std::size_t get_size(std::size_t item_size = 1) {
    const auto n = get<std::uint64_t>();
    need(n, item_size);
    return static_cast<std::size_t>(n);
  }
  std::span<const std::byte> get_bytes() { return take(get_size()); }
  /// The next `n` bytes as they are (what put_raw wrote).
  std::span<const std::byte> get_raw(std::size_t n) { return take(n); }
  /// All bytes not read yet.
  std::span<const std::byte> get_rest() { return take(bytes_.size() - pos_); }
  std::string get_string() {
    const auto b = get_bytes();
    return std::string(reinterpret_cast<const char*>(b.data()), b.size());
  }
  /// Fails unless `n` items of `item_size` bytes are left (overflow-safe).
  void need(std::uint64_t n, std::size_t item_size = 1) const {
    if (item_size != 0 && n > (bytes_.size() - pos_) / item_size) fail();
  }
  bool at_end() const noexcept { return pos_ == bytes_.size(); }
  [[noreturn]] void fail() const { throw Error(message_); }

 private:
  std::span<const std::byte> take(std::size_t n) {
    need(n);
    const auto out = bytes_.subspan(pos_, n);
    pos_ += n;
    return out;
  }
  std::span<const std::byte> bytes_;
  std::size_t pos_ = 0;
  std::string message_;
};

}  // namespace stride::common
