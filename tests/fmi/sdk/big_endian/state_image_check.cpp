// Built for a big-endian machine (s390x) and run under emulation: the state image the SDK writes
// there is byte for byte the little-endian image written on x86-64, and an image written on
// x86-64 reads back there to the same values. Exit 0 when both hold.
#include <bit>
#include <cstdio>
#include <stdexcept>

#include "../state_sample.hpp"
#include "stride/sdk/state_fields.hpp"

namespace sample = stride::sdk::sample;

int main() {
  if constexpr (std::endian::native != std::endian::big) {
    std::puts("not a big-endian build: nothing shown");
    return 1;
  }
  stride::common::byte_writer w;
  stride::sdk::put_state(w, sample::values());
  if (w.bytes() != sample::image()) {
    std::puts("the image written on this big-endian host differs from the little-endian one");
    return 1;
  }
  const std::vector<std::byte> image = sample::image();
  stride::common::byte_reader<std::runtime_error> r(image, "ends early");
  sample::outer back;
  stride::sdk::get_state(r, back);
  const sample::outer expected = sample::values();
  const bool same =
      r.at_end() && back.flag == expected.flag && back.counts[0] == expected.counts[0] &&
      back.counts[1] == expected.counts[1] && back.nested[0].a == expected.nested[0].a &&
      back.nested[0].b == expected.nested[0].b && back.nested[1].a == expected.nested[1].a &&
      back.nested[1].b == expected.nested[1].b && back.tag.view() == "ab";
  std::puts(same ? "big-endian host: image written and read as on little-endian hosts"
                 : "the little-endian image read back wrong on this big-endian host");
  return same ? 0 : 1;
}
