// State images field by field: the same bytes on every host (numbers little-endian, no padding),
// read back exactly, damaged images refused, and incomplete field lists caught.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "state_sample.hpp"
#include "stride/sdk/model.hpp"
#include "stride/sdk/state_fields.hpp"
#include "stride/sdk/types.hpp"

namespace stride::sdk {
namespace {

using ::testing::HasSubstr;

struct forgetful {
  double kept = 0;
  int forgotten = 0;
};
template <class F>
void state_fields(forgetful& s, F&& f) {
  f(s.kept);
}

struct twice {
  double x = 0;
};
template <class F>
void state_fields(twice& s, F&& f) {
  f(s.x, s.x);
}

TEST(state_fields, an_image_is_each_field_little_endian_without_padding) {
  common::byte_writer w;
  put_state(w, sample::values());
  EXPECT_EQ(w.bytes(), sample::image());
}

TEST(state_fields, an_image_reads_back_into_an_equal_struct) {
  common::byte_writer w;
  put_state(w, sample::values());
  const std::vector<std::byte> image = w.take();
  state_reader r(image);
  sample::outer back;
  get_state(r, back);
  EXPECT_TRUE(r.at_end());
  common::byte_writer again;
  put_state(again, back);
  EXPECT_EQ(again.bytes(), image);
  EXPECT_EQ(back.nested[1].b, -2.5);
  EXPECT_EQ(back.tag.view(), "ab");
}

TEST(state_fields, a_damaged_image_is_refused) {
  common::byte_writer w;
  put_state(w, sample::values());
  std::vector<std::byte> image = w.take();
  sample::outer back;
  state_reader short_one{std::span(image).first(image.size() - 1)};
  EXPECT_THROW(get_state(short_one, back), model_error);
  image[0] = std::byte{2};  // a Boolean neither false nor true
  state_reader bad_bool(image);
  EXPECT_THROW(get_state(bad_bool, back), model_error);
}

TEST(state_fields, one_struct_alone_is_imaged_and_read_back_all_or_nothing) {
  const std::vector<std::byte> image = state_image(sample::values());
  EXPECT_EQ(image, sample::image());
  sample::outer back;
  read_state_image(image, back);
  EXPECT_EQ(state_image(back), image);

  const std::vector<std::byte> fresh = state_image(sample::outer{});
  sample::outer kept;
  std::vector<std::byte> longer = image;
  longer.push_back(std::byte{0});
  EXPECT_THROW(read_state_image(longer, kept), model_error);
  EXPECT_THROW(read_state_image(std::span(image).first(image.size() - 1), kept), model_error);
  EXPECT_EQ(state_image(kept), fresh);
}

TEST(state_fields, a_list_missing_a_member_or_naming_one_twice_is_caught) {
  EXPECT_EQ(state_fields_gap<sample::outer>(), "");
  EXPECT_EQ(state_fields_gap<sample::inner>(), "");
#ifdef STRIDE_SDK_CHECKS_STATE_FIELDS
  EXPECT_THAT(state_fields_gap<forgetful>(),
              HasSubstr("belongs to a member that state_fields() does not list"));
  EXPECT_THAT(state_fields_gap<twice>(), HasSubstr("is in two listed fields"));
#endif
}

// a component whose field list misses a member cannot be instantiated: its states would lose it
class forgetful_model : public model_base<forgetful> {
 public:
  step_result do_step(time_ns, time_ns) override { return step_result::ok; }
};

class complete_model : public model_base<sample::outer> {
 public:
  step_result do_step(time_ns, time_ns) override { return step_result::ok; }
  sample::outer& values() { return data_; }
};

TEST(state_fields, a_model_with_an_incomplete_list_is_refused_and_a_complete_one_round_trips) {
#ifdef STRIDE_SDK_CHECKS_STATE_FIELDS
  EXPECT_THROW(forgetful_model{}, model_error);
#endif
  complete_model a;
  a.values() = sample::values();
  const std::vector<std::byte> image = a.save_state();
  complete_model b;
  b.restore_state(image);
  EXPECT_EQ(b.save_state(), image);
  EXPECT_EQ(b.values().counts[0], 0x01020304);

  std::vector<std::byte> longer = image;
  longer.push_back(std::byte{0});
  EXPECT_THROW(b.restore_state(longer), model_error);
  // a refused image changes nothing
  EXPECT_THROW(b.restore_state(std::span(image).first(10)), model_error);
  EXPECT_EQ(b.save_state(), image);
}

}  // namespace
}  // namespace stride::sdk
