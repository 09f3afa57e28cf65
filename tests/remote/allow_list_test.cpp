// The worker's FMU allow-list: sha256sum files and folders of FMUs, and what is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "protocol.hpp"
#include "stride/remote/allow_list.hpp"

namespace stride::remote {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class allow_list : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("stride-allow-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string error_of(const fs::path& source) {
    fmu_allow_list list;
    try {
      add_allowed_fmus(source, list);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

const std::string k_digest(64, 'a');

TEST_F(allow_list, a_sha256sum_file_gives_its_digests_in_lowercase) {
  std::ofstream(dir_ / "allowed.txt") << "# FMUs of the study\n\n"
                                      << std::string(64, 'B') << "  robot.fmu\n"
                                      << k_digest << "\n";
  fmu_allow_list list;
  add_allowed_fmus(dir_ / "allowed.txt", list);
  EXPECT_EQ(list, (fmu_allow_list{k_digest, std::string(64, 'b')}));
}

TEST_F(allow_list, a_folder_gives_the_digest_of_each_fmu_file_in_it) {
  std::ofstream(dir_ / "one.fmu") << "first archive";
  std::ofstream(dir_ / "two.fmu") << "second archive";
  std::ofstream(dir_ / "notes.txt") << "not an FMU";
  fmu_allow_list list;
  add_allowed_fmus(dir_, list);
  const std::string one = "first archive";
  EXPECT_EQ(list.size(), 2u);
  EXPECT_EQ(list.count(content_hash(std::as_bytes(std::span(one.data(), one.size())))), 1u);
}

TEST_F(allow_list, a_line_that_is_not_a_digest_is_named_with_file_and_line) {
  std::ofstream(dir_ / "allowed.txt") << k_digest << "\nabc123 short.fmu\n";
  EXPECT_THAT(error_of(dir_ / "allowed.txt"), HasSubstr("allowed.txt:2: 'abc123'"));
  std::ofstream(dir_ / "hex.txt") << std::string(63, 'a') << "g\n";
  EXPECT_THAT(error_of(dir_ / "hex.txt"), HasSubstr("not a SHA-256"));
}

TEST_F(allow_list, a_folder_without_fmus_or_a_missing_file_is_an_error) {
  EXPECT_THAT(error_of(dir_), HasSubstr("no .fmu file in"));
  EXPECT_THAT(error_of(dir_ / "missing.txt"), HasSubstr("cannot read"));
}

}  // namespace
}  // namespace stride::remote
