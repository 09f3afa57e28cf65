// URDF loading: the DARwIn-OP model, small test models, malformed and unsupported files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "stride/robot/darwin.hpp"
#include "stride/robot/robot_model.hpp"

namespace {

using stride::robot::load_robot_model;
using stride::robot::model_error;
using stride::robot::parse_robot_model;
using stride::robot::robot_model;
using stride::robot::shape_type;
using stride::robot::weld_joint;
using testing::HasSubstr;

const std::string k_data = STRIDE_TEST_DATA_DIR;
const std::string k_darwin = std::string(STRIDE_SOURCE_DIR) + "/models/darwin-op/darwin-op.urdf";

// the message of the model_error thrown by `f`
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const model_error& e) {
    return e.what();
  }
  return "<no model_error>";
}

std::string robot(const std::string& body) {
  return "<?xml version=\"1.0\"?><robot name=\"t\">" + body + "</robot>";
}

const std::string k_inertial =
    "<inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" "
    "iyz=\"0\" izz=\"0.01\"/></inertial>";

TEST(robot_model, darwin_has_the_documented_structure) {
  const robot_model m = load_robot_model(k_darwin);
  EXPECT_EQ(m.name, "darwin-op");
  EXPECT_FALSE(m.fixed_base);
  ASSERT_EQ(m.bodies.size(), 21u);  // imu_link is merged into base_link
  ASSERT_EQ(m.joints.size(), 20u);
  EXPECT_EQ(m.servo_count(), 20);
  EXPECT_NEAR(m.total_mass(), 2.9253, 5e-4);  // docs/robot-model.md §1.5
  EXPECT_EQ(m.bodies[0].link, "base_link");
  // servo IDs from the <servo> extension, docs/robot-model.md §1.3
  const char* names[20] = {"r_sho_pitch", "l_sho_pitch", "r_sho_roll", "l_sho_roll", "r_el",
                           "l_el",        "r_hip_yaw",   "l_hip_yaw",  "r_hip_roll", "l_hip_roll",
                           "r_hip_pitch", "l_hip_pitch", "r_knee",     "l_knee",     "r_ank_pitch",
                           "l_ank_pitch", "r_ank_roll",  "l_ank_roll", "head_pan",   "head_tilt"};
  for (int id = 1; id <= 20; ++id) {
    const int j = m.joint_of_servo(id);
    ASSERT_GE(j, 0) << id;
    EXPECT_EQ(m.joints[static_cast<std::size_t>(j)].name, names[id - 1]);
    EXPECT_TRUE(m.joints[static_cast<std::size_t>(j)].limited);
  }
  // the IMU frame rides on the torso at the accelerometer position
  const int imu = m.find_link("imu_link");
  ASSERT_GE(imu, 0);
  EXPECT_EQ(m.links[static_cast<std::size_t>(imu)].body, 0);
  EXPECT_DOUBLE_EQ(m.links[static_cast<std::size_t>(imu)].in_body.position[2], -0.068);
  // the head is a capsule (extension), the soles are boxes
  const int head = m.find_link("head_tilt_link");
  ASSERT_GE(head, 0);
  const auto& head_body =
      m.bodies[static_cast<std::size_t>(m.links[static_cast<std::size_t>(head)].body)];
  ASSERT_EQ(head_body.shapes.size(), 1u);
  EXPECT_EQ(head_body.shapes[0].type, shape_type::capsule);
  EXPECT_DOUBLE_EQ(head_body.shapes[0].size[0], 0.042);
  const int sole = m.find_link("l_ank_roll_link");
  const auto& foot =
      m.bodies[static_cast<std::size_t>(m.links[static_cast<std::size_t>(sole)].body)];
  ASSERT_EQ(foot.shapes.size(), 1u);
  EXPECT_EQ(foot.shapes[0].type, shape_type::box);
  EXPECT_DOUBLE_EQ(foot.shapes[0].size[0], 0.105);
}

TEST(robot_model, fixed_joints_merge_mass_properties) {
  const robot_model m = load_robot_model(k_data + "/pendulum.urdf");
  EXPECT_TRUE(m.fixed_base);
  ASSERT_EQ(m.bodies.size(), 1u);  // rod + bob
  ASSERT_EQ(m.joints.size(), 1u);
  EXPECT_EQ(m.joints[0].parent_body, -1);
  EXPECT_EQ(m.joints[0].servo_id, 0);
  const auto& b = m.bodies[0];
  EXPECT_DOUBLE_EQ(b.mass, 1.0);
  // CoM: (0.4 * -0.2 + 0.6 * -0.4) / 1.0
  EXPECT_NEAR(b.com[2], -0.32, 1e-12);
  // parallel axis: rod 0.005347 + 0.4 * 0.12^2, bob 0.00024 + 0.6 * 0.08^2
  EXPECT_NEAR(b.inertia[1], 0.005347 + 0.4 * 0.0144 + 0.00024 + 0.6 * 0.0064, 1e-12);
  EXPECT_EQ(b.shapes.size(), 2u);
  // the bob's sphere moved into the rod's frame
  EXPECT_EQ(b.shapes[1].type, shape_type::sphere);
  EXPECT_DOUBLE_EQ(b.shapes[1].origin.position[2], -0.4);
  const int bob = m.find_link("bob");
  ASSERT_GE(bob, 0);
  EXPECT_EQ(m.links[static_cast<std::size_t>(bob)].body, 0);
}

TEST(robot_model, servo_ids_may_have_gaps_and_joints_may_slide) {
  const robot_model m = load_robot_model(k_data + "/arm.urdf");
  EXPECT_EQ(m.servo_count(), 3);
  EXPECT_EQ(m.joint_of_servo(2), -1);
  ASSERT_GE(m.joint_of_servo(3), 0);
  EXPECT_EQ(m.joints[static_cast<std::size_t>(m.joint_of_servo(3))].type,
            stride::robot::joint_type::prismatic);
}

TEST(robot_model, weld_joint_merges_the_child_body) {
  robot_model m = load_robot_model(k_darwin);
  const double mass = m.total_mass();
  const int elbow = m.joint_of_servo(5);
  stride::robot::weld_joint(m, elbow, 0.5);
  EXPECT_EQ(m.bodies.size(), 20u);
  EXPECT_EQ(m.joints.size(), 19u);
  EXPECT_EQ(m.joint_of_servo(5), -1);
  EXPECT_NEAR(m.total_mass(), mass, 1e-12);
  const int forearm = m.find_link("r_el_link");
  const int upper_arm = m.find_link("r_sho_roll_link");
  EXPECT_EQ(m.links[static_cast<std::size_t>(forearm)].body,
            m.links[static_cast<std::size_t>(upper_arm)].body);
  // every joint still refers to a body that exists, parents before children
  for (const auto& j : m.joints) {
    EXPECT_LT(j.parent_body, j.child_body);
    EXPECT_LT(j.child_body, static_cast<int>(m.bodies.size()));
  }
}

// base --yaw about z at (0, 0, 0.1)--> upper --pitch about y at (0.5, 0, 0)--> lower
//      --slide along x at (0.3, 0, 0)--> tip
std::string chain(const std::string& root) {
  auto link = [](const std::string& name) {
    return "<link name=\"" + name + "\">" + (name == "world" ? "" : k_inertial) + "</link>";
  };
  return robot(link(root) + link("upper") + link("lower") + link("tip") +
               "<joint name=\"yaw\" type=\"continuous\"><parent link=\"" + root +
               "\"/><child link=\"upper\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/></joint>"
               "<joint name=\"pitch\" type=\"continuous\"><parent link=\"upper\"/><child "
               "link=\"lower\"/><origin xyz=\"0.5 0 0\"/><axis xyz=\"0 1 0\"/></joint>"
               "<joint name=\"slide\" type=\"prismatic\"><parent link=\"lower\"/><child "
               "link=\"tip\"/><origin xyz=\"0.3 0 0\"/><axis xyz=\"1 0 0\"/><limit lower=\"0\" "
               "upper=\"0.2\" effort=\"1\" velocity=\"1\"/></joint>");
}

// the frame of `link`'s body
stride::robot::pose frame_of(const robot_model& m, const std::vector<stride::robot::pose>& frames,
                             const std::string& link) {
  const int l = m.find_link(link);
  EXPECT_GE(l, 0) << link;
  return frames[static_cast<std::size_t>(m.links[static_cast<std::size_t>(l)].body)];
}

void expect_pose(const stride::robot::pose& p, const stride::robot::vec3& position,
                 const stride::robot::mat3& rotation) {
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(p.position[i], position[i], 1e-12) << i;
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(p.rotation[i], rotation[i], 1e-12) << i;
}

TEST(robot_model, forward_kinematics_of_a_chain_matches_the_hand_computed_frames) {
  const robot_model m = parse_robot_model(chain("base"), "chain.urdf");
  ASSERT_EQ(m.joints.size(), 3u);
  // root at (1, 2, 3) turned 90 deg about z; yaw +90 deg, pitch -90 deg (lower's x points up),
  // slide 0.1 m
  stride::robot::pose root;
  root.position = {1.0, 2.0, 3.0};
  root.rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  const std::vector<double> q = {std::numbers::pi / 2, -std::numbers::pi / 2, 0.1};
  const auto frames = m.forward_kinematics(root, q);
  ASSERT_EQ(frames.size(), 4u);
  expect_pose(frame_of(m, frames, "base"), {1, 2, 3}, root.rotation);
  // upper: 0.1 up, turned 180 deg about z in all
  expect_pose(frame_of(m, frames, "upper"), {1, 2, 3.1}, {-1, 0, 0, 0, -1, 0, 0, 0, 1});
  // lower: 0.5 along upper's x = world -x; x axis up, y axis = world -y, z axis = world +x
  expect_pose(frame_of(m, frames, "lower"), {0.5, 2, 3.1}, {0, 0, 1, 0, -1, 0, 1, 0, 0});
  // tip: 0.3 + 0.1 along lower's x = up
  expect_pose(frame_of(m, frames, "tip"), {0.5, 2, 3.5}, {0, 0, 1, 0, -1, 0, 1, 0, 0});

  // empty q: the zero pose, everything along the root's axes
  const auto zero = m.forward_kinematics(root, {});
  expect_pose(frame_of(m, zero, "tip"), {1, 2.8, 3.1}, root.rotation);
  const std::vector<double> two = {0.0, 0.0};
  EXPECT_THROW((void)m.forward_kinematics(root, two), std::invalid_argument);
}

TEST(robot_model, forward_kinematics_of_a_fixed_base_ignores_the_root_pose) {
  const robot_model m = parse_robot_model(chain("world"), "chain.urdf");
  ASSERT_TRUE(m.fixed_base);
  stride::robot::pose root;
  root.position = {1.0, 2.0, 3.0};
  const std::vector<double> q = {std::numbers::pi / 2, 0.0, 0.0};
  const auto frames = m.forward_kinematics(root, q);
  ASSERT_EQ(frames.size(), 3u);
  expect_pose(frame_of(m, frames, "upper"), {0, 0, 0.1}, {0, -1, 0, 1, 0, 0, 0, 0, 1});
  expect_pose(frame_of(m, frames, "tip"), {0, 0.8, 0.1}, {0, -1, 0, 1, 0, 0, 0, 0, 1});
}

TEST(robot_model, walk_ready_stance_has_the_documented_torso_height_and_lean) {
  // docs/robot-model.md §5.2: with the soles level on the floor, the torso origin is 0.317 m
  // above them and leans 12.94 deg forward
  const robot_model m = load_robot_model(k_darwin);
  const auto by_servo = stride::robot::darwin::walk_ready_pose();
  std::vector<double> q(m.joints.size(), 0.0);
  for (std::size_t j = 0; j < q.size(); ++j) {
    q[j] = by_servo[static_cast<std::size_t>(m.joints[j].servo_id - 1)];
  }
  const int foot_link = m.find_link("l_ank_roll_link");
  ASSERT_GE(foot_link, 0);
  const auto& foot_in_body = m.links[static_cast<std::size_t>(foot_link)].in_body;
  auto rotation = [](const stride::robot::pose& p) {
    Eigen::Matrix3d r;
    r << p.rotation[0], p.rotation[1], p.rotation[2], p.rotation[3], p.rotation[4], p.rotation[5],
        p.rotation[6], p.rotation[7], p.rotation[8];
    return r;
  };
  // torso upright first: the left foot's orientation in the torso frame
  const auto upright = m.forward_kinematics({}, q);
  const Eigen::Matrix3d foot =
      rotation(frame_of(m, upright, "l_ank_roll_link")) * rotation(foot_in_body);
  // turn the torso so that the foot is level
  stride::robot::pose root;
  const Eigen::Matrix3d r = foot.transpose();
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) root.rotation[static_cast<std::size_t>(3 * i + k)] = r(i, k);
  }
  const auto level = m.forward_kinematics(root, q);
  // the sole: the bottom face of the foot box, here level
  const stride::robot::pose foot_body = frame_of(m, level, "l_ank_roll_link");
  const auto& box =
      m.bodies[static_cast<std::size_t>(m.links[static_cast<std::size_t>(foot_link)].body)]
          .shapes.front();
  ASSERT_EQ(box.type, shape_type::box);
  const Eigen::Vector3d centre =
      rotation(foot_body) *
          Eigen::Vector3d(box.origin.position[0], box.origin.position[1], box.origin.position[2]) +
      Eigen::Vector3d(foot_body.position[0], foot_body.position[1], foot_body.position[2]);
  const double sole_z = centre.z() - 0.5 * box.size[2];
  EXPECT_NEAR(-sole_z, stride::robot::darwin::k_walk_ready_torso_height, 0.0005);
  // lean: pitch of the torso (R = Rz·Ry·Rx, pitch = asin(−r20)), + forward
  const double lean_deg = std::asin(-r(2, 0)) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(lean_deg, stride::robot::darwin::k_walk_ready_lean_deg, 0.01);
  EXPECT_NEAR(std::atan2(r(2, 1), r(2, 2)), 0.0, 0.02);  // hardly any roll
}

TEST(robot_model, missing_file_is_named) {
  const std::string msg = error_of([] { load_robot_model(k_data + "/does_not_exist.urdf"); });
  EXPECT_THAT(msg, HasSubstr("does_not_exist.urdf"));
  EXPECT_THAT(msg, HasSubstr("cannot open"));
}

TEST(robot_model, malformed_xml_reports_the_parser_message_and_file) {
  const std::string msg = error_of([] { load_robot_model(k_data + "/malformed.urdf"); });
  EXPECT_THAT(msg, HasSubstr("malformed.urdf"));
  EXPECT_THAT(msg, HasSubstr("XML error"));
  EXPECT_THAT(msg, HasSubstr("Line number"));  // tinyxml2 names the line
}

TEST(robot_model, urdfdom_errors_are_captured_into_the_message) {
  const std::string msg = error_of([] { load_robot_model(k_data + "/missing_link.urdf"); });
  EXPECT_THAT(msg, HasSubstr("missing_link.urdf"));
  EXPECT_THAT(msg, HasSubstr("ghost"));  // urdfdom's own message names the missing link
}

TEST(robot_model, unsupported_content_names_the_element) {
  const std::string floating =
      robot("<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" + k_inertial +
            "</link><joint name=\"free\" type=\"floating\"><parent "
            "link=\"a\"/><child link=\"b\"/></joint>");
  EXPECT_THAT(error_of([&] { parse_robot_model(floating, "mem.urdf"); }),
              HasSubstr("mem.urdf: joint 'free': floating joints are not supported"));
  const std::string planar =
      robot("<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" + k_inertial +
            "</link><joint name=\"slide2d\" type=\"planar\"><parent "
            "link=\"a\"/><child link=\"b\"/><axis xyz=\"0 0 1\"/></joint>");
  EXPECT_THAT(error_of([&] { parse_robot_model(planar, "mem.urdf"); }),
              HasSubstr("joint 'slide2d': planar joints are not supported"));
}

TEST(robot_model, a_collision_without_geometry_is_named) {
  const std::string empty = robot("<link name=\"a\">" + k_inertial +
                                  "<collision><origin xyz=\"0 0 0\"/></collision></link>");
  EXPECT_THAT(error_of([&] { parse_robot_model(empty, "mem.urdf"); }),
              HasSubstr("mem.urdf: link 'a': <collision> 1 has no <geometry>"));
  const std::string hollow =
      robot("<link name=\"a\">" + k_inertial + "<collision><geometry/></collision></link>");
  EXPECT_THAT(error_of([&] { parse_robot_model(hollow, "mem.urdf"); }),
              HasSubstr("mem.urdf: link 'a': <collision> 1: <geometry> is empty"));
  const std::string unknown =
      robot("<link name=\"a\">" + k_inertial +
            "<collision><geometry><box size=\"1 1 1\"/></geometry></collision>"
            "<collision><geometry><cone/></geometry></collision></link>");
  EXPECT_THAT(error_of([&] { parse_robot_model(unknown, "mem.urdf"); }),
              HasSubstr("mem.urdf: link 'a': <collision> 2: unsupported geometry <cone> "
                        "(collision shapes: box, cylinder, sphere, capsule, mesh)"));
}

TEST(robot_model, two_root_links_are_named) {
  const std::string two =
      robot("<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" + k_inertial + "</link>");
  const std::string msg = error_of([&] { parse_robot_model(two, "mem.urdf"); });
  EXPECT_THAT(msg, HasSubstr("mem.urdf: URDF error"));
  EXPECT_THAT(msg, HasSubstr("Two root links found: [a] and [b]"));  // urdfdom's words
}

TEST(robot_model, a_mesh_collision_keeps_its_scale_origin_and_triangles) {
  // mesh_box.urdf: unit_cube.stl (12 triangles) scaled 0.2 0.1 0.05, origin z -0.03, roll 90 deg;
  // its <visual> names a package that exists nowhere: visuals are not read
  const robot_model m = load_robot_model(k_data + "/mesh_box.urdf");
  ASSERT_EQ(m.bodies.size(), 1u);
  ASSERT_EQ(m.bodies[0].shapes.size(), 1u);
  const auto& s = m.bodies[0].shapes[0];
  EXPECT_EQ(s.type, shape_type::mesh);
  EXPECT_EQ(s.link, "crate");
  EXPECT_EQ(s.size, (stride::robot::vec3{0.2, 0.1, 0.05}));
  ASSERT_NE(s.mesh, nullptr);
  EXPECT_EQ(s.mesh->indices.size(), 36u);
  EXPECT_EQ(s.mesh->file, k_data + "/unit_cube.stl");  // relative to the URDF's folder
  EXPECT_NEAR(s.origin.position[2], -0.03, 1e-15);
  // Rx(90 deg): y -> z, z -> -y
  const std::array<double, 9> rx = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(s.origin.rotation[k], rx[k], 1e-12) << k;
  double top = -1.0;
  for (std::size_t k = 1; k < s.mesh->vertices.size(); k += 3) {
    top = std::max(top, s.mesh->vertices[k]);  // scaled y, before the origin's rotation
  }
  EXPECT_DOUBLE_EQ(top, 0.05);
}

TEST(robot_model, package_uris_use_the_package_path_and_name_every_place_searched) {
  // the test data folder is itself a package named "data"
  const std::string urdf =
      robot("<link name=\"a\">" + k_inertial +
            "<collision><geometry><mesh filename=\"package://data/unit_cube.stl\"/></geometry>"
            "</collision></link>");
  stride::robot::model_options options;
  options.package_path = {k_data};
  options.use_ros_package_path = false;
  const robot_model m = parse_robot_model(urdf, "mem.urdf", options);
  EXPECT_EQ(m.bodies[0].shapes[0].mesh->file, k_data + "/unit_cube.stl");
  // without it the package is not found; the message names the link, URI and places searched
  options.package_path = {"/nonexistent/one", "/nonexistent/two"};
  const std::string msg = error_of([&] { parse_robot_model(urdf, "mem.urdf", options); });
  EXPECT_THAT(msg, HasSubstr("mem.urdf: link 'a' collision mesh: 'package://data/unit_cube.stl': "
                             "package 'data' not found; searched /nonexistent/one/data/"
                             "unit_cube.stl, /nonexistent/two/data/unit_cube.stl"));
  EXPECT_THAT(msg, HasSubstr("(collision shapes: box, cylinder, sphere, capsule, mesh)"));
  EXPECT_THAT(error_of([] { load_robot_model(k_data + "/mesh_collision.urdf"); }),
              HasSubstr("mesh_collision.urdf: link 'base' collision mesh: "
                        "'package://nowhere/foot.stl': package 'nowhere' not found"));
}

TEST(robot_model, ros_package_path_is_searched_after_the_configured_folders) {
  const std::string urdf =
      robot("<link name=\"a\">" + k_inertial +
            "<collision><geometry><mesh filename=\"package://data/unit_cube.stl\"/></geometry>"
            "</collision></link>");
  // this process alone: ctest runs every test in a process of its own
  ::setenv("ROS_PACKAGE_PATH", ("/nonexistent/ros:" + k_data).c_str(), 1);
  const robot_model m = parse_robot_model(urdf, "mem.urdf");
  EXPECT_EQ(m.bodies[0].shapes[0].mesh->file, k_data + "/unit_cube.stl");
  stride::robot::model_options options;
  options.package_path = {"/nonexistent/first"};
  EXPECT_THAT(error_of([&] {
                options.use_ros_package_path = false;
                parse_robot_model(urdf, "mem.urdf", options);
              }),
              HasSubstr("searched /nonexistent/first/data/unit_cube.stl (collision shapes"));
  ::unsetenv("ROS_PACKAGE_PATH");
}

TEST(robot_model, unreadable_mesh_files_name_the_file_and_the_link) {
  const std::string obj =
      robot("<link name=\"a\">" + k_inertial +
            "<collision><geometry><mesh filename=\"hull.obj\"/></geometry></collision></link>");
  EXPECT_THAT(error_of([&] { parse_robot_model(obj, k_data + "/mem.urdf"); }),
              HasSubstr("link 'a' collision mesh: mesh file '" + k_data +
                        "/hull.obj': unsupported format '.obj'"));
  const std::string missing = robot(
      "<link name=\"a\">" + k_inertial +
      "<collision><geometry><mesh filename=\"file://gone.stl\"/></geometry></collision></link>");
  EXPECT_THAT(
      error_of([&] { parse_robot_model(missing, k_data + "/mem.urdf"); }),
      HasSubstr("link 'a' collision mesh: mesh file '" + k_data + "/gone.stl' cannot be read"));
}

TEST(robot_model, mimic_joints_name_their_master) {
  const robot_model m = load_robot_model(k_data + "/mimic.urdf");
  ASSERT_EQ(m.joints.size(), 2u);
  EXPECT_EQ(m.joints[0].mimic_joint, -1);
  EXPECT_EQ(m.joints[1].name, "grip_b");
  EXPECT_EQ(m.joints[1].mimic_joint, 0);
  EXPECT_EQ(m.joints[1].mimic_multiplier, 1.0);
  EXPECT_EQ(m.joints[1].mimic_offset, 0.0);
  // welding the master would leave the follower without one
  robot_model welded = m;
  EXPECT_THAT(error_of([&] { weld_joint(welded, 0, 0.0); }), HasSubstr("joint"));
}

TEST(robot_model, impossible_mimic_joints_are_named) {
  const std::string links = "<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" +
                            k_inertial + "</link><link name=\"c\">" + k_inertial +
                            "</link><link name=\"d\">" + k_inertial + "</link>";
  const auto joint = [](const std::string& name, const std::string& type, const std::string& child,
                        const std::string& inner) {
    return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"a\"/><child link=\"" +
           child +
           "\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
           "velocity=\"1\"/>" +
           inner + "</joint>";
  };
  const auto mimic = [](const std::string& master) { return "<mimic joint=\"" + master + "\"/>"; };
  const auto parse = [&](const std::string& joints) {
    return error_of([&] { parse_robot_model(robot(links + joints), "m.urdf"); });
  };
  EXPECT_THAT(parse(joint("j1", "revolute", "b", "") + joint("j2", "revolute", "c", mimic("nope")) +
                    joint("j3", "revolute", "d", "")),
              HasSubstr("m.urdf: joint 'j2': <mimic> joint 'nope' does not exist"));
  EXPECT_THAT(parse(joint("j1", "revolute", "b", "") + joint("j2", "revolute", "c", mimic("j1")) +
                    joint("j3", "revolute", "d", mimic("j2"))),
              HasSubstr("m.urdf: joint 'j3': <mimic> joint 'j2' is itself a mimic joint"));
  EXPECT_THAT(parse(joint("j1", "fixed", "b", "") + joint("j2", "revolute", "c", mimic("j1")) +
                    joint("j3", "revolute", "d", "")),
              HasSubstr("m.urdf: joint 'j2': <mimic> joint 'j1' is a fixed joint"));
  EXPECT_THAT(parse(joint("j1", "revolute", "b", "") + joint("j2", "fixed", "c", mimic("j1")) +
                    joint("j3", "revolute", "d", "")),
              HasSubstr("m.urdf: joint 'j2': a fixed joint cannot <mimic> another joint"));
  EXPECT_THAT(parse(joint("j1", "revolute", "b", "") +
                    joint("j2", "revolute", "c", "<servo id=\"1\"/>" + mimic("j1")) +
                    joint("j3", "revolute", "d", "")),
              HasSubstr("m.urdf: joint 'j2': a <mimic> joint cannot carry a <servo>"));
  EXPECT_THAT(parse(joint("j1", "revolute", "b", "") + joint("j2", "revolute", "c", mimic("j2")) +
                    joint("j3", "revolute", "d", "")),
              HasSubstr("m.urdf: joint 'j2': <mimic> names the joint itself"));
}

TEST(robot_model, joints_that_do_not_form_a_tree_are_named) {
  const std::string links = "<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" +
                            k_inertial + "</link><link name=\"c\">" + k_inertial + "</link>";
  const auto joint = [](const std::string& name, const std::string& parent,
                        const std::string& child) {
    return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/></joint>";
  };
  // a -> b -> c -> a: urdfdom would not see it (and leaked the links it had tied together)
  EXPECT_THAT(error_of([&] {
                parse_robot_model(robot(links + joint("ab", "a", "b") + joint("bc", "b", "c") +
                                        joint("ca", "c", "a")),
                                  "loop.urdf");
              }),
              HasSubstr("loop.urdf: the joints form a loop: ca -> bc -> ab"));
  EXPECT_THAT(
      error_of([&] { parse_robot_model(robot(links + joint("self", "b", "b")), "self.urdf"); }),
      HasSubstr("self.urdf: joint 'self': link 'b' is its own parent"));
  EXPECT_THAT(error_of([&] {
                parse_robot_model(robot(links + joint("ac", "a", "c") + joint("bc", "b", "c")),
                                  "two.urdf");
              }),
              HasSubstr("two.urdf: link 'c' is the child of two joints, 'ac' and 'bc'"));
}

TEST(robot_model, physically_impossible_models_are_rejected) {
  // a moving link without mass
  const std::string massless = robot("<link name=\"a\">" + k_inertial +
                                     "</link><link name=\"b\"/><joint name=\"j\" "
                                     "type=\"continuous\"><parent link=\"a\"/><child "
                                     "link=\"b\"/><axis xyz=\"0 0 1\"/></joint>");
  EXPECT_THAT(error_of([&] { parse_robot_model(massless, "m.urdf"); }),
              HasSubstr("link 'b' has no mass"));
  // inertia violating the triangle inequality
  const std::string bad_inertia = robot(
      "<link name=\"a\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
      "iyy=\"1\" iyz=\"0\" izz=\"3\"/></inertial></link>");
  EXPECT_THAT(error_of([&] { parse_robot_model(bad_inertia, "m.urdf"); }),
              HasSubstr("link 'a': principal moments violate the triangle inequality"));
  // duplicate servo ID
  const std::string twice =
      robot("<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" + k_inertial +
            "</link><link name=\"c\">" + k_inertial +
            "</link><joint name=\"j1\" type=\"continuous\"><servo id=\"4\"/><parent "
            "link=\"a\"/><child link=\"b\"/></joint><joint name=\"j2\" "
            "type=\"continuous\"><servo id=\"4\"/><parent link=\"a\"/><child "
            "link=\"c\"/></joint>");
  EXPECT_THAT(error_of([&] { parse_robot_model(twice, "m.urdf"); }),
              HasSubstr("joint 'j2': servo id 4 is already used by joint 'j1'"));
  const std::string bad_id =
      robot("<link name=\"a\">" + k_inertial + "</link><link name=\"b\">" + k_inertial +
            "</link><joint name=\"j1\" type=\"continuous\"><servo id=\"two\"/><parent "
            "link=\"a\"/><child link=\"b\"/></joint>");
  EXPECT_THAT(error_of([&] { parse_robot_model(bad_id, "m.urdf"); }),
              HasSubstr("joint 'j1': servo id 'two' is not an integer"));
  const std::string no_robot = "<?xml version=\"1.0\"?><model/>";
  EXPECT_THAT(error_of([&] { parse_robot_model(no_robot, "m.urdf"); }),
              HasSubstr("no <robot> root element"));
}

}  // namespace
