// A struct of every kind of state field and its image, byte for byte: what put_state must write
// on any host (state_fields_test on this one, state_image_on_big_endian under an emulated
// big-endian machine).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "stride/sdk/types.hpp"

namespace stride::sdk::sample {

struct inner {
  std::int16_t a = 0;
  double b = 0;  // 6 bytes of padding before it on common hosts
};
template <class F>
void state_fields(inner& s, F&& f) {
  f(s.a, s.b);
}

struct outer {
  bool flag = false;
  std::int32_t counts[2] = {};
  inner nested[2]{};
  fixed_string<3> tag{};
};
template <class F>
void state_fields(outer& s, F&& f) {
  f(s.flag, s.counts, s.nested, s.tag);
}

inline outer values() {
  outer o;
  o.flag = true;
  o.counts[0] = 0x01020304;
  o.counts[1] = -2;
  o.nested[0] = {0x0506, 1.0};
  o.nested[1] = {-1, -2.5};
  o.tag.assign("ab");
  return o;
}

inline std::vector<std::byte> bytes_of(std::initializer_list<int> values) {
  std::vector<std::byte> out;
  for (int v : values) out.push_back(static_cast<std::byte>(v));
  return out;
}

/// put_state(values()), little-endian, no padding.
inline std::vector<std::byte> image() {
  return bytes_of({
      0x01,                                                        // flag
      0x04, 0x03, 0x02, 0x01, 0xfe, 0xff, 0xff, 0xff,              // counts
      0x06, 0x05, 0,    0,    0,    0,    0,    0,    0xf0, 0x3f,  // nested[0]: 0x0506, 1.0
      0xff, 0xff, 0,    0,    0,    0,    0,    0,    0x04, 0xc0,  // nested[1]: -1, -2.5
      'a',  'b',  0,    0,                                         // tag, all its capacity
  });
}

}  // namespace stride::sdk::sample
