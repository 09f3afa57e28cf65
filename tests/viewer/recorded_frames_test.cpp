// Reading the frames a page replays (viewer/src/recorded_frames.cpp) from a hand-written CSV
// (data/frames.csv: rows every 0.04 s, a fall at 0.12 s, episodes 1 and 2): which rows are kept
// for a frame rate and a window, the fall row always, spans of the episode column, thinning.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "recorded_frames.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"

namespace stride::viewer {
namespace {

const std::filesystem::path k_csv = std::filesystem::path(STRIDE_TEST_DATA_DIR) / "frames.csv";
using cosim::temp_dir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(recorded_frames, every_row_with_joint_angles_by_servo_id) {
  frame_selection all;
  all.fps = 0;
  const recorded_frames f = read_frames(k_csv, "r", {1, 3}, {}, all);
  EXPECT_THAT(f.t, ElementsAre(0, 0.04, 0.08, 0.12, 0.16, 0.2, 0.24));
  EXPECT_THAT(f.x, ElementsAre(0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06));
  ASSERT_EQ(f.q.size(), 3u);  // by servo ID − 1; ID 2 is no joint here
  EXPECT_TRUE(f.q[1].empty());
  EXPECT_THAT(f.q[2], ElementsAre(0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9));
  EXPECT_THAT(f.fallen, ElementsAre(0, 0, 0, 1, 1, 0, 0));
  EXPECT_THAT(f.falls, ElementsAre(0.12));
}

TEST(recorded_frames, a_frame_rate_keeps_the_first_row_of_each_bin_and_the_fall) {
  frame_selection s;
  s.fps = 10;  // bins of 0.1 s: [0, 0.1) holds 0, 0.04, 0.08; [0.1, 0.2) holds 0.12, 0.16; ...
  const recorded_frames f = read_frames(k_csv, "r", {1}, {}, s);
  // 0 and 0.12 open their bins, 0.2 opens the third; the fall row 0.12 is one of them anyway
  EXPECT_THAT(f.t, ElementsAre(0, 0.12, 0.2));
  s.fps = 5;  // bins of 0.2 s: 0 and 0.2 open them; 0.12 is kept because the robot falls there
  EXPECT_THAT(read_frames(k_csv, "r", {1}, {}, s).t, ElementsAre(0, 0.12, 0.2));
  s.fps = 2;  // one bin: 0, and the fall
  EXPECT_THAT(read_frames(k_csv, "r", {1}, {}, s).t, ElementsAre(0, 0.12));
}

// a time far beyond any integer (a file is input: any finite number may be in it) still falls
// into a bin of its own, each row after the first opening a new one
TEST(recorded_frames, times_beyond_an_integers_range_are_binned_too) {
  temp_dir dir("stride-frames-");
  const auto csv = dir.path() / "far.csv";
  std::ofstream(csv) << "time,r.base_x,r.base_y,r.base_z,r.roll,r.pitch,r.yaw,r.joint_angle[1]\n"
                        "1e300,0,0,0.3,0,0,0,0.1\n"
                        "2e300,0,0,0.3,0,0,0,0.2\n"
                        "2e300,0,0,0.3,0,0,0,0.3\n";
  frame_selection s;
  s.fps = 25;
  EXPECT_THAT(read_frames(csv, "r", {1}, {}, s).t, ElementsAre(1e300, 2e300));
}

TEST(recorded_frames, a_window_and_the_spans_of_an_episode_column) {
  frame_selection s;
  s.fps = 0;
  s.from = 0.08;
  s.to = 0.2;
  s.span_column = "l.episode";
  const recorded_frames f = read_frames(k_csv, "r", {1}, {"l.episode"}, s);
  EXPECT_THAT(f.t, ElementsAre(0.08, 0.12, 0.16, 0.2));
  ASSERT_EQ(f.spans.size(), 2u);
  EXPECT_EQ(f.spans[0].value, 1);
  EXPECT_EQ(f.spans[0].from, 0.08);
  EXPECT_EQ(f.spans[0].to, 0.12);
  EXPECT_EQ(f.spans[1].from, 0.16);
  EXPECT_EQ(f.spans[1].to, 0.2);
  ASSERT_EQ(f.state.size(), 1u);
  EXPECT_THAT(f.state[0].second, ElementsAre(1, 1, 2, 2));
  const value_span second = find_span(k_csv, "l.episode", 2);
  EXPECT_EQ(second.from, 0.16);
  EXPECT_EQ(second.to, 0.24);
}

TEST(recorded_frames, thinning_keeps_every_kth_frame_and_the_fall) {
  frame_selection s;
  s.fps = 0;
  recorded_frames f = read_frames(k_csv, "r", {1}, {}, s);
  thin_frames(f, 3);  // 7 frames → every 3rd: 0, 0.12, 0.24 (0.12 also the fall)
  EXPECT_THAT(f.t, ElementsAre(0, 0.12, 0.24));
  EXPECT_THAT(f.q[0], ElementsAre(0.1, 0.4, 0.7));
  EXPECT_THAT(f.fallen, ElementsAre(0, 1, 0));
}

TEST(recorded_frames, missing_columns_are_named) {
  try {
    read_frames(k_csv, "r", {1, 2, 3}, {}, {});
    FAIL() << "no error";
  } catch (const cosim::validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("has no column r.joint_angle[2]"));
  }
  EXPECT_THAT(full_pose_prefixes(csv_header(k_csv)), ElementsAre("r"));
}

}  // namespace
}  // namespace stride::viewer
