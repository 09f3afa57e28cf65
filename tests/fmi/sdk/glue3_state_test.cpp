// FMI 3.0 FMU state of glue3_state.cpp: get/set, serialize/deserialize, and the resumed run
// equal to the uninterrupted one.
#include <gtest/gtest.h>

#include <vector>

#include "fmi3_harness.hpp"

namespace stride::test {
namespace {

void drive(fmi3_harness& h, double from, int steps) {
  for (int k = 0; k < steps; ++k) {
    ASSERT_EQ(h.set_float64("u", 1.0 + from + 0.1 * k), fmi3OK);
    ASSERT_EQ(h.step(from + 0.1 * k, 0.1), fmi3OK);
  }
}

TEST(glue3_state, set_state_rewinds_to_the_saved_point) {
  fmi3_harness h;
  h.to_step_mode();
  drive(h, 0, 3);
  fmi3FMUState s = nullptr;
  ASSERT_EQ(fmi3GetFMUState(h.instance(), &s), fmi3OK);
  ASSERT_NE(s, nullptr);
  const double at_save = h.get_float64("integral");
  drive(h, 0.3, 2);
  ASSERT_NE(h.get_float64("integral"), at_save);
  ASSERT_EQ(fmi3SetFMUState(h.instance(), s), fmi3OK);
  EXPECT_EQ(h.get_float64("integral"), at_save);
  EXPECT_DOUBLE_EQ(h.get_float64("time"), 0.3);
  EXPECT_EQ(fmi3FreeFMUState(h.instance(), &s), fmi3OK);
  EXPECT_EQ(s, nullptr);
}

TEST(glue3_state, a_serialized_state_resumes_identically_in_another_instance) {
  fmi3_harness a;
  a.to_step_mode();
  drive(a, 0, 4);
  fmi3FMUState s = nullptr;
  ASSERT_EQ(fmi3GetFMUState(a.instance(), &s), fmi3OK);
  size_t size = 0;
  ASSERT_EQ(fmi3SerializedFMUStateSize(a.instance(), s, &size), fmi3OK);
  std::vector<fmi3Byte> bytes(size);
  EXPECT_EQ(fmi3SerializeFMUState(a.instance(), s, bytes.data(), size - 1), fmi3Error);
  ASSERT_EQ(fmi3SerializeFMUState(a.instance(), s, bytes.data(), size), fmi3OK);
  drive(a, 0.4, 5);

  fmi3_harness b;
  b.to_step_mode();
  fmi3FMUState t = nullptr;
  ASSERT_EQ(fmi3DeserializeFMUState(b.instance(), bytes.data(), bytes.size(), &t), fmi3OK);
  ASSERT_EQ(fmi3SetFMUState(b.instance(), t), fmi3OK);
  drive(b, 0.4, 5);
  EXPECT_EQ(b.get_float64("integral"), a.get_float64("integral"));  // bit-identical
  EXPECT_EQ(b.get_float64("time"), a.get_float64("time"));
  fmi3FreeFMUState(a.instance(), &s);
  fmi3FreeFMUState(b.instance(), &t);
}

TEST(glue3_state, corrupt_and_unknown_states_are_refused) {
  fmi3_harness h;
  h.to_step_mode();
  const std::vector<fmi3Byte> garbage(16, 0x5a);
  fmi3FMUState t = nullptr;
  EXPECT_EQ(fmi3DeserializeFMUState(h.instance(), garbage.data(), garbage.size(), &t), fmi3Error);
  EXPECT_EQ(t, nullptr);
  int not_a_state = 0;
  EXPECT_EQ(fmi3SetFMUState(h.instance(), &not_a_state), fmi3Error);
  EXPECT_TRUE(h.logged("fmi3SetFMUState: unknown FMUState"));
  EXPECT_EQ(fmi3GetFMUState(h.instance(), nullptr), fmi3Error);
}

}  // namespace
}  // namespace stride::test
