// The stride CLI without FMUs: help, exit codes and one-line errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "zip_writer.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::run_command;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const std::string k_cli = STRIDE_CLI;

class cosim_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-cli-test-"};
  test::process_result stride(const std::string& args) {
    return run_command("'" + k_cli + "' " + args, scratch.path());
  }
};

std::size_t lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

TEST_F(cosim_cli, help_lists_the_subcommands) {
  const auto r = stride("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_THAT(r.out, HasSubstr("run"));
  EXPECT_THAT(r.out, HasSubstr("inspect"));
  EXPECT_THAT(r.out, HasSubstr("validate"));
  for (const char* sub : {"run", "inspect", "validate"}) {
    const auto h = stride(std::string(sub) + " --help");
    EXPECT_EQ(h.exit_code, 0) << sub;
  }
  EXPECT_THAT(stride("run --help").out, HasSubstr("--stop-time"));
  EXPECT_THAT(stride("run --help").out, HasSubstr("--set"));
}

TEST_F(cosim_cli, no_subcommand_or_unknown_option_fails) {
  EXPECT_NE(stride("").exit_code, 0);
  EXPECT_NE(stride("run --bogus").exit_code, 0);
  EXPECT_NE(stride("inspect /no/such.fmu").exit_code, 0);
}

TEST_F(cosim_cli, malformed_system_gives_one_line_with_file_and_line) {
  const auto r = stride("validate " + quoted(k_data / "malformed.xml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("stride: error: " + (k_data / "malformed.xml").string() + ":5:"));
  EXPECT_EQ(lines(r.err), 1u);
}

TEST_F(cosim_cli, missing_bundled_fmu_is_reported) {
  const auto r = run_command(
      "STRIDE_FMU_PATH=/nowhere '" + k_cli + "' validate " + quoted(k_data / "loop.xml"),
      scratch.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("loop.xml:4: component 'a': bundled FMU 'mock' not found"));
  EXPECT_EQ(lines(r.err), 1u);
}

TEST_F(cosim_cli, run_rejects_a_bad_override_and_stop_time) {
  auto r = stride("run " + quoted(k_data / "chain.xml") + " --set nodot --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--set 'nodot': expected component.variable=value"));
  r = stride("run " + quoted(k_data / "chain.xml") + " --stop-time 1s --quiet");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--stop-time: '1s' is not a number of seconds"));
}

TEST_F(cosim_cli, inspect_lists_variables_without_loading_the_binary) {
  const fs::path fmu = scratch.path() / "demo.fmu";
  test::write_zip(fmu, {{"modelDescription.xml", R"(<?xml version="1.0"?>
<fmiModelDescription fmiVersion="2.0" modelName="demo" guid="{42}">
  <CoSimulation modelIdentifier="demo" canGetAndSetFMUstate="true"/>
  <DefaultExperiment stepSize="0.01"/>
  <ModelVariables>
    <ScalarVariable name="gain" valueReference="0" causality="parameter" variability="tunable">
      <Real start="2" unit="1"/>
    </ScalarVariable>
    <ScalarVariable name="label" valueReference="1" causality="parameter" variability="fixed">
      <String start="hi"/>
    </ScalarVariable>
    <ScalarVariable name="y" valueReference="2" causality="output"><Real/></ScalarVariable>
  </ModelVariables>
  <ModelStructure><Outputs><Unknown index="3"/></Outputs></ModelStructure>
</fmiModelDescription>)"}});
  const auto r = stride("inspect " + quoted(fmu));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("{42}"));
  EXPECT_THAT(r.out, HasSubstr("canGetAndSetFMUstate"));
  EXPECT_THAT(r.out, HasSubstr("0.01"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("gain +parameter +tunable +Real +2 +1"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("label +parameter +fixed +String +\"hi\""));
  // validate loads the binary, which this archive does not have
  const auto v = stride("validate " + quoted(fmu));
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_THAT(v.err, HasSubstr("missing binary binaries/linux64/demo.so"));
}

TEST_F(cosim_cli, inspect_shows_model_exchange_capabilities_and_settings) {
  const fs::path fmu = scratch.path() / "me.fmu";
  test::write_zip(fmu, {{"modelDescription.xml", R"xml(<?xml version="1.0"?>
<fmiModelDescription fmiVersion="2.0" modelName="me" guid="{7}" numberOfEventIndicators="3">
  <ModelExchange modelIdentifier="me" completedIntegratorStepNotNeeded="true"/>
  <ModelVariables>
    <ScalarVariable name="x" valueReference="0"><Real/></ScalarVariable>
    <ScalarVariable name="der(x)" valueReference="1"><Real derivative="1"/></ScalarVariable>
  </ModelVariables>
  <ModelStructure><Derivatives><Unknown index="2"/></Derivatives></ModelStructure>
</fmiModelDescription>)xml"}});
  auto r = stride("inspect " + quoted(fmu));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Model Exchange Capabilities"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("continuous states +1\n"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("numberOfEventIndicators +3\n"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("completedIntegratorStepNotNeeded +true"));

  const fs::path system = scratch.path() / "me.xml";
  std::ofstream(system) << "<system><simulation stop='1' step='0.1'/>\n"
                           "<component name='a' fmu='me.fmu' kind='model-exchange' "
                           "method='adams' rtol='1e-8'/>\n"
                           "<component name='b' fmu='me.fmu' solver='euler' max_step='0.01'/>\n"
                           "<component name='c' fmu='me.fmu'/></system>\n";
  r = stride("inspect " + quoted(system));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("me.fmu  (model-exchange cvode adams rtol=1e-08)"));
  EXPECT_THAT(r.out,
              HasSubstr("me.fmu  (model-exchange if the FMU is ME-only euler max_step=0.01)"));
  EXPECT_THAT(r.out, ::testing::ContainsRegex("c +this process +me.fmu\n"));
}

// `stride plot` on a run folder of any system (a results CSV written here, no FMU needed)
TEST_F(cosim_cli, plot_draws_any_run_and_refuses_what_it_cannot_draw) {
  const fs::path run = scratch.path() / "run";
  fs::create_directories(run);
  std::ofstream(run / "results.csv") << "time,a.y,b.echo\n0,1,2\n0.5,2,3\n1,4,5\n";
  // no pose, no signals chosen: says so, non-zero, no empty figures/ left
  auto r = stride("plot " + quoted(run));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("nothing to plot"));
  EXPECT_EQ(lines(r.err), 1u);
  EXPECT_FALSE(fs::exists(run / "figures"));
  // a pattern matching no column is named
  r = stride("plot " + quoted(run) + " --signals 'a.y,c.*'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("pattern 'c.*' matches no column"));
  EXPECT_FALSE(fs::exists(run / "figures"));
  // without gnuplot: says so, and no figures folder stays behind
  const auto no_gnuplot = run_command(
      "PATH=/nonexistent '" + k_cli + "' plot " + quoted(run) + " --signals 'a.y'", scratch.path());
  EXPECT_EQ(no_gnuplot.exit_code, 1);
  EXPECT_THAT(no_gnuplot.err, HasSubstr("gnuplot not found"));
  EXPECT_FALSE(fs::exists(run / "figures"));
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  r = stride("plot " + quoted(run) + " --signals 'a.*'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("figure: " + (run / "figures" / "signal_a.y.png").string()));
  EXPECT_TRUE(fs::is_regular_file(run / "figures" / "signal_a.y.png"));
  EXPECT_FALSE(fs::exists(run / "figures" / "signal_b.echo.png"));
  // a pose by the naming rule, whatever its prefix
  std::ofstream(run / "results.csv") << "time,cart.base_x,cart.base_y\n0,0,0\n1,1,0.5\n";
  r = stride("plot " + quoted(run) + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(fs::is_regular_file(run / "figures" / "path_cart.png"));
  EXPECT_THAT(stride("plot --help").out, HasSubstr("P.base_x with P.base_y"));
}

}  // namespace
}  // namespace stride::cosim
