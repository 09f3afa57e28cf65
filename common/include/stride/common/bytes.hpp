// Saved states and checkpoints as bytes: fixed-width integers and doubles in host byte order,
// lengths (64-bit) before byte strings. Files written this way are read back on the machine kind
// that wrote them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace stride::common {

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
  template <class T>
  requires std::is_trivially_copyable_v<T> T get() {
    T v;
    std::memcpy(&v, take(sizeof v).data(), sizeof v);
    return v;
  }
  /// A length; never more than `item_size`-byte items can follow in what is left.
  std::size_t get_size(std::size_t item_size = 1) {
    const auto n = get<std::uint64_t>();
    need(n, item_size);
    return static_cast<std::size_t>(n);
  }
  std::span<const std::byte> get_bytes() { return take(get_size()); }
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
