// stride::fmi_check::check_fmu on archives written with libzip at test time.
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"
#include "test_support.hpp"

namespace {

namespace check = stride::fmi_check;
using check::test::zip_entry;

const std::filesystem::path k_data = STRIDE_TEST_DATA_DIR;

std::string describe(const std::vector<check::finding>& findings) {
  std::string out;
  for (const auto& f : findings) out += check::format_finding("fmu", f) + "\n";
  return out.empty() ? "(no findings)\n" : out;
}

bool has_rule(const std::vector<check::finding>& findings, std::string_view rule,
              check::finding::severity level = check::finding::severity::error) {
  return std::any_of(findings.begin(), findings.end(),
                     [&](const check::finding& f) { return f.rule == rule && f.level == level; });
}

zip_entry model_description(std::string name = "modelDescription.xml") {
  zip_entry e;
  e.name = std::move(name);
  e.from_file = k_data / "valid_minimal.xml";
  return e;
}

zip_entry file(std::string name, std::string content =
                                     "\x7f"
                                     "ELF placeholder") {
  zip_entry e;
  e.name = std::move(name);
  e.content = std::move(content);
  return e;
}

class fmi_check_archive : public testing::Test {
 protected:
  std::vector<check::finding> check_archive(const std::vector<zip_entry>& entries,
                                            const std::string& name = "test.fmu") {
    const auto path = dir_.path() / name;
    check::test::write_zip(path, entries);
    return check::check_fmu(path);
  }

  check::test::temp_dir dir_;
};

TEST_F(fmi_check_archive, valid_archive_has_no_finding) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"),
                     file("resources/data.txt", "1"), file("documentation/index.html", "<html/>")});
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST_F(fmi_check_archive, stored_entries_are_allowed) {
  auto md = model_description();
  md.compression = ZIP_CM_STORE;
  auto so = file("binaries/linux64/check_minimal.so");
  so.compression = ZIP_CM_STORE;
  const auto findings = check_archive({md, so});
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST_F(fmi_check_archive, nested_root_is_reported) {
  const auto findings = check_archive({model_description("check_minimal/modelDescription.xml"),
                                       file("check_minimal/binaries/linux64/check_minimal.so")});
  ASSERT_TRUE(has_rule(findings, "archive.model_description")) << describe(findings);
  const auto it = std::find_if(findings.begin(), findings.end(),
                               [](const auto& f) { return f.rule == "archive.model_description"; });
  EXPECT_NE(it->message.find("check_minimal/modelDescription.xml"), std::string::npos)
      << it->message;
}

TEST_F(fmi_check_archive, missing_binary_is_reported) {
  const auto findings = check_archive({model_description(), file("sources/model.c", "int x;")});
  EXPECT_TRUE(has_rule(findings, "archive.binary")) << describe(findings);
}

TEST_F(fmi_check_archive, binary_not_named_after_model_identifier_is_reported) {
  const auto findings = check_archive({model_description(), file("binaries/linux64/other.so")});
  EXPECT_TRUE(has_rule(findings, "archive.binary")) << describe(findings);
}

TEST_F(fmi_check_archive, fmi3_platform_directory_in_fmi2_is_reported) {
  const auto findings =
      check_archive({model_description(), file("binaries/x86_64-linux/check_minimal.so")});
  EXPECT_TRUE(has_rule(findings, "archive.platform_dir")) << describe(findings);
  EXPECT_TRUE(has_rule(findings, "archive.binary")) << describe(findings);
}

TEST_F(fmi_check_archive, other_platform_tuples_are_allowed) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"),
                     file("binaries/aarch64-linux/check_minimal.so")});
  EXPECT_TRUE(findings.empty()) << describe(findings);
}

TEST_F(fmi_check_archive, backslash_entry_is_reported) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"),
                     file("resources\\data.txt", "1")});
  EXPECT_TRUE(has_rule(findings, "archive.backslash")) << describe(findings);
}

TEST_F(fmi_check_archive, dot_dot_entry_is_reported) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"),
                     file("resources/../../evil.sh", "rm -rf /")});
  EXPECT_TRUE(has_rule(findings, "archive.path")) << describe(findings);
}

TEST_F(fmi_check_archive, absolute_entry_is_reported) {
  const auto findings = check_archive(
      {model_description(), file("binaries/linux64/check_minimal.so"), file("/etc/evil", "x")});
  EXPECT_TRUE(has_rule(findings, "archive.path")) << describe(findings);
}

TEST_F(fmi_check_archive, symlink_entry_is_reported) {
  auto link = file("resources/link", "/etc/passwd");
  link.symlink = true;
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"), link});
  EXPECT_TRUE(has_rule(findings, "archive.link")) << describe(findings);
}

TEST_F(fmi_check_archive, bzip2_entry_is_reported) {
  if (zip_compression_method_supported(ZIP_CM_BZIP2, 1) == 0) {
    GTEST_SKIP() << "this libzip cannot write bzip2";
  }
  auto data = file("resources/data.txt", std::string(1000, 'a'));
  data.compression = ZIP_CM_BZIP2;
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"), data});
  EXPECT_TRUE(has_rule(findings, "archive.compression")) << describe(findings);
}

TEST_F(fmi_check_archive, encrypted_entry_is_reported) {
  if (zip_encryption_method_supported(ZIP_EM_AES_128, 1) == 0) {
    GTEST_SKIP() << "this libzip cannot write AES encryption";
  }
  auto data = file("resources/data.txt", "secret data");
  data.encrypt = true;
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"), data});
  EXPECT_TRUE(has_rule(findings, "archive.encryption")) << describe(findings);
}

TEST_F(fmi_check_archive, version_needed_above_2_0_is_reported) {
  const auto path = dir_.path() / "v45.fmu";
  check::test::write_zip(path, {model_description(), file("binaries/linux64/check_minimal.so")});
  // raise "version needed to extract" of the first central directory header to 4.5
  std::string bytes = check::test::read_text(path);
  const auto at = bytes.find(std::string("PK\x01\x02", 4));
  ASSERT_NE(at, std::string::npos);
  bytes[at + 6] = 45;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const auto findings = check::check_fmu(path);
  EXPECT_TRUE(has_rule(findings, "archive.format")) << describe(findings);
}

TEST_F(fmi_check_archive, corrupt_entry_data_is_reported) {
  const auto path = dir_.path() / "corrupt.fmu";
  auto data = file("resources/data.txt", "stored payload, checked by CRC");
  data.compression = ZIP_CM_STORE;
  check::test::write_zip(path,
                         {model_description(), file("binaries/linux64/check_minimal.so"), data});
  std::string bytes = check::test::read_text(path);
  const auto at = bytes.find("stored payload");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'S';
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const auto findings = check::check_fmu(path);
  EXPECT_TRUE(has_rule(findings, "archive.open")) << describe(findings);
}

TEST_F(fmi_check_archive, non_ascii_name_is_a_warning) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so"),
                     file("resources/d\xc3\xa4ten.txt", "1")});
  EXPECT_TRUE(has_rule(findings, "archive.name_ascii", check::finding::severity::warning))
      << describe(findings);
  EXPECT_FALSE(check::has_errors(findings)) << describe(findings);
}

TEST_F(fmi_check_archive, wrong_extension_is_a_warning) {
  const auto findings =
      check_archive({model_description(), file("binaries/linux64/check_minimal.so")}, "test.zip");
  EXPECT_TRUE(has_rule(findings, "archive.extension", check::finding::severity::warning))
      << describe(findings);
}

TEST_F(fmi_check_archive, model_description_defects_are_reported_through_the_archive) {
  auto md = file("modelDescription.xml", check::test::read_text(k_data / "valid_minimal.xml"));
  const auto at = md.content.find("fmiVersion=\"2.0\"");
  ASSERT_NE(at, std::string::npos);
  md.content.replace(at, 16, "fmiVersion=\"2.1\"");
  const auto findings = check_archive({md, file("binaries/linux64/check_minimal.so")});
  EXPECT_TRUE(has_rule(findings, "root.fmi_version")) << describe(findings);
}

TEST_F(fmi_check_archive, not_a_zip_is_reported) {
  const auto path = dir_.path() / "text.fmu";
  std::ofstream(path) << "this is not a zip archive\n";
  EXPECT_TRUE(has_rule(check::check_fmu(path), "archive.open"));
}

TEST_F(fmi_check_archive, missing_file_is_reported) {
  const auto findings = check::check_fmu(dir_.path() / "does_not_exist.fmu");
  EXPECT_TRUE(has_rule(findings, "archive.open")) << describe(findings);
}

TEST(fmi_check_archive_listing, binary_rules_need_only_the_listing) {
  const std::string xml = check::test::read_text(k_data / "valid_minimal.xml");
  const check::archive_listing good = {"modelDescription.xml", "binaries/", "binaries/linux64/",
                                       "binaries/linux64/check_minimal.so"};
  EXPECT_TRUE(check::check_model_description(xml, &good).empty());
  const check::archive_listing wrong = {"modelDescription.xml",
                                        "binaries/x86_64-linux/check_minimal.so"};
  const auto findings = check::check_model_description(xml, &wrong);
  EXPECT_TRUE(has_rule(findings, "archive.platform_dir")) << describe(findings);
  EXPECT_TRUE(has_rule(findings, "archive.binary")) << describe(findings);
}

}  // namespace
