// The SSP 1.0 exporter without running anything (FMUs that hold only their
// modelDescription.xml): the archive passes Stride's own SSP importer, which checks every
// element against the SSP 1.0 schema's order, and reads back as the system exported; the SSD
// and SSV say it in SSP terms; the same system gives the same bytes, also when re-exported
// from the archive; every refusal names the file, the line and what cannot be exported.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>

#include "export_fixture.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::summary;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

class ssp_export : public test::export_fixture {
 protected:
  // the entries of the archive by name
  std::map<std::string, std::string> entries(const fs::path& archive) const {
    std::map<std::string, std::string> out;
    for (auto& e : test::read_zip(archive)) out[e.name] = std::move(e.content);
    return out;
  }

  std::string refusal(const system_structure& s) const {
    return export_fixture::refusal(export_ssp, s, "refused.ssp");
  }
};

const std::vector<std::string> k_read_back = {
    "start 0.5 stop 2 step 0.01 jacobi",
    R"(component a stride_test.fmu x1 gain=3 enable=true label=a & <b> "c" n=7)",
    "component b stride_test.fmu x1",
    "connection a.y -> b.u * 2 + 1",
    "connection a.counter -> b.n delayed",
    "connection a.echo -> b.suffix",
    "connection a.vec_out[1] -> b.vec_in[1]",
    "connection a.vec_out[2] -> b.vec_in[2]",
    "connection a.vec_out[3] -> b.vec_in[3]"};

TEST_F(ssp_export, the_archive_reads_back_as_the_system_exported) {
  const fs::path archive = scratch.path() / "pair.ssp";
  const export_report report = export_ssp(system_xml(), archive, options);
  EXPECT_EQ(report.target, archive);
  EXPECT_THAT(report.files, ElementsAre("SystemStructure.ssd", "resources/parameters.ssv",
                                        "resources/stride_test.fmu"));
  std::vector<std::string> warnings;
  const system_structure back =
      load_system_file(archive, [&](log_level, std::string_view, std::string_view,
                                    std::string_view message) { warnings.emplace_back(message); });
  EXPECT_EQ(summary(back), k_read_back);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(back.name, "pair");
  EXPECT_EQ(back.description, "two of stride_test");
}

TEST_F(ssp_export, the_ssd_and_ssv_say_it_in_ssp_terms) {
  const fs::path archive = scratch.path() / "pair.ssp";
  export_ssp(system_xml(), archive, options);
  auto files = entries(archive);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files["resources/stride_test.fmu"],
            test::file_text(scratch.path() / "fmus" / "stride_test.fmu"));
  const std::string& ssd = files["SystemStructure.ssd"];
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:Component name="a" source="resources/stride_test.fmu">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:Connector name="y" kind="output">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:Connector name="suffix" kind="input">)"));
  EXPECT_THAT(ssd, HasSubstr("<ssc:String/>"));
  // only connected variables are connectors: a's enable has a value, no connection
  EXPECT_THAT(ssd, Not(HasSubstr(R"(name="enable")")));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssc:LinearTransformation factor="2" offset="1"/>)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssc:Annotation type="org.stride-sim.connection">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Connection delay="true"/>)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:ParameterBinding source="resources/parameters.ssv"/>)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:DefaultExperiment startTime="0.5" stopTime="2">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Simulation step="0.01" algorithm="jacobi"/>)"));
  const std::string& ssv = files["resources/parameters.ssv"];
  EXPECT_THAT(ssv, HasSubstr(R"(<ssv:Parameter name="a.gain">)"));
  EXPECT_THAT(ssv, HasSubstr(R"(<ssv:Real value="3"/>)"));
  EXPECT_THAT(ssv, HasSubstr(R"(<ssv:Boolean value="true"/>)"));
  EXPECT_THAT(ssv, HasSubstr(R"(<ssv:Integer value="7"/>)"));
  EXPECT_THAT(ssv, HasSubstr(R"(<ssv:String value="a &amp; &lt;b&gt; &quot;c&quot;"/>)"));
}

TEST_F(ssp_export, the_same_system_gives_the_same_bytes) {
  // archives named after the system: the importer names the system after its archive
  const auto in = [&](const std::string& folder) {
    fs::create_directories(scratch.path() / folder);
    return scratch.path() / folder / "pair.ssp";
  };
  const fs::path one = in("one");
  export_ssp(system_xml(), one, options);
  // another day for the FMU file: the archive keeps no file time
  const fs::path fmu = scratch.path() / "fmus" / "stride_test.fmu";
  fs::last_write_time(fmu, fs::last_write_time(fmu) - std::chrono::hours(30));
  const fs::path two = in("two");
  export_ssp(system_xml(), two, options);
  EXPECT_EQ(test::file_text(two), test::file_text(one));
  // the archive exported again, from its own extracted copy
  const fs::path three = in("three");
  export_ssp(load_system_file(one), three, options);
  EXPECT_EQ(test::file_text(three), test::file_text(one));
}

TEST_F(ssp_export, a_variable_given_twice_keeps_its_first_place_and_last_value) {
  system_structure s = in_code();
  auto& a = *s.find_component("a");
  a.parameters = {{"gain", "1", {}}, {"offset", "0.25", {}}, {"gain", "2", {}}};
  const fs::path archive = scratch.path() / "twice.ssp";
  export_ssp(s, archive, options);
  EXPECT_EQ(summary(load_system_file(archive)).at(1),
            "component a stride_test.fmu x1 gain=2 offset=0.25");
}

TEST_F(ssp_export, fmu_files_keep_their_names_percent_encoded_and_apart) {
  // a blank in a name, and two different files of one name
  fs::copy_file(scratch.path() / "fmus" / "stride_test.fmu", scratch.path() / "my model.fmu");
  test::write_fake_fmu(scratch.path() / "other" / "stride_test.fmu",
                       {{"y", "output", "Real", ""}, {"u", "input", "Real", ""}});
  system_structure s = in_code();
  s.add_component("c", "my model.fmu");
  s.add_component("d", "other/stride_test.fmu");
  const fs::path archive = scratch.path() / "names.ssp";
  EXPECT_THAT(export_ssp(s, archive, options).files,
              ElementsAre("SystemStructure.ssd", "resources/my model.fmu",
                          "resources/stride_test-2.fmu", "resources/stride_test.fmu"));
  const std::string ssd = entries(archive)["SystemStructure.ssd"];
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:Component name="c" source="resources/my%20model.fmu"/>)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<ssd:Component name="d" source="resources/stride_test-2.fmu"/>)"));
  const system_structure back = load_system_file(archive);
  EXPECT_EQ(fs::path(back.components.at(2).fmu).filename(), "my model.fmu");
  EXPECT_EQ(fs::path(back.components.at(3).fmu).filename(), "stride_test-2.fmu");
  EXPECT_EQ(fs::path(back.components.at(0).fmu).filename(), "stride_test.fmu");
}

TEST_F(ssp_export, an_existing_archive_is_replaced_only_when_asked) {
  const fs::path archive = write("pair.ssp", "not yet an archive");
  try {
    export_ssp(system_xml(), archive, options);
    ADD_FAILURE() << "replaced";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(archive.string() + ": exists (give --force to replace it)"));
  }
  EXPECT_EQ(test::file_text(archive), "not yet an archive");
  options.overwrite = true;
  export_ssp(system_xml(), archive, options);
  EXPECT_EQ(summary(load_system_file(archive)), k_read_back);
  const auto refused = [&](const fs::path& target) {
    try {
      export_ssp(system_xml(), target, options);
      ADD_FAILURE() << "exported";
    } catch (const validation_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(refused(scratch.path() / "pair.zip"),
              HasSubstr("pair.zip: an SSP archive's name ends in .ssp"));
  fs::create_directory(scratch.path() / "folder.ssp");
  EXPECT_THAT(refused(scratch.path() / "folder.ssp"),
              HasSubstr("folder.ssp: exists and is not a file"));
  EXPECT_THAT(refused(scratch.path() / "missing" / "pair.ssp"),
              HasSubstr("missing/pair.ssp: cannot write the archive"));
}

// the system XML with `extra` on a line of its own before `before`
std::string with(const std::string& extra, const std::string& before = "</system>",
                 std::string text = test::k_export_system) {
  text.insert(text.find(before), extra + "\n");
  return text;
}

TEST_F(ssp_export, replica_copies_recording_workers_agents_and_standbys_read_back_as_written) {
  // a group of two copies of c, fed by a through a copy range, recorded by signal patterns into
  // another file
  const std::string group = with(R"(<replicate name="w" count="2">
  <component name="c" fmu="fmus/stride_test.fmu" worker="far${copy}">
    <parameter name="gain" value="${copy:0.5;1e3}"/>
    <parameter name="n" value="${agent}"/>
  </component>
  <connection from="c.y" to="c.u" delay="true"/></replicate>)",
                                 "  <connection");
  system_structure s = system_xml(with(R"(<connection from="a.vec_out[1:2]" to="c[*].gain"/>
<record enabled="false" interval="0.02" file="out/r.csv"><signal name="c[*].y"/></record>)",
                                       "</system>", group));
  s.agents = {3, false, {"w1", "w2"}, {}};
  s.failover = {{"s1", "s2"}, 25, {}};
  const fs::path archive = scratch.path() / "pair.ssp";
  export_ssp(s, archive, options);
  system_structure back = load_system_file(archive);
  const std::vector<std::string> copies = {"component c[1] stride_test.fmu x1 n=${agent} gain=0.5",
                                           "component c[2] stride_test.fmu x1 n=${agent} gain=1000",
                                           "connection c[1].y -> c[1].u delayed",
                                           "connection a.vec_out[1] -> c[1].gain",
                                           "connection c[2].y -> c[2].u delayed",
                                           "connection a.vec_out[2] -> c[2].gain"};
  for (const auto& line : copies) EXPECT_THAT(summary(back), testing::Contains(line));
  EXPECT_TRUE(back.groups.empty());  // expanded: every copy an SSP component of its own
  EXPECT_EQ(back.find_component("c[2]")->worker, "far2");
  EXPECT_EQ(back.find_component("a")->worker, "");
  EXPECT_FALSE(back.record.enabled);
  EXPECT_EQ(back.record.interval, std::chrono::milliseconds(20));
  EXPECT_EQ(back.record.file, "out/r.csv");
  EXPECT_THAT(back.record.signals, ElementsAre("c[*].y"));
  EXPECT_EQ(back.agents.count, 3);
  EXPECT_FALSE(back.agents.synchronous);
  EXPECT_THAT(back.agents.workers, ElementsAre("w1", "w2"));
  EXPECT_THAT(back.failover.standby, ElementsAre("s1", "s2"));
  EXPECT_EQ(back.failover.snapshot_every, 25);
  const std::string ssd = entries(archive).at("SystemStructure.ssd");
  EXPECT_THAT(ssd, HasSubstr(R"(<ssc:Annotation type="org.stride-sim.component">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Component worker="far1">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Value name="n" value="${agent}"/>)"));
  EXPECT_THAT(ssd,
              HasSubstr(R"(<stride:Record enabled="false" interval="0.02" file="out/r.csv">)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Agents count="3" mode="asynchronous" workers="w1 w2"/>)"));
  // the export of what was read is the same archive
  fs::create_directories(scratch.path() / "again");
  export_ssp(back, scratch.path() / "again" / "pair.ssp", options);
  EXPECT_EQ(test::file_text(scratch.path() / "again" / "pair.ssp"), test::file_text(archive));
}

TEST_F(ssp_export, the_step_is_also_written_as_libcosim_and_omsimulator_read_it) {
  const fs::path archive = scratch.path() / "pair.ssp";
  export_ssp(system_xml(), archive, options);
  std::string ssd = entries(archive).at("SystemStructure.ssd");
  EXPECT_THAT(ssd, HasSubstr(R"(<osp:FixedStepAlgorithm baseStepSize="0.01"/>)"));
  EXPECT_THAT(ssd, HasSubstr(R"(<oms:FixedStepMaster description="oms-ma" stepSize="0.01"/>)"));
  // Stride's own annotation decides when it reads its export back ...
  EXPECT_THAT(load_system_file(archive).notes.stepping_from, HasSubstr("Stride's annotation"));
  // ... without it, the two tools' annotations give the step (they agree) and their algorithm
  const auto begin = ssd.rfind("<ssc:Annotation", ssd.find("org.stride-sim.system"));
  const auto end = ssd.find("</ssc:Annotation>", begin) + std::string("</ssc:Annotation>").size();
  ssd.erase(begin, end - begin);
  fs::create_directories(scratch.path() / "tools");
  std::ofstream(scratch.path() / "tools" / "SystemStructure.ssd") << ssd;
  for (const auto& e : test::read_zip(archive)) {
    if (e.name.starts_with("resources/")) {
      fs::create_directories(scratch.path() / "tools" / "resources");
      std::ofstream(scratch.path() / "tools" / e.name, std::ios::binary) << e.content;
    }
  }
  const system_structure back = load_system_file(scratch.path() / "tools");
  EXPECT_EQ(back.base_step, std::chrono::milliseconds(10));
  EXPECT_EQ(back.algorithm, algorithm_kind::jacobi);
  EXPECT_THAT(back.notes.stepping_from, HasSubstr("OMSimulator's annotation (org.openmodelica)"));
  EXPECT_THAT(back.notes.stepping_from, HasSubstr("and libcosim's annotation"));
}

TEST_F(ssp_export, model_exchange_components_keep_their_kind_and_integrator) {
  test::write_fake_fmu(scratch.path() / "fmus" / "me.fmu", test::stride_test_variables(), false);
  system_structure s = in_code();
  component_spec& b = *s.find_component("b");
  b.fmu = "fmus/me.fmu";
  b.kind = "model-exchange";
  model_exchange_options o;
  o.method = model_exchange_options::method_kind::adams;
  o.rtol = 1e-8;
  o.max_step = 0.5;
  b.model_exchange = o;
  s.find_component("a")->kind = "co-simulation";
  const fs::path archive = scratch.path() / "me.ssp";
  export_ssp(s, archive, options);
  const std::string ssd = entries(archive).at("SystemStructure.ssd");
  EXPECT_THAT(ssd, HasSubstr(R"(implementation="ModelExchange")"));
  EXPECT_THAT(ssd, HasSubstr(R"(<stride:Component solver="cvode" method="adams" rtol="1e-08" )"
                             R"(max_step="0.5"/>)"));
  const system_structure back = load_system_file(archive);
  EXPECT_EQ(back.components.at(0).kind, "co-simulation");
  const component_spec& b_back = back.components.at(1);
  EXPECT_EQ(b_back.kind, "model-exchange");
  ASSERT_TRUE(b_back.model_exchange.has_value());
  EXPECT_EQ(b_back.model_exchange->method, model_exchange_options::method_kind::adams);
  EXPECT_EQ(b_back.model_exchange->rtol, 1e-8);
  EXPECT_EQ(b_back.model_exchange->atol, std::nullopt);
  EXPECT_EQ(b_back.model_exchange->max_step, 0.5);
}

TEST_F(ssp_export, a_step_multiple_is_kept_in_the_component_annotation) {
  system_structure s = in_code();
  s.find_component("b")->step_multiple = 3;
  const fs::path archive = scratch.path() / "multiple.ssp";
  export_ssp(s, archive, options);
  EXPECT_THAT(entries(archive).at("SystemStructure.ssd"),
              HasSubstr(R"(<stride:Component step_multiple="3"/>)"));
  const system_structure back = load_system_file(archive);
  EXPECT_EQ(back.components.at(0).step_multiple, 1);
  EXPECT_EQ(back.components.at(1).step_multiple, 3);
}

TEST_F(ssp_export, default_recording_writes_no_record_annotation) {
  const fs::path archive = scratch.path() / "pair.ssp";
  export_ssp(system_xml(), archive, options);
  EXPECT_THAT(entries(archive).at("SystemStructure.ssd"), Not(HasSubstr("stride:Record")));
  // the base step given as interval is kept as given: it reads back the same
  export_options replace = options;
  replace.overwrite = true;
  export_ssp(system_xml(with(R"(<record interval="0.01"/>)")), archive, replace);
  EXPECT_EQ(load_system_file(archive).record.interval, std::chrono::milliseconds(10));
}

TEST_F(ssp_export, what_the_system_xml_says_beyond_ssp_is_refused_naming_file_and_line) {
  const std::string file = (scratch.path() / "pair.xml").string();
  std::string real = test::k_export_system;
  real.replace(real.find(R"(value="3")"), 9, R"(value="three")");
  EXPECT_THAT(refusal(system_xml(real)),
              HasSubstr(file + ":5: cannot export to SSP: parameter 'a.gain': 'three' is not a "
                               "Real"));
  std::string unknown = test::k_export_system;
  unknown.replace(unknown.find(R"(name="gain")"), 11, R"(name="gian")");
  EXPECT_THAT(refusal(system_xml(unknown)),
              HasSubstr(file + ":5: cannot export to SSP: parameter 'a.gian': no such variable"));
}

TEST_F(ssp_export, components_that_ssp_cannot_hold_are_refused) {
  system_structure s = in_code();
  s = in_code();
  s.add_component("engine.pump", "fmus/stride_test.fmu");
  EXPECT_THAT(refusal(s), HasSubstr("component 'engine.pump': the name \"engine.pump\" holds a "
                                    "'.'"));
  s = in_code();
  s.components.clear();
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to SSP: the system has no component"));
}

TEST_F(ssp_export, connections_other_than_output_to_input_or_parameter_are_refused) {
  const auto refused = [&](const std::string& from, const std::string& to) {
    system_structure s = in_code();
    s.connect(from, to);
    return refusal(s);
  };
  EXPECT_THAT(refused("a.u", "b.u"),
              HasSubstr("connection a.u -> b.u: its source u is input, not an output"));
  EXPECT_THAT(refused("a.y", "b.y"),
              HasSubstr("connection a.y -> b.y: its target y is output, not an input or "
                        "parameter"));
  EXPECT_THAT(refused("c.y", "b.u"), HasSubstr("connection c.y -> b.u: 'c.y' names no component"));
  EXPECT_THAT(refused("a.vec_out[*]", "b.vec_in[1:2]"), HasSubstr("3 sources for 2 targets"));
  EXPECT_THAT(refused("a.y", "b.w"),
              HasSubstr("cannot export to SSP: connection a.y -> b.w: 'b.w': no variable 'w'"));
  system_structure s = in_code();
  s.connect("a.y", "b.u");
  s.connect("a.integral", "b.u");
  EXPECT_THAT(refusal(s), HasSubstr("b.u is the target of two connections"));
  // a parameter may be a connection's target
  s = in_code();
  s.connect("a.y", "b.gain");
  EXPECT_NO_THROW(export_ssp(s, scratch.path() / "gain.ssp", options));
}

}  // namespace
}  // namespace stride::cosim
