// buffer_table_builder: the layout of a table built at run time, and its start values.
#include <gtest/gtest.h>

#include <cstring>

#include "stride/sdk/model.hpp"
#include "stride/sdk/variable_table.hpp"

namespace stride::sdk {
namespace {

template <class T>
T start_of(const variable_table& t, const variable& v) {
  T value;
  std::memcpy(&value, static_cast<const char*>(t.defaults()) + v.offset, sizeof(T));
  return value;
}

TEST(buffer_table_builder, lays_values_out_aligned_and_in_declaration_order) {
  buffer_table_builder b;
  std::size_t flag = 0, gain = 0, count = 0;
  b.add<bool>("on", true, &flag).parameter();
  b.add<double>("gain", 2.5, &gain).parameter();
  b.add<int>("count", 7, &count).parameter();
  EXPECT_EQ(flag, 0u);
  EXPECT_EQ(gain, 8u);  // a double after one bool starts at the next multiple of 8
  EXPECT_EQ(count, 16u);
  const variable_table t = b.finish();
  ASSERT_EQ(t.variables().size(), 3u);
  EXPECT_EQ(t.data_size(), 20u);
  EXPECT_TRUE(start_of<bool>(t, *t.find("on")));
  EXPECT_EQ(start_of<double>(t, *t.find("gain")), 2.5);
  EXPECT_EQ(start_of<int>(t, *t.find("count")), 7);
  EXPECT_EQ(t.find("count")->value_reference, 2u);
}

TEST(buffer_table_builder, an_array_and_its_named_elements_share_storage) {
  buffer_table_builder b;
  const std::size_t at = b.reserve<double>(3, 0.0);
  b.set_start(at + sizeof(double), 1.25);
  b.declare<double>("q", at, 3, true).input().unit("rad");
  b.declare<double>("knee", at + sizeof(double)).input();
  const variable_table t = b.finish();
  ASSERT_EQ(t.variables().size(), 4u);
  EXPECT_EQ(t.find("q[2]")->offset, t.find("knee")->offset);
  EXPECT_NE(t.find("q[2]")->value_reference, t.find("knee")->value_reference);
  EXPECT_EQ(start_of<double>(t, *t.find("knee")), 1.25);
  EXPECT_EQ(start_of<double>(t, *t.find("q[1]")), 0.0);
  EXPECT_EQ(t.find("q[3]")->unit, "rad");
}

TEST(buffer_table_builder, a_one_element_array_keeps_its_index) {
  buffer_table_builder b;
  b.declare<double>("q", b.reserve<double>(1, 0.0), 1, true).output();
  const variable_table t = b.finish();
  EXPECT_NE(t.find("q[1]"), nullptr);
}

TEST(buffer_table_builder, refuses_storage_that_was_not_reserved) {
  buffer_table_builder b;
  const std::size_t at = b.reserve<int>(1, 0);
  EXPECT_THROW(b.declare<double>("wide", at), std::logic_error);  // 8 bytes over 4
  EXPECT_THROW(b.set_start(at + 4, 1), std::logic_error);
}

TEST(buffer_table_builder, strings_keep_their_capacity_and_start) {
  buffer_table_builder b;
  text name;
  name.assign("webots");
  b.add<text>("profile", name).parameter();
  const variable_table t = b.finish();
  const variable& v = *t.find("profile");
  EXPECT_EQ(v.type, value_type::string);
  EXPECT_EQ(v.string_capacity, text::capacity());
  EXPECT_EQ(start_of<text>(t, v).view(), "webots");
}

// a buffer_model starts from the table's start values and its state is the buffer
class counter final : public buffer_model {
 public:
  counter(const variable_table& t, std::size_t at) : buffer_model(t), at_(at) {}
  step_result do_step(time_ns, time_ns) override {
    value<int>(at_) += 1;
    return step_result::ok;
  }
  int count() const { return value<int>(at_); }

 private:
  std::size_t at_;
};

TEST(buffer_model, starts_at_the_start_values_and_restores_its_buffer) {
  buffer_table_builder b;
  std::size_t at = 0;
  b.add<double>("pad", 0.0);
  b.add<int>("n", 40, &at).output();
  const variable_table t = b.finish();
  counter m(t, at);
  EXPECT_EQ(m.count(), 40);
  const auto saved = m.save_state();
  m.do_step(0, 1);
  m.do_step(1, 1);
  EXPECT_EQ(m.count(), 42);
  m.restore_state(saved);
  EXPECT_EQ(m.count(), 40);
  std::vector<std::byte> short_state(saved.begin(), saved.end() - 1);
  EXPECT_THROW(m.restore_state(short_state), model_error);
}

}  // namespace
}  // namespace stride::sdk
