// The SSP 1.0 importer without running anything: SSDs written here and under data/ssp/, FMUs
// that hold only their modelDescription.xml (made at test time). What an SSD becomes (names,
// connections with their factor and offset, parameters, times) and every refusal, which must
// name file, line and element.
#include "ssp_import_fixture.hpp"

namespace stride::cosim {
namespace {

using namespace test;  // the SSD pieces and the ssp_import fixture

const connection_spec& only_connection(const system_structure& s) {
  EXPECT_EQ(s.connections.size(), 1u);
  return s.connections.at(0);
}

TEST_F(ssp_import, the_pair_fixture_becomes_the_system_of_stride_test_pair_xml) {
  fs::copy(k_data / "ssp" / "pair", scratch.path() / "pair", fs::copy_options::recursive);
  test::write_fake_fmu(scratch.path() / "pair" / "resources" / "stride_test.fmu",
                       test::stride_test_variables());
  const system_structure s = load_system_file(scratch.path() / "pair");
  EXPECT_EQ(s.name, "pair");  // the folder's name
  EXPECT_EQ(s.start, time_point{});
  EXPECT_EQ(s.stop, time_point(std::chrono::seconds(1)));
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(10));
  EXPECT_EQ(s.algorithm, algorithm_kind::gauss_seidel);
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[0].name, "a");
  EXPECT_EQ(s.components[1].name, "b");
  EXPECT_EQ(s.components[0].fmu, "resources/stride_test.fmu");
  // inline values first, then those of resources/vectors.ssv
  std::vector<std::pair<std::string, std::string>> values;
  for (const auto& p : s.components[0].parameters) values.emplace_back(p.variable, p.value);
  EXPECT_EQ(values, (std::vector<std::pair<std::string, std::string>>{{"gain", "3"},
                                                                      {"u", "1"},
                                                                      {"label", "hello"},
                                                                      {"vec_in[1]", "1"},
                                                                      {"vec_in[2]", "2"},
                                                                      {"vec_in[3]", "3"}}));
  EXPECT_THAT(s.components[0].parameters[3].where.str(), HasSubstr("vectors.ssv:6"));
  std::vector<std::pair<std::string, std::string>> wires;
  for (const auto& c : s.connections) {
    wires.emplace_back(c.from, c.to);
    EXPECT_FALSE(c.transforms()) << c.from;
    EXPECT_FALSE(c.delayed) << c.from;
  }
  // the active -> enable connection is written from its input end
  EXPECT_THAT(wires, ::testing::UnorderedElementsAre(
                         std::pair<std::string, std::string>{"a.y", "b.u"},
                         std::pair<std::string, std::string>{"a.counter", "b.n"},
                         std::pair<std::string, std::string>{"a.active", "b.enable"},
                         std::pair<std::string, std::string>{"a.echo", "b.suffix"},
                         std::pair<std::string, std::string>{"a.vec_out[1]", "b.vec_in[1]"},
                         std::pair<std::string, std::string>{"a.vec_out[2]", "b.vec_in[2]"},
                         std::pair<std::string, std::string>{"a.vec_out[3]", "b.vec_in[3]"}));
  // nothing said of recording: every output, every step, into results.csv
  EXPECT_TRUE(s.record.enabled);
  EXPECT_TRUE(s.record.signals.empty());
  EXPECT_FALSE(s.record.interval);
  EXPECT_EQ(s.record.file, "results.csv");
}

TEST_F(ssp_import, a_linear_transformation_becomes_the_connections_factor_and_offset) {
  const system_structure s = load(pair(R"(<ssd:Connection startElement="a" startConnector="y"
      endElement="b" endConnector="u"><ssc:LinearTransformation factor="2" offset="1"/>
      </ssd:Connection>)"));
  const connection_spec& c = only_connection(s);
  EXPECT_EQ(c.from, "a.y");
  EXPECT_EQ(c.to, "b.u");
  EXPECT_EQ(c.factor, 2.0);
  EXPECT_EQ(c.offset, 1.0);
}

TEST_F(ssp_import, declared_units_convert_before_the_linear_transformation) {
  // km → m: × 1000; then × 2 + 1 (SSP: the transformation sees the target's unit)
  const system_structure s =
      load(pair(R"(<ssd:Connection startElement="a" startConnector="y"
      endElement="b" endConnector="u"><ssc:LinearTransformation factor="2" offset="1"/>
      </ssd:Connection>)",
                R"(<ssc:Real unit="km"/>)", R"(<ssc:Real unit="m"/>)", k_units));
  EXPECT_EQ(only_connection(s).factor, 2000.0);
  EXPECT_EQ(only_connection(s).offset, 1.0);
  // degC → K: + 273.15, no factor
  const system_structure t =
      load(pair(k_plain, R"(<ssc:Real unit="degC"/>)", R"(<ssc:Real unit="K"/>)", k_units));
  EXPECT_EQ(only_connection(t).factor, 1.0);
  EXPECT_EQ(only_connection(t).offset, 273.15);
}

TEST_F(ssp_import, suppress_unit_conversion_leaves_only_the_transformation) {
  const system_structure s =
      load(pair(R"(<ssd:Connection startElement="a" startConnector="y" endElement="b"
          endConnector="u" suppressUnitConversion="true">
          <ssc:LinearTransformation offset="-1"/></ssd:Connection>)",
                R"(<ssc:Real unit="km"/>)", R"(<ssc:Real unit="m"/>)", k_units));
  EXPECT_EQ(only_connection(s).factor, 1.0);
  EXPECT_EQ(only_connection(s).offset, -1.0);
}

TEST_F(ssp_import, units_of_different_quantities_are_refused_on_the_connection) {
  const std::string body =
      pair(k_plain, R"(<ssc:Real unit="km"/>)", R"(<ssc:Real unit="s"/>)", k_units);
  EXPECT_THAT(refusal(body, "<ssd:Connection "),
              HasSubstr("<ssd:Connection>: units \"km\" and \"s\" measure different quantities"));
}

TEST_F(ssp_import, nested_systems_are_flattened_with_dotted_names) {
  const system_structure s = load_nested();
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[0].name, "ctrl");
  EXPECT_EQ(s.components[1].name, "engine.pump");
  // through the system connector: × 2 outside, then + 1 inside
  const connection_spec& c = only_connection(s);
  EXPECT_EQ(c.from, "ctrl.y");
  EXPECT_EQ(c.to, "engine.pump.u");
  EXPECT_EQ(c.factor, 2.0);
  EXPECT_EQ(c.offset, 1.0);
  // the enclosing system's binding wins over the component's own (SSP 1.0)
  std::map<std::string, std::string> values;
  for (const auto& p : s.components[1].parameters) values[p.variable] = p.value;
  EXPECT_EQ(values, (std::map<std::string, std::string>{{"gain", "5"}, {"offset", "0.5"}}));
}

TEST_F(ssp_import, a_dotted_name_is_set_on_the_longest_component_that_prefixes_it) {
  system_structure s = load_nested();
  apply_override(s, "engine.pump.gain=7");
  EXPECT_EQ(s.find_component("engine.pump")->parameters.front().value, "7");
}

TEST_F(ssp_import, parameter_files_mappings_and_prefixes) {
  write("params/gains.ssv", R"(<?xml version="1.0"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="g">
  <ssv:Parameters>
    <ssv:Parameter name="k"><ssv:Real value="2" unit="km"/></ssv:Parameter>
    <ssv:Parameter name="on"><ssv:Boolean value="1"/></ssv:Parameter>
    <ssv:Parameter name="steps"><ssv:Integer value="3"/></ssv:Parameter>
    <ssv:Parameter name="nobody"><ssv:Real value="1"/></ssv:Parameter>
  </ssv:Parameters>
  <ssv:Units><ssc:Unit name="km"><ssc:BaseUnit m="1" factor="1000"/></ssc:Unit></ssv:Units>
</ssv:ParameterSet>
)");
  write("params/names.ssm", R"(<?xml version="1.0"?>
<ssm:ParameterMapping xmlns:ssm="http://ssp-standard.org/SSP1/SystemStructureParameterMapping"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0">
  <ssm:MappingEntry source="b.k" target="b.gain">
    <ssc:LinearTransformation factor="10" offset="1"/>
  </ssm:MappingEntry>
  <ssm:MappingEntry source="b.on" target="b.enable">
    <ssc:BooleanMappingTransformation>
      <ssc:MapEntry source="true" target="false"/>
    </ssc:BooleanMappingTransformation>
  </ssm:MappingEntry>
  <ssm:MappingEntry source="b.steps" target="b.stop_after_steps">
    <ssc:IntegerMappingTransformation><ssc:MapEntry source="3" target="30"/></ssc:IntegerMappingTransformation>
  </ssm:MappingEntry>
</ssm:ParameterMapping>
)");
  // b.gain declares metres: 2 km = 2000 m, then × 10 + 1 (units first, SSP 1.0)
  system_structure s = load(R"(
  <ssd:System name="top">
    <ssd:ParameterBindings>
      <ssd:ParameterBinding source="params/gains.ssv" prefix="b.">
        <ssd:ParameterMapping source="params/names.ssm"/>
      </ssd:ParameterBinding>
    </ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="b" source="resources/stride_test.fmu">
        <ssd:Connectors>
          <ssd:Connector name="gain" kind="parameter"><ssc:Real unit="m"/></ssd:Connector>
        </ssd:Connectors>
      </ssd:Component>
    </ssd:Elements>
  </ssd:System>
  )" + k_units);
  std::map<std::string, std::string> values;
  for (const auto& p : s.find_component("b")->parameters) values[p.variable] = p.value;
  EXPECT_EQ(values, (std::map<std::string, std::string>{
                        {"gain", "20001"}, {"enable", "false"}, {"stop_after_steps", "30"}}));
  // "b.nobody" matches no variable: ignored, as SSP says, but said
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("gains.ssv:8: <ssv:Parameter name=\"nobody\">: ignored"));
}

TEST_F(ssp_import, a_connection_annotation_delays_and_the_system_annotation_steps) {
  const system_structure s = load(pair(R"(<ssd:Connection startElement="a" startConnector="y"
      endElement="b" endConnector="u"><ssd:Annotations>
        <ssc:Annotation type="org.stride-sim.connection"><stride:Connection delay="true"/></ssc:Annotation>
        <ssc:Annotation type="com.example.other"><anything/></ssc:Annotation>
      </ssd:Annotations></ssd:Connection>)") +
                                  R"(
  <ssd:DefaultExperiment startTime="0.5" stopTime="2.5"/>
  <ssd:Annotations>
    <ssc:Annotation type="org.stride-sim.system">
      <stride:Simulation step="0.004" algorithm="jacobi"/>
    </ssc:Annotation>
  </ssd:Annotations>)");
  EXPECT_TRUE(only_connection(s).delayed);
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(4));
  EXPECT_EQ(s.algorithm, algorithm_kind::jacobi);
  EXPECT_EQ(s.start, time_point(std::chrono::milliseconds(500)));
  EXPECT_EQ(s.stop, time_point(std::chrono::milliseconds(2500)));
}

// --- refusals: each names file, line and element

TEST_F(ssp_import, unknown_elements_and_attributes_are_refused) {
  EXPECT_THAT(refusal(replaced(pair(k_plain), "<ssd:Elements>", "<ssd:Elements><ssd:Gadget/>"),
                      "<ssd:Gadget"),
              HasSubstr("<ssd:Gadget>: unknown element here"));
  EXPECT_THAT(refusal(replaced(pair(k_plain), R"(name="a" )", R"(name="a" colour="red" )"),
                      R"(name="a" colour)"),
              HasSubstr("<ssd:Component name=\"a\">: unknown attribute 'colour'"));
  // the children of a system come in the SSP's order
  const std::string late = replaced(
      pair(k_plain), "  </ssd:System>",
      R"(<ssd:Connectors><ssd:Connector name="z" kind="input"/></ssd:Connectors></ssd:System>)");
  EXPECT_THAT(refusal(late, "<ssd:Connectors><ssd:Connector name=\"z\""),
              HasSubstr("out of order"));
}

TEST_F(ssp_import, a_connection_to_a_missing_connector_or_element_is_refused) {
  EXPECT_THAT(refusal(pair(R"(<ssd:Connection startElement="a" startConnector="yy"
      endElement="b" endConnector="u"/>)"),
                      "<ssd:Connection "),
              HasSubstr("<ssd:Connection>: connection to a missing connector: element \"a\" has no "
                        "connector \"yy\""));
  EXPECT_THAT(refusal(pair(R"(<ssd:Connection startElement="c" startConnector="y"
      endElement="b" endConnector="u"/>)"),
                      "<ssd:Connection "),
              HasSubstr("the system has no element \"c\""));
}

TEST_F(ssp_import, a_missing_fmu_is_refused) {
  EXPECT_THAT(refusal(replaced(pair(k_plain), R"(name="b" source="resources/stride_test.fmu")",
                               R"(name="b" source="resources/none.fmu")"),
                      "resources/none.fmu"),
              HasSubstr("<ssd:Component name=\"b\">: FMU \"resources/none.fmu\" not found"));
}

TEST_F(ssp_import, unsupported_features_are_refused_by_name) {
  const auto refused = [&](const std::string& body, const std::string& needle,
                           const std::string& what) {
    EXPECT_THAT(refusal(body, needle), HasSubstr(what)) << needle;
  };
  refused(
      replaced(
          pair(k_plain), "  </ssd:System>",
          R"(<ssd:SignalDictionaries><ssd:SignalDictionary name="d"/></ssd:SignalDictionaries></ssd:System>)"),
      "<ssd:SignalDictionaries>", "signal dictionaries are not supported");
  refused(replaced(pair(k_plain), "<ssd:Elements>",
                   R"(<ssd:Elements><ssd:SignalDictionaryReference name="r" dictionary="d"/>)"),
          "<ssd:SignalDictionaryReference", "signal dictionary references are not supported");
  refused(replaced(pair(k_plain), R"(name="b" source)",
                   R"(name="b" implementation="Scheduled" source)"),
          R"(name="b" implementation)", "is not any, CoSimulation or ModelExchange");
  refused(replaced(pair(k_plain), R"(name="b" source)",
                   R"(name="b" type="application/x-ssp-package" source)"),
          R"(name="b" type)", "not nested SSPs");
  refused(pair(R"(<ssd:Connection startElement="a" startConnector="y" endElement="b"
      endConnector="u"><ssc:BooleanMappingTransformation><ssc:MapEntry source="true" target="false"/>
      </ssc:BooleanMappingTransformation></ssd:Connection>)"),
          "<ssc:BooleanMappingTransformation>", "ssc:LinearTransformation only");
  refused(replaced(pair(k_plain), R"(<ssd:Connector name="y" kind="output">)",
                   R"(<ssd:Connector name="y" kind="output"><ssc:Binary/>)"),
          "<ssc:Binary/>", "Binary connectors are not supported");
  refused(replaced(pair(k_plain), R"(<ssd:Component name="a")", R"(<ssd:Component name="a.b")"),
          R"(name="a.b")", "holds a '.'");
}

TEST_F(ssp_import, stride_annotations_are_read_only_where_they_belong) {
  const std::string on_component = replaced(
      pair(k_plain), R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>)",
      R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>
        <ssd:Annotations><ssc:Annotation type="org.stride-sim.system">
          <stride:Simulation step="0.1"/></ssc:Annotation></ssd:Annotations>)");
  EXPECT_THAT(refusal(on_component, R"(<ssc:Annotation type="org.stride-sim.system">)"),
              HasSubstr("<ssc:Annotation>: Stride's system annotation belongs to the"));
  const std::string twice = pair(k_plain) + R"(
  <ssd:DefaultExperiment><ssd:Annotations><ssc:Annotation type="org.stride-sim.system">
    <stride:Simulation step="0.1"/></ssc:Annotation></ssd:Annotations></ssd:DefaultExperiment>
  <ssd:Annotations><ssc:Annotation type="org.stride-sim.system">
    <stride:Simulation step="0.2"/></ssc:Annotation></ssd:Annotations>)";
  EXPECT_THAT(refusal(twice, R"(<ssd:Annotations><ssc:Annotation type="org.stride-sim.system">
    <stride:Simulation step="0.2"/>)"),
              HasSubstr("a second Stride annotation (the first at "));
}

TEST_F(ssp_import, model_exchange_components_take_their_integrator_from_strides_annotation) {
  test::write_fake_fmu(scratch.path() / "resources" / "me.fmu", test::stride_test_variables(),
                       false);
  const std::string me_only =
      replaced(pair(k_plain), R"(name="b" source="resources/stride_test.fmu")",
               R"(name="b" source="resources/me.fmu")");
  // an FMU that offers Model Exchange only needs nothing more (the run integrates it)
  const system_structure plain = load(me_only);
  EXPECT_EQ(plain.components.at(1).kind, "");
  EXPECT_EQ(plain.components.at(1).model_exchange, std::nullopt);
  const std::string annotated = replaced(
      replaced(me_only, R"(name="b" source)", R"(name="b" implementation="ModelExchange" source)"),
      R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>)",
      R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>
        <ssd:Annotations><ssc:Annotation type="org.stride-sim.component">
          <stride:Component solver="cvode" method="adams" rtol="1e-8" atol="1e-10" max_step="0.5"/>
        </ssc:Annotation></ssd:Annotations>)");
  const system_structure with_integrator = load(annotated);
  const component_spec& b = with_integrator.components.at(1);
  EXPECT_EQ(b.kind, "model-exchange");
  ASSERT_TRUE(b.model_exchange.has_value());
  EXPECT_EQ(b.model_exchange->method, model_exchange_options::method_kind::adams);
  EXPECT_EQ(b.model_exchange->rtol, 1e-8);
  EXPECT_EQ(b.model_exchange->atol, 1e-10);
  EXPECT_EQ(b.model_exchange->max_step, 0.5);
  // the integrator of a Co-Simulation component, and bad settings, are refused with the line
  EXPECT_THAT(refusal(replaced(annotated, "ModelExchange", "CoSimulation"), "<stride:Component"),
              HasSubstr("apply to kind=\"model-exchange\" only"));
  EXPECT_THAT(refusal(replaced(annotated, R"(rtol="1e-8")", R"(rtol="-1")"), "<stride:Component"),
              HasSubstr("rtol=\"-1\" must be > 0"));
  EXPECT_THAT(
      refusal(replaced(annotated,
                       R"(solver="cvode" method="adams" rtol="1e-8" atol="1e-10" max_step="0.5")",
                       R"(solver="euler")"),
              "<stride:Component"),
      HasSubstr("solver=\"euler\" needs max_step"));
}

TEST_F(ssp_import, connectors_must_match_their_fmu_variables) {
  EXPECT_THAT(
      refusal(replaced(pair(k_plain), R"(name="u" kind="input")", R"(name="u" kind="output")"),
              R"(name="u" kind)"),
      HasSubstr("<ssd:Connector name=\"u\">: kind=\"output\", but the FMU's variable is input"));
  EXPECT_THAT(refusal(pair(k_plain, "", "<ssc:Integer/>"), "<ssc:Integer/>"),
              HasSubstr("type Integer, but the FMU's variable is Real"));
  EXPECT_THAT(
      refusal(replaced(pair(k_plain), R"(name="u" kind)", R"(name="w" kind)"), R"(name="w" kind)"),
      HasSubstr("the FMU of 'b' has no variable so named"));
  EXPECT_THAT(refusal(pair(k_plain, R"(<ssc:Real unit="furlong"/>)"), R"(unit="furlong")"),
              HasSubstr("unit \"furlong\" is not defined"));
}

TEST_F(ssp_import, inputs_driven_twice_and_two_outputs_joined_are_refused) {
  const std::string twice = R"(
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="a" source="resources/stride_test.fmu">
        <ssd:Connectors>
          <ssd:Connector name="y" kind="output"/>
          <ssd:Connector name="vec_out[1]" kind="output"/>
        </ssd:Connectors>
      </ssd:Component>
      <ssd:Component name="b" source="resources/stride_test.fmu">
        <ssd:Connectors><ssd:Connector name="u" kind="input"/></ssd:Connectors>
      </ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="a" startConnector="y" endElement="b" endConnector="u"/>
      <ssd:Connection startElement="a" startConnector="vec_out[1]" endElement="b" endConnector="u"/>
    </ssd:Connections>
  </ssd:System>)";
  EXPECT_THAT(refusal(twice, R"(startConnector="vec_out[1]")"),
              HasSubstr("b.u is driven twice: by a.y"));
  const std::string outputs = replaced(pair(R"(<ssd:Connection startElement="a" startConnector="y"
      endElement="b" endConnector="y"/>)"),
                                       R"(<ssd:Connector name="u" kind="input">)",
                                       R"(<ssd:Connector name="y" kind="output">)");
  EXPECT_THAT(refusal(outputs, "<ssd:Connection "),
              HasSubstr("connects a.y (output) with b.y (output)"));
}

TEST_F(ssp_import, times_and_files_that_are_not_ssp_1_are_refused) {
  EXPECT_THAT(refusal(pair(k_plain) + R"(<ssd:DefaultExperiment stopTime="1e-10"/>)",
                      "<ssd:DefaultExperiment"),
              HasSubstr("<ssd:DefaultExperiment>: stopTime: "));
  EXPECT_THAT(
      refusal(pair(k_plain) + R"(<ssd:Annotations><ssc:Annotation type="org.stride-sim.system">
      <stride:Simulation step="0.0000000001"/></ssc:Annotation></ssd:Annotations>)",
              "<stride:Simulation"),
      HasSubstr("<stride:Simulation>: step: "));
  const fs::path v2 = write("v2.ssd", replaced(ssd(pair(k_plain)), R"(version="1.0" name="t")",
                                               R"(version="2.0" name="t")"));
  try {
    load_system_file(v2);
    ADD_FAILURE() << "SSP 2.0 read";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("v2.ssd:2: <ssd:SystemStructureDescription name=\"t\">: "
                                    "version \"2.0\": Stride reads SSP 1.0"));
  }
  const fs::path other_ns =
      write("ns.ssd", replaced(ssd(pair(k_plain)), "SSP1/SystemStructureDescription",
                               "SSP2/SystemStructureDescription"));
  EXPECT_THROW(load_system_file(other_ns), validation_error);
}

TEST_F(ssp_import, an_enumeration_parameter_value_is_refused) {
  const std::string body = R"(
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="a" source="resources/stride_test.fmu">
        <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
          <ssv:ParameterSet version="1.0" name="e"><ssv:Parameters>
            <ssv:Parameter name="n"><ssv:Enumeration value="High"/></ssv:Parameter>
          </ssv:Parameters></ssv:ParameterSet>
        </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
      </ssd:Component>
    </ssd:Elements>
  </ssd:System>)";
  EXPECT_THAT(refusal(body, "<ssv:Enumeration"), HasSubstr("<ssv:Enumeration>: not supported"));
}

}  // namespace
}  // namespace stride::cosim
