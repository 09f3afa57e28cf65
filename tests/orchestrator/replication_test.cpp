// Replica groups: N copies of a group of components with their internal connections, connected
// to array variables outside the group (expansion, XML, building with mock components).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mock_component.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/placement.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {
namespace {

using test::mock_component;
using ::testing::HasSubstr;

// a walker-like pair and a monitor with array inputs, by component name
std::unique_ptr<component> make_mock(const component_spec& spec) {
  auto m = std::make_unique<mock_component>(spec.name);
  if (spec.name.starts_with("monitor")) {
    for (int i = 1; i <= 3; ++i) m->real("x[" + std::to_string(i) + "]", causality::input);
    return m;
  }
  m->real("gain", causality::parameter);
  m->real("u", causality::input);
  m->real("y", causality::output);
  return m;
}

build_options mock_options() {
  build_options o;
  o.placements.push_back(std::make_shared<function_placement>(make_mock));
  o.log = [](log_level, std::string_view, std::string_view, std::string_view) {};
  return o;
}

const char* k_walkers = R"(<system name="w" version="1">
  <simulation stop="1" step="0.1"/>
  <component name="monitor" fmu="m"/>
  <replicate name="walker" count="3">
    <component name="gait" fmu="m">
      <parameter name="gain" value="${copy:0.5;1;1.5}"/>
    </component>
    <component name="robot" fmu="m"/>
    <connection from="gait.y" to="robot.u"/>
    <connection from="robot.y" to="gait.u" delay="true"/>
  </replicate>
  <connection from="robot[*].y" to="monitor.x[*]"/>
</system>)";

TEST(cosim_replication, copies_get_indexed_names_and_their_own_connections) {
  const system_structure s = expand_replicas(parse_system_text(k_walkers, "t/w.xml"));
  std::vector<std::string> names;
  for (const auto& c : s.components) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"monitor", "gait[1]", "robot[1]", "gait[2]",
                                             "robot[2]", "gait[3]", "robot[3]"}));
  ASSERT_EQ(s.connections.size(), 7u);
  EXPECT_EQ(s.connections[0].from, "robot[*].y");  // the system's own connections first
  EXPECT_EQ(s.connections[3].from, "gait[2].y");
  EXPECT_EQ(s.connections[3].to, "robot[2].u");
  EXPECT_EQ(s.connections[4].from, "robot[2].y");
  EXPECT_TRUE(s.connections[4].delayed);
  EXPECT_EQ(s.components[3].parameters.at(0).value, "1");  // ${copy:...} of copy 2
  EXPECT_TRUE(s.groups.empty());
}

TEST(cosim_replication, copies_can_be_placed_on_different_workers) {
  std::string xml = k_walkers;
  xml.replace(xml.find("<component name=\"robot\" fmu=\"m\"/>"), 32,
              "<component name=\"robot\" fmu=\"m\" worker=\"${copy:near;far;far}\"/>");
  const system_structure s = expand_replicas(parse_system_text(xml, "t/w.xml"));
  ASSERT_EQ(s.components.size(), 7u);
  EXPECT_EQ(s.components[1].worker, "");  // gait[1]
  EXPECT_EQ(s.components[2].worker, "near");
  EXPECT_EQ(s.components[4].worker, "far");
  EXPECT_EQ(s.components[6].worker, "far");
  xml.replace(xml.find("${copy:near;far;far}"), 20, "w${copy:a;b}");
  try {
    expand_replicas(parse_system_text(xml, "t/w.xml"));
    ADD_FAILURE() << "two workers for three copies accepted";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("t/w.xml:8: worker of 'robot': ${copy:...} has 2 values for 3 copies"));
  }
}

TEST(cosim_replication, the_copies_connect_to_array_variables_outside_the_group) {
  const built_system b = build_system(parse_system_text(k_walkers, "t/w.xml"), mock_options());
  const execution& ex = *b.execution;
  EXPECT_EQ(ex.component_count(), 7u);
  std::vector<std::string> pairs;
  for (const auto& c : ex.connections())
    pairs.push_back(ex.full_name(c.from) + ">" + ex.full_name(c.to));
  EXPECT_THAT(pairs, ::testing::Contains("robot[1].y>monitor.x[1]"));
  EXPECT_THAT(pairs, ::testing::Contains("robot[3].y>monitor.x[3]"));
  EXPECT_THAT(pairs, ::testing::Contains("gait[3].y>robot[3].u"));
}

TEST(cosim_replication, writes_the_group_back_unexpanded) {
  const system_structure s = parse_system_text(k_walkers, "t/w.xml");
  const system_structure again = parse_system_text(to_xml(s), "t/w.xml");
  ASSERT_EQ(again.groups.size(), 1u);
  EXPECT_EQ(again.groups[0].count, 3);
  EXPECT_EQ(again.groups[0].components[0].parameters[0].value, "${copy:0.5;1;1.5}");
  EXPECT_EQ(again.groups[0].connections.size(), 2u);
}

TEST(cosim_replication, a_member_parameter_is_set_in_every_copy_and_one_copy_is_refused) {
  system_structure s = parse_system_text(k_walkers, "t/w.xml");
  s.set("robot.gain", "7");
  const system_structure x = expand_replicas(s);
  for (const auto& c : x.components) {
    if (c.name.starts_with("robot[")) {
      EXPECT_EQ(c.parameters.at(0).value, "7") << c.name;
    }
  }
  try {
    s.set("robot[2].gain", "7");
    FAIL() << "no error";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'robot.gain' sets it in every copy"));
  }
}

std::string build_error(const std::string& xml) {
  try {
    build_system(parse_system_text(xml, "t/w.xml"), mock_options());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(cosim_replication, bad_counts_and_dangling_ports_are_named) {
  std::string xml = k_walkers;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string x = xml;
    x.replace(x.find(from), from.size(), to);
    return x;
  };
  EXPECT_THAT(build_error(with("count=\"3\"", "count=\"0\"")),
              HasSubstr("t/w.xml:4: count=\"0\" is not a positive integer"));
  EXPECT_THAT(build_error(with("count=\"3\"", "count=\"two\"")),
              HasSubstr("count=\"two\" is not a positive integer"));
  // a copy that does not exist
  EXPECT_THAT(build_error(with("robot[*].y", "robot[4].y")),
              HasSubstr("t/w.xml:12: connection robot[4].y -> monitor.x[*]: unknown component "
                        "'robot[4]'"));
  EXPECT_THAT(build_error(with("robot[*].y", "robot[2:5].y")),
              HasSubstr("'robot[2:5]': only 3 copies of 'robot' exist"));
  // four copies for three array elements
  EXPECT_THAT(build_error(with("count=\"3\"", "count=\"4\"")),
              HasSubstr("${copy:...} has 3 values for 4 copies"));
  EXPECT_THAT(
      build_error(
          with("count=\"3\"", "count=\"4\"").replace(xml.find("${copy:0.5;1;1.5}"), 17, "${copy}")),
      HasSubstr("the source group has 4 variables, the target group 3"));
  // an internal connection to a port no member has
  EXPECT_THAT(
      build_error(with("to=\"robot.u\"", "to=\"robot.v\"")),
      HasSubstr("t/w.xml:9: connection gait[1].y -> robot[1].v: robot[1]: no variable 'v'"));
  // a member named like a component outside the group
  EXPECT_THAT(build_error(with("name=\"robot\"", "name=\"monitor\"")),
              HasSubstr("group 'walker': member name 'monitor' is already used"));
}

}  // namespace
}  // namespace stride::cosim
