// config.ini reading/writing (docs/walking-generator.md §2.1) and the parameter table.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "gait_test_util.hpp"
#include "stride/gait/config_ini.hpp"
#include "stride/gait/walking_params.hpp"

namespace {

using namespace stride::gait;
namespace fs = std::filesystem;

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// A scratch directory per test.
class gait_config : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("stride_gait_config_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

  /// Reads `text` as a config file and returns the config_error message ("" if none thrown).
  std::string error_of(const std::string& text) {
    const fs::path file = write("bad.ini", text);
    try {
      read_walking_config(file, walking_params{}, nullptr);
    } catch (const config_error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

// ---------------------------------------------------------------------------------------------

TEST_F(gait_config, webots_style_trailing_semicolons_and_other_sections) {
  std::vector<std::string> warnings;
  const walking_params p =
      read_walking_config(gait_test::data_path("webots_style.ini"), walking_params{}, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.x_offset, -10.0);
  EXPECT_EQ(p.period_time, 600.0);
  EXPECT_EQ(p.dsp_ratio, 0.1);
  EXPECT_EQ(p.balance_hip_roll_gain, 0.0);  // "0.0; comment" style
  EXPECT_EQ(p.balance_ankle_roll_gain, 0.0);
  EXPECT_EQ(p.balance_knee_gain, 0.3);
  EXPECT_EQ(p.p_gain, 32);  // absent -> base
}

TEST_F(gait_config, case_insensitive_keys_separators_comments_sentinel) {
  std::vector<std::string> warnings;
  walking_params base;
  base.foot_height = 33;
  const walking_params p = read_walking_config(gait_test::data_path("tuned.ini"), base, &warnings);
  EXPECT_EQ(p.x_offset, -7.5);
  EXPECT_EQ(p.y_offset, 8.0);  // ':' separator
  EXPECT_EQ(p.period_time, 550.0);
  EXPECT_EQ(p.dsp_ratio, 0.16);
  EXPECT_EQ(p.foot_height, 33.0) << "-1024 means absent";
  EXPECT_EQ(p.hip_pitch_offset, 11.25);
  EXPECT_EQ(p.p_gain, 28);
  EXPECT_EQ(p.z_offset, 20.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("tuned.ini:12:"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("my_robot_note"), std::string::npos) << warnings[0];
}

TEST_F(gait_config, legacy_keys_are_ignored_with_a_warning_naming_file_and_line) {
  std::vector<std::string> warnings;
  const walking_params p =
      read_walking_config(gait_test::data_path("legacy_r1.ini"), walking_params{}, &warnings);
  EXPECT_EQ(p.x_offset, 0.0);
  EXPECT_EQ(p.foot_height, 40.0);       // z_move_amplitude ignored
  EXPECT_EQ(p.swing_right_left, 20.0);  // y_swap_amplitude ignored
  EXPECT_EQ(p.swing_top_down, 5.0);     // z_swap_amplitude ignored
  ASSERT_EQ(warnings.size(), 6u);
  const char* keys[] = {"a_offset",         "p_offset",         "r_offset",
                        "z_move_amplitude", "y_swap_amplitude", "z_swap_amplitude"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_NE(warnings[i].find("legacy_r1.ini:" + std::to_string(4 + i) + ":"), std::string::npos)
        << warnings[i];
    EXPECT_NE(warnings[i].find(keys[i]), std::string::npos) << warnings[i];
    EXPECT_NE(warnings[i].find("legacy"), std::string::npos) << warnings[i];
  }
  EXPECT_NO_THROW(read_walking_config(gait_test::data_path("legacy_r1.ini"), {}, nullptr));
}

// a device would be read until memory runs out, a huge file nearly so
TEST_F(gait_config, devices_and_huge_files_are_refused_with_the_file_named) {
  try {
    ini_document::load("/dev/zero");
    ADD_FAILURE() << "/dev/zero was read";
  } catch (const config_error& e) {
    EXPECT_STREQ(e.what(), "/dev/zero: not a regular file");
  }
  const fs::path big = write("big.ini", std::string(5 * 1024 * 1024, ';'));
  try {
    ini_document::load(big);
    ADD_FAILURE() << "a 5 MB file was read";
  } catch (const config_error& e) {
    EXPECT_EQ(std::string(e.what()),
              big.string() + ": larger than 4194304 bytes: not a config.ini");
  }
}

TEST_F(gait_config, round_trip_keeps_unknown_keys_comments_and_order) {
  const std::string original = slurp(gait_test::data_path("tuned.ini"));
  const fs::path file = write("tuned.ini", original);
  // unchanged document: byte-identical
  ini_document doc = ini_document::load(file);
  EXPECT_EQ(doc.str(), original);

  // write back changed parameters: in place, comments and unknown keys kept
  walking_params p = read_walking_config(doc, walking_params{}, nullptr);
  p.x_offset = -5;
  p.swing_top_down = 6.5;
  write_walking_config(file, p);
  const std::string written = slurp(file);
  EXPECT_NE(written.find("X_OFFSET = -5.000000        ; feet a bit further forward"),
            std::string::npos)
      << written;
  EXPECT_NE(written.find("Period_Time = 550      # slower cycle"), std::string::npos)
      << "unchanged values keep their text";
  EXPECT_NE(written.find("my_robot_note = knee pads fitted"), std::string::npos);
  EXPECT_NE(written.find("brightness = 128   ; not ours"), std::string::npos);
  EXPECT_NE(written.find("[Find Color]\nhue = 356\n"), std::string::npos);
  EXPECT_EQ(written.rfind("; A hand-tuned file", 0), 0u);
  // new keys go after the section's last entry, before the next section
  const auto added = written.find("swing_top_down=6.500000");
  ASSERT_NE(added, std::string::npos);
  EXPECT_LT(added, written.find("[Find Color]"));
  EXPECT_GT(added, written.find("p_gain = 28"));
  // and it reads back to the same parameters
  std::vector<std::string> warnings;
  const walking_params back = read_walking_config(file, walking_params{}, &warnings);
  for (const param_info& info : walking_param_table())
    EXPECT_EQ(get_param(back, info), get_param(p, info)) << info.key;
  EXPECT_EQ(warnings.size(), 1u);  // still just the unknown key
  // writing the same parameters again changes nothing
  write_walking_config(file, back);
  EXPECT_EQ(slurp(file), written);
}

TEST_F(gait_config, crlf_and_missing_final_newline_survive) {
  const std::string text = "[Walking Config]\r\nx_offset = 1 ; a\r\nz_offset = 2";
  ini_document doc = ini_document::parse(text, "mem.ini");
  EXPECT_EQ(doc.str(), text);
  doc.set("WALKING CONFIG", "z_offset", "3");
  doc.set("Walking Config", "y_offset", "4");
  doc.set("Other", "k", "v;w");
  EXPECT_EQ(doc.str(),
            "[Walking Config]\r\nx_offset = 1 ; a\r\nz_offset = 3\r\ny_offset=4\r\n\r\n[Other]\r\n"
            "k=\"v;w\"\r\n");
  EXPECT_EQ(doc.get("other", "K"), "v;w");
  EXPECT_EQ(doc.get("Walking Config", "x_offset"), "1");
  EXPECT_FALSE(doc.get("Walking Config", "nope").has_value());
  EXPECT_THROW(doc.set("Walking Config", "x", "a\nb"), std::invalid_argument);
}

TEST_F(gait_config, new_file_and_resources_config_are_the_writer_output) {
  const fs::path file = dir_ / "new.ini";
  walking_params p;
  p.dsp_ratio = 0.1 + 0.2;  // not exact in six decimals: written in shortest exact form
  p.arm_swing_gain = 1.0 / 3.0;
  p.d_gain = 3;
  write_walking_config(file, p);
  const walking_params back = read_walking_config(file, walking_params{}, nullptr);
  for (const param_info& info : walking_param_table())
    EXPECT_EQ(get_param(back, info), get_param(p, info)) << info.key;
  EXPECT_NE(slurp(file).find("x_offset=-10.000000\n"), std::string::npos);
  EXPECT_NE(slurp(file).find("p_gain=32\n"), std::string::npos);

  const fs::path resources =
      fs::path(STRIDE_SOURCE_DIR) / "components" / "gait_fmu" / "resources" / "config.ini";
  EXPECT_EQ(slurp(resources), make_walking_config_text(walking_params{}));
  std::vector<std::string> warnings;
  const walking_params defaults = read_walking_config(resources, walking_params{}, &warnings);
  EXPECT_TRUE(warnings.empty());
  for (const param_info& info : walking_param_table())
    EXPECT_EQ(get_param(defaults, info), get_param(walking_params{}, info)) << info.key;
}

// ---------------------------------------------------------------------------------------------

TEST_F(gait_config, errors_name_file_line_and_key) {
  std::string e = error_of("[Walking Config]\nx_offset = -10\nperiod_time = abc\n");
  EXPECT_NE(e.find("bad.ini:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("period_time"), std::string::npos) << e;
  EXPECT_NE(e.find("not a number"), std::string::npos) << e;

  e = error_of("[Walking Config]\nfoot_height = 40mm\n");
  EXPECT_NE(e.find("bad.ini:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("foot_height"), std::string::npos) << e;

  e = error_of("[Walking Config]\nz_offset =\n");
  EXPECT_NE(e.find("bad.ini:2:"), std::string::npos) << e;

  e = error_of("[Camera]\nx_offset = 1\n");
  EXPECT_NE(e.find("bad.ini"), std::string::npos) << e;
  EXPECT_NE(e.find("[Walking Config]"), std::string::npos) << e;

  for (const char* bad : {"0", "-600", "0.0;"}) {
    e = error_of(std::string("; header\n[Walking Config]\nperiod_time = ") + bad + "\n");
    EXPECT_NE(e.find("bad.ini:3:"), std::string::npos) << bad << ": " << e;
    EXPECT_NE(e.find("period_time"), std::string::npos) << e;
    EXPECT_NE(e.find("> 0"), std::string::npos) << e;
  }
  for (const char* bad : {"1", "1.5", "-0.01"}) {
    e = error_of(std::string("[Walking Config]\ndsp_ratio = ") + bad + "\n");
    EXPECT_NE(e.find("bad.ini:2:"), std::string::npos) << bad << ": " << e;
    EXPECT_NE(e.find("dsp_ratio"), std::string::npos) << e;
  }
  EXPECT_EQ(error_of("[Walking Config]\ndsp_ratio = 0\n"), "") << "dsp_ratio 0 is valid";
  EXPECT_EQ(error_of("[Walking Config]\ndsp_ratio = 0.99\n"), "");

  e = error_of("[Walking Config]\np_gain = 32.5\n");
  EXPECT_NE(e.find("bad.ini:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("p_gain"), std::string::npos) << e;
  EXPECT_NE(e.find("integer"), std::string::npos) << e;
  EXPECT_EQ(error_of("[Walking Config]\np_gain = 16.0\n"), "");

  e = error_of("[Walking Config]\nx_offset = nan\n");
  EXPECT_NE(e.find("x_offset"), std::string::npos) << e;
  e = error_of("[Walking Config]\nthis line has no separator\n");
  EXPECT_NE(e.find("bad.ini:2:"), std::string::npos) << e;

  try {
    read_walking_config(dir_ / "missing.ini", walking_params{}, nullptr);
    ADD_FAILURE() << "missing file accepted";
  } catch (const config_error& err) {
    EXPECT_NE(std::string(err.what()).find("missing.ini"), std::string::npos);
  }
}

TEST_F(gait_config, repeated_keys_and_sections_first_wins_with_warning) {
  const fs::path file = write("dup.ini",
                              "[Walking Config]\nx_offset = 1\nx_offset = 2\n[Walking Config]\n"
                              "x_offset = 3\n");
  std::vector<std::string> warnings;
  const walking_params p = read_walking_config(file, walking_params{}, &warnings);
  EXPECT_EQ(p.x_offset, 1.0);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("dup.ini:3:"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("dup.ini:4:"), std::string::npos) << warnings[1];
}

// ---------------------------------------------------------------------------------------------

TEST(gait_param_table, covers_every_member_once) {
  const auto table = walking_param_table();
  ASSERT_EQ(table.size(), 22u);
  std::set<std::string> keys;
  walking_params p;
  int index = 0;
  for (const param_info& info : table) {
    EXPECT_TRUE((info.real_member == nullptr) != (info.int_member == nullptr)) << info.key;
    EXPECT_TRUE(keys.insert(info.key).second) << info.key;
    const std::string latch = info.latch;
    EXPECT_TRUE(latch == "live" || latch == "half" || latch == "quarter") << info.key;
    EXPECT_NO_THROW(check_param_value(info, get_param(p, info))) << "default of " << info.key;
    set_param(p, info, get_param(p, info) + (info.int_member ? 1 : 0.001) * (index + 1));
    ++index;
  }
  // every member was reached exactly once: all values moved by their own amount
  const walking_params d;
  EXPECT_DOUBLE_EQ(p.x_offset, d.x_offset + 0.001);
  EXPECT_DOUBLE_EQ(p.dsp_ratio, d.dsp_ratio + 0.009);
  EXPECT_EQ(p.p_gain, d.p_gain + 20);
  EXPECT_EQ(p.d_gain, d.d_gain + 22);
  EXPECT_DOUBLE_EQ(p.balance_ankle_roll_gain, d.balance_ankle_roll_gain + 0.001 * 19);
  EXPECT_EQ(find_param("PERIOD_TIME"), find_param("period_time"));
  EXPECT_EQ(find_param("a_offset"), nullptr);
  EXPECT_STREQ(find_param("Dsp_Ratio")->latch, "half");
  EXPECT_STREQ(find_param("foot_height")->latch, "quarter");
  EXPECT_STREQ(find_param("x_offset")->latch, "live");
}

TEST(gait_param_table, check_param_value_names_the_key) {
  const param_info& period = *find_param("period_time");
  EXPECT_THROW(check_param_value(period, 0), std::invalid_argument);
  EXPECT_NO_THROW(check_param_value(period, 1e-3));
  try {
    check_param_value(*find_param("dsp_ratio"), 1.0);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("dsp_ratio"), std::string::npos);
  }
  EXPECT_THROW(check_param_value(*find_param("x_offset"), INFINITY), std::invalid_argument);
  EXPECT_THROW(check_param_value(*find_param("x_offset"), NAN), std::invalid_argument);
  EXPECT_THROW(check_param_value(*find_param("p_gain"), 255), std::invalid_argument);
  EXPECT_THROW(check_param_value(*find_param("i_gain"), -1), std::invalid_argument);
  walking_params p;
  EXPECT_THROW(set_param(p, *find_param("dsp_ratio"), -0.1), std::invalid_argument);
  EXPECT_EQ(p.dsp_ratio, 0.1) << "rejected value not stored";
}

}  // namespace
