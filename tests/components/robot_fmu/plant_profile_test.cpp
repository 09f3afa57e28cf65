// Reading plant profile files: what each element sets, and an error naming file and line for
// anything malformed or unknown.
#include "stride/robot/plant_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stride::robot {
namespace {

std::string error_of(const std::string& xml) {
  try {
    parse_plant_profile(xml, "p.xml");
  } catch (const model_error& e) {
    return e.what();
  }
  return "(no error)";
}

std::size_t setting_index(std::string_view profile_name) {
  const auto all = plant_settings();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].profile_name == profile_name) return i;
  }
  ADD_FAILURE() << "no setting " << profile_name;
  return 0;
}

TEST(plant_profile, reads_settings_servo_rules_and_outputs) {
  const plant_profile p = parse_plant_profile(R"(<plant_profile name="arm" version="1">
  <physics step="0.004" cfm="2e-5"/>
  <fall tilt="0.5"/>
  <joints order="urdf" passive="wheel_* caster"/>
  <servo joints="*" p_gain="12" clamp_to_limits="false"/>
  <servo joints="elbow wrist_?" torque_limit="1.5"/>
  <pose joints="elbow" value="0.25"/>
  <weld joints="wrist_*" parameter="weld_wrist" description="rigid wrist"/>
  <imu link="imu"/>
  <contact_force name="foot_force" link="foot"/>
  <board name="gyro_counts" signal="gyro_y" gain="-2" offset="512" round="nearest"/>
  <presets parameter="mode" default="soft">
    <preset name="soft"><servo joints="*" p_gain="4"/></preset>
    <preset name="hard"><physics step="0.002"/></preset>
  </presets>
</plant_profile>)",
                                              "p.xml");
  EXPECT_EQ(p.name, "arm");
  EXPECT_EQ(p.base.settings[setting_index("physics.step")], 0.004);
  EXPECT_EQ(p.base.settings[setting_index("physics.cfm")], 2e-5);
  EXPECT_EQ(p.base.settings[setting_index("fall.tilt")], 0.5);
  EXPECT_TRUE(std::isnan(p.base.settings[setting_index("fall.height")]));
  EXPECT_EQ(p.passive, (std::vector<std::string>{"wheel_*", "caster"}));
  ASSERT_EQ(p.base.servos.size(), 2u);
  EXPECT_EQ(p.base.servos[0].values.p_gain, 12.0);
  EXPECT_TRUE(p.base.servos[0].clamp_set);
  EXPECT_FALSE(p.base.servos[0].values.clamp_to_limits);
  EXPECT_TRUE(std::isnan(p.base.servos[0].values.torque_limit));
  EXPECT_EQ(p.base.servos[1].patterns, (std::vector<std::string>{"elbow", "wrist_?"}));
  EXPECT_EQ(p.base.servos[1].values.torque_limit, 1.5);
  EXPECT_EQ(p.base.servos[1].line, 6);
  ASSERT_EQ(p.pose.size(), 1u);
  EXPECT_EQ(p.pose[0], (std::pair<std::string, double>{"elbow", 0.25}));
  ASSERT_EQ(p.welds.size(), 1u);
  EXPECT_EQ(p.welds[0].parameter, "weld_wrist");
  EXPECT_EQ(p.imu_link, "imu");
  ASSERT_EQ(p.contact_forces.size(), 1u);
  EXPECT_EQ(p.contact_forces[0].link, "foot");
  ASSERT_EQ(p.board.size(), 1u);
  EXPECT_EQ(p.board[0].from, board_channel::source::gyro_y);
  EXPECT_EQ(p.board[0].gain, -2.0);
  EXPECT_EQ(p.board[0].offset, 512.0);
  EXPECT_EQ(p.board[0].round, board_channel::rounding::nearest);
  EXPECT_EQ(p.preset_parameter, "mode");
  EXPECT_EQ(p.default_preset, "soft");
  ASSERT_EQ(p.presets.size(), 2u);
  EXPECT_EQ(p.presets[0].layer.servos.at(0).values.p_gain, 4.0);
  EXPECT_EQ(p.presets[1].layer.settings[setting_index("physics.step")], 0.002);
}

TEST(plant_profile, an_empty_profile_sets_nothing) {
  const plant_profile p = parse_plant_profile("<plant_profile/>", "p.xml");
  for (double v : p.base.settings) EXPECT_TRUE(std::isnan(v));
  EXPECT_TRUE(p.base.servos.empty());
  EXPECT_TRUE(p.presets.empty());
  EXPECT_EQ(p.joint_order, "urdf");
}

TEST(plant_profile, errors_name_the_file_line_and_element) {
  const std::pair<const char*, const char*> cases[] = {
      {"<plant_profile>\n<physiks step=\"1\"/></plant_profile>",
       "p.xml:2: unknown element <physiks>"},
      {"<plant_profile>\n<physics stepp=\"1\"/></plant_profile>",
       "p.xml:2: <physics>: unknown attribute 'stepp'"},
      {"<plant_profile>\n<physics step=\"fast\"/></plant_profile>",
       "p.xml:2: <physics step=\"fast\">: not a finite number"},
      {"<plant_profile>\n<physics step=\"nan\"/></plant_profile>", "not a finite number"},
      {"<plant_profile>\n<physics step=\"1\"/></plant_profile>", "physics.step = 1 is outside"},
      {"<plant_profile>\n<servo p_gain=\"1\"/></plant_profile>",
       "p.xml:2: <servo>: missing attribute 'joints'"},
      {"<plant_profile>\n<servo joints=\"*\" p_gain=\"-1\"/></plant_profile>",
       "<servo p_gain>: must not be negative"},
      {"<plant_profile>\n<servo joints=\"*\" gain=\"1\"/></plant_profile>",
       "<servo>: unknown attribute 'gain'"},
      {"<plant_profile>\n<joints order=\"alphabetic\"/></plant_profile>", "not urdf or servo_id"},
      {"<plant_profile>\n<board name=\"b\" signal=\"gyro_w\"/></plant_profile>",
       "<board signal=\"gyro_w\">"},
      {"<plant_profile>\n<board name=\"b\" signal=\"acc_x\" round=\"up\"/></plant_profile>",
       "not none, floor or nearest"},
      {"<plant_profile><contact_force name=\"f\" link=\"a\"/>\n<contact_force name=\"f\" "
       "link=\"b\"/></plant_profile>",
       "p.xml:2: name 'f' is used twice"},
      {"<plant_profile><presets default=\"x\"><preset name=\"y\"/></presets></plant_profile>",
       "no such preset"},
      {"<plant_profile><presets default=\"y\"><preset name=\"y\"><imu "
       "link=\"a\"/></preset></presets></plant_profile>",
       "<preset> may hold"},
      {"<plant_profile version=\"2\"/>", "reads version 1"},
      {"<robot/>", "the root element must be <plant_profile>"},
      {"<plant_profile>\n<physics", "p.xml:2: not well-formed XML"},
  };
  for (const auto& [xml, expected] : cases) {
    EXPECT_NE(error_of(xml).find(expected), std::string::npos)
        << "profile: " << xml << "\nerror: " << error_of(xml);
  }
}

TEST(plant_profile, a_missing_file_is_named) {
  try {
    load_plant_profile("no/such/profile.xml");
    FAIL();
  } catch (const model_error& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/profile.xml: cannot read"), std::string::npos);
  }
}

}  // namespace
}  // namespace stride::robot
