// stride::fmi_check::check_fmu on FMI 3.0 archives (fmi/check/src/archive_check3.cpp): the
// binary's folder and name, and the functions its ELF dynamic symbol table exports, read from
// shared objects built for the test (data/fmi3_exports).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "defects.hpp"
#include "test_support.hpp"

namespace stride::fmi_check::test {
namespace {

zip_entry model_description3() {
  zip_entry e;
  e.name = "modelDescription.xml";
  e.from_file = std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal3.xml";
  return e;
}

zip_entry binary(std::string name, const char* built = STRIDE_FMI3_EXPORTS) {
  zip_entry e;
  e.name = std::move(name);
  e.from_file = built;
  return e;
}

zip_entry text(std::string name, std::string content) {
  zip_entry e;
  e.name = std::move(name);
  e.content = std::move(content);
  return e;
}

const finding* find_rule(const std::vector<finding>& findings, std::string_view rule) {
  const auto it = std::find_if(findings.begin(), findings.end(),
                               [&](const finding& f) { return f.rule == rule; });
  return it == findings.end() ? nullptr : &*it;
}

class fmi_check_archive3 : public testing::Test {
 protected:
  std::vector<finding> check_archive(const std::vector<zip_entry>& entries) {
    const auto path = dir_.path() / "test3.fmu";
    write_zip(path, entries);
    return check_fmu(path);
  }

  temp_dir dir_;
};

TEST_F(fmi_check_archive3, valid_archive_has_no_finding) {
  const auto findings =
      check_archive({model_description3(), binary("binaries/x86_64-linux/check_minimal3.so"),
                     text("resources/data.txt", "1")});
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST_F(fmi_check_archive3, fmi2_layout_is_reported) {
  const auto findings =
      check_archive({model_description3(), binary("binaries/linux64/check_minimal3.so")});
  EXPECT_TRUE(has_rule(findings, "fmi3.archive.platform_dir", finding::severity::error))
      << describe(findings);
  const finding* missing = find_rule(findings, "fmi3.archive.binary");
  ASSERT_NE(missing, nullptr) << describe(findings);
  EXPECT_NE(missing->message.find("binaries/x86_64-linux/check_minimal3.so"), std::string::npos)
      << missing->message;
  EXPECT_NE(missing->message.find("found: binaries/linux64/check_minimal3.so"), std::string::npos)
      << missing->message;
}

TEST_F(fmi_check_archive3, binary_named_after_another_identifier_is_reported) {
  const auto findings =
      check_archive({model_description3(), binary("binaries/x86_64-linux/other.so")});
  EXPECT_TRUE(has_rule(findings, "fmi3.archive.binary", finding::severity::error))
      << describe(findings);
}

TEST_F(fmi_check_archive3, missing_function_is_named) {
  const auto findings =
      check_archive({model_description3(), binary("binaries/x86_64-linux/check_minimal3.so",
                                                  STRIDE_FMI3_EXPORTS_NO_DO_STEP)});
  const finding* f = find_rule(findings, "fmi3.exports.functions");
  ASSERT_NE(f, nullptr) << describe(findings);
  EXPECT_NE(f->message.find("1 of the 75"), std::string::npos) << f->message;
  EXPECT_NE(f->message.find(": fmi3DoStep"), std::string::npos) << f->message;
  EXPECT_EQ(findings.size(), 1u) << describe(findings);
}

TEST_F(fmi_check_archive3, binary_that_is_no_elf_is_reported) {
  const auto findings =
      check_archive({model_description3(), text("binaries/x86_64-linux/check_minimal3.so",
                                                "\x7f"
                                                "ELF placeholder")});
  EXPECT_TRUE(has_rule(findings, "fmi3.exports.elf", finding::severity::error))
      << describe(findings);
}

TEST_F(fmi_check_archive3, truncated_elf_is_reported_not_read_past_its_end) {
  // the ELF header of a real binary, cut before its section headers
  const std::string head = read_text(STRIDE_FMI3_EXPORTS).substr(0, 200);
  const auto findings =
      check_archive({model_description3(), text("binaries/x86_64-linux/check_minimal3.so", head)});
  EXPECT_TRUE(has_rule(findings, "fmi3.exports.elf", finding::severity::error))
      << describe(findings);
}

TEST_F(fmi_check_archive3, fmi2_archive_is_not_searched_for_fmi3_functions) {
  zip_entry md;
  md.name = "modelDescription.xml";
  md.from_file = std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal.xml";
  const auto findings =
      check_archive({md, text("binaries/linux64/check_minimal.so", "not an ELF")});
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

}  // namespace
}  // namespace stride::fmi_check::test
