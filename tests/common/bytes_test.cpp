// Saved states as bytes: what byte_writer writes (little-endian on every host), byte_reader reads
// back, and damaged bytes (cut short, or a length larger than what follows) throw the caller's
// error type.
#include "stride/common/bytes.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace stride::common {
namespace {

struct damaged : std::runtime_error {
  using std::runtime_error::runtime_error;
};

TEST(common_bytes, values_and_strings_read_back_in_order) {
  byte_writer w;
  w.put(std::int32_t{-5});
  w.put(0.1);
  w.put_string("gait");
  w.put_string("");
  w.put(std::uint8_t{7});
  byte_reader<damaged> r(w.bytes(), "state damaged");
  EXPECT_EQ(r.get<std::int32_t>(), -5);
  EXPECT_EQ(r.get<double>(), 0.1);
  EXPECT_EQ(r.get_string(), "gait");
  EXPECT_EQ(r.get_string(), "");
  EXPECT_FALSE(r.at_end());
  EXPECT_EQ(r.get<std::uint8_t>(), 7);
  EXPECT_TRUE(r.at_end());
}

// The bytes are the same on every host: least significant first, doubles as IEEE 754.
TEST(common_bytes, numbers_are_little_endian_whatever_the_host) {
  byte_writer w;
  w.put(std::uint32_t{0x01020304});
  w.put(1.0);
  w.put(std::int16_t{-2});
  const std::vector<std::byte> expected = {
      std::byte{0x04}, std::byte{0x03}, std::byte{0x02}, std::byte{0x01},  // uint32
      std::byte{0x00}, std::byte{0x00}, std::byte{0x00}, std::byte{0x00},  // 1.0
      std::byte{0x00}, std::byte{0x00}, std::byte{0xf0}, std::byte{0x3f},
      std::byte{0xfe}, std::byte{0xff}};  // int16 -2
  EXPECT_EQ(w.bytes(), expected);
  byte_reader<damaged> r(expected, "x");
  EXPECT_EQ(r.get<std::uint32_t>(), 0x01020304u);
  EXPECT_EQ(r.get<double>(), 1.0);
  EXPECT_EQ(r.get<std::int16_t>(), -2);
}

TEST(common_bytes, reading_past_the_end_throws_the_callers_error_with_its_message) {
  byte_writer w;
  w.put(std::int32_t{1});
  byte_reader<damaged> r(w.bytes(), "robot state: cut short");
  EXPECT_EQ(r.get<std::int16_t>(), 1);
  try {
    (void)r.get<std::int32_t>();
    FAIL() << "no exception";
  } catch (const damaged& e) {
    EXPECT_STREQ(e.what(), "robot state: cut short");
  }
}

TEST(common_bytes, a_length_larger_than_what_follows_is_refused_before_allocating) {
  byte_writer w;
  w.put(std::numeric_limits<std::uint64_t>::max());  // a string length no input can hold
  w.put(std::int64_t{0});
  {
    byte_reader<damaged> r(w.bytes(), "x");
    EXPECT_THROW((void)r.get_string(), damaged);
  }
  {
    // 2 items of 8 bytes do not fit in the 8 bytes left; 1 does
    byte_writer v;
    v.put_size(2);
    v.put(1.0);
    byte_reader<damaged> r(v.bytes(), "x");
    EXPECT_THROW((void)r.get_size(sizeof(double)), damaged);
    byte_reader<damaged> again(v.bytes(), "x");
    (void)again.get<std::uint64_t>();
    EXPECT_NO_THROW(again.need(1, sizeof(double)));
    EXPECT_THROW(again.need(std::numeric_limits<std::uint64_t>::max(), 2), damaged);
  }
}

TEST(common_bytes, take_moves_the_bytes_out) {
  byte_writer w;
  w.put_string("abc");
  const std::size_t size = w.bytes().size();
  const std::vector<std::byte> bytes = w.take();
  EXPECT_EQ(bytes.size(), size);
  EXPECT_EQ(size, sizeof(std::uint64_t) + 3);
}

}  // namespace
}  // namespace stride::common
