// Stride's annotations of the run settings SSP has no word for (docs/ssp.md, "Stride's
// annotations"): recording and agents in the system annotation, the worker in a component's,
// read exactly; a replica group's copy names ("a[1]") taken as component names; and every
// malformed or misplaced annotation refused naming file, line and element.
#include "ssp_import_fixture.hpp"

namespace stride::cosim {
namespace {

using namespace test;  // the SSD pieces and the ssp_import fixture
using ::testing::ElementsAre;

// the pair with SETTINGS inside the system annotation's <stride:Simulation>
std::string with_settings(const std::string& settings) {
  return pair(k_plain) + R"(
  <ssd:DefaultExperiment startTime="0" stopTime="1"><ssd:Annotations>
    <ssc:Annotation type="org.stride-sim.system">
      <stride:Simulation step="0.01">)" +
         settings + R"(</stride:Simulation>
    </ssc:Annotation></ssd:Annotations></ssd:DefaultExperiment>)";
}

// the pair with b's connectors followed by ANNOTATIONS
std::string b_annotated(const std::string& annotations) {
  return replaced(pair(k_plain),
                  R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>)",
                  R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>
        <ssd:Annotations>)" +
                      annotations + "</ssd:Annotations>");
}

TEST_F(ssp_import, recording_agents_and_workers_come_from_strides_annotations) {
  const system_structure s =
      load(replaced(with_settings(R"(<stride:Record enabled="false" interval="0.2" file="out/r.csv">
        <stride:Signal name="a.y"/><stride:Signal name="b[*].u"/></stride:Record>
        <stride:Agents count="3" mode="asynchronous" workers="w1  w2"/>
        <stride:Failover standby="s1 s2" snapshot-every="40"/>)"),
                    R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>)",
                    R"(<ssd:Connector name="u" kind="input"></ssd:Connector></ssd:Connectors>
        <ssd:Annotations><ssc:Annotation type="org.stride-sim.component">
          <stride:Component worker="far"/></ssc:Annotation></ssd:Annotations>)"));
  EXPECT_FALSE(s.record.enabled);
  EXPECT_EQ(s.record.interval, std::chrono::milliseconds(200));
  EXPECT_EQ(s.record.file, "out/r.csv");
  EXPECT_THAT(s.record.signals, ElementsAre("a.y", "b[*].u"));
  EXPECT_EQ(s.agents.count, 3);
  EXPECT_FALSE(s.agents.synchronous);
  EXPECT_THAT(s.agents.workers, ElementsAre("w1", "w2"));
  EXPECT_THAT(s.failover.standby, ElementsAre("s1", "s2"));
  EXPECT_EQ(s.failover.snapshot_every, 40);
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[0].worker, "");
  EXPECT_EQ(s.components[1].worker, "far");
}

TEST_F(ssp_import, placeholders_the_run_fills_in_come_from_the_component_annotation) {
  const system_structure s = load(b_annotated(R"(<ssc:Annotation type="org.stride-sim.component">
          <stride:Component><stride:Value name="n" value="${agent}"/>
            <stride:Value name="enable" value="${resume}"/></stride:Component>
          </ssc:Annotation>)"));
  ASSERT_EQ(s.components.size(), 2u);
  const auto& values = s.components[1].parameters;
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].variable + "=" + values[0].value, "n=${agent}");
  EXPECT_EQ(values[1].variable + "=" + values[1].value, "enable=${resume}");
  EXPECT_EQ(s.components[1].worker, "");
}

TEST_F(ssp_import, without_them_the_defaults_hold) {
  const system_structure s = load(with_settings(""));
  EXPECT_TRUE(s.record.enabled);
  EXPECT_FALSE(s.record.interval);
  EXPECT_EQ(s.record.file, "results.csv");
  EXPECT_TRUE(s.record.signals.empty());
  EXPECT_EQ(s.agents.count, 0);
}

TEST_F(ssp_import, a_replica_copys_name_is_a_component_name) {
  const std::string copies =
      replaced(replaced(pair(R"(<ssd:Connection startElement="a[1]" startConnector="y"
                     endElement="b[12]" endConnector="u"/>)"),
                        R"(<ssd:Component name="a")", R"(<ssd:Component name="a[1]")"),
               R"(<ssd:Component name="b")", R"(<ssd:Component name="b[12]")");
  const system_structure s = load(copies);
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[0].name, "a[1]");
  EXPECT_EQ(s.connections.at(0).from, "a[1].y");
  EXPECT_EQ(s.connections.at(0).to, "b[12].u");
  for (const std::string bad : {"a[01]", "a[0]", "a[x]", "a[1][2]", "a[]", "[1]", "a [1]"}) {
    const std::string body = replaced(pair(k_plain), R"(<ssd:Component name="a")",
                                      "<ssd:Component name=\"" + bad + "\"");
    EXPECT_THAT(refusal(body, "name=\"" + bad + "\""),
                HasSubstr("which Stride's names do not allow"))
        << bad;
  }
}

TEST_F(ssp_import, malformed_or_misplaced_settings_are_refused) {
  EXPECT_THAT(refusal(with_settings(R"(<stride:Record file="../x.csv"/>)"), "<stride:Record"),
              HasSubstr("<stride:Record>: file=\"../x.csv\" must be a relative path inside the "
                        "output folder"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Record interval="0"/>)"), "<stride:Record"),
              HasSubstr("interval must be positive"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Record><stride:Signals/></stride:Record>)"),
                      "<stride:Signals"),
              HasSubstr("<stride:Signals>: unknown element here"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Agents count="0"/>)"), "<stride:Agents"),
              HasSubstr("count=\"0\" is not a positive integer"));
  EXPECT_THAT(
      refusal(with_settings(R"(<stride:Agents count="2" mode="later"/>)"), "<stride:Agents"),
      HasSubstr("mode \"later\" is not synchronous or asynchronous"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Agents count="2" workers=" "/>)"), "<stride:Agents"),
              HasSubstr("workers=\"\" names no worker"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Failover standby=" "/>)"), "<stride:Failover"),
              HasSubstr("standby=\"\" names no worker"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Failover standby="s1" snapshot-every="x"/>)"),
                      "<stride:Failover"),
              HasSubstr("snapshot-every=\"x\" is not a positive integer"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Failover standby="s1"/>
        <stride:Agents count="2"/>)"),
                      "<stride:Agents"),
              HasSubstr("out of order"));
  EXPECT_THAT(refusal(with_settings(R"(<stride:Agents count="2"/>
        <stride:Record/>)"),
                      "<stride:Record"),
              HasSubstr("out of order"));
  const std::string component_annotation = R"(<ssc:Annotation type="org.stride-sim.component">
          <stride:Component worker="w"/></ssc:Annotation>)";
  EXPECT_THAT(refusal(with_settings("") + "\n<ssd:Annotations>" + component_annotation +
                          "</ssd:Annotations>",
                      R"(<ssc:Annotation type="org.stride-sim.component">)"),
              HasSubstr("Stride's component annotation belongs to an ssd:Component"));
  EXPECT_THAT(refusal(b_annotated(R"(<ssc:Annotation type="org.stride-sim.component">
          <stride:Component worker=""/></ssc:Annotation>)"),
                      "<stride:Component"),
              HasSubstr("<stride:Component>: needs a worker attribute"));
  EXPECT_THAT(refusal(b_annotated(R"(<ssc:Annotation type="org.stride-sim.component">
          <stride:Component><stride:Value name="nothing" value="${agent}"/></stride:Component>
          </ssc:Annotation>)"),
                      "<stride:Value"),
              HasSubstr("<stride:Value name=\"nothing\">: the FMU of 'b' has no variable"));
  EXPECT_THAT(refusal(b_annotated(R"(<ssc:Annotation type="org.stride-sim.component">
          <stride:Placement worker="w"/></ssc:Annotation>)"),
                      R"(<ssc:Annotation type="org.stride-sim.component">)"),
              HasSubstr("must hold one <Component> element"));
}

}  // namespace
}  // namespace stride::cosim
