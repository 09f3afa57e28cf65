// SSP and OSP systems through the built `stride` CLI with the real FMUs: every form of the
// stride_test pair (.ssd, folder, .ssp, OspSystemStructure.xml) records byte for byte what
// stride_test_pair.xml records; transformations and nested names reach the results; refusals
// end with exit status 1 and one line naming file, line and element; validate, inspect, test
// and sweep take the same paths. With the DARwIn FMUs, the walk as an SSD walks as walk.xml.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "zip_writer.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_file;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_fmus = STRIDE_FMU_DIR;
const std::string k_cli = STRIDE_CLI;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class import_run : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-import-run-"};

  test::process_result stride(const std::string& args) const {
    return test::run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                             scratch.path());
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = scratch.path() / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

  // a fixture folder of data/ssp/ with the built FMUs copied in
  fs::path fixture(const std::string& name, const fs::path& fmu_folder,
                   std::initializer_list<const char*> fmus) const {
    const fs::path dir = scratch.path() / name;
    fs::copy(k_data / "ssp" / name, dir, fs::copy_options::recursive);
    fs::create_directories(dir / fmu_folder);
    for (const char* f : fmus) {
      fs::copy_file(k_fmus / (std::string(f) + ".fmu"),
                    dir / fmu_folder / (std::string(f) + ".fmu"));
    }
    return dir;
  }

  // `folder` zipped into `name`, entries relative to it
  fs::path zipped(const fs::path& folder, const std::string& name) const {
    std::vector<test::zip_entry> entries;
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
      if (e.is_regular_file()) {
        entries.push_back(
            {e.path().lexically_relative(folder).generic_string(), read_file(e.path())});
      }
    }
    const fs::path file = scratch.path() / name;
    test::write_zip(file, entries);
    return file;
  }

  // the results.csv of `stride run SYSTEM ARGS`, which must succeed
  std::string results(const fs::path& system, const std::string& out,
                      const std::string& args = "") const {
    const auto r = stride("run " + quoted(system) + " --quiet --threads 1 -o " + out + " " + args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_file(scratch.path() / out / "results.csv");
  }

  // `stride ARGS` must fail with one line that names `place` (file:line: <element...)
  void refused(const std::string& args, const std::string& place, const std::string& what) const {
    const auto r = stride(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_THAT(r.err, StartsWith("stride: error: ")) << args;
    EXPECT_THAT(r.err, HasSubstr(place)) << args;
    EXPECT_THAT(r.err, HasSubstr(what)) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
};

TEST_F(import_run, every_form_of_the_pair_records_what_its_system_xml_records) {
  const std::string reference = results(k_data / "stride_test_pair.xml", "xml");
  ASSERT_EQ(lines(reference).size(), 102u);  // t = 0, 0.01, ..., 1
  const fs::path pair = fixture("pair", "resources", {"stride_test"});
  EXPECT_EQ(results(pair / "SystemStructure.ssd", "ssd"), reference);
  EXPECT_EQ(results(pair, "folder"), reference);
  EXPECT_EQ(results(zipped(pair, "pair.ssp"), "ssp"), reference);
  const fs::path osp = fixture("pair_osp", ".", {"stride_test"});
  EXPECT_EQ(results(osp / "OspSystemStructure.xml", "osp"), reference);
  EXPECT_EQ(results(osp, "osp_folder"), reference);
}

TEST_F(import_run, a_linear_transformation_changes_the_downstream_value_as_computed) {
  const fs::path ssd = fixture("transformed", ".", {"stride_test"}) / "SystemStructure.ssd";
  // a.y = 3 * 1 = 3; b.u = 2 * 3 + 1 = 7; b.y = 2 * 7 = 14 (b's gain 2); step: the FMU's 0.01 s
  EXPECT_EQ(
      lines(results(ssd, "out", "--record 'a.y,b.u,b.y'")),
      (std::vector<std::string>{"time,a.y,b.u,b.y", "0,3,7,14", "0.01,3,7,14", "0.02,3,7,14"}));
  // the transformation stays in the system as run
  EXPECT_THAT(read_file(scratch.path() / "out" / "system.xml"),
              HasSubstr(R"(<connection from="a.y" to="b.u" factor="2" offset="1"/>)"));
}

TEST_F(import_run, nested_names_come_out_dotted_and_can_be_set) {
  const fs::path nested = fixture("nested", "resources", {"stride_test"});
  // ctrl.y = 2 * 1 = 2; engine.pump.u = 2 * 2 + 1 = 5; engine.pump.y = gain * 5 + 0.5 with the
  // top system's gain 5 (over the pump's own 4), then 3 from the command line
  EXPECT_EQ(
      lines(results(nested, "out", "--set ctrl.u=1 --record ctrl.y,engine.pump.u,engine.pump.y")),
      (std::vector<std::string>{"time,ctrl.y,engine.pump.u,engine.pump.y", "0,2,5,25.5",
                                "0.01,2,5,25.5"}));
  EXPECT_EQ(lines(results(nested, "set",
                          "--set ctrl.u=1 --set engine.pump.gain=3 "
                          "--record engine.pump.y")),
            (std::vector<std::string>{"time,engine.pump.y", "0,15.5", "0.01,15.5"}));
  // every output recorded when nothing is said, under its dotted name
  const std::string header = lines(results(nested, "all")).at(0);
  EXPECT_THAT(header, HasSubstr(",ctrl.y,"));
  EXPECT_THAT(header, HasSubstr(",engine.pump.y,"));
}

TEST_F(import_run, the_command_line_gives_the_step_and_algorithm) {
  const fs::path ssd = fixture("transformed", ".", {"stride_test"}) / "SystemStructure.ssd";
  EXPECT_EQ(lines(results(ssd, "out", "--record b.u --step 0.02 --algorithm jacobi")),
            (std::vector<std::string>{"time,b.u", "0,7", "0.02,7"}));
  const auto r = stride("validate " + quoted(ssd) + " --step 0.02 --algorithm jacobi");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("jacobi order a -> b, base step 0.02 s"));
  refused("run " + quoted(ssd) + " --step 0.0000000001 -o x", "--step: ", "nanoseconds");
  refused("run " + quoted(ssd) + " --algorithm newton -o x", "--algorithm newton",
          "not gauss-seidel or jacobi");
}

TEST_F(import_run, refusals_end_with_status_1_and_name_file_line_and_element) {
  const fs::path dir = fixture("transformed", ".", {"stride_test"});
  const std::string original = read_file(dir / "SystemStructure.ssd");
  std::string missing = original;
  missing.replace(missing.find(R"(endConnector="u")"), 16, R"(endConnector="w")");
  const fs::path bad = write("transformed/bad.ssd", missing);
  refused("run " + quoted(bad) + " -o x",
          bad.string() + ":24: <ssd:Connection>: ", "connection to a missing connector");
  refused("validate " + quoted(bad),
          bad.string() + ":24: <ssd:Connection>: ", "no connector \"w\"");
  refused("inspect " + quoted(bad), bad.string() + ":24: ", "missing connector");
  std::string dictionary = original;
  dictionary.replace(dictionary.find("  </ssd:System>"), 15,
                     "<ssd:SignalDictionaries/></ssd:System>");
  const fs::path dict = write("transformed/dict.ssd", dictionary);
  refused("run " + quoted(dict) + " -o x", dict.string() + ":28: <ssd:SignalDictionaries>: ",
          "signal dictionaries are not supported");
  const fs::path zip = write("broken.ssp", "PK but no zip");
  refused("run " + quoted(zip) + " -o x", zip.string() + ": ", "not a zip archive");
  fs::create_directory(scratch.path() / "nothing");
  refused("validate nothing", "nothing: a folder holding neither", "SystemStructure.ssd");
}

TEST_F(import_run, inspect_validate_test_and_sweep_take_ssp_systems) {
  const fs::path pair = fixture("pair", "resources", {"stride_test"});
  const fs::path archive = zipped(pair, "pair.ssp");
  auto r = stride("inspect " + quoted(archive));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out,
              HasSubstr("System 'pair' (" + archive.string() + "): 2 components, 7 connections"));
  r = stride("validate " + quoted(pair));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("OK: system 'pair', 2 components, 7 connections"));
  // a suite case whose system is the SSP folder: b.y = 2 * a.y = 2 * 3
  write("suite.xml", R"(<?xml version="1.0" encoding="UTF-8"?>
<suite name="ssp" version="1">
  <case name="pair" system="pair" stop="0.05">
    <final signal="b.y" value="6" tolerance="0"/>
  </case>
</suite>
)");
  r = stride("test suite.xml --quiet -o suite-out");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("1 passed"));
  r = stride("sweep " + quoted(archive) +
             " --grid a.gain=gain:1:2:1 --stop-time 0.02 -o sweep --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out + r.err, HasSubstr("2 of 2 points"));
}

TEST_F(import_run, the_pair_as_libcosim_and_omsimulator_write_it_runs_as_their_jacobi_masters) {
  const std::string jacobi = results(k_data / "stride_test_pair.xml", "xml", "--algorithm jacobi");
  ASSERT_NE(jacobi, results(k_data / "stride_test_pair.xml", "gauss-seidel"));
  // libcosim's shape: FMUs beside the SSD, the step in its annotation
  const fs::path libcosim = fixture("libcosim", ".", {"stride_test"});
  EXPECT_EQ(results(libcosim, "libcosim-out"), jacobi);
  EXPECT_EQ(results(zipped(libcosim, "libcosim.ssp"), "libcosim-ssp"), jacobi);
  // OMSimulator's shape, with a second SSD in the archive
  const fs::path oms = fixture("omsimulator", "resources", {"stride_test"});
  fs::copy_file(k_data / "ssp" / "pair" / "resources" / "vectors.ssv",
                oms / "resources" / "vectors.ssv");
  EXPECT_EQ(results(oms, "oms-out"), jacobi);
  const fs::path archive = zipped(oms, "oms.ssp");
  EXPECT_EQ(results(archive, "oms-ssp"), jacobi);
  // the command line still wins
  EXPECT_EQ(results(archive, "oms-gs", "--algorithm gauss-seidel"),
            read_file(scratch.path() / "gauss-seidel" / "results.csv"));

  const std::string variable = read_file(oms / "Variable.ssd");
  const auto line =
      std::count(variable.begin(), variable.begin() + variable.find(R"(<ssd:Component name="a")"),
                 '\n') +
      1;
  refused(
      "run " + quoted(archive) + " --ssd Variable.ssd --quiet",
      archive.string() + "/Variable.ssd:" + std::to_string(line) + ": <ssd:Component name=\"a\">",
      "the system 'pair' integrates Model Exchange FMUs (OMSimulator's solver annotation), but "
      "this component has an FMU without Model Exchange");
  refused("validate " + quoted(archive) + " --ssd Missing.ssd",
          archive.string() + ": no Missing.ssd at its root",
          "the .ssd files there: SystemStructure.ssd, Variable.ssd");

  const auto r = stride("inspect " + quoted(archive));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Base step 0.01 s, jacobi, from OMSimulator's annotation "
                               "(org.openmodelica) at " +
                               archive.string() + "/SystemStructure.ssd:"));
  EXPECT_THAT(r.out, HasSubstr("  SystemStructure.ssd  (read)\n  Variable.ssd\n"));
  // its DefaultExperiment's annotation holds result-file settings Stride does not read
  EXPECT_THAT(r.out, HasSubstr("Annotations of other tools, not read:\n  org.openmodelica at " +
                               archive.string() + "/SystemStructure.ssd:"));
}

#ifdef STRIDE_HAVE_WALK_FMUS
TEST_F(import_run, the_jacobi_walk_exported_reads_back_through_libcosims_annotation_alone) {
  std::string walk = read_file(fs::path(STRIDE_SOURCE_DIR) / "models" / "walk.xml");
  walk.replace(walk.find("gauss-seidel"), 12, "jacobi");
  const fs::path xml = write("walk.xml", walk);
  const std::string reference = results(xml, "xml", "--stop-time 1");
  ASSERT_EQ(lines(reference).size(), 127u);  // t = 0, 0.008, ..., 1
  const auto r = stride("export walk.xml --ssp walk.ssp");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path dir = scratch.path() / "walk";
  extract_archive(scratch.path() / "walk.ssp", dir);
  // only libcosim's annotation left to give step and algorithm
  std::string ssd = read_file(dir / "SystemStructure.ssd");
  for (const char* type : {"org.stride-sim.system", "org.openmodelica"}) {
    const auto begin = ssd.rfind("<ssc:Annotation", ssd.find(type));
    const auto end = ssd.find("</ssc:Annotation>", begin) + std::string("</ssc:Annotation>").size();
    ssd.erase(begin, end - begin);
  }
  ASSERT_EQ(ssd.find("org.stride-sim.system"), std::string::npos);
  ASSERT_NE(ssd.find("osp:FixedStepAlgorithm baseStepSize=\"0.008\""), std::string::npos);
  write("walk/SystemStructure.ssd", ssd);
  EXPECT_EQ(results(dir, "ssp", "--stop-time 1"), reference);
}

TEST_F(import_run, the_walk_as_an_ssd_walks_as_walk_xml) {
  const fs::path walk = fixture("walk", "resources", {"gait", "robot"});
  const std::string reference =
      results(fs::path(STRIDE_SOURCE_DIR) / "models" / "walk.xml", "xml", "--stop-time 2");
  ASSERT_EQ(lines(reference).size(), 252u);  // t = 0, 0.008, ..., 2
  EXPECT_EQ(results(walk, "ssd", "--stop-time 2"), reference);
}
#endif

}  // namespace
}  // namespace stride::cosim
