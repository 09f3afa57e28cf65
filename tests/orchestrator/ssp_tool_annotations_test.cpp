// SSP files in the shapes other tools write (docs/ssp.md, "Other tools' annotations" and
// "Files from other tools"): the step and algorithm of libcosim's and OMSimulator's annotations,
// which of them wins, what is refused and what is listed as not read; connectors without kind
// or not listed at all; FMI 2.0 scalar names with dots and brackets; SSDs other than
// SystemStructure.ssd. Without running anything (FMUs hold only their modelDescription.xml).
#include "ssp_import_fixture.hpp"

namespace stride::cosim {
namespace {

using namespace test;  // the SSD pieces and the ssp_import fixture
using ::testing::ElementsAre;

const std::string k_osp_step = R"(
  <ssd:DefaultExperiment startTime="0" stopTime="1">
    <ssd:Annotations>
      <ssc:Annotation type="com.opensimulationplatform">
        <osp:Algorithm xmlns:osp="http://opensimulationplatform.com/SSP/OSPAnnotations">
          <osp:FixedStepAlgorithm baseStepSize="STEP"/>
        </osp:Algorithm>
      </ssc:Annotation>
    </ssd:Annotations>
  </ssd:DefaultExperiment>)";

// OMSimulator's annotation on the top system, in its newer shape
const std::string k_oms_on_system = R"(<ssd:Annotations>
      <ssc:Annotation type="org.openmodelica">
        <oms:Annotations xmlns:oms="https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd">
          <oms:SimulationInformation>
            <oms:FixedStepMaster description="oms-ma" stepSize="STEP"/>
          </oms:SimulationInformation>
        </oms:Annotations>
      </ssc:Annotation>
    </ssd:Annotations>
  </ssd:System>)";

std::string with_osp(const std::string& step) {
  return pair(k_plain) + replaced(k_osp_step, "STEP", step);
}

// OMSimulator's master on the top system (the last to close)
std::string with_oms(std::string body, const std::string& step) {
  const std::string close = "</ssd:System>";
  return body.replace(body.rfind(close), close.size(), replaced(k_oms_on_system, "STEP", step));
}

TEST_F(ssp_import, libcosims_annotation_gives_the_step_and_jacobi) {
  const std::string body = with_osp("0.004");
  const system_structure s = load(body);
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(4));
  EXPECT_EQ(s.algorithm, algorithm_kind::jacobi);
  EXPECT_EQ(s.notes.stepping_from,
            "libcosim's annotation (com.opensimulationplatform) at " +
                (scratch.path() / "t.ssd").string() + ":" +
                std::to_string(line_of(ssd(body), "<osp:FixedStepAlgorithm")));
  EXPECT_TRUE(s.notes.ignored_annotations.empty());
}

TEST_F(ssp_import, omsimulators_annotation_gives_the_step_and_jacobi_in_both_spellings) {
  const system_structure newer = load(with_oms(pair(k_plain), "0.002000"));
  EXPECT_EQ(newer.base_step, std::chrono::milliseconds(2));
  EXPECT_EQ(newer.algorithm, algorithm_kind::jacobi);
  EXPECT_THAT(newer.notes.stepping_from, HasSubstr("OMSimulator's annotation (org.openmodelica)"));
  // older files: ssd:Annotation, no oms:Annotations around the content, prefix undeclared
  const std::string older = replaced(pair(k_plain), "</ssd:System>", R"(<ssd:Annotations>
      <ssd:Annotation type="org.openmodelica">
        <oms:SimulationInformation>
          <oms:FixedStepMaster description="oms-ma" stepSize="1e-3"/>
        </oms:SimulationInformation>
      </ssd:Annotation>
    </ssd:Annotations>
  </ssd:System>)");
  const system_structure s = load(older);
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(1));
  EXPECT_EQ(s.algorithm, algorithm_kind::jacobi);
}

TEST_F(ssp_import, strides_annotation_wins_over_the_other_tools) {
  const std::string body = with_oms(with_osp("0.004"), "0.004") + R"(
  <ssd:Annotations>
    <ssc:Annotation type="org.stride-sim.system">
      <stride:Simulation step="0.01" algorithm="gauss-seidel"/>
    </ssc:Annotation>
  </ssd:Annotations>)";
  const system_structure s = load(body);
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(10));
  EXPECT_EQ(s.algorithm, algorithm_kind::gauss_seidel);
  EXPECT_THAT(s.notes.stepping_from, HasSubstr("Stride's annotation (org.stride-sim.system) at "));
  // without a step of its own it still decides: the FMUs' step, as in a system XML
  const system_structure no_step = load(replaced(body, R"(step="0.01" )", ""));
  EXPECT_EQ(no_step.base_step, std::nullopt);
  EXPECT_EQ(no_step.algorithm, algorithm_kind::gauss_seidel);
}

TEST_F(ssp_import, the_tools_annotations_agree_or_are_refused) {
  const system_structure same = load(with_oms(with_osp("0.004"), "0.004000"));
  EXPECT_EQ(same.base_step, std::chrono::milliseconds(4));
  EXPECT_THAT(same.notes.stepping_from, HasSubstr("OMSimulator's annotation"));
  EXPECT_THAT(same.notes.stepping_from, HasSubstr(" and libcosim's annotation"));
  const std::string differ = with_oms(with_osp("0.004"), "0.005");
  EXPECT_THAT(refusal(differ, "<osp:FixedStepAlgorithm"),
              HasSubstr("the step 0.004 s of libcosim's annotation (com.opensimulationplatform) "
                        "at "));
  EXPECT_THAT(refusal(differ, "<osp:FixedStepAlgorithm"),
              HasSubstr("differs from the step 0.005 s of OMSimulator's annotation"));
}

TEST_F(ssp_import, what_the_tools_annotations_cannot_say_is_refused_with_its_line) {
  EXPECT_THAT(refusal(with_osp("0"), "<osp:FixedStepAlgorithm"),
              HasSubstr("baseStepSize must be positive"));
  EXPECT_THAT(refusal(with_osp("0.1 s"), "<osp:FixedStepAlgorithm"),
              HasSubstr("baseStepSize: '0.1 s' is not a number of seconds"));
  EXPECT_THAT(refusal(with_osp("1e-10"), "<osp:FixedStepAlgorithm"),
              HasSubstr("not a whole number of nanoseconds"));
  const std::string ecco =
      replaced(with_osp("0.1"), R"(<osp:FixedStepAlgorithm baseStepSize="0.1"/>)",
               R"(<osp:EccoAlgorithm safetyFactor="0.8"/>)");
  EXPECT_THAT(refusal(ecco, "<osp:EccoAlgorithm"),
              HasSubstr("libcosim's algorithm 'EccoAlgorithm' is not supported"));
  const std::string variable =
      replaced(with_oms(pair(k_plain), "0.1"),
               R"(<oms:FixedStepMaster description="oms-ma" stepSize="0.1"/>)",
               R"(<oms:VariableStepSolver description="cvode" absoluteTolerance="1e-4"/>)");
  EXPECT_THAT(refusal(variable, R"(<ssd:Component name="a")"),
              HasSubstr("the system 'top' integrates Model Exchange FMUs (OMSimulator's solver "
                        "annotation), but this component has an FMU without Model Exchange"));
  EXPECT_THAT(refusal(replaced(variable, R"(description="cvode")", R"(description="ida")"),
                      "<oms:VariableStepSolver"),
              HasSubstr("OMSimulator's variable-step solver \"ida\" is not supported"));
  EXPECT_THAT(
      refusal(replaced(with_osp("0.1"), "baseStepSize", "stepsize"), "<osp:FixedStepAlgorithm"),
      HasSubstr("unknown attribute 'stepsize'"));
}

// OMSimulator's usual shape: a weakly coupled top system (a master) holding a strongly coupled
// one whose solver integrates its Model Exchange FMUs
TEST_F(ssp_import, omsimulators_solver_system_integrates_its_model_exchange_components) {
  test::write_fake_fmu(scratch.path() / "resources" / "me.fmu", test::stride_test_variables(),
                       false);
  const std::string body = with_oms(R"(
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="a" source="resources/stride_test.fmu"/>
      <ssd:System name="sc">
        <ssd:Elements>
          <ssd:Component name="m" source="resources/me.fmu"/>
          <ssd:Component name="own" source="resources/me.fmu">
            <ssd:Annotations><ssc:Annotation type="org.stride-sim.component">
              <stride:Component solver="euler" max_step="0.001"/>
            </ssc:Annotation></ssd:Annotations>
          </ssd:Component>
        </ssd:Elements>
        <ssd:Annotations>
          <ssc:Annotation type="org.openmodelica">
            <oms:Annotations xmlns:oms="https://raw.githubusercontent.com/OpenModelica/OMSimulator/master/schema/oms.xsd">
              <oms:SimulationInformation>
                <oms:VariableStepSolver description="cvode" absoluteTolerance="1e-10" relativeTolerance="1e-8" minimumStepSize="1e-12" maximumStepSize="0.002" initialStepSize="1e-6"/>
              </oms:SimulationInformation>
            </oms:Annotations>
          </ssc:Annotation>
        </ssd:Annotations>
      </ssd:System>
    </ssd:Elements>
  </ssd:System>)",
                                    "0.01");
  const system_structure s = load(body);
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(10));
  EXPECT_EQ(s.algorithm, algorithm_kind::jacobi);
  ASSERT_EQ(s.components.size(), 3u);
  EXPECT_EQ(s.components[0].name, "a");
  EXPECT_EQ(s.components[0].model_exchange, std::nullopt);
  const component_spec& m = s.components[1];
  EXPECT_EQ(m.name, "sc.m");
  EXPECT_EQ(m.kind, "model-exchange");
  ASSERT_TRUE(m.model_exchange.has_value());
  EXPECT_EQ(m.model_exchange->solver, model_exchange_options::solver_kind::cvode);
  EXPECT_EQ(m.model_exchange->rtol, 1e-8);
  EXPECT_EQ(m.model_exchange->atol, 1e-10);
  EXPECT_EQ(m.model_exchange->max_step, 0.002);
  // a component's own integrator wins over its system's
  ASSERT_TRUE(s.components[2].model_exchange.has_value());
  EXPECT_EQ(s.components[2].model_exchange->solver, model_exchange_options::solver_kind::euler);
  EXPECT_EQ(s.components[2].model_exchange->max_step, 0.001);
  // OMSimulator's fixed-step solver is explicit Euler at its step
  const std::string euler = replaced(
      body,
      R"(<oms:VariableStepSolver description="cvode" absoluteTolerance="1e-10" relativeTolerance="1e-8" minimumStepSize="1e-12" maximumStepSize="0.002" initialStepSize="1e-6"/>)",
      R"(<oms:FixedStepSolver description="euler" stepSize="0.0005"/>)");
  const system_structure with_euler = load(euler);
  const component_spec& e = with_euler.components.at(1);
  EXPECT_EQ(e.model_exchange->solver, model_exchange_options::solver_kind::euler);
  EXPECT_EQ(e.model_exchange->max_step, 0.0005);
  // a Co-Simulation component inside the solver's system has no place there
  EXPECT_THAT(refusal(replaced(body, R"(<ssd:Component name="m" source)",
                               R"(<ssd:Component name="m" implementation="CoSimulation" source)"),
                      R"(<ssd:Component name="m")"),
              HasSubstr("the system 'sc' integrates Model Exchange FMUs (OMSimulator's solver "
                        "annotation), but this component has implementation=\"CoSimulation\""));
}

TEST_F(ssp_import, other_annotations_are_listed_as_not_read_with_their_place) {
  // libcosim's annotation on the top system and OMSimulator's in the DefaultExperiment say
  // nothing of stepping there; other tools' types are theirs
  const std::string body = replaced(pair(k_plain), "</ssd:System>", R"(<ssd:Annotations>
      <ssc:Annotation type="com.opensimulationplatform"><osp:Algorithm><osp:FixedStepAlgorithm baseStepSize="0.5"/></osp:Algorithm></ssc:Annotation>
      <ssc:Annotation type="com.example.viewer"><layout/></ssc:Annotation>
    </ssd:Annotations>
  </ssd:System>
  <ssd:DefaultExperiment>
    <ssd:Annotations>
      <ssc:Annotation type="org.openmodelica"><oms:SimulationInformation><oms:FixedStepMaster stepSize="0.5"/></oms:SimulationInformation></ssc:Annotation>
    </ssd:Annotations>
  </ssd:DefaultExperiment>)");
  const system_structure s = load(body);
  EXPECT_EQ(s.base_step, std::nullopt);
  EXPECT_EQ(s.algorithm, algorithm_kind::gauss_seidel);
  EXPECT_EQ(s.notes.stepping_from, "");
  const std::string file = (scratch.path() / "t.ssd").string() + ":";
  EXPECT_THAT(
      s.notes.ignored_annotations,
      ElementsAre("com.opensimulationplatform at " + file +
                      std::to_string(line_of(ssd(body), R"(type="com.opensimulationplatform")")),
                  "com.example.viewer at " + file +
                      std::to_string(line_of(ssd(body), R"(type="com.example.viewer")")),
                  "org.openmodelica at " + file +
                      std::to_string(line_of(ssd(body), R"(type="org.openmodelica")"))));
}

TEST_F(ssp_import, connectors_without_kind_or_not_listed_are_the_fmus_variables) {
  const std::string body = replaced(
      replaced(
          pair(
              R"(<ssd:Connection startElement="a" startConnector="y" endElement="b" endConnector="u"/>
      <ssd:Connection startElement="a" startConnector="vec_out[2]" endElement="b" endConnector="vec_in[1]"/>)"),
          R"(<ssd:Connector name="y" kind="output">)", R"(<ssd:Connector name="y">)"),
      R"(<ssd:Connectors><ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>)",
      "<ssd:Connectors/>");
  const system_structure s = load(body);
  ASSERT_EQ(s.connections.size(), 2u);
  EXPECT_EQ(s.connections[0].from, "a.y");
  EXPECT_EQ(s.connections[0].to, "b.u");
  EXPECT_EQ(s.connections[1].from, "a.vec_out[2]");
  EXPECT_EQ(s.connections[1].to, "b.vec_in[1]");
  // a kind that is given must still be the FMU's
  EXPECT_THAT(
      refusal(replaced(pair(k_plain), R"(name="y" kind="output")", R"(name="y" kind="input")"),
              R"(<ssd:Connector name="y")"),
      HasSubstr("kind=\"input\", but the FMU's variable is output"));
  // a name the FMU lacks is still no connector
  EXPECT_THAT(refusal(pair(R"(<ssd:Connection startElement="a" startConnector="y"
      endElement="b" endConnector="vec_in[4]"/>)"),
                      "<ssd:Connection "),
              HasSubstr("element \"b\" has no connector \"vec_in[4]\" and its FMU no variable so "
                        "named"));
}

TEST_F(ssp_import, fmi2_scalar_names_with_dots_and_brackets_connect_and_take_values) {
  test::write_fake_fmu(scratch.path() / "resources" / "dotted.fmu",
                       {{"p.e[1]", "output", "Real", ""},
                        {"p.e[2]", "output", "Real", ""},
                        {"body.q[1].in", "input", "Real", ""},
                        {"body.k", "parameter", "Real", ""}});
  const system_structure s = load(R"(
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="src" source="resources/dotted.fmu"><ssd:Connectors/></ssd:Component>
      <ssd:System name="engine">
        <ssd:Connectors><ssd:Connector name="x"/></ssd:Connectors>
        <ssd:Elements>
          <ssd:Component name="pump" source="resources/dotted.fmu">
            <ssd:Connectors><ssd:Connector name="body.q[1].in" kind="input"/></ssd:Connectors>
            <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
              <ssv:ParameterSet version="1.0" name="p"><ssv:Parameters>
                <ssv:Parameter name="body.k"><ssv:Real value="2.5"/></ssv:Parameter>
              </ssv:Parameters></ssv:ParameterSet>
            </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
          </ssd:Component>
        </ssd:Elements>
        <ssd:Connections>
          <ssd:Connection startConnector="x" endElement="pump" endConnector="body.q[1].in"/>
        </ssd:Connections>
      </ssd:System>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="src" startConnector="p.e[2]" endElement="engine" endConnector="x"/>
    </ssd:Connections>
  </ssd:System>)");
  const connection_spec& c = s.connections.at(0);
  EXPECT_EQ(c.from, "src.p.e[2]");
  EXPECT_EQ(c.to, "engine.pump.body.q[1].in");
  const component_spec* pump = nullptr;
  for (const auto& component : s.components) {
    if (component.name == "engine.pump") pump = &component;
  }
  ASSERT_NE(pump, nullptr);
  ASSERT_EQ(pump->parameters.size(), 1u);
  EXPECT_EQ(pump->parameters[0].variable, "body.k");
  EXPECT_EQ(pump->parameters[0].value, "2.5");
}

TEST_F(ssp_import, an_archive_reads_the_ssd_it_is_asked_for_and_lists_them_all) {
  const std::string body = with_osp("0.004");
  write("tree/SystemStructure.ssd", ssd(body));
  write("tree/Variant.ssd", ssd(replaced(body, "0.004", "0.008")));
  write("tree/notes.txt", "not a system");
  fs::copy(scratch.path() / "resources", scratch.path() / "tree" / "resources",
           fs::copy_options::recursive);
  const fs::path archive = scratch.path() / "two.ssp";
  std::vector<test::zip_entry> entries;
  for (const auto& e : fs::recursive_directory_iterator(scratch.path() / "tree")) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    entries.push_back({e.path().lexically_relative(scratch.path() / "tree").generic_string(),
                       std::string(std::istreambuf_iterator<char>(in), {})});
  }
  test::write_zip(archive, entries);

  const system_structure first = load_system_file(archive);
  EXPECT_EQ(first.base_step, std::chrono::milliseconds(4));
  EXPECT_THAT(first.notes.descriptions, ElementsAre("SystemStructure.ssd", "Variant.ssd"));
  const system_structure variant = load_system_file(archive / "Variant.ssd");
  EXPECT_EQ(variant.base_step, std::chrono::milliseconds(8));
  EXPECT_EQ(variant.where.file, (archive / "Variant.ssd").string());
  EXPECT_THAT(variant.notes.descriptions, ElementsAre("SystemStructure.ssd", "Variant.ssd"));
  // the folder form holds both too
  EXPECT_THAT(load_system_file(scratch.path() / "tree").notes.descriptions,
              ElementsAre("SystemStructure.ssd", "Variant.ssd"));
  try {
    load_system_file(archive / "Other.ssd");
    ADD_FAILURE() << "a missing SSD was read";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(),
                HasSubstr(archive.string() + ": no Other.ssd at its root; the .ssd files there: "
                                             "SystemStructure.ssd, Variant.ssd (pick one as "));
  }
}

}  // namespace
}  // namespace stride::cosim
