// Target files and offset selections: what is accepted, and errors that name file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stride/calibration/offsets.hpp"
#include "stride/calibration/targets.hpp"

namespace stride::calibration {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;

// the message of the target_error thrown by f
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const target_error& e) {
    return e.what();
  }
  return "(no target_error)";
}

std::string joint_error(const std::string& text) {
  return error_of([&] { parse_joint_target(text, "t.csv"); });
}

std::string plant_error(const std::string& text) {
  return error_of([&] { parse_plant_target(text, "t.ini"); });
}

TEST(calibration_joint_target, reads_counts_degrees_and_radians_as_counts) {
  const auto c = parse_joint_target("id,count\n11,1637\n7,2048\n", "c.csv");
  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(c.joints[0].id, 7);  // sorted by ID
  EXPECT_EQ(c.joints[1].id, 11);
  EXPECT_EQ(c.joints[1].count, 1637.0);
  EXPECT_EQ(c.joints[1].line, 2);
  EXPECT_EQ(c.unit, angle_unit::count);

  const auto d = parse_joint_target("name , DEG, id\nknee, 8.8, 13\n", "d.csv");
  ASSERT_EQ(d.joints.size(), 1u);
  EXPECT_NEAR(d.joints[0].count, 2148.0, 1e-9);  // 8.8 deg = 100 counts of 0.088 deg

  const auto r = parse_joint_target("\xEF\xBB\xBFid,rad\r\n# a comment\r\n\r\n13,0.5\r\n", "r.csv");
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_NEAR(r.joints[0].count, 2048 + 0.5 * 180 / std::numbers::pi / 0.088, 1e-9);
  EXPECT_NEAR(from_counts(r.joints[0].count, angle_unit::rad), 0.5, 1e-12);
}

TEST(calibration_joint_target, bad_files_name_file_and_line) {
  EXPECT_EQ(error_of([] { read_joint_target(k_data / "unknown_id.csv"); }),
            (k_data / "unknown_id.csv").string() +
                ":4: unknown servo ID 21 (DARwIn-OP servo IDs are 1..20)");
  EXPECT_EQ(error_of([] { read_joint_target(k_data / "duplicate_id.csv"); }),
            (k_data / "duplicate_id.csv").string() + ":4: duplicate servo ID 11 (first on line 2)");
  EXPECT_EQ(error_of([] { read_joint_target(k_data / "non_numeric.csv"); }),
            (k_data / "non_numeric.csv").string() + ":3: value 'abc' of servo 14 is not a number");
  EXPECT_EQ(error_of([] { read_joint_target(k_data / "empty.csv"); }),
            (k_data / "empty.csv").string() + ": empty target: no joint rows");
  EXPECT_THAT(error_of([] { read_joint_target(k_data / "no-such-file.csv"); }),
              HasSubstr("no-such-file.csv: cannot read the target file"));
}

TEST(calibration_joint_target, rejects_malformed_rows_and_headers) {
  EXPECT_EQ(joint_error(""), "t.csv: empty target: no CSV header (id and one of count, deg, rad)");
  EXPECT_THAT(joint_error("servo,count\n1,2\n"),
              StartsWith("t.csv:1: expected a CSV header with column 'id'"));
  EXPECT_EQ(joint_error("id,count,deg\n1,2,3\n"),
            "t.csv:1: the header has both 'count' and 'deg': give exactly one of count, deg, rad");
  EXPECT_THAT(joint_error("[Plant Target]\npitch_deg = 0\n"),
              HasSubstr("(a plant target? use --mode plant)"));
  EXPECT_EQ(joint_error("id,count\n7,2048,1\n"),
            "t.csv:2: expected 2 fields as in the header, got 3");
  EXPECT_EQ(joint_error("id,count\n7.5,2048\n"), "t.csv:2: servo ID '7.5' is not an integer");
  EXPECT_EQ(joint_error("id,count\n0,2048\n"),
            "t.csv:2: unknown servo ID 0 (DARwIn-OP servo IDs are 1..20)");
  EXPECT_EQ(joint_error("id,count\n\n7,\n"), "t.csv:3: value '' of servo 7 is not a number");
  EXPECT_EQ(joint_error("id,count\n7,nan\n"), "t.csv:2: value of servo 7 is not finite");
  EXPECT_EQ(joint_error("id,count\n7,5000\n"),
            "t.csv:2: value 5000 count of servo 7 is outside the servo range 0..4095 counts");
}

TEST(calibration_joint_target, delta_columns_group_rows_into_postures) {
  const auto t = parse_joint_target(
      "id,count,delta_z_offset,Delta_X_Offset\n"
      "13,2600,0,0\n"
      "13,2700,10,0\n"
      "11,1600,10,0\n"
      "11,1650,0,0\n"
      "13,2750,10,-5.5\n",
      "p.csv");
  ASSERT_EQ(t.postures.size(), 3u);
  EXPECT_EQ(t.postures[0].line, 2);
  EXPECT_EQ(t.postures[1].line, 3);
  EXPECT_EQ(t.postures[1].delta[*find_offset("z_offset")], 10.0);
  EXPECT_EQ(t.postures[2].delta[*find_offset("x_offset")], -5.5);
  EXPECT_EQ(t.postures[2].delta[*find_offset("y_offset")], 0.0);
  // sorted by posture, then ID; the same servo may appear once in every posture
  ASSERT_EQ(t.joints.size(), 5u);
  const std::pair<int, int> order[] = {{0, 11}, {0, 13}, {1, 11}, {1, 13}, {2, 13}};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(t.joints[i].posture, order[i].first) << i;
    EXPECT_EQ(t.joints[i].id, order[i].second) << i;
  }
  EXPECT_EQ(t.joints[1].count, 2600.0);

  // without delta columns: one posture, no delta
  const auto plain = parse_joint_target("id,count\n13,2600\n", "c.csv");
  ASSERT_EQ(plain.postures.size(), 1u);
  EXPECT_EQ(plain.postures[0].delta, offset_values{});
}

TEST(calibration_joint_target, bad_posture_columns_name_file_and_line) {
  EXPECT_EQ(joint_error("id,count,delta_z\n13,2600,0\n"),
            "t.csv:1: unknown column 'delta_z' (known: delta_x_offset, delta_y_offset, "
            "delta_z_offset, delta_roll_offset, delta_pitch_offset, delta_yaw_offset, "
            "delta_hip_pitch_offset)");
  EXPECT_EQ(joint_error("id,count,delta_z_offset,DELTA_Z_OFFSET\n"),
            "t.csv:1: the header has column 'delta_z_offset' twice");
  EXPECT_EQ(joint_error("id,count,delta_z_offset\n13,2600,0\n13,2601,5\n13,2602,0\n"),
            "t.csv:4: duplicate servo ID 13 in one posture (same deltas) (first on line 2)");
  EXPECT_EQ(joint_error("id,count,delta_z_offset\n13,2600,deep\n"),
            "t.csv:2: delta_z_offset 'deep' is not a finite number");
  EXPECT_EQ(joint_error("id,count,delta_z_offset\n13,2600,inf\n"),
            "t.csv:2: delta_z_offset 'inf' is not a finite number");
}

TEST(calibration_plant_target, reads_targets_scales_and_settle_settings) {
  const auto t = parse_plant_target(
      "; comment\n[Plant Target]\npitch_deg = 1.5 ; lean\nroll_deg=0\nheight_m = 0.3\n"
      "com_over_support = yes\nheight_sigma_m = 0.001\n[settle]\ntime_s = 2\naverage_s = 0.5\n"
      "max_iterations = 7\n",
      "t.ini");
  EXPECT_EQ(t.pitch_deg, 1.5);
  EXPECT_EQ(t.roll_deg, 0.0);
  EXPECT_EQ(t.height_m, 0.3);
  EXPECT_TRUE(t.com_over_support);
  EXPECT_EQ(t.height_sigma_m, 0.001);
  EXPECT_EQ(t.pitch_sigma_deg, 0.2);
  EXPECT_EQ(t.settle_s, 2.0);
  EXPECT_EQ(t.average_s, 0.5);
  EXPECT_EQ(t.max_iterations, 7);
  EXPECT_EQ(t.residual_count(), 5);

  const auto p = read_plant_target(k_data / "pitch_zero.ini");
  EXPECT_EQ(p.pitch_deg, 0.0);
  EXPECT_FALSE(p.height_m);
  EXPECT_EQ(p.residual_count(), 1);
}

TEST(calibration_plant_target, bad_files_name_file_and_line) {
  EXPECT_THAT(error_of([] { read_plant_target(k_data / "bad_plant.ini"); }),
              StartsWith((k_data / "bad_plant.ini").string() +
                         ":3: unknown key 'hieght_m' in [Plant Target]"));
  EXPECT_EQ(plant_error("pitch_deg = 0\n"),
            "t.ini:1: 'pitch_deg' is outside a section ([Plant Target] or [Settle])");
  EXPECT_EQ(plant_error("[Plant Target]\npitch_deg = flat\n"),
            "t.ini:2: 'pitch_deg' = 'flat' is not a number");
  EXPECT_EQ(plant_error("[Plant Target]\npitch_deg = 0\npitch_deg = 1\n"),
            "t.ini:3: 'pitch_deg' is given twice (first on line 2)");
  EXPECT_EQ(plant_error("[Plant Target]\nheight_m = 3\n"),
            "t.ini:2: 'height_m' = 3 is outside 0.01..1 m");
  EXPECT_EQ(plant_error("[Plant Target]\ncom_over_support = maybe\n"),
            "t.ini:2: 'com_over_support' = 'maybe' is not true or false");
  EXPECT_EQ(plant_error("[Plant Target]\npitch_sigma_deg = 0\npitch_deg = 1\n"),
            "t.ini:2: 'pitch_sigma_deg' = 0 must be positive");
  EXPECT_EQ(plant_error("[Targets]\npitch_deg = 1\n"),
            "t.ini:1: unknown section [Targets] (known: [Plant Target], [Settle])");
  EXPECT_EQ(plant_error("[Plant Target]\npitch_deg 1\n"),
            "t.ini:2: expected 'key = value' or '[section]', got 'pitch_deg 1'");
  EXPECT_EQ(plant_error("id,count\n7,2048\n"),
            "t.ini:1: expected 'key = value' or '[section]', got 'id,count' (a joint posture? "
            "use --mode joints)");
  EXPECT_EQ(plant_error("[Plant Target]\npitch_deg = 1\n[Settle]\ntime_s = 0.5\naverage_s = 1\n"),
            "t.ini:5: average_s is longer than the settle time time_s");
  EXPECT_EQ(plant_error("[Plant Target]\ncom_over_support = false\n[Settle]\ntime_s = 1\n"),
            "t.ini: empty target: set at least one of pitch_deg, roll_deg, height_m or "
            "com_over_support = true in [Plant Target]");
}

TEST(calibration_offsets, selection_and_bounds_are_checked) {
  EXPECT_EQ(parse_offset_selection("z_offset, X_OFFSET"), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(parse_offset_selection("all").size(), offset_count);
  EXPECT_THROW(parse_offset_selection("x_offset,foo"), std::invalid_argument);
  EXPECT_THROW(parse_offset_selection("x_offset,x_offset"), std::invalid_argument);
  EXPECT_THROW(parse_offset_selection(" , "), std::invalid_argument);

  offset_bounds b = offset_bounds::defaults();
  apply_bound(b, "hip_pitch_offset=0:20");
  EXPECT_EQ(b.lower[6], 0.0);
  EXPECT_EQ(b.upper[6], 20.0);
  apply_bound(b, "x_offset=:5");
  EXPECT_EQ(b.lower[0], -50.0);
  EXPECT_EQ(b.upper[0], 5.0);
  EXPECT_THROW(apply_bound(b, "x_offset=5:1"), std::invalid_argument);
  EXPECT_THROW(apply_bound(b, "x_offset"), std::invalid_argument);
  EXPECT_THROW(apply_bound(b, "foo=1:2"), std::invalid_argument);
  EXPECT_THROW(apply_bound(b, "x_offset=a:2"), std::invalid_argument);
}

}  // namespace
}  // namespace stride::calibration
