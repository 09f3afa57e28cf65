// A plant profile applied to a model: the DARwIn-OP's profile gives exactly the configuration the
// plant had before profiles existed (darwin::default_config), and a profile that does not fit
// its model is refused naming what does not fit.
#include <gtest/gtest.h>

#include <cmath>

#include "stride/robot/darwin.hpp"
#include "stride/robot/plant_profile.hpp"

namespace stride::robot {
namespace {

const std::string k_darwin_dir = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/";
const std::string k_data = std::string(STRIDE_SOURCE_DIR) + "/tests/components/robot_fmu/data/";

void expect_same_servo(const servo_config& a, const servo_config& b) {
  EXPECT_EQ(a.p_gain, b.p_gain);
  EXPECT_EQ(a.max_velocity, b.max_velocity);
  EXPECT_EQ(a.max_acceleration, b.max_acceleration);
  EXPECT_EQ(a.torque_limit, b.torque_limit);
  EXPECT_EQ(a.compliance, b.compliance);
  EXPECT_EQ(a.damping, b.damping);
  EXPECT_EQ(a.static_friction, b.static_friction);
  EXPECT_EQ(a.clamp_to_limits, b.clamp_to_limits);
}

class darwin_profile : public ::testing::TestWithParam<darwin::plant_profile> {};

TEST_P(darwin_profile, gives_the_configuration_of_darwin_default_config) {
  const robot_model model = load_robot_model(k_darwin_dir + "darwin-op.urdf");
  const plant_profile profile = load_plant_profile(k_darwin_dir + "darwin-op.profile.xml");
  const resolved_plant r = resolve_plant(profile, model, darwin::to_string(GetParam()));
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  const robot_config expected = darwin::default_config("", GetParam());
  const robot_config& c = r.config;
  expect_same_servo(c.servo, expected.servo);
  EXPECT_TRUE(c.joint_servos.empty()) << "one servo model for all";
  EXPECT_EQ(c.initial_pose, expected.initial_pose);  // bit for bit
  EXPECT_EQ(c.rigid_servos, expected.rigid_servos);
  EXPECT_EQ(c.physics_step, expected.physics_step);
  EXPECT_EQ(c.erp, expected.erp);
  EXPECT_EQ(c.cfm, expected.cfm);
  EXPECT_EQ(c.gravity, expected.gravity);
  EXPECT_EQ(c.contact.mu, expected.contact.mu);
  EXPECT_EQ(c.contact.bounce, expected.contact.bounce);
  EXPECT_EQ(c.contact.bounce_velocity, expected.contact.bounce_velocity);
  EXPECT_EQ(c.contact.soft_erp, expected.contact.soft_erp);
  EXPECT_EQ(c.contact.soft_cfm, expected.contact.soft_cfm);
  EXPECT_EQ(c.fall_tilt, expected.fall_tilt);
  EXPECT_EQ(c.fall_height, expected.fall_height);
  EXPECT_EQ(c.reset_clearance, expected.reset_clearance);
  EXPECT_EQ(c.imu_link, expected.imu_link);
  EXPECT_EQ(c.left_foot_link, expected.left_foot_link);
  EXPECT_EQ(c.right_foot_link, expected.right_foot_link);
  // servo i + 1 is the joint with <servo id="i + 1">
  ASSERT_EQ(c.servo_joints.size(), 20u);
  for (std::size_t i = 0; i < 20; ++i) {
    const int j = model.joint_of_servo(static_cast<int>(i) + 1);
    ASSERT_GE(j, 0);
    EXPECT_EQ(c.servo_joints[i], model.joints[static_cast<std::size_t>(j)].name);
  }
}

INSTANTIATE_TEST_SUITE_P(presets, darwin_profile,
                         ::testing::Values(darwin::plant_profile::stiff,
                                           darwin::plant_profile::webots));

TEST(resolve_plant, later_servo_rules_and_the_preset_win_per_attribute) {
  const robot_model model = load_robot_model(k_darwin_dir + "darwin-op.urdf");
  const plant_profile p = parse_plant_profile(R"(<plant_profile>
    <joints order="servo_id"/>
    <servo joints="*" p_gain="10" torque_limit="2"/>
    <servo joints="?_knee" torque_limit="4"/>
    <presets default="a"><preset name="a"><servo joints="r_*" p_gain="7"/></preset></presets>
  </plant_profile>)",
                                              "p.xml");
  const resolved_plant r = resolve_plant(p, model, "");
  ASSERT_EQ(r.config.joint_servos.size(), 20u);
  for (const auto& [joint, servo] : r.config.joint_servos) {
    EXPECT_EQ(servo.torque_limit, joint.ends_with("_knee") ? 4.0 : 2.0) << joint;
    EXPECT_EQ(servo.p_gain, joint.starts_with("r_") ? 7.0 : 10.0) << joint;
  }
  // an explicitly set servo setting applies to every servo
  std::vector<double> overrides(plant_settings().size(), std::nan(""));
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    if (std::string_view(plant_settings()[i].profile_name) == "servo.torque_limit")
      overrides[i] = 1;
  }
  const resolved_plant o = resolve_plant(p, model, "", overrides);
  for (const auto& [joint, servo] : o.config.joint_servos) EXPECT_EQ(servo.torque_limit, 1.0);
}

TEST(resolve_plant, passive_joints_are_left_out_of_the_urdf_order) {
  const robot_model model = load_robot_model(k_darwin_dir + "darwin-op.urdf");
  const plant_profile p = parse_plant_profile(
      R"(<plant_profile><joints passive="head_* *_el"/></plant_profile>)", "p.xml");
  const resolved_plant r = resolve_plant(p, model, "");
  ASSERT_EQ(r.config.servo_joints.size(), 16u);
  std::size_t k = 0;
  for (const model_joint& j : model.joints) {
    if (j.name.starts_with("head_") || j.name.ends_with("_el")) continue;
    EXPECT_EQ(r.config.servo_joints[k++], j.name);
  }
}

TEST(resolve_plant, a_profile_that_does_not_fit_the_model_is_refused) {
  const robot_model model = load_robot_model(k_darwin_dir + "darwin-op.urdf");
  const std::pair<const char*, const char*> cases[] = {
      {"<joints passive=\"wheel\"/>", "<joints passive>: 'wheel' matches no joint"},
      {"<servo joints=\"wheel_*\" p_gain=\"1\"/>",
       "<servo joints> 'wheel_*' matches no servo joint"},
      {"<pose joints=\"r_knee\" value=\"9\"/>",
       "initial pose of joint 'r_knee' (9.000000) is outside its URDF limits"},
      {"<weld joints=\"tail\"/>", "<weld joints> 'tail' matches no servo joint"},
      {"<imu link=\"nose\"/>", "<imu>: the model has no link 'nose'"},
      {"<feet left=\"l_ank_roll_link\" right=\"r_toe\"/>",
       "<feet right>: the model has no link 'r_toe'"},
      {"<contact_force name=\"f\" link=\"hand\"/>", "the model has no link 'hand'"},
  };
  for (const auto& [element, expected] : cases) {
    const plant_profile p =
        parse_plant_profile("<plant_profile>" + std::string(element) + "</plant_profile>", "p.xml");
    try {
      resolve_plant(p, model, "");
      ADD_FAILURE() << element << " was accepted";
    } catch (const model_error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("p.xml: ", 0), 0u) << e.what();
    }
  }
  const plant_profile presets = parse_plant_profile(
      "<plant_profile><presets default=\"a\"><preset name=\"a\"/><preset name=\"b\"/></presets>"
      "</plant_profile>",
      "p.xml");
  try {
    resolve_plant(presets, model, "c");
    ADD_FAILURE();
  } catch (const model_error& e) {
    EXPECT_NE(std::string(e.what()).find("no preset 'c' (presets: a, b)"), std::string::npos);
  }
}

TEST(resolve_plant, servo_id_order_needs_servo_tags) {
  const robot_model model = load_robot_model(k_data + "pendulum.urdf");
  const plant_profile p =
      parse_plant_profile("<plant_profile><joints order=\"servo_id\"/></plant_profile>", "p.xml");
  try {
    resolve_plant(p, model, "");
    FAIL();
  } catch (const model_error& e) {
    EXPECT_NE(std::string(e.what()).find("joint 'pivot' has no <servo id>"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace stride::robot
