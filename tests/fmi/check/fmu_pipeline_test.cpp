// The per-FMU acceptance tools (stride-fmu-check, check_fmu_exports.sh, the plain-C
// fmu_importer, valgrind) on the mini_fmu fixture and on variants with one defect each: the
// honest FMU passes every tool, each defect makes the right tool fail with a clear message.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"
#include "test_support.hpp"

namespace {

namespace check = stride::fmi_check;
using check::test::command_result;
using check::test::run_command;
using check::test::shell_quote;
using check::test::zip_entry;

const std::filesystem::path k_mini_dir = std::filesystem::path(STRIDE_TEST_DATA_DIR) / "mini_fmu";
const std::filesystem::path k_variant_dir = STRIDE_MINI_FMU_BINARY_DIR;

class fmi_check_pipeline : public testing::Test {
 protected:
  /// Packs variant `so_name` (a built mini_fmu*.so) as binaries/linux64/mini_fmu.so.
  std::filesystem::path pack(const std::string& so_name, std::vector<zip_entry> extra = {},
                             std::string model_description = {}) {
    std::vector<zip_entry> entries;
    zip_entry md;
    md.name = "modelDescription.xml";
    if (model_description.empty()) {
      md.from_file = k_mini_dir / "modelDescription.xml";
    } else {
      md.content = std::move(model_description);
    }
    entries.push_back(md);
    zip_entry so;
    so.name = "binaries/linux64/mini_fmu.so";
    so.from_file = k_variant_dir / so_name;
    entries.push_back(so);
    zip_entry resource;
    resource.name = "resources/initial_state.txt";
    resource.from_file = k_mini_dir / "resources" / "initial_state.txt";
    entries.push_back(resource);
    for (auto& e : extra) entries.push_back(std::move(e));
    const auto path = dir_.path() / (so_name + "_" + std::to_string(++count_) + ".fmu");
    check::test::write_zip(path, entries);
    return path;
  }

  /// fmu_importer with TMPDIR pointing to a private folder that must end up empty.
  command_result import(const std::filesystem::path& fmu, const std::string& options = "--twice",
                        const std::string& prefix = "") {
    const auto tmp = dir_.path() / ("tmp_" + std::to_string(++count_));
    std::filesystem::create_directory(tmp);
    const auto result = run_command("TMPDIR=" + shell_quote(tmp.string()) + " " + prefix +
                                    shell_quote(STRIDE_FMU_IMPORTER) + " " +
                                    shell_quote(fmu.string()) + " " + options);
    EXPECT_TRUE(std::filesystem::is_empty(tmp)) << "fmu_importer left files in its temp dir";
    return result;
  }

  command_result exports(const std::filesystem::path& fmu) {
    return run_command("CMAKE_COMMAND=" + shell_quote(STRIDE_CMAKE_COMMAND) + " " +
                       shell_quote(STRIDE_BASH) + " " + shell_quote(STRIDE_EXPORTS_SCRIPT) + " " +
                       shell_quote(fmu.string()));
  }

  check::test::temp_dir dir_;
  int count_ = 0;
};

TEST_F(fmi_check_pipeline, honest_fmu_passes_every_tool) {
  const auto fmu = pack("mini_fmu.so");
  const auto findings = check::check_fmu(fmu);
  EXPECT_FALSE(check::has_errors(findings));
  for (const auto& f : findings) ADD_FAILURE() << check::format_finding(fmu.string(), f);

  const auto validate =
      run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " " + shell_quote(fmu.string()));
  EXPECT_EQ(validate.exit_code, 0) << validate.output;

  const auto exported = exports(fmu);
  EXPECT_EQ(exported.exit_code, 0) << exported.output;

  const auto imported = import(fmu);
  EXPECT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_NE(imported.output.find("two instances side by side passed"), std::string::npos)
      << imported.output;
  EXPECT_NE(imported.output.find("wrong GUID rejected"), std::string::npos) << imported.output;
}

TEST_F(fmi_check_pipeline, cli_reports_findings_in_the_documented_format) {
  std::string md = check::test::read_text(k_mini_dir / "modelDescription.xml");
  md.replace(md.find("fmiVersion=\"2.0\""), 16, "fmiVersion=\"2.1\"");
  const auto fmu = pack("mini_fmu.so", {}, md);
  const auto result =
      run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " " + shell_quote(fmu.string()));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(fmu.string() + ": error: [root.fmi_version] "), std::string::npos)
      << result.output;

  const auto help = run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("usage: stride-fmu-check"), std::string::npos) << help.output;
  EXPECT_EQ(run_command(shell_quote(STRIDE_FMU_CHECK_CLI)).exit_code, 2);
}

TEST_F(fmi_check_pipeline, cli_checks_fmi3_fmus_and_lists_their_rules) {
  auto pack3 = [&](const char* binary, const std::string& name) {
    const auto fmu = dir_.path() / name;
    check::test::zip_entry md;
    md.name = "modelDescription.xml";
    md.from_file = std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal3.xml";
    check::test::zip_entry so;
    so.name = "binaries/x86_64-linux/check_minimal3.so";
    so.from_file = binary;
    check::test::write_zip(fmu, {md, so});
    return run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " " + shell_quote(fmu.string()));
  };
  const auto honest = pack3(STRIDE_FMI3_EXPORTS, "honest3.fmu");
  EXPECT_EQ(honest.exit_code, 0) << honest.output;
  const auto no_do_step = pack3(STRIDE_FMI3_EXPORTS_NO_DO_STEP, "no_do_step3.fmu");
  EXPECT_EQ(no_do_step.exit_code, 1) << no_do_step.output;
  EXPECT_NE(no_do_step.output.find("error: [fmi3.exports.functions] "), std::string::npos)
      << no_do_step.output;

  const auto rules = run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " --list-rules");
  EXPECT_EQ(rules.exit_code, 0);
  EXPECT_NE(rules.output.find("\nfmi3.variable.start_count  "), std::string::npos) << rules.output;
}

TEST_F(fmi_check_pipeline, importer_names_a_missing_function) {
  const auto result = import(pack("mini_fmu_no_do_step.so"));
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("fmi2DoStep"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("does not export 1 of the 34"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, export_check_names_a_missing_function) {
  const auto result = exports(pack("mini_fmu_no_do_step.so"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("[exports.functions]"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("fmi2DoStep"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, export_check_rejects_a_non_fmi2_symbol) {
  const auto result = exports(pack("mini_fmu_extra_export.so"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("[exports.symbols]"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("mini_fmu_helper"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, export_check_rejects_an_unshipped_library) {
  const auto result = exports(pack("mini_fmu_extra_needed.so"));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("[exports.needed]"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("libz.so"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, importer_rejects_an_fmu_that_accepts_a_wrong_guid) {
  const auto result = import(pack("mini_fmu_any_guid.so"));
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("accepted a wrong GUID"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, importer_fails_on_a_guid_mismatch_between_xml_and_binary) {
  std::string md = check::test::read_text(k_mini_dir / "modelDescription.xml");
  const std::string guid = "{5a3c1e7e-2b64-4d0f-9a51-6f0e0c1d2b3a}";
  md.replace(md.find(guid), guid.size(), "{11111111-2222-3333-4444-555555555555}");
  const auto result = import(pack("mini_fmu.so", {}, md));
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("fmi2Instantiate(run_1"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("Wrong GUID"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, importer_rejects_nan_outputs) {
  const auto result = import(pack("mini_fmu_nan.so"));
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("is NaN"), std::string::npos) << result.output;
}

TEST_F(fmi_check_pipeline, importer_detects_state_shared_between_instances) {
  const auto fmu = pack("mini_fmu_shared_state.so");
  const auto once = import(fmu, "");
  EXPECT_EQ(once.exit_code, 0) << "a single instance cannot notice: " << once.output;
  const auto twice = import(fmu, "--twice");
  EXPECT_NE(twice.exit_code, 0) << twice.output;
  EXPECT_NE(twice.output.find("shared between instances"), std::string::npos) << twice.output;
}

TEST_F(fmi_check_pipeline, importer_refuses_unsafe_archives) {
  zip_entry escape;
  escape.name = "resources/../../escape.txt";
  escape.content = "x";
  const auto dot_dot = import(pack("mini_fmu.so", {escape}));
  EXPECT_NE(dot_dot.exit_code, 0) << dot_dot.output;
  EXPECT_NE(dot_dot.output.find("unsafe entry name"), std::string::npos) << dot_dot.output;

  zip_entry link;
  link.name = "resources/link";
  link.content = "/etc/passwd";
  link.symlink = true;
  const auto symlink = import(pack("mini_fmu.so", {link}));
  EXPECT_NE(symlink.exit_code, 0) << symlink.output;
  EXPECT_NE(symlink.output.find("symbolic link"), std::string::npos) << symlink.output;
}

TEST_F(fmi_check_pipeline, importer_reports_a_missing_binary) {
  std::string md = check::test::read_text(k_mini_dir / "modelDescription.xml");
  md.replace(md.find("modelIdentifier=\"mini_fmu\""), 26, "modelIdentifier=\"other_fmu\"");
  const auto result = import(pack("mini_fmu.so", {}, md));
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("no binaries/linux64/other_fmu.so"), std::string::npos)
      << result.output;
}

TEST_F(fmi_check_pipeline, importer_usage_errors_exit_with_2) {
  EXPECT_EQ(run_command(shell_quote(STRIDE_FMU_IMPORTER)).exit_code, 2);
  EXPECT_EQ(run_command(shell_quote(STRIDE_FMU_IMPORTER) + " a.fmu --steps x").exit_code, 2);
}

#ifdef STRIDE_VALGRIND
class fmi_check_pipeline_valgrind : public fmi_check_pipeline {
 protected:
  std::string valgrind() const {
    return shell_quote(STRIDE_VALGRIND) +
           " --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect "
           "--suppressions=" +
           shell_quote(STRIDE_VALGRIND_SUPPRESSIONS) + " --quiet ";
  }
};

TEST_F(fmi_check_pipeline_valgrind, honest_fmu_and_importer_are_clean) {
  const auto result = import(pack("mini_fmu.so"), "--twice --steps 20", valgrind());
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST_F(fmi_check_pipeline_valgrind, leaking_fmu_is_caught) {
  const auto result = import(pack("mini_fmu_leak.so"), "--twice --steps 20", valgrind());
  EXPECT_NE(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("definitely lost"), std::string::npos) << result.output;
}
#endif

}  // namespace
