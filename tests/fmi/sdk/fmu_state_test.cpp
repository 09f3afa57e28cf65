// FMU state: get/set and serialisation restore the continuation bit-exactly.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "fmi_harness.hpp"

namespace stride::test {
namespace {

std::vector<double> run(fmi_harness& h, double t0, int steps) {
  std::vector<double> out;
  for (int i = 0; i < steps; ++i) {
    EXPECT_EQ(h.set_real("u", 0.1 * (i + 1)), fmi2OK);
    EXPECT_EQ(fmi2DoStep(h.c(), t0 + 0.01 * i, 0.01, fmi2True), fmi2OK);
    out.push_back(h.get_real("integral"));
    out.push_back(h.get_integer("counter"));
  }
  return out;
}

TEST(fmu_state, get_and_set_restore_the_continuation) {
  fmi_harness h;
  h.to_step_complete();
  run(h, 0.0, 5);
  fmi2FMUstate saved = nullptr;
  ASSERT_EQ(fmi2GetFMUstate(h.c(), &saved), fmi2OK);
  const std::vector<double> first = run(h, 0.05, 5);
  ASSERT_EQ(fmi2SetFMUstate(h.c(), saved), fmi2OK);
  fmi2Real time = 0;
  ASSERT_EQ(fmi2GetRealStatus(h.c(), fmi2LastSuccessfulTime, &time), fmi2OK);
  EXPECT_DOUBLE_EQ(time, 0.05);
  const std::vector<double> second = run(h, 0.05, 5);
  EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
  ASSERT_EQ(fmi2FreeFMUstate(h.c(), &saved), fmi2OK);
  EXPECT_EQ(saved, nullptr);
}

TEST(fmu_state, serialized_state_restores_in_another_instance) {
  fmi_harness a;
  a.to_step_complete();
  run(a, 0.0, 3);
  fmi2FMUstate state = nullptr;
  ASSERT_EQ(fmi2GetFMUstate(a.c(), &state), fmi2OK);
  size_t size = 0;
  ASSERT_EQ(fmi2SerializedFMUstateSize(a.c(), state, &size), fmi2OK);
  std::vector<fmi2Byte> bytes(size);
  ASSERT_EQ(fmi2SerializeFMUstate(a.c(), state, bytes.data(), size), fmi2OK);
  EXPECT_EQ(fmi2SerializeFMUstate(a.c(), state, bytes.data(), size - 1), fmi2Error);
  const std::vector<double> expected = run(a, 0.03, 4);

  fmi_harness b;
  b.to_step_complete();
  fmi2FMUstate restored = nullptr;
  ASSERT_EQ(fmi2DeSerializeFMUstate(b.c(), bytes.data(), size, &restored), fmi2OK);
  ASSERT_EQ(fmi2SetFMUstate(b.c(), restored), fmi2OK);
  EXPECT_EQ(run(b, 0.03, 4), expected);
  fmi2FreeFMUstate(a.c(), &state);
  fmi2FreeFMUstate(b.c(), &restored);
}

TEST(fmu_state, foreign_bytes_and_handles_are_rejected) {
  fmi_harness h;
  h.to_step_complete();
  std::vector<fmi2Byte> junk(200, 'x');
  fmi2FMUstate state = nullptr;
  EXPECT_EQ(fmi2DeSerializeFMUstate(h.c(), junk.data(), junk.size(), &state), fmi2Error);
  EXPECT_TRUE(h.logged("not a Stride FMU state"));
  EXPECT_EQ(fmi2DeSerializeFMUstate(h.c(), junk.data(), 3, &state), fmi2Error);
  int not_a_state = 0;
  EXPECT_EQ(fmi2SetFMUstate(h.c(), &not_a_state), fmi2Error);
  EXPECT_TRUE(h.logged("unknown FMUstate"));
}

// little-endian number of `n` bytes at `p`
std::uint64_t little_endian(const fmi2Byte* p, int n) {
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

std::vector<fmi2Byte> serialized(fmi_harness& h) {
  fmi2FMUstate state = nullptr;
  EXPECT_EQ(fmi2GetFMUstate(h.c(), &state), fmi2OK);
  size_t size = 0;
  EXPECT_EQ(fmi2SerializedFMUstateSize(h.c(), state, &size), fmi2OK);
  std::vector<fmi2Byte> bytes(size);
  EXPECT_EQ(fmi2SerializeFMUstate(h.c(), state, bytes.data(), size), fmi2OK);
  fmi2FreeFMUstate(h.c(), &state);
  return bytes;
}

// docs/sdk.md, "State images": the same bytes on any host
TEST(fmu_state, a_serialized_state_is_laid_out_little_endian_field_by_field) {
  fmi_harness h;
  h.to_step_complete();
  run(h, 0.0, 3);
  const std::vector<fmi2Byte> bytes = serialized(h);
  ASSERT_GT(bytes.size(), 64u);
  EXPECT_EQ(std::string(bytes.data(), 8), "STRDSTA2");
  const auto guid_size = static_cast<std::size_t>(little_endian(&bytes[8], 8));
  ASSERT_LT(guid_size, 64u);
  const std::size_t time_at = 16 + guid_size;
  EXPECT_EQ(little_endian(&bytes[time_at], 8), 30'000'000u);  // 3 steps of 10 ms, in ns
  // then the lifecycle (u32) and the termination flag (u8); then the data, gain first
  const double gain = h.get_real("gain");
  std::uint64_t gain_bits = 0;
  std::memcpy(&gain_bits, &gain, sizeof gain);
  EXPECT_EQ(little_endian(&bytes[time_at + 8 + 4 + 1], 8), gain_bits);
}

TEST(fmu_state, a_state_of_the_earlier_memory_layout_or_cut_short_is_refused) {
  fmi_harness h;
  h.to_step_complete();
  std::vector<fmi2Byte> bytes = serialized(h);
  bytes[7] = '1';
  fmi2FMUstate state = nullptr;
  EXPECT_EQ(fmi2DeSerializeFMUstate(h.c(), bytes.data(), bytes.size(), &state), fmi2Error);
  EXPECT_TRUE(h.logged("an FMU state of an earlier Stride (format 1"));

  bytes[7] = '2';
  ASSERT_EQ(fmi2DeSerializeFMUstate(h.c(), bytes.data(), bytes.size() - 1, &state), fmi2OK);
  EXPECT_EQ(fmi2SetFMUstate(h.c(), state), fmi2Error);
  EXPECT_TRUE(h.logged("the FMU state is damaged or is not of this component (it ends early)"));
}

TEST(fmu_state, state_of_another_instance_is_unknown_here) {
  fmi_harness a, b;
  a.to_step_complete();
  b.to_step_complete();
  fmi2FMUstate state = nullptr;
  ASSERT_EQ(fmi2GetFMUstate(a.c(), &state), fmi2OK);
  EXPECT_EQ(fmi2SetFMUstate(b.c(), state), fmi2Error);
  fmi2FreeFMUstate(a.c(), &state);
}

}  // namespace
}  // namespace stride::test
