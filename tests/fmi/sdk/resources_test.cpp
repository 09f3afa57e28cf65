// sdk::find_resource: a relative name that does not exist as given is found in resources/.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "stride/sdk/resources.hpp"

namespace stride::test {
namespace {

namespace fs = std::filesystem;

// A scratch folder with resources/ holding config.ini, and the working directory moved into
// it, so "relative as given" means something known; both are undone afterwards.
class find_resource : public testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "stride_resources_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    root_ = pattern;
    resources_ = root_ / "resources";
    fs::create_directories(resources_ / "sub");
    std::ofstream(resources_ / "config.ini") << "x";
    std::ofstream(resources_ / "sub" / "model.urdf") << "x";
    old_cwd_ = fs::current_path();
    fs::current_path(root_);
  }
  void TearDown() override {
    fs::current_path(old_cwd_);
    fs::remove_all(root_);
  }

  fs::path root_;
  fs::path resources_;
  fs::path old_cwd_;
};

TEST_F(find_resource, relative_name_missing_as_given_comes_from_resources) {
  EXPECT_EQ(sdk::find_resource("config.ini", resources_), resources_ / "config.ini");
  EXPECT_EQ(sdk::find_resource("sub/model.urdf", resources_), resources_ / "sub" / "model.urdf");
}

TEST_F(find_resource, existing_relative_name_wins_over_resources) {
  std::ofstream("config.ini") << "local";
  EXPECT_EQ(sdk::find_resource("config.ini", resources_), fs::path("config.ini"));
}

TEST_F(find_resource, absolute_path_is_never_redirected) {
  const fs::path absolute = root_ / "config.ini";  // does not exist; resources/ has the name
  EXPECT_EQ(sdk::find_resource(absolute, resources_), absolute);
}

TEST_F(find_resource, name_found_nowhere_is_returned_as_given) {
  EXPECT_EQ(sdk::find_resource("missing.ini", resources_), fs::path("missing.ini"));
}

TEST_F(find_resource, no_resource_folder_means_no_lookup) {
  EXPECT_EQ(sdk::find_resource("config.ini", ""), fs::path("config.ini"));
}

}  // namespace
}  // namespace stride::test
