// buffer_model: the image of a table built at run time is each reserved value by its type,
// little-endian and without the buffer's alignment gaps; it reads back only whole.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "stride/sdk/model.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {
namespace {

class values_model : public buffer_model {
 public:
  using buffer_model::buffer_model;
  using buffer_model::value;
  step_result do_step(time_ns, time_ns) override { return step_result::ok; }
};

struct layout {
  std::size_t flag = 0, gain = 0, counts = 0, name = 0;
};

variable_table make_table(layout& at) {
  buffer_table_builder b;
  b.add<bool>("on", true, &at.flag).parameter();
  b.add<double>("gain", 2.5, &at.gain).parameter();
  at.counts = b.reserve<int>(2, -2);
  b.declare<int>("counts", at.counts, 2, true).output();
  b.add<fixed_string<3>>("name", fixed_string<3>{"ab"}, &at.name).parameter();
  return b.finish();
}

std::vector<std::byte> bytes_of(std::initializer_list<int> values) {
  std::vector<std::byte> out;
  for (int v : values) out.push_back(static_cast<std::byte>(v));
  return out;
}

TEST(buffer_model, an_image_is_each_reserved_value_without_the_alignment_gaps) {
  layout at;
  const variable_table table = make_table(at);
  values_model m(table);
  m.value<int>(at.counts) = 0x01020304;
  const std::vector<std::byte> expected = bytes_of({
      0x01,                                            // on
      0,    0,    0,    0,    0,    0,    0x04, 0x40,  // gain 2.5
      0x04, 0x03, 0x02, 0x01, 0xfe, 0xff, 0xff, 0xff,  // counts
      'a',  'b',  0,    0,                             // name
  });
  EXPECT_EQ(m.save_state(), expected);
}

TEST(buffer_model, an_image_reads_back_whole_or_not_at_all) {
  layout at;
  const variable_table table = make_table(at);
  values_model a(table), b(table);
  a.value<double>(at.gain) = -1.5;
  a.value<bool>(at.flag) = false;
  const std::vector<std::byte> image = a.save_state();
  void* const buffer = b.data();
  b.restore_state(image);
  EXPECT_EQ(b.data(), buffer);  // the glue holds this address: restored in place
  EXPECT_EQ(b.value<double>(at.gain), -1.5);
  EXPECT_FALSE(b.value<bool>(at.flag));
  EXPECT_EQ(b.save_state(), image);

  values_model c(table);
  const std::vector<std::byte> before = c.save_state();
  EXPECT_THROW(c.restore_state(std::span(image).first(image.size() - 1)), model_error);
  std::vector<std::byte> longer = image;
  longer.push_back(std::byte{0});
  EXPECT_THROW(c.restore_state(longer), model_error);
  std::vector<std::byte> bad_flag = image;
  bad_flag[0] = std::byte{7};
  EXPECT_THROW(c.restore_state(bad_flag), model_error);
  EXPECT_EQ(c.save_state(), before);
}

}  // namespace
}  // namespace stride::sdk
