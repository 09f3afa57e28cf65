// A component's state image, field by field. The data struct names its fields once, in a
// `state_fields` function found next to it:
//
//   struct counter_data { double gain = 1; int ticks[4] = {}; sdk::text label{}; };
//   template <class F> void state_fields(counter_data& d, F&& f) { f(d.gain, d.ticks, d.label); }
//
// and its image is those fields in that order, numbers little-endian (stride/common/bytes.hpp),
// arrays element by element, nested structs by their own state_fields. So the image is the same
// bytes on every host, whatever its byte order or padding (docs/sdk.md, "State images").
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "stride/common/bytes.hpp"

// The compiler can tell padding from members: field lists are checked (state_fields_gap).
#if defined(__has_builtin)
#if __has_builtin(__builtin_clear_padding)
#define STRIDE_SDK_CHECKS_STATE_FIELDS 1
#endif
#endif

namespace stride::sdk {

/// A struct whose fields `state_fields(s, f)` lists (found by argument-dependent lookup).
template <class T>
concept described_state = std::is_class_v<T> && requires(T& s) {
  state_fields(s, [](auto&...) {});
};

namespace detail {

template <class T>
inline constexpr bool unsupported_state_field = false;

// an array of numbers whose image is its memory: one copy instead of one call per element
// (not bool: a damaged image must not make one that is neither true nor false)
template <class E>
inline constexpr bool copied_whole = common::encodable_number<E> && !std::is_same_v<E, bool> &&
                                     (sizeof(E) == 1 || std::endian::native == std::endian::little);

}  // namespace detail

/// Appends the image of `s` (a number, an enumeration, an array of them or a described struct).
template <class T>
void put_state(common::byte_writer& w, const T& s) {
  if constexpr (common::encodable_number<T>) {
    w.put(s);
  } else if constexpr (std::is_array_v<T>) {
    using element = std::remove_all_extents_t<T>;
    if constexpr (detail::copied_whole<element>) {
      w.put_raw(std::as_bytes(std::span(&s, 1)));
    } else {
      for (const auto& e : s) put_state(w, e);
    }
  } else if constexpr (described_state<T>) {
    // state_fields takes the struct by non-const reference so that one list serves both ways;
    // writing only reads the fields
    state_fields(const_cast<T&>(s), [&w](const auto&... f) { (put_state(w, f), ...); });
  } else {
    static_assert(detail::unsupported_state_field<T>,
                  "a state field is a number, an enumeration, an array of them or a struct with "
                  "state_fields()");
  }
}

/// Reads what put_state wrote into `s`; `Reader` is a common::byte_reader, which throws its
/// error when the image ends early.
template <class T, class Reader>
void get_state(Reader& r, T& s) {
  if constexpr (std::is_same_v<T, bool>) {
    const auto b = r.template get<std::uint8_t>();
    if (b > 1) r.fail();
    s = b == 1;
  } else if constexpr (common::encodable_number<T>) {
    s = r.template get<T>();
  } else if constexpr (std::is_array_v<T>) {
    using element = std::remove_all_extents_t<T>;
    if constexpr (detail::copied_whole<element>) {
      std::memcpy(&s, r.get_raw(sizeof s).data(), sizeof s);
    } else {
      for (auto& e : s) get_state(r, e);
    }
  } else if constexpr (described_state<T>) {
    state_fields(s, [&r](auto&... f) { (get_state(r, f), ...); });
  } else {
    static_assert(detail::unsupported_state_field<T>,
                  "a state field is a number, an enumeration, an array of them or a struct with "
                  "state_fields()");
  }
}

namespace detail {

// Marks the bytes of every listed field of the object at `base` in `covered` (a count per byte).
template <class T>
void mark_fields(const std::byte* base, const T& s, std::vector<int>& covered) {
  if constexpr (common::encodable_number<T>) {
    const auto at = static_cast<std::size_t>(reinterpret_cast<const std::byte*>(&s) - base);
    for (std::size_t i = 0; i < sizeof s; ++i) ++covered[at + i];
  } else if constexpr (std::is_array_v<T>) {
    for (const auto& e : s) mark_fields(base, e, covered);
  } else {
    state_fields(const_cast<T&>(s),
                 [&](const auto&... f) { (mark_fields(base, f, covered), ...); });
  }
}

}  // namespace detail

/// What is wrong with `Data`'s field list: a byte of a member that no field covers (a member
/// missing from state_fields) or one listed twice; empty when the list is complete. Padding
/// is told apart from members by the compiler (__builtin_clear_padding); without it, "".
template <described_state Data>
std::string state_fields_gap() {
#ifdef STRIDE_SDK_CHECKS_STATE_FIELDS
  static_assert(std::is_trivially_copyable_v<Data>);
  alignas(Data) std::byte image[sizeof(Data)];
  std::memset(image, 0xff, sizeof image);
  auto* object = reinterpret_cast<Data*>(image);
  __builtin_clear_padding(object);  // every byte still non-zero belongs to some member
  std::vector<int> covered(sizeof(Data), 0);
  detail::mark_fields(image, *object, covered);
  for (std::size_t i = 0; i < sizeof(Data); ++i) {
    if (covered[i] > 1) return "byte " + std::to_string(i) + " is in two listed fields";
    if (covered[i] == 0 && image[i] != std::byte{0}) {
      return "byte " + std::to_string(i) + " of " + std::to_string(sizeof(Data)) +
             " belongs to a member that state_fields() does not list";
    }
  }
#endif
  return {};
}

}  // namespace stride::sdk
