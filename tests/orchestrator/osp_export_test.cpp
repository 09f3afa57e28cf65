// The OSP exporter without running anything (FMUs that hold only their modelDescription.xml):
// the folder reads back through the OSP importer as the system exported, step multiples
// included; the same system gives the same files; what OSP cannot say (delays, factors,
// Jacobi) is refused naming it, and a non-empty folder is written into only when asked.
#include "export_fixture.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::summary;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// the export fixture's pair without what OSP cannot say, b stepping every 2 base steps
std::string osp_system() {
  std::string text = test::k_export_system;
  const auto cut = [&](const std::string& from, const std::string& what) {
    text.replace(text.find(from), from.size(), what);
  };
  cut(R"( algorithm="jacobi")", "");
  cut(R"( factor="2" offset="1")", "");
  cut(R"( delay="true")", "");
  cut(R"(<component name="b" fmu="fmus/stride_test.fmu"/>)",
      R"(<component name="b" fmu="fmus/stride_test.fmu" step_multiple="2"/>)");
  return text;
}

class osp_export : public test::export_fixture {
 protected:
  std::string refusal(const system_structure& s) const {
    return export_fixture::refusal(export_osp, s, "refused");
  }
};

TEST_F(osp_export, the_folder_reads_back_through_the_osp_importer) {
  const fs::path folder = scratch.path() / "osp";
  const export_report report = export_osp(system_xml(osp_system()), folder, options);
  EXPECT_THAT(report.files, ElementsAre("OspSystemStructure.xml", "stride_test.fmu"));
  EXPECT_EQ(test::file_text(folder / "stride_test.fmu"),
            test::file_text(scratch.path() / "fmus" / "stride_test.fmu"));
  EXPECT_EQ(
      summary(load_system_file(folder)),
      (std::vector<std::string>{
          "start 0.5 stop 2 step 0.01 gauss-seidel",
          R"(component a stride_test.fmu x1 gain=3 enable=true label=a & <b> "c" n=7)",
          "component b stride_test.fmu x2", "connection a.y -> b.u", "connection a.counter -> b.n",
          "connection a.echo -> b.suffix", "connection a.vec_out[1] -> b.vec_in[1]",
          "connection a.vec_out[2] -> b.vec_in[2]", "connection a.vec_out[3] -> b.vec_in[3]"}));
  const std::string xml = test::file_text(folder / "OspSystemStructure.xml");
  EXPECT_THAT(xml, HasSubstr(R"(<Simulator name="b" source="stride_test.fmu" stepSize="0.02"/>)"));
  EXPECT_THAT(xml, HasSubstr("<BaseStepSize>0.01</BaseStepSize>"));
  EXPECT_THAT(xml, HasSubstr(R"(<Variable simulator="a" name="y"/>)"));
}

TEST_F(osp_export, the_same_system_gives_the_same_files) {
  const fs::path one = scratch.path() / "one";
  export_osp(system_xml(osp_system()), one, options);
  const std::string xml = test::file_text(one / "OspSystemStructure.xml");
  const fs::path two = scratch.path() / "two";
  export_osp(load_system_file(one), two, options);
  EXPECT_EQ(test::file_text(two / "OspSystemStructure.xml"), xml);
  // into itself, when asked: the same files again
  options.overwrite = true;
  export_osp(load_system_file(one), one, options);
  EXPECT_EQ(test::file_text(one / "OspSystemStructure.xml"), xml);
  EXPECT_EQ(test::file_text(one / "stride_test.fmu"),
            test::file_text(scratch.path() / "fmus" / "stride_test.fmu"));
}

TEST_F(osp_export, a_folder_that_is_not_empty_is_written_into_only_when_asked) {
  const fs::path folder = scratch.path() / "busy";
  write("busy/notes.txt", "mine");
  try {
    export_osp(system_xml(osp_system()), folder, options);
    ADD_FAILURE() << "written";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(folder.string() + ": a folder that is not empty (give --force "
                                                      "to write into it)"));
  }
  EXPECT_FALSE(fs::exists(folder / "OspSystemStructure.xml"));
  options.overwrite = true;
  export_osp(system_xml(osp_system()), folder, options);
  EXPECT_TRUE(fs::exists(folder / "OspSystemStructure.xml"));
  EXPECT_EQ(test::file_text(folder / "notes.txt"), "mine");
  try {
    export_osp(system_xml(osp_system()), folder / "notes.txt", options);
    ADD_FAILURE() << "written";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("notes.txt: exists and is not a folder"));
  }
  try {
    export_osp(system_xml(osp_system()), folder / "notes.txt" / "below", options);
    ADD_FAILURE() << "written";
  } catch (const validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("notes.txt/below: cannot create the folder"));
  }
}

TEST_F(osp_export, what_osp_cannot_say_is_refused_naming_it) {
  const std::string file = (scratch.path() / "pair.xml").string();
  std::string delayed = osp_system();
  delayed.replace(delayed.find(R"(to="b.n")"), 8, R"(to="b.n" delay="true")");
  EXPECT_THAT(refusal(system_xml(delayed)),
              HasSubstr(file + ":12: cannot export to OSP: the delayed connection a.counter -> "
                               "b.n (OSP has no delay; SSP export keeps it)"));
  std::string factor = osp_system();
  factor.replace(factor.find(R"(to="b.u")"), 8, R"(to="b.u" offset="1")");
  EXPECT_THAT(refusal(system_xml(factor)),
              HasSubstr(file + ":11: cannot export to OSP: the factor or offset of a.y -> b.u"));
  EXPECT_THAT(refusal(system_xml()), HasSubstr("cannot export to OSP: the jacobi algorithm"));
  // the checks both formats share speak of OSP here
  system_structure s = in_code();
  s.find_component("a")->worker = "far";
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: component 'a': runs on worker 'far'"));
  // what the SSP export keeps in Stride's annotations
  s = in_code();
  s.find_component("b")->kind = "model-exchange";
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: component 'b': Model Exchange (OSP "
                                    "runs Co-Simulation; SSP export keeps it)"));
  s = in_code();
  s.groups.push_back({"w", 2, {s.components.front()}, {}, {}});
  s.groups.back().components.front().name = "c";
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: replica group 'w': the copies' names "
                                    "(\"c[1]\") are not valid element names"));
  s = in_code();
  s.record.signals = {"a.y"};
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: the recorded signals (a.y) (OSP says "
                                    "nothing of recording"));
  s = in_code();
  s.record.file = "other.csv";
  EXPECT_THAT(refusal(s), HasSubstr("the results file \"other.csv\" (the OSP importer records"));
  s = in_code();
  s.agents.count = 2;
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: <agents>"));
  s = in_code();
  s.failover.standby = {"s1"};
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: <failover>: standby workers"));
  s = in_code();
  s.find_component("a")->parameters.push_back({"gain", "${output_dir}", {}});
  EXPECT_THAT(refusal(s), HasSubstr("parameter 'a.gain': the placeholder in '${output_dir}'"));
  // no base step given and none declared by the FMU (the fake declares no DefaultExperiment)
  s = in_code();
  s.base_step.reset();
  EXPECT_THAT(refusal(s), HasSubstr("cannot export to OSP: no base step"));
}

}  // namespace
}  // namespace stride::cosim
