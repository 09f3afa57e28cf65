// URI resolution (resource_path.cpp): package:// against the search path, file://, plain paths.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stride/robot/resource_path.hpp"
#include "stride/robot/robot_model.hpp"

namespace {

namespace fs = std::filesystem;
using stride::robot::model_error;
using stride::robot::package_search_path;
using stride::robot::resolve_resource;
using testing::HasSubstr;

std::string error_of(const std::string& uri, const std::vector<std::string>& path) {
  try {
    (void)resolve_resource(uri, "/base", path);
  } catch (const model_error& e) {
    return e.what();
  }
  return "<no model_error>";
}

// a scratch tree: <root>/ws/src/gripper/meshes/finger.stl and <root>/solo/arm/meshes/link.stl
class resource_path : public testing::Test {
 protected:
  void SetUp() override {
    // one folder per test: ctest runs the tests of this file in parallel processes
    root_ = fs::temp_directory_path() /
            ("stride_resource_path_test_" +
             std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    touch(root_ / "ws/src/gripper/meshes/finger.stl");
    touch(root_ / "solo/arm/meshes/link.stl");
  }
  void TearDown() override { fs::remove_all(root_); }
  static void touch(const fs::path& p) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
  }
  [[nodiscard]] std::string at(const std::string& rel) const { return (root_ / rel).string(); }
  fs::path root_;
};

TEST(package_search_path, configured_folders_come_before_the_environment) {
  EXPECT_EQ(package_search_path({"/a", "", "/b"}, "/c::/d:"),
            (std::vector<std::string>{"/a", "/b", "/c", "/d"}));
  EXPECT_EQ(package_search_path({"/a"}, nullptr), (std::vector<std::string>{"/a"}));
  EXPECT_EQ(package_search_path({}, ""), std::vector<std::string>{});
}

TEST_F(resource_path, a_package_is_a_folder_inside_an_entry_or_the_entry_itself) {
  // inside: <entry>/gripper/...
  EXPECT_EQ(
      resolve_resource("package://gripper/meshes/finger.stl", "/base", {at("solo"), at("ws/src")}),
      at("ws/src/gripper/meshes/finger.stl"));
  // the entry itself, with or without a trailing slash
  EXPECT_EQ(resolve_resource("package://arm/meshes/link.stl", "/base", {at("solo/arm")}),
            at("solo/arm/meshes/link.stl"));
  EXPECT_EQ(resolve_resource("package://arm/meshes/link.stl", "/base", {at("solo/arm/")}),
            at("solo/arm/meshes/link.stl"));
}

TEST_F(resource_path, the_first_entry_holding_the_file_wins) {
  touch(root_ / "solo/gripper/meshes/finger.stl");
  EXPECT_EQ(
      resolve_resource("package://gripper/meshes/finger.stl", "/base", {at("solo"), at("ws/src")}),
      at("solo/gripper/meshes/finger.stl"));
  EXPECT_EQ(
      resolve_resource("package://gripper/meshes/finger.stl", "/base", {at("ws/src"), at("solo")}),
      at("ws/src/gripper/meshes/finger.stl"));
}

TEST_F(resource_path, a_missing_package_names_the_uri_and_every_place_searched) {
  const std::string msg = error_of("package://gripper/meshes/palm.stl", {at("solo"), at("ws/src")});
  EXPECT_THAT(msg, HasSubstr("'package://gripper/meshes/palm.stl': package 'gripper' not found"));
  EXPECT_THAT(msg, HasSubstr("searched " + at("solo/gripper/meshes/palm.stl") + ", " +
                             at("ws/src/gripper/meshes/palm.stl")));
  EXPECT_THAT(error_of("package://gripper/x.stl", {}), HasSubstr("the package path is empty"));
  EXPECT_THAT(error_of("package://gripper", {at("ws/src")}),
              HasSubstr("needs the form package://NAME/PATH"));
}

TEST(resolve_resource, file_uris_and_plain_paths_are_relative_to_the_base_folder) {
  EXPECT_EQ(resolve_resource("file:///abs/m.stl", "/base", {}), "/abs/m.stl");
  EXPECT_EQ(resolve_resource("file://meshes/m.stl", "/base", {}), "/base/meshes/m.stl");
  EXPECT_EQ(resolve_resource("../meshes/./m.stl", "/base/urdf", {}), "/base/meshes/m.stl");
  EXPECT_EQ(resolve_resource("/abs/m.stl", "/base", {}), "/abs/m.stl");
  EXPECT_EQ(resolve_resource("m.stl", "", {}), "m.stl");  // no base: the working directory
  EXPECT_THAT(error_of("http://example.org/m.stl", {}), HasSubstr("unsupported URI scheme"));
}

}  // namespace
