// `stride security init|add|show` through the built CLI: what it prints, that it never
// overwrites, and one-line errors that name the file, with a non-zero exit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string k_cli = STRIDE_CLI;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

class security_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-security-cli-test-"};
  test::process_result stride(const std::string& args) {
    return run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                       scratch.path());
  }
  // a failed command: non-zero, one line on stderr saying "error:" and `what`
  void expect_one_line_error(const test::process_result& r, const std::string& what) {
    EXPECT_NE(r.exit_code, 0);
    const auto err = lines(r.err);
    ASSERT_EQ(err.size(), 1u) << r.err;
    EXPECT_THAT(err[0], HasSubstr("error: "));
    EXPECT_THAT(err[0], HasSubstr(what));
  }
};

TEST_F(security_cli, help_documents_the_subcommands_and_options) {
  const auto r = stride("security --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"init", "add", "show"}) EXPECT_THAT(r.out, HasSubstr(word));
  const auto init = stride("security init --help");
  for (const char* option : {"--domains", "--protection", "--valid-days"}) {
    EXPECT_THAT(init.out, HasSubstr(option));
  }
}

TEST_F(security_cli, init_add_and_show_print_what_they_made_and_read_back) {
  const auto init = stride("security init ks --domains 0,3-5 --protection sign --valid-days 30");
  ASSERT_EQ(init.exit_code, 0) << init.err;
  const auto made = lines(init.out);
  ASSERT_EQ(made.size(), 4u) << init.out;
  for (const auto& line : made) EXPECT_THAT(line, StartsWith("made ks/"));
  EXPECT_THAT(init.out, HasSubstr("domains 0,3-5, protection sign"));

  const auto add = stride("security add ks alice --valid-days 7");
  ASSERT_EQ(add.exit_code, 0) << add.err;
  EXPECT_EQ(lines(add.out).size(), 7u) << add.out;
  EXPECT_THAT(add.out, HasSubstr("made ks/alice/key.pem"));
  EXPECT_TRUE(fs::exists(scratch.path() / "ks" / "alice" / "permissions.p7s"));

  const auto ks = stride("security show ks");
  ASSERT_EQ(ks.exit_code, 0) << ks.err;
  EXPECT_THAT(ks.out, HasSubstr("CN=Stride keystore CA "));
  EXPECT_THAT(ks.out, HasSubstr("0,3-5"));
  EXPECT_THAT(ks.out, HasSubstr("sign"));
  EXPECT_THAT(ks.out, HasSubstr("alice: CN=alice"));

  const auto alice = stride("security show ks/alice");
  ASSERT_EQ(alice.exit_code, 0) << alice.err;
  EXPECT_THAT(alice.out, HasSubstr("CN=alice,O=Stride keystore "));
  EXPECT_THAT(alice.out, HasSubstr("0,3-5"));
  EXPECT_THAT(alice.out, HasSubstr("mode 0600"));
  EXPECT_THAT(alice.out, HasSubstr("(valid)"));
}

TEST_F(security_cli, refuses_to_overwrite_with_one_line_errors) {
  ASSERT_EQ(stride("security init ks").exit_code, 0);
  ASSERT_EQ(stride("security add ks alice").exit_code, 0);
  const std::string cert = test::read_file(scratch.path() / "ks" / "alice" / "cert.pem");
  expect_one_line_error(stride("security init ks"), "ks: not empty");
  expect_one_line_error(stride("security add ks alice"), "ks/alice: already exists");
  EXPECT_EQ(test::read_file(scratch.path() / "ks" / "alice" / "cert.pem"), cert);
}

TEST_F(security_cli, bad_input_is_refused_naming_what_is_wrong) {
  expect_one_line_error(stride("security init ks --domains 0,300"), "--domains");
  EXPECT_FALSE(fs::exists(scratch.path() / "ks"));
  EXPECT_NE(stride("security init ks --protection none").exit_code, 0);
  ASSERT_EQ(stride("security init ks").exit_code, 0);
  expect_one_line_error(stride("security add ks 'a b'"), "not allowed");
  expect_one_line_error(stride("security add nowhere bob"), "nowhere/ca.cert.pem");
  expect_one_line_error(stride("security show nowhere"), "nowhere");
  fs::remove(scratch.path() / "ks" / "governance.p7s");
  expect_one_line_error(stride("security show ks"), "ks/governance.p7s");
}

}  // namespace
}  // namespace stride::cosim
