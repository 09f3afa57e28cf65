// System XML parsing, the C++ system API and the builder (with mock components).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "mock_component.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/run.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_structure.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::mock_component;
using ::testing::HasSubstr;

const fs::path k_data = STRIDE_TEST_DATA_DIR;

log_sink quiet_log() {
  return [](log_level, std::string_view, std::string_view, std::string_view) {};
}

// every mock has the same variables
std::unique_ptr<component> make_mock(const component_spec& spec) {
  auto m = std::make_unique<mock_component>(spec.name);
  m->real("level", causality::parameter);
  m->real("gain", causality::parameter);
  m->add("label", variable_type::string, causality::parameter);
  m->real("u", causality::input);
  m->real("y", causality::output, std::vector<std::string>{"u"});
  m->real("z", causality::output);
  for (int i = 1; i <= 3; ++i) {
    m->real("vec[" + std::to_string(i) + "]", causality::output);
    m->real("vin[" + std::to_string(i) + "]", causality::input);
  }
  m->add("n", variable_type::integer, causality::output);
  m->add("k", variable_type::integer, causality::input);
  m->on_update = [](mock_component& s) {
    s.r("y") = s.r("gain") * s.r("u") + s.r("level");
    for (int i = 1; i <= 3; ++i) {
      s.r("vec[" + std::to_string(i) + "]") = s.r("level") * i;
    }
  };
  return m;
}

build_options mock_options() {
  build_options o;
  o.placements.push_back(std::make_shared<function_placement>(make_mock));
  o.log = quiet_log();
  return o;
}

std::string build_error(const system_structure& s) {
  try {
    build_system(s, mock_options());
  } catch (const error& e) {
    return e.what();
  }
  return "no error";
}

system_structure parse(const std::string& xml) {
  return parse_system_text(xml, "t/test.xml");
}

// the message parse() refuses `xml` with, or "no error"
std::string error_of(const std::string& xml) {
  try {
    parse(xml);
  } catch (const validation_error& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

TEST(cosim_system_xml, parses_every_element) {
  const auto s = parse_system_file(k_data / "chain.xml");
  EXPECT_EQ(s.name, "chain");
  EXPECT_EQ(s.description, "source, amplifier, sink");
  EXPECT_EQ(s.base_dir, k_data);
  EXPECT_EQ(s.start, time_point{});
  EXPECT_EQ(*s.stop, time_point(std::chrono::seconds(1)));
  EXPECT_EQ(*s.base_step, duration(10'000'000));
  EXPECT_EQ(s.algorithm, algorithm_kind::gauss_seidel);
  ASSERT_EQ(s.components.size(), 3u);
  EXPECT_EQ(s.components[1].name, "amp");
  EXPECT_EQ(s.components[1].step_multiple, 2);
  EXPECT_EQ(s.components[0].parameters[1].value, "a \"quoted\" label");
  EXPECT_EQ(s.components[0].parameters[1].where.line, 7);
  EXPECT_EQ(s.components[2].fmu, "../elsewhere/sink.fmu");
  ASSERT_EQ(s.connections.size(), 3u);
  EXPECT_TRUE(s.connections[2].delayed);
  EXPECT_EQ(s.connections[0].where.str(), (k_data / "chain.xml").string() + ":13");
  EXPECT_EQ(s.record.file, "out/chain.csv");
  EXPECT_EQ(*s.record.interval, duration(20'000'000));
  EXPECT_EQ(s.record.signals, (std::vector<std::string>{"amp.*", "sink.u"}));
}

TEST(cosim_system_xml, writes_xml_that_reads_back_the_same) {
  auto s = parse_system_file(k_data / "chain.xml");
  s.algorithm = algorithm_kind::jacobi;
  const auto back = parse_system_text(to_xml(s, false), k_data / "copy.xml");
  EXPECT_EQ(back.name, s.name);
  EXPECT_EQ(back.stop, s.stop);
  EXPECT_EQ(back.base_step, s.base_step);
  EXPECT_EQ(back.algorithm, algorithm_kind::jacobi);
  ASSERT_EQ(back.components.size(), 3u);
  EXPECT_EQ(back.components[0].parameters[1].value, "a \"quoted\" label");
  EXPECT_EQ(back.components[1].step_multiple, 2);
  EXPECT_EQ(back.connections[1].from, "src.vec[*]");
  EXPECT_TRUE(back.connections[2].delayed);
  EXPECT_EQ(back.record.signals, s.record.signals);
  // with absolute paths, a relative FMU path is resolved against the original folder
  const auto abs = parse_system_text(to_xml(s, true), "/nowhere/copy.xml");
  EXPECT_EQ(abs.components[2].fmu, (k_data.parent_path() / "elsewhere" / "sink.fmu").string());
  EXPECT_EQ(abs.components[0].fmu, "mock");
}

TEST(cosim_system_xml, malformed_xml_names_file_and_line) {
  try {
    parse_system_file(k_data / "malformed.xml");
    FAIL();
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr((k_data / "malformed.xml").string() +
                                    ":5: malformed XML: mismatched element (XMLElement "
                                    "name=parameter)"));
  }
}

TEST(cosim_system_xml, reads_and_writes_the_model_exchange_settings) {
  const auto s = parse(
      "<system>\n<component name='a' fmu='m' kind='model-exchange' solver='cvode' "
      "method='adams' rtol='1e-8' atol='1e-10' max_step='0.5'/>\n"
      "<component name='b' fmu='m' solver='euler' max_step='0.001'/>\n"
      "<component name='c' fmu='m' kind='co-simulation'/>\n<component name='d' fmu='m'/>\n"
      "</system>");
  using me = model_exchange_options;
  ASSERT_EQ(s.components.size(), 4u);
  for (const auto& back : {s, parse_system_text(to_xml(s, false), "t/copy.xml")}) {
    const auto& a = back.components[0];
    EXPECT_EQ(a.kind, "model-exchange");
    ASSERT_TRUE(a.model_exchange);
    EXPECT_EQ(a.model_exchange->solver, me::solver_kind::cvode);
    EXPECT_EQ(a.model_exchange->method, me::method_kind::adams);
    EXPECT_EQ(a.model_exchange->rtol, 1e-8);
    EXPECT_EQ(a.model_exchange->atol, 1e-10);
    EXPECT_EQ(a.model_exchange->max_step, 0.5);
    const auto& b = back.components[1];
    EXPECT_EQ(b.kind, "");  // decided by the FMU: an ME-only FMU needs no kind
    ASSERT_TRUE(b.model_exchange);
    EXPECT_EQ(b.model_exchange->solver, me::solver_kind::euler);
    EXPECT_EQ(b.model_exchange->max_step, 0.001);
    EXPECT_FALSE(b.model_exchange->rtol);
    EXPECT_EQ(back.components[2].kind, "co-simulation");
    EXPECT_FALSE(back.components[2].model_exchange);
    EXPECT_FALSE(back.components[3].model_exchange);
  }
}

TEST(cosim_system_xml, invalid_model_exchange_settings_name_the_line) {
  auto error_of = [](const std::string& attributes) {
    try {
      parse_system_text("<system>\n<component name='a' fmu='m' " + attributes + "/>\n</system>",
                        "t/test.xml");
    } catch (const validation_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("kind='co-simulation' solver='cvode'"),
            "t/test.xml:2: solver, method, rtol, atol and max_step apply to "
            "kind=\"model-exchange\" only (a Co-Simulation FMU integrates itself)");
  EXPECT_EQ(error_of("solver='euler'"),
            "t/test.xml:2: solver=\"euler\" needs max_step (its fixed step in seconds)");
  EXPECT_EQ(error_of("rtol='0'"), "t/test.xml:2: rtol=\"0\" must be > 0");
  EXPECT_EQ(error_of("atol='-1e-6'"), "t/test.xml:2: atol=\"-1e-6\" must be > 0");
  EXPECT_EQ(error_of("rtol='nan'"), "t/test.xml:2: rtol=\"nan\" is not a finite number");
  EXPECT_EQ(error_of("kind='me'"),
            "t/test.xml:2: kind=\"me\" is not co-simulation or model-exchange");
  EXPECT_EQ(error_of("solver='rk4'"), "t/test.xml:2: solver=\"rk4\" is not cvode or euler");
  EXPECT_EQ(error_of("method='gear'"), "t/test.xml:2: method=\"gear\" is not bdf or adams");
  EXPECT_EQ(error_of("solver='euler' max_step='0.1' method='bdf'"),
            "t/test.xml:2: method applies to solver=\"cvode\" only");
  EXPECT_EQ(error_of("kind='model-exchange' solver='euler' max_step='0.1'"), "no error");
}

TEST(cosim_system_xml, strict_syntax_errors_name_the_line) {
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m' colour='red'/>\n</system>"),
            "t/test.xml:2: unknown attribute 'colour' on <component>");
  // names and values go into result files: UTF-8 only, the line of the first bad byte named
  EXPECT_EQ(error_of("<system>\n<component name='a\xff' fmu='m'/>\n</system>"),
            "t/test.xml:2: not UTF-8 text (XML's encoding); save the file as UTF-8");
  EXPECT_EQ(error_of("<system>\n\n<component name='\xc0\xaf' fmu='m'/>\n</system>"),  // overlong
            "t/test.xml:3: not UTF-8 text (XML's encoding); save the file as UTF-8");
  EXPECT_EQ(error_of("<system name='gr\xc3\xbc\xc3\x9f'>\n<simulation stop='1' step='1'/>\n"
                     "<component name='a' fmu='m'/>\n</system>"),
            "no error");  // ü and ß are fine
  // children in the documented (and XSD) order
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<simulation stop='1'/>\n</system>"),
            "t/test.xml:3: <simulation> after <component> (line 2): the children of <system> come "
            "in the order simulation, agents, failover, component and replicate, connection, "
            "record");
  EXPECT_EQ(error_of("<system>\n<agents count='2'/>\n<simulation stop='1'/>\n"
                     "<component name='a' fmu='m'/>\n</system>"),
            "t/test.xml:3: <simulation> after <agents> (line 2): the children of <system> come "
            "in the order simulation, agents, failover, component and replicate, connection, "
            "record");
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<record/>\n"
                     "<connection from='a.y' to='a.u'/>\n</system>"),
            "t/test.xml:4: <connection> after <record> (line 3): the children of <system> come "
            "in the order simulation, agents, failover, component and replicate, connection, "
            "record");
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<connection from='a.y' to='a.u'/>\n"
                     "<component name='b' fmu='m'/>\n</system>"),
            "t/test.xml:4: <component> after <connection> (line 3): the children of <system> "
            "come in the order simulation, agents, failover, component and replicate, connection, "
            "record");
  EXPECT_EQ(error_of("<system>\n<replicate name='g' count='2'>\n<connection from='a.y' "
                     "to='a.u'/>\n<component name='a' fmu='m'/>\n</replicate>\n</system>"),
            "t/test.xml:4: <component> after <connection> (line 3): the children of <replicate> "
            "come in the order component, connection");
  // components and replica groups mix freely
  EXPECT_EQ(error_of("<system>\n<replicate name='g' count='2'>\n<component name='a' fmu='m'/>\n"
                     "</replicate>\n<component name='b' fmu='m'/>\n</system>"),
            "no error");
  // the run's own files are not a record file
  for (const std::string file : {"manifest.json", "./system.xml"}) {
    EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<record file='" + file +
                       "'/>\n</system>"),
              "t/test.xml:3: file=\"" + file +
                  "\" is a file the run writes itself (manifest.json, system.xml)");
  }
  // the name becomes the default output folder's name
  for (const std::string name : {"../../escape", "/tmp/x", "a\\b", "..", ""}) {
    EXPECT_EQ(error_of("<system name='" + name + "'>\n<component name='a' fmu='m'/>\n</system>"),
              "t/test.xml:1: system name \"" + name +
                  "\" must be a folder name: not empty, '.' or '..', and without '/', '\\' or "
                  "control characters")
        << name;
  }
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<wire/>\n</system>"),
            "t/test.xml:3: unknown element <wire> (expected simulation, component, connection, "
            "replicate, record, agents or failover)");
  EXPECT_EQ(error_of("<system>\n<simulation step='0.0000000001'/>\n<component name='a' fmu='m'/>"
                     "</system>"),
            "t/test.xml:2: step: '0.0000000001' is not a whole number of nanoseconds");
  EXPECT_EQ(error_of("<system>\n<simulation algorithm='newton'/>\n<component name='a' fmu='m'/>"
                     "</system>"),
            "t/test.xml:2: algorithm \"newton\" is not gauss-seidel or jacobi");
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m' step_multiple='0'/></system>"),
            "t/test.xml:2: step_multiple=\"0\" is not a positive integer");
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<component name='a' fmu='m'/>"
                     "</system>"),
            "t/test.xml:3: duplicate component name \"a\" (first at t/test.xml:2)");
  EXPECT_EQ(error_of("<system>\n<component name='a'/></system>"),
            "t/test.xml:2: <component> needs a fmu attribute");
  EXPECT_EQ(error_of("<system/>"), "t/test.xml:1: the system has no <component>");
  EXPECT_EQ(error_of("<model/>"), "t/test.xml:1: the root element must be <system>");
  EXPECT_EQ(error_of("<system>\n<component name='a' fmu='m'/>\n<record file='../x.csv'/>"
                     "</system>"),
            "t/test.xml:3: file=\"../x.csv\" must be a relative path inside the output folder");
}

TEST(cosim_system_xml, connections_carry_a_factor_and_an_offset) {
  const auto s = parse(
      "<system>\n<component name='a' fmu='m'/>\n"
      "<connection from='a.y' to='a.u' factor='2.5' offset='-1e-3'/>\n</system>");
  EXPECT_EQ(s.connections[0].factor, 2.5);
  EXPECT_EQ(s.connections[0].offset, -1e-3);
  const auto back = parse(to_xml(s));
  EXPECT_EQ(back.connections[0].factor, 2.5);
  EXPECT_EQ(back.connections[0].offset, -1e-3);
  // the defaults are not written
  EXPECT_EQ(to_xml(parse("<system>\n<component name='a' fmu='m'/>\n"
                         "<connection from='a.y' to='a.u'/>\n</system>"))
                .find("factor"),
            std::string::npos);
  try {
    parse(
        "<system>\n<component name='a' fmu='m'/>\n"
        "<connection from='a.y' to='a.u' factor='inf'/>\n</system>");
    ADD_FAILURE() << "factor inf read";
  } catch (const validation_error& e) {
    EXPECT_STREQ(e.what(), "t/test.xml:3: factor=\"inf\" is not a finite number");
  }
}

// names of nested SSP systems ("engine.pump") hold dots; a connection side or --set names the
// longest component that prefixes it
TEST(cosim_system_xml, component_names_may_hold_dots_outside_replica_groups) {
  auto s = parse(
      "<system>\n<simulation stop='1' step='1'/>\n<component name='engine' fmu='m'/>\n"
      "<component name='engine.pump' fmu='m'/>\n</system>");
  s.set("engine.pump.gain", "3");
  s.set("engine.gain", "4");
  EXPECT_EQ(s.find_component("engine.pump")->parameters.at(0).value, "3");
  EXPECT_EQ(s.find_component("engine")->parameters.at(0).value, "4");
  s.connect("engine.y", "engine.pump.u");
  const built_system b = build_system(s, mock_options());
  const auto& c = b.execution->connections().at(0);
  EXPECT_EQ(b.execution->component_at(c.to.component).name(), "engine.pump");
  EXPECT_EQ(b.execution->component_at(c.from.component).name(), "engine");
  EXPECT_THAT(error_of("<system>\n<component name='a..b' fmu='m'/>\n</system>"),
              HasSubstr("t/test.xml:2: component name \"a..b\" must not contain"));
  EXPECT_THAT(error_of("<system>\n<replicate name='g' count='2'>\n<component name='a.b' "
                       "fmu='m'/>\n</replicate>\n</system>"),
              HasSubstr("t/test.xml:3: component name \"a.b\" must not contain '.'"));
}

TEST(cosim_system_xml, agents_are_read_written_and_checked) {
  const system_structure s = parse(
      "<system>\n<agents count='4' mode='asynchronous'/>\n<component name='a' fmu='m'/>"
      "</system>");
  EXPECT_EQ(s.agents.count, 4);
  EXPECT_FALSE(s.agents.synchronous);
  EXPECT_EQ(s.agents.where.str(), "t/test.xml:2");
  const system_structure back = parse(to_xml(s, false));
  EXPECT_EQ(back.agents.count, 4);
  EXPECT_FALSE(back.agents.synchronous);
  EXPECT_TRUE(parse("<system><agents count='2'/><component name='a' fmu='m'/></system>")
                  .agents.synchronous);
  EXPECT_EQ(parse("<system><component name='a' fmu='m'/></system>").agents.count, 0);
  EXPECT_EQ(to_xml(parse("<system><component name='a' fmu='m'/></system>"), false).find("<agents"),
            std::string::npos);
  EXPECT_EQ(error_of("<system>\n<agents count='0'/><component name='a' fmu='m'/></system>"),
            "t/test.xml:2: count=\"0\" is not a positive integer");
  EXPECT_EQ(error_of("<system>\n<agents count='2' mode='eventually'/>"
                     "<component name='a' fmu='m'/></system>"),
            "t/test.xml:2: mode \"eventually\" is not synchronous or asynchronous");
  EXPECT_EQ(error_of("<system><agents count='2'/>\n<agents count='3'/>"
                     "<component name='a' fmu='m'/></system>"),
            "t/test.xml:2: more than one <agents>");
  EXPECT_EQ(error_of("<system>\n<agents/><component name='a' fmu='m'/></system>"),
            "t/test.xml:2: <agents> needs a count attribute");
}

TEST(cosim_system_xml, failover_is_read_written_and_checked) {
  const system_structure s = parse(
      "<system>\n<agents count='2'/>\n<failover standby='s1  s2' snapshot-every='25'/>"
      "<component name='a' fmu='m' worker='w1'/></system>");
  EXPECT_EQ(s.failover.standby, (std::vector<std::string>{"s1", "s2"}));
  EXPECT_EQ(s.failover.snapshot_every, 25);
  EXPECT_EQ(s.failover.where.str(), "t/test.xml:3");
  const system_structure back = parse(to_xml(s, false));
  EXPECT_EQ(back.failover.standby, s.failover.standby);
  EXPECT_EQ(back.failover.snapshot_every, 25);
  const system_structure plain = parse(
      "<system><failover standby='s1'/>"
      "<component name='a' fmu='m'/></system>");
  EXPECT_FALSE(plain.failover.snapshot_every.has_value());
  EXPECT_EQ(to_xml(plain, false).find("snapshot-every"), std::string::npos);
  EXPECT_EQ(
      to_xml(parse("<system><component name='a' fmu='m'/></system>"), false).find("<failover"),
      std::string::npos);
  EXPECT_EQ(error_of("<system>\n<failover standby=' '/><component name='a' fmu='m'/></system>"),
            "t/test.xml:2: standby=\"\" names no worker");
  EXPECT_EQ(error_of("<system>\n<failover/><component name='a' fmu='m'/></system>"),
            "t/test.xml:2: <failover> needs a standby attribute");
  EXPECT_EQ(error_of("<system>\n<failover standby='s1' snapshot-every='0'/>"
                     "<component name='a' fmu='m'/></system>"),
            "t/test.xml:2: snapshot-every=\"0\" is not a positive integer");
  EXPECT_EQ(error_of("<system><failover standby='s1'/>\n<failover standby='s2'/>"
                     "<component name='a' fmu='m'/></system>"),
            "t/test.xml:2: more than one <failover>");
  EXPECT_THAT(error_of("<system>\n<failover standby='s1' every='3'/>"
                       "<component name='a' fmu='m'/></system>"),
              ::testing::StartsWith("t/test.xml:2: unknown attribute 'every' on <failover>"));
}

TEST(cosim_system_builder, builds_the_chain_with_groups_parameters_and_decimation) {
  const auto s = parse_system_file(k_data / "chain.xml");
  auto built = build_system(s, mock_options());
  auto& algo = *built.execution;
  EXPECT_TRUE(algo.frozen());
  EXPECT_EQ(algo.connections().size(), 5u);  // 1 + 3 (group) + 1
  EXPECT_EQ(algo.step_multiple(1), 2);
  EXPECT_EQ(built.stop, time_point(std::chrono::seconds(1)));
  EXPECT_EQ(built.components[0].guid, "{mock-src}");
  const auto amp_y = algo.observe({1, *algo.component_at(1).model_description().index_of("y")});
  const auto amp_vin3 =
      algo.observe({1, *algo.component_at(1).model_description().index_of("vin[3]")});
  built.execution->simulate_until(time_point(std::chrono::milliseconds(20)));
  // src.y = 0 * u + 1.5 → amp.y = 3 * 1.5 + 0
  EXPECT_EQ(algo.real_value(amp_y), 4.5);
  EXPECT_EQ(algo.real_value(amp_vin3), 4.5);  // src.vec[3] = 1.5 * 3
}

// a placement that records what the builder asks of it
class recording_placement final : public placement_resolver {
 public:
  std::vector<std::string> calls;
  void prepare(const system_structure& system) noexcept override {
    std::string names;
    for (const auto& c : system.components) names += " " + c.name;
    calls.push_back("prepare" + names);
  }
  std::unique_ptr<component> create(const component_spec& spec,
                                    const placement_context& /*context*/) override {
    calls.push_back("create " + spec.name);
    return make_mock(spec);
  }
};

// a placement's slow start (joining a network) may overlap the creation of every component
TEST(cosim_system_builder, each_placement_is_prepared_with_the_whole_system_before_any_creation) {
  const auto s = parse(
      "<system><simulation stop='1' step='0.5'/><component name='a' fmu='m'/>"
      "<replicate name='g' count='2'><component name='b' fmu='m'/></replicate></system>");
  auto first = std::make_shared<recording_placement>();
  auto second = std::make_shared<recording_placement>();
  build_options o;
  o.placements = {first, second};
  o.log = quiet_log();
  build_system(s, o);
  // replicas expanded; the first placement takes every component, the second none
  EXPECT_EQ(first->calls, (std::vector<std::string>{"prepare a b[1] b[2]", "create a",
                                                    "create b[1]", "create b[2]"}));
  EXPECT_EQ(second->calls, (std::vector<std::string>{"prepare a b[1] b[2]"}));
}

TEST(cosim_system_builder, ranges_pair_in_order_and_sizes_must_match) {
  auto s = parse(
      "<system><simulation stop='1' step='0.5'/><component name='a' fmu='m'/>"
      "<component name='b' fmu='m'/>"
      "<connection from='a.vec[3:2]' to='b.vin[1:2]'/></system>");
  auto built = build_system(s, mock_options());
  const auto& conns = built.execution->connections();
  ASSERT_EQ(conns.size(), 2u);
  const auto& md = built.execution->component_at(0).model_description();
  EXPECT_EQ(md.variables[conns[0].from.variable].name, "vec[3]");
  EXPECT_EQ(md.variables[conns[0].to.variable].name, "vin[1]");
  EXPECT_EQ(md.variables[conns[1].from.variable].name, "vec[2]");

  s.connections[0].to = "b.vin[*]";
  EXPECT_THAT(build_error(s), HasSubstr("the source group has 2 variables, the target group 3"));
  s.connections[0].from = "a.vec[1:4]";
  EXPECT_THAT(build_error(s), HasSubstr("no variable 'vec[4]' (from range 'vec[1:4]')"));
}

TEST(cosim_system_builder, unknown_component_and_variable_name_file_and_line) {
  const auto s = parse_system_file(k_data / "unknown_variable.xml");
  EXPECT_EQ(build_error(s), (k_data / "unknown_variable.xml").string() +
                                ":7: connection a.nope -> b.u: a: no variable 'nope'");
  auto t = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='m'/>\n"
      "<connection from='x.y' to='a.u'/></system>");
  EXPECT_EQ(build_error(t), "t/test.xml:4: connection x.y -> a.u: unknown component 'x'");
}

TEST(cosim_system_builder, type_mismatch_and_double_driven_inputs_name_lines) {
  auto s = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='m'/>\n"
      "<component name='b' fmu='m'/>\n<connection from='a.n' to='b.u'/></system>");
  EXPECT_THAT(build_error(s), HasSubstr("t/test.xml:5: connection a.n -> b.u: type mismatch, a.n "
                                        "is Integer but b.u is Real"));
  auto d = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='m'/>\n"
      "<component name='b' fmu='m'/>\n<connection from='a.y' to='b.u'/>\n"
      "<connection from='a.z' to='b.u'/></system>");
  EXPECT_EQ(build_error(d),
            "t/test.xml:6: input b.u is driven twice: by a.y (t/test.xml:5) and by a.z");
}

TEST(cosim_system_builder, algebraic_loop_from_xml_spells_out_the_cycle) {
  const auto s = parse_system_file(k_data / "loop.xml");
  const std::string file = (k_data / "loop.xml").string();
  const std::string message = build_error(s);
  EXPECT_THAT(message, HasSubstr("a.y -> b.u => b.y -> a.u => a.y"));
  EXPECT_THAT(message, HasSubstr(file + ":6, " + file + ":7"));
  auto delayed = s;
  delayed.connections[1].delayed = true;
  EXPECT_EQ(build_error(delayed), "no error");
}

TEST(cosim_system_builder, parameter_errors_name_file_and_line) {
  auto s = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='m'>\n"
      "<parameter name='gain' value='abc'/>\n</component></system>");
  EXPECT_EQ(build_error(s), "t/test.xml:4: a.gain: 'abc' is not a Real");
  s.components[0].parameters[0] = {"missing", "1", {"t/test.xml", 4}};
  EXPECT_EQ(build_error(s), "t/test.xml:4: component 'a' has no variable 'missing'");
  s.components[0].parameters[0] = {"y", "1", {"t/test.xml", 4}};
  EXPECT_THAT(build_error(s), HasSubstr("t/test.xml:4: a.y is output; only parameters and inputs"));
}

TEST(cosim_system_builder, run_length_must_be_whole_base_steps) {
  auto s = parse(
      "<system><simulation stop='1.25' step='0.5'/><component name='a' fmu='m'/>"
      "</system>");
  EXPECT_THAT(build_error(s), HasSubstr("run length 1.25 s is not a whole number of base steps"));
  s.stop.reset();
  EXPECT_THAT(build_error(s), HasSubstr("no stop time"));
}

TEST(cosim_system_builder, missing_fmu_files_are_reported_with_the_search_path) {
  auto s = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='nope'/>\n"
      "<component name='b' fmu='dir/none.fmu'/></system>");
  build_options o;
  o.log = quiet_log();
  o.fmu_search_path = {"/no/such/dir"};
  try {
    build_system(s, o);
    FAIL();
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("t/test.xml:3: component 'a': bundled FMU 'nope' not found"));
    EXPECT_THAT(e.what(), HasSubstr("/no/such/dir"));
  }
  s.components.erase(s.components.begin());
  try {
    build_system(s, o);
    FAIL();
  } catch (const validation_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "t/test.xml:4: component 'b': FMU file t/dir/none.fmu not found");
  }
}

TEST(cosim_system_builder, one_rule_tells_bundled_names_from_paths) {
  EXPECT_TRUE(is_bundled_fmu_name("gait"));
  EXPECT_FALSE(is_bundled_fmu_name(""));
  EXPECT_FALSE(is_bundled_fmu_name(".fmu"));
  EXPECT_FALSE(is_bundled_fmu_name("gait.fmu"));
  EXPECT_FALSE(is_bundled_fmu_name("fmus/gait"));
  // the XML writer follows the same rule: a path is made absolute, a name stays a name
  system_structure s;
  s.base_dir = "/models";
  s.add_component("a", "gait");
  s.add_component("b", ".fmu");
  const system_structure back = parse_system_text(to_xml(s), "/models/x.xml");
  EXPECT_EQ(back.components[0].fmu, "gait");
  EXPECT_EQ(back.components[1].fmu, "/models/.fmu");
}

TEST(cosim_system_builder, bundled_names_and_the_search_path) {
  EXPECT_TRUE(is_bundled_fmu_name("gait"));
  EXPECT_FALSE(is_bundled_fmu_name("gait.fmu"));
  EXPECT_FALSE(is_bundled_fmu_name("x/gait"));
  ::setenv("STRIDE_FMU_PATH", "/a:/b", 1);
  const auto path = default_fmu_search_path();
  ::unsetenv("STRIDE_FMU_PATH");
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path[0], "/a");
  EXPECT_EQ(path[1], "/b");
  EXPECT_EQ(path.back(), fs::path(STRIDE_FMU_DIR));
}

TEST(cosim_system_api, builds_the_same_system_as_the_xml) {
  system_structure s;
  s.name = "api";
  s.stop = time_point(std::chrono::seconds(1));
  s.base_step = duration(10'000'000);
  s.add_component("src", "mock");
  s.add_component("amp", "mock", 2);
  s.connect("src.y", "amp.u");
  s.set("src.level", "1.5");
  s.set("amp.gain", "3");
  apply_override(s, "amp.gain=4");
  EXPECT_EQ(s.components[1].parameters[0].value, "4");
  EXPECT_THROW(apply_override(s, "amp.gain"), validation_error);
  EXPECT_THROW(apply_override(s, "nobody.gain=1"), validation_error);
  // values end up in system.xml and manifest.json: one line of UTF-8, or refused by name
  for (const std::string bad : {"amp.label=\xff\xfe", "amp.label=a\nb", "amp.label=\xc0\xaf"}) {
    try {
      apply_override(s, bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const validation_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("is not one line of UTF-8 text"));
      EXPECT_THAT(e.what(), HasSubstr("amp.label="));
    }
  }
  apply_override(s, "amp.gain=4");  // the refused ones changed nothing
  EXPECT_EQ(s.components[1].parameters.size(), 1u);
  auto built = build_system(s, mock_options());
  auto& algo = *built.execution;
  const auto y = algo.observe({1, *algo.component_at(1).model_description().index_of("y")});
  built.execution->simulate_until(time_point(std::chrono::milliseconds(20)));
  EXPECT_EQ(algo.real_value(y), 6.0);
}

TEST(cosim_run, writes_results_system_copy_and_manifest) {
  temp_dir dir("stride-run-test-");
  auto s = parse_system_file(k_data / "chain.xml");
  run_options o;
  o.output_dir = dir.path() / "out";
  o.overrides = {"amp.gain=2"};
  o.stop = time_point(std::chrono::milliseconds(100));
  o.progress = false;
  o.build = mock_options();
  const auto report = run_system(s, o);
  EXPECT_EQ(report.result.steps, 10);
  EXPECT_EQ(report.results_file, o.output_dir / "out/chain.csv");
  std::ifstream csv(report.results_file);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "time,amp.u,amp.y,amp.z,amp.vec[1],amp.vin[1],amp.vec[2],amp.vin[2],"
            "amp.vec[3],amp.vin[3],amp.n,amp.k,sink.u");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 6);  // 0, 0.02, ..., 0.1
  const auto copy = parse_system_file(o.output_dir / "system.xml");
  EXPECT_EQ(copy.components[1].parameters[0].value, "2");
  EXPECT_EQ(*copy.stop, time_point(std::chrono::milliseconds(100)));
  std::ifstream manifest(report.manifest_file);
  std::stringstream text;
  text << manifest.rdbuf();
  EXPECT_THAT(text.str(), HasSubstr("\"status\": \"ok\""));
  EXPECT_THAT(text.str(), HasSubstr("\"guid\": \"{mock-amp}\""));
  EXPECT_THAT(text.str(), HasSubstr("\"stride_version\": \"" + std::string(version()) + "\""));
  EXPECT_THAT(text.str(), HasSubstr("\"real_time_factor\": "));
}

TEST(cosim_run, record_signal_without_match_names_the_line) {
  temp_dir dir("stride-run-test-");
  auto s = parse(
      "<system>\n<simulation stop='1' step='0.5'/>\n<component name='a' fmu='m'/>\n"
      "<record>\n<signal name='a.nothing*'/>\n</record></system>");
  run_options o;
  o.output_dir = dir.path();
  o.progress = false;
  o.build = mock_options();
  try {
    run_system(s, o);
    FAIL();
  } catch (const validation_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "t/test.xml:5: record signal 'a.nothing*' matches no variable");
  }
}

}  // namespace
}  // namespace stride::cosim
