// Model Exchange components in systems: next to a Co-Simulation FMU, chosen by kind, and saved
// and restored with the rest of the system.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "../remote/worker_process.hpp"
#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/execution.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_import.hpp"
#include "zip_writer.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class me_system_test : public ::testing::Test {
 protected:
  me_system_test() {
    test::write_zip(
        decay_, {{"modelDescription.xml", read_text(fs::path(STRIDE_ME_FMU_SOURCES) / "decay.xml")},
                 {"binaries/linux64/me_decay.so", read_text(STRIDE_ME_DECAY)}});
  }

  // decay.u <- source.y = offset (gain 0); decay.x -> source.u
  system_structure system(double stop) const {
    system_structure s;
    s.stop = time_from_seconds(stop);
    s.base_step = duration_from_seconds(0.1);
    auto& d = s.add_component("decay", decay_.string());
    model_exchange_options o;
    o.rtol = 1e-9;
    o.atol = 1e-12;
    d.model_exchange = o;
    auto& c = s.add_component("source", "stride_test");
    c.parameters.push_back({"gain", "0", {}});
    c.parameters.push_back({"offset", "0.5", {}});
    s.connect("source.y", "decay.u");
    s.connect("decay.x", "source.u");
    return s;
  }

  static observed_variable observe(execution& ex, const std::string& component,
                                   const std::string& variable) {
    const std::size_t c = *ex.find_component(component);
    return ex.observe({c, *ex.component_at(c).model_description().index_of(variable)});
  }

  temp_dir dir_{"stride-me-system-"};
  fs::path decay_ = dir_.path() / "decay.fmu";
};

// x' = -x + 1/2 from x(0) = 1: x = 1/2 + e^-t / 2
TEST_F(me_system_test, a_model_exchange_fmu_runs_beside_a_co_simulation_fmu) {
  auto built = build_system(system(2.0));
  auto& ex = *built.execution;
  const auto x = observe(ex, "decay", "x");
  const auto u = observe(ex, "source", "u");
  const auto y = observe(ex, "source", "y");
  const auto du = observe(ex, "decay", "u");
  const auto result = ex.simulate_until(built.stop);
  EXPECT_EQ(result.end_time, built.stop);
  EXPECT_EQ(ex.real_value(y), 0.5);
  EXPECT_EQ(ex.real_value(du), 0.5);
  EXPECT_NEAR(ex.real_value(x), 0.5 + 0.5 * std::exp(-2.0), 1e-6);
  EXPECT_EQ(ex.real_value(u), ex.real_value(x));  // the ME output reached the CS input
}

TEST_F(me_system_test, solver_settings_on_a_co_simulation_fmu_are_refused) {
  auto s = system(1.0);
  s.components[1].model_exchange = model_exchange_options{};
  try {
    build_system(s);
    FAIL() << "solver settings accepted on a Co-Simulation component";
  } catch (const fmu_import_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'source'"));
    EXPECT_THAT(e.what(), HasSubstr("solver settings need that kind"));
  }
  s.components[1].model_exchange.reset();
  s.components[1].kind = "model-exchange";
  EXPECT_THROW(build_system(s), fmu_import_error);  // stride_test has no <ModelExchange>
}

// OMSimulator's shape: a master system at 0.1 s with the source, holding a solver system whose
// CVODE settings integrate the decay. It runs step for step as the system built here with the
// same integrator and Jacobi (the fixed-step master's algorithm).
TEST_F(me_system_test, an_ssp_solver_system_integrates_its_model_exchange_fmu_as_said) {
  fs::create_directories(dir_.path() / "ssp" / "resources");
  fs::copy_file(decay_, dir_.path() / "ssp" / "resources" / "decay.fmu");
  fs::copy_file(fs::path(STRIDE_FMU_DIR) / "stride_test.fmu",
                dir_.path() / "ssp" / "resources" / "stride_test.fmu");
  std::ofstream(dir_.path() / "ssp" / "SystemStructure.ssd") << R"(<?xml version="1.0"?>
<ssd:SystemStructureDescription version="1.0" name="decay"
    xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues"
    xmlns:oms="https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd">
  <ssd:System name="wc">
    <ssd:Elements>
      <ssd:Component name="source" source="resources/stride_test.fmu">
        <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
          <ssv:ParameterSet version="1.0" name="p"><ssv:Parameters>
            <ssv:Parameter name="gain"><ssv:Real value="0"/></ssv:Parameter>
            <ssv:Parameter name="offset"><ssv:Real value="0.5"/></ssv:Parameter>
          </ssv:Parameters></ssv:ParameterSet>
        </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
      </ssd:Component>
      <ssd:System name="sc">
        <ssd:Connectors>
          <ssd:Connector name="u" kind="input"/><ssd:Connector name="x" kind="output"/>
        </ssd:Connectors>
        <ssd:Elements><ssd:Component name="decay" source="resources/decay.fmu"/></ssd:Elements>
        <ssd:Connections>
          <ssd:Connection startConnector="u" endElement="decay" endConnector="u"/>
          <ssd:Connection startElement="decay" startConnector="x" endConnector="x"/>
        </ssd:Connections>
        <ssd:Annotations><ssc:Annotation type="org.openmodelica"><oms:Annotations>
          <oms:SimulationInformation>
            <oms:VariableStepSolver description="cvode" absoluteTolerance="1e-12" relativeTolerance="1e-9"/>
          </oms:SimulationInformation>
        </oms:Annotations></ssc:Annotation></ssd:Annotations>
      </ssd:System>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="source" startConnector="y" endElement="sc" endConnector="u"/>
      <ssd:Connection startElement="sc" startConnector="x" endElement="source" endConnector="u"/>
    </ssd:Connections>
    <ssd:Annotations><ssc:Annotation type="org.openmodelica"><oms:Annotations>
      <oms:SimulationInformation><oms:FixedStepMaster description="oms-ma" stepSize="0.1"/></oms:SimulationInformation>
    </oms:Annotations></ssc:Annotation></ssd:Annotations>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="2"/>
</ssd:SystemStructureDescription>
)";
  const system_structure imported = load_system_file(dir_.path() / "ssp");
  system_structure here = system(2.0);
  here.components[0].name = "sc.decay";
  here.connections[0].to = "sc.decay.u";
  here.connections[1].from = "sc.decay.x";
  here.algorithm = algorithm_kind::jacobi;

  std::vector<double> expected, actual;
  for (auto* out : {&expected, &actual}) {
    auto built = build_system(out == &expected ? here : imported);
    const auto x = observe(*built.execution, "sc.decay", "x");
    built.execution->initialize(built.stop);
    while (built.execution->current_time() < built.stop) {
      built.execution->step();
      out->push_back(built.execution->real_value(x));
    }
  }
  ASSERT_EQ(expected.size(), 20u);
  EXPECT_EQ(actual, expected);
  EXPECT_NEAR(expected.back(), 0.5 + 0.5 * std::exp(-2.0), 1e-3);  // Jacobi lags one step of u
}

// a checkpoint of the whole system, restored into a fresh build, continues bit for bit
TEST_F(me_system_test, a_system_with_a_model_exchange_component_resumes_byte_identically) {
  auto first = build_system(system(2.0));
  const auto x1 = observe(*first.execution, "decay", "x");
  first.execution->initialize(first.stop);  // the whole run's stop: the steps go past 0.7 s
  first.execution->simulate_until(time_from_seconds(0.7));
  const auto image = first.execution->save_state_bytes();
  std::vector<double> expected;
  for (int i = 0; i < 13; ++i) {
    first.execution->step();
    expected.push_back(first.execution->real_value(x1));
  }

  auto second = build_system(system(2.0));
  const auto x2 = observe(*second.execution, "decay", "x");
  second.execution->initialize(second.stop);
  second.execution->restore_state_bytes(image);
  std::vector<double> actual;
  for (int i = 0; i < 13; ++i) {
    second.execution->step();
    actual.push_back(second.execution->real_value(x2));
  }
  EXPECT_EQ(actual, expected);
  EXPECT_NE(expected.front(), expected.back());  // the state moves: the comparison means something
}

// The ME FMU driven by the gait generator's hip joint angle: over each communication step of h
// the input is constant, so x' = -x + u has the exact step x <- x e^-h + u (1 - e^-h), where u
// is the value decay.u is observed with at the end of that step (Jacobi: the inputs a step
// integrates are set at its start, from the outputs of the step before).
TEST_F(me_system_test, a_model_exchange_fmu_follows_the_gait_generator) {
  system_structure s;
  s.stop = time_from_seconds(2.0);
  s.base_step = duration_from_seconds(0.008);
  s.algorithm = algorithm_kind::jacobi;
  auto& d = s.add_component("decay", decay_.string());
  model_exchange_options o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  d.model_exchange = o;
  auto& g = s.add_component("gait", "gait");
  g.parameters.push_back({"walking", "true", {}});
  g.parameters.push_back({"x_move", "10", {}});
  s.connect("gait.joint_angle[9]", "decay.u");  // a hip pitch joint: it swings while walking
  auto built = build_system(s);
  auto& ex = *built.execution;
  const auto x = observe(ex, "decay", "x");
  const auto u = observe(ex, "decay", "u");
  ex.initialize(built.stop);
  const double h = 0.008;
  double previous_x = ex.real_value(x);
  double lowest_u = ex.real_value(u), highest_u = lowest_u;
  int steps = 0;
  while (ex.current_time() < built.stop) {
    ex.step();
    const double now_u = ex.real_value(u);
    const double expected = previous_x * std::exp(-h) + now_u * -std::expm1(-h);
    ASSERT_NEAR(ex.real_value(x), expected, 1e-9) << "step " << steps;
    previous_x = ex.real_value(x);
    lowest_u = std::min(lowest_u, now_u);
    highest_u = std::max(highest_u, now_u);
    ++steps;
  }
  EXPECT_EQ(steps, 250);
  EXPECT_GT(highest_u - lowest_u, 0.05) << "the hip did not move: the test would mean nothing";
}

// The system of the first test from the command line, with the Model Exchange component on a
// `stride worker` (DDS domain 131): its integrator settings travel with it, and the results
// equal those of the run in one process. Adams is asked for; BDF, the default a worker would
// fall back to if the settings were lost, gives other digits.
TEST_F(me_system_test, a_model_exchange_component_on_a_worker_gives_the_same_csv) {
  const auto system_file = [&](const std::string& name, const std::string& settings) {
    const fs::path file = dir_.path() / (name + ".xml");
    std::ofstream(file) << "<system name=\"" << name << "\">\n"
                        << "  <simulation start=\"0\" stop=\"2\" step=\"0.1\"/>\n"
                        << "  <component name=\"decay\" fmu=\"" << decay_.string() << "\" "
                        << settings << " rtol=\"1e-5\"/>\n"
                        << "  <component name=\"source\" fmu=\"stride_test\">\n"
                        << "    <parameter name=\"gain\" value=\"0\"/>\n"
                        << "    <parameter name=\"offset\" value=\"0.5\"/>\n"
                        << "  </component>\n"
                        << "  <connection from=\"source.y\" to=\"decay.u\"/>\n"
                        << "  <connection from=\"decay.x\" to=\"source.u\"/>\n"
                        << "</system>\n";
    return file;
  };
  const std::string cli = STRIDE_CLI;
  const auto run = [&](const fs::path& system, const std::string& args) {
    const auto out = dir_.path() / system.stem();
    const auto r = test::run_command("'" + cli + "' run " + test::quoted(system) +
                                         " --quiet --output " + test::quoted(out) + " " + args,
                                     dir_.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_text(out / "results.csv");
  };
  const std::string local = run(system_file("local", "method=\"adams\""), "");
  const std::string bdf = run(system_file("bdf", "method=\"bdf\""), "");
  remote::test::worker_process worker(cli, "w1", 131, dir_.path() / "w1.log");
  ASSERT_TRUE(worker.ready()) << worker.output();
  const std::string remote =
      run(system_file("remote", "method=\"adams\" worker=\"w1\""), "--domain 131");
  ASSERT_NE(local.find("decay.x"), std::string::npos) << local;
  EXPECT_EQ(remote, local) << worker.output();
  EXPECT_NE(bdf, local);
}

}  // namespace
}  // namespace stride::cosim
