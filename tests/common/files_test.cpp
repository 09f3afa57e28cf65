// write_file_atomically: the file holds the new bytes in full afterwards, and a failed write
// leaves the old file and no temporary behind.
#include "stride/common/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace stride::common {
namespace {

namespace fs = std::filesystem;

class common_files : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("stride_common_files_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(common_files, replaces_the_content_in_full) {
  const fs::path file = dir_ / "v_table.csv";
  write_file_atomically(file, "old content that is longer\n");
  const std::string bytes(100000, 'x');
  write_file_atomically(file, bytes);
  EXPECT_EQ(read(file), bytes);
  EXPECT_FALSE(fs::exists(dir_ / "v_table.csv.tmp"));
  write_file_atomically(file, "");
  EXPECT_TRUE(fs::exists(file));
  EXPECT_EQ(fs::file_size(file), 0u);
}

TEST_F(common_files, a_failed_write_names_the_file_and_keeps_the_old_one) {
  // the target is a directory that is not empty: rename fails after the temporary was written
  const fs::path target = dir_ / "busy";
  fs::create_directories(target / "inside");
  try {
    write_file_atomically(target, "new");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot write " + target.string()), std::string::npos) << what;
    EXPECT_NE(what.find("rename"), std::string::npos) << what;
  }
  EXPECT_TRUE(fs::is_directory(target / "inside"));
  EXPECT_FALSE(fs::exists(dir_ / "busy.tmp"));
}

TEST_F(common_files, a_missing_folder_is_reported_at_open) {
  const fs::path file = dir_ / "no" / "such" / "folder" / "x.csv";
  try {
    write_file_atomically(file, "x");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("open"), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir_ / "no"));
}

}  // namespace
}  // namespace stride::common
