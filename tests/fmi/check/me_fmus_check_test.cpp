// The acceptance tools on the project's Model Exchange test FMUs (tests/orchestrator/me_fmus),
// packed as archives at test time: stride-fmu-check finds nothing, and check_fmu_exports.sh
// wants the Model Exchange functions of an FMU with <ModelExchange> but not the
// Co-Simulation-only ones of an FMU without <CoSimulation>; the ball and the chain, whose
// libraries also implement Co-Simulation, pass declaring both.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>

#include "stride/fmi_check/fmu_check.hpp"
#include "test_support.hpp"

namespace {

namespace check = stride::fmi_check;
namespace fs = std::filesystem;
using check::test::command_result;
using check::test::run_command;
using check::test::shell_quote;
using check::test::zip_entry;

struct me_fmu {
  std::string model;
  fs::path library;
};

void PrintTo(const me_fmu& m, std::ostream* os) {
  *os << m.model;
}

class fmi_check_me_fmus : public testing::TestWithParam<me_fmu> {
 protected:
  /// The archive as the Model Exchange runner tests pack it.
  fs::path pack(const me_fmu& m, std::string description = {}) {
    zip_entry md;
    md.name = "modelDescription.xml";
    if (description.empty()) {
      md.from_file = fs::path(STRIDE_ME_FMU_SOURCES) / (m.model + ".xml");
    } else {
      md.content = std::move(description);
    }
    zip_entry so;
    so.name = "binaries/linux64/me_" + m.model + ".so";
    so.from_file = m.library;
    const fs::path file = dir_.path() / (m.model + std::to_string(++count_) + ".fmu");
    check::test::write_zip(file, {md, so});
    return file;
  }

  static command_result exports(const fs::path& fmu) {
    return run_command("CMAKE_COMMAND=" + shell_quote(STRIDE_CMAKE_COMMAND) + " " +
                       shell_quote(STRIDE_BASH) + " " + shell_quote(STRIDE_EXPORTS_SCRIPT) + " " +
                       shell_quote(fmu.string()));
  }

  check::test::temp_dir dir_;
  int count_ = 0;
};

std::string describe(const fs::path& fmu, const std::vector<check::finding>& findings) {
  std::string out;
  for (const auto& f : findings) out += check::format_finding(fmu.string(), f) + "\n";
  return out;
}

TEST_P(fmi_check_me_fmus, checker_finds_nothing) {
  const fs::path fmu = pack(GetParam());
  const auto findings = check::check_fmu(fmu);
  EXPECT_TRUE(findings.empty()) << describe(fmu, findings);
  const auto cli = run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " " + shell_quote(fmu.string()));
  EXPECT_EQ(cli.exit_code, 0) << cli.output;
}

TEST_P(fmi_check_me_fmus, export_check_passes_without_co_simulation_functions) {
  const auto result = exports(pack(GetParam()));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("exports the 35 FMI 2.0 Model Exchange functions"),
            std::string::npos)
      << result.output;
}

// the description with <CoSimulation> declared as well, for the same binary
std::string with_co_simulation(const me_fmu& m) {
  std::string description =
      check::test::read_text(fs::path(STRIDE_ME_FMU_SOURCES) / (m.model + ".xml"));
  // after <ModelExchange/>: the schema orders the two
  const auto me = description.find("<ModelExchange modelIdentifier=\"me_" + m.model + "\"");
  const auto end = me == std::string::npos ? me : description.find("/>", me);
  if (end != std::string::npos) {
    description.insert(end + 2, "\n  <CoSimulation modelIdentifier=\"me_" + m.model + "\"/>");
  }
  return description;
}

INSTANTIATE_TEST_SUITE_P(
    me_fmus, fmi_check_me_fmus,
    testing::Values(me_fmu{"decay", STRIDE_ME_DECAY}, me_fmu{"ball", STRIDE_ME_BALL},
                    me_fmu{"stair", STRIDE_ME_STAIR}, me_fmu{"chain", STRIDE_ME_CHAIN}),
    [](const testing::TestParamInfo<me_fmu>& info) { return info.param.model; });

// Model Exchange only binaries
class fmi_check_me_only_fmus : public fmi_check_me_fmus {};

TEST_P(fmi_check_me_only_fmus, export_check_wants_co_simulation_functions_when_declared) {
  const std::string description = with_co_simulation(GetParam());
  ASSERT_NE(description.find("<CoSimulation"), std::string::npos) << description;
  const auto result = exports(pack(GetParam(), description));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("of the 44 FMI 2.0 Co-Simulation + Model Exchange functions"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("fmi2DoStep"), std::string::npos) << result.output;
}

INSTANTIATE_TEST_SUITE_P(me_fmus, fmi_check_me_only_fmus,
                         testing::Values(me_fmu{"decay", STRIDE_ME_DECAY},
                                         me_fmu{"stair", STRIDE_ME_STAIR}),
                         [](const testing::TestParamInfo<me_fmu>& info) {
                           return info.param.model;
                         });

// binaries with both interfaces
class fmi_check_twin_fmus : public fmi_check_me_fmus {};

TEST_P(fmi_check_twin_fmus, both_interfaces_declared_pass) {
  const std::string description = with_co_simulation(GetParam());
  ASSERT_NE(description.find("<CoSimulation"), std::string::npos) << description;
  const fs::path fmu = pack(GetParam(), description);
  const auto findings = check::check_fmu(fmu);
  EXPECT_TRUE(findings.empty()) << describe(fmu, findings);
  const auto result = exports(fmu);
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

INSTANTIATE_TEST_SUITE_P(me_fmus, fmi_check_twin_fmus,
                         testing::Values(me_fmu{"ball", STRIDE_ME_BALL},
                                         me_fmu{"chain", STRIDE_ME_CHAIN}),
                         [](const testing::TestParamInfo<me_fmu>& info) {
                           return info.param.model;
                         });

TEST(fmi_check_me_exports, co_simulation_binary_declared_as_model_exchange_is_rejected) {
  // mini_fmu implements Co-Simulation only; declaring <ModelExchange> for it must make the
  // export check ask for the Model Exchange functions
  check::test::temp_dir dir;
  const fs::path mini = fs::path(STRIDE_TEST_DATA_DIR) / "mini_fmu";
  std::string description = check::test::read_text(mini / "modelDescription.xml");
  const std::string cs = "<CoSimulation modelIdentifier=\"mini_fmu\"";
  const auto at = description.find(cs);
  ASSERT_NE(at, std::string::npos) << description;
  description.insert(at, "<ModelExchange modelIdentifier=\"mini_fmu\"/>\n  ");
  zip_entry md;
  md.name = "modelDescription.xml";
  md.content = description;
  zip_entry so;
  so.name = "binaries/linux64/mini_fmu.so";
  so.from_file = fs::path(STRIDE_MINI_FMU_BINARY_DIR) / "mini_fmu.so";
  const fs::path fmu = dir.path() / "mini_me.fmu";
  check::test::write_zip(fmu, {md, so});
  const auto result = run_command(
      "CMAKE_COMMAND=" + shell_quote(STRIDE_CMAKE_COMMAND) + " " + shell_quote(STRIDE_BASH) + " " +
      shell_quote(STRIDE_EXPORTS_SCRIPT) + " " + shell_quote(fmu.string()));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("[exports.functions]"), std::string::npos) << result.output;
  for (const char* f : {"fmi2EnterEventMode", "fmi2GetDerivatives", "fmi2SetContinuousStates",
                        "fmi2GetNominalsOfContinuousStates"}) {
    EXPECT_NE(result.output.find(f), std::string::npos) << f << "\n" << result.output;
  }
}

// FMI 3.0 Model Exchange: the ball and the stair behind the 3.0 wrapper pass the checker and the
// export check (which wants all 75 functions of the 3.0 API); without its <ModelExchange> the
// description names no interface at all
class fmi_check_me3_fmus : public fmi_check_me_fmus {
 protected:
  fs::path pack3(const me_fmu& m, std::string description) {
    zip_entry md;
    md.name = "modelDescription.xml";
    md.content = std::move(description);
    zip_entry so;
    so.name = "binaries/x86_64-linux/me3_" + m.model + ".so";
    so.from_file = m.library;
    const fs::path file = dir_.path() / (m.model + "3_" + std::to_string(++count_) + ".fmu");
    check::test::write_zip(file, {md, so});
    return file;
  }
  static std::string description3(const me_fmu& m) {
    return check::test::read_text(fs::path(STRIDE_ME_FMU_SOURCES) / (m.model + "3.xml"));
  }
};

TEST_P(fmi_check_me3_fmus, checker_and_export_check_find_nothing) {
  const fs::path fmu = pack3(GetParam(), description3(GetParam()));
  const auto findings = check::check_fmu(fmu);
  EXPECT_TRUE(findings.empty()) << describe(fmu, findings);
  const auto cli = run_command(shell_quote(STRIDE_FMU_CHECK_CLI) + " " + shell_quote(fmu.string()));
  EXPECT_EQ(cli.exit_code, 0) << cli.output;
  const auto result = run_command(
      "CMAKE_COMMAND=" + shell_quote(STRIDE_CMAKE_COMMAND) + " " + shell_quote(STRIDE_BASH) + " " +
      shell_quote(STRIDE_EXPORTS_SCRIPT) + " " + shell_quote(fmu.string()) + " 3");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("75"), std::string::npos) << result.output;
}

TEST_P(fmi_check_me3_fmus, a_description_without_an_interface_is_an_error) {
  std::string description = description3(GetParam());
  const auto me = description.find("<ModelExchange");
  ASSERT_NE(me, std::string::npos);
  description.erase(me, description.find("/>", me) + 2 - me);
  const fs::path fmu = pack3(GetParam(), description);
  const auto findings = check::check_fmu(fmu);
  EXPECT_TRUE(std::any_of(findings.begin(), findings.end(), [](const check::finding& f) {
    return f.rule == "fmi3.interface.missing";
  })) << describe(fmu, findings);
}

// the derivative is listed, not the state: the 3.0 ModelStructure rule says so
TEST_P(fmi_check_me3_fmus, a_state_listed_as_its_derivative_is_an_error) {
  std::string description = description3(GetParam());
  const std::string derivative = "<ContinuousStateDerivative valueReference=\"1\"/>";
  const auto at = description.find(derivative);
  ASSERT_NE(at, std::string::npos);
  description.replace(at, derivative.size(), "<ContinuousStateDerivative valueReference=\"0\"/>");
  const fs::path fmu = pack3(GetParam(), description);
  const auto findings = check::check_fmu(fmu);
  EXPECT_TRUE(std::any_of(findings.begin(), findings.end(), [](const check::finding& f) {
    return f.rule == "fmi3.derivatives.value_reference";
  })) << describe(fmu, findings);
}

INSTANTIATE_TEST_SUITE_P(me_fmus, fmi_check_me3_fmus,
                         testing::Values(me_fmu{"ball", STRIDE_ME3_BALL},
                                         me_fmu{"stair", STRIDE_ME3_STAIR}),
                         [](const testing::TestParamInfo<me_fmu>& info) {
                           return info.param.model;
                         });

}  // namespace
