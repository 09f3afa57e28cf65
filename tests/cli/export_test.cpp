// `stride export` through the built CLI with the real FMUs: the exported SSP (and OSP, where it
// can say the system) runs to the same results.csv, byte for byte, as the system it came from;
// exporting the export gives the same archive; `stride validate` takes the archive; refusals and
// usage errors end with a non-zero status and one line naming what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "process.hpp"
#include "stride/cosim/archive.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_file;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_models = fs::path(STRIDE_SOURCE_DIR) / "models";
const std::string k_cli = STRIDE_CLI;

// a → b with a factor and offset, b → a back with a one-step delay, Jacobi: every setting the
// SSP export keeps in SSP terms or in Stride's annotations
const std::string k_loop = R"(<?xml version="1.0" encoding="UTF-8"?>
<system name="loop" version="1">
  <simulation start="0" stop="0.3" step="0.01" algorithm="jacobi"/>
  <component name="a" fmu="stride_test">
    <parameter name="gain" value="0.5"/>
    <parameter name="label" value="loop &amp; back"/>
  </component>
  <component name="b" fmu="stride_test">
    <parameter name="gain" value="1.5"/>
  </component>
  <connection from="a.y" to="b.u" factor="2" offset="0.25"/>
  <connection from="b.y" to="a.u" delay="true"/>
  <connection from="a.vec_out[*]" to="b.vec_in[*]"/>
</system>
)";

class export_cli : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-export-cli-"};

  test::process_result stride(const std::string& args) const {
    return test::run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' " + args,
                             scratch.path());
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = scratch.path() / name;
    std::ofstream(file) << text;
    return file;
  }

  // `stride export ARGS`, which must succeed
  std::string exported(const std::string& args) const {
    const auto r = stride("export " + args);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    return r.out;
  }

  // the results.csv of `stride run SYSTEM ARGS`, which must succeed
  std::string results(const fs::path& system, const std::string& out,
                      const std::string& args = "") const {
    const auto r = stride("run " + quoted(system) + " --quiet --threads 1 -o " + out + " " + args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string csv = read_file(scratch.path() / out / "results.csv");
    EXPECT_FALSE(csv.empty()) << system;
    return csv;
  }

  // `stride ARGS` must fail with status `status` and one line holding `what`
  void refused(const std::string& args, const std::string& what, int status = 1) const {
    const auto r = stride(args);
    EXPECT_EQ(r.exit_code, status) << args;
    EXPECT_THAT(r.err, HasSubstr(what)) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
};

TEST_F(export_cli, the_pair_exported_to_ssp_and_osp_records_what_its_system_xml_records) {
  const fs::path pair = k_data / "stride_test_pair.xml";
  const std::string reference = results(pair, "xml", "--stop-time 0.2");
  ASSERT_THAT(reference, StartsWith("time,"));
  const std::string out = exported(quoted(pair) + " --ssp pair.ssp");
  EXPECT_THAT(out, HasSubstr("wrote pair.ssp:\n  SystemStructure.ssd\n  resources/parameters.ssv\n"
                             "  resources/stride_test.fmu\n"));
  EXPECT_EQ(results(scratch.path() / "pair.ssp", "ssp", "--stop-time 0.2"), reference);
  EXPECT_THAT(exported(quoted(pair) + " --osp pair-osp"),
              HasSubstr("  OspSystemStructure.xml\n  stride_test.fmu\n"));
  EXPECT_EQ(results(scratch.path() / "pair-osp", "osp", "--stop-time 0.2"), reference);
  const auto r = stride("validate pair.ssp");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("OK: system 'pair', 2 components"));
}

TEST_F(export_cli, factors_delays_and_the_algorithm_survive_the_archive) {
  const fs::path loop = write("loop.xml", k_loop);
  const std::string reference = results(loop, "xml");
  exported("loop.xml --ssp loop.ssp --quiet");
  EXPECT_EQ(results(scratch.path() / "loop.ssp", "ssp"), reference);
  // the algorithm matters: Gauss-Seidel gives other values, so the archive kept Jacobi
  EXPECT_NE(results(loop, "gauss-seidel", "--algorithm gauss-seidel"), reference);
}

TEST_F(export_cli, exporting_the_export_gives_the_same_archive) {
  const fs::path loop = write("loop.xml", k_loop);
  exported("loop.xml --ssp loop.ssp -q");
  // the same name elsewhere: the importer names the system after the archive
  fs::create_directory(scratch.path() / "again");
  exported("loop.ssp --ssp again/loop.ssp -q");
  const std::string first = read_file(scratch.path() / "loop.ssp");
  EXPECT_EQ(read_file(scratch.path() / "again" / "loop.ssp"), first);
  refused("export loop.xml --ssp loop.ssp", "loop.ssp: exists (give --force to replace it)");
  exported("loop.xml --ssp loop.ssp --force -q");
  EXPECT_EQ(read_file(scratch.path() / "loop.ssp"), first);
}

TEST_F(export_cli, refusals_and_usage_errors_say_what_is_wrong) {
  const fs::path walkers = k_models / "walkers.xml";
  refused("export " + quoted(walkers) + " --osp walkers-osp",
          "stride: error: " + walkers.string() +
              ":11: cannot export to OSP: replica group 'walker': the copies' names (\"gait[1]\")");
  EXPECT_FALSE(fs::exists(scratch.path() / "walkers-osp"));
  write("loop.xml", k_loop);
  refused("export loop.xml --osp loop-osp", "cannot export to OSP: the jacobi algorithm");
  refused("export loop.xml", "stride: error: export: give --ssp OUT.ssp or --osp DIR");
  refused("export loop.xml --ssp loop.zip", "loop.zip: an SSP archive's name ends in .ssp");
  const auto both = stride("export loop.xml --ssp x.ssp --osp x");
  EXPECT_NE(both.exit_code, 0);
  EXPECT_THAT(both.err, HasSubstr("excludes"));
  const auto help = stride("export --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_THAT(help.out, HasSubstr("--ssp"));
  EXPECT_THAT(help.out, HasSubstr("--osp"));
  EXPECT_THAT(help.out, HasSubstr("--force"));
}

#ifdef STRIDE_HAVE_WALK_FMUS
TEST_F(export_cli, the_walk_exported_walks_as_walk_xml) {
  const fs::path walk = k_models / "walk.xml";
  const std::string reference = results(walk, "xml", "--stop-time 1");
  ASSERT_GT(std::count(reference.begin(), reference.end(), '\n'), 100);
  exported(quoted(walk) + " --ssp walk.ssp -q");
  EXPECT_EQ(results(scratch.path() / "walk.ssp", "ssp", "--stop-time 1"), reference);
  fs::create_directory(scratch.path() / "again");
  exported("walk.ssp --ssp again/walk.ssp -q");
  EXPECT_EQ(read_file(scratch.path() / "again" / "walk.ssp"),
            read_file(scratch.path() / "walk.ssp"));
  // the gyro's delayed feedback has no OSP form
  refused("export " + quoted(walk) + " --osp walk-osp",
          walk.string() +
              ":20: cannot export to OSP: the delayed connection robot.gyro_fb -> "
              "gait.gyro_fb");
}
#endif

#ifdef STRIDE_HAVE_LEARNER_FMU
TEST_F(export_cli, the_evaluated_gait_point_exported_measures_as_its_system_xml) {
  // three FMUs, values of every type, a String value with the ${output_dir} placeholder
  const fs::path point = k_models / "experiments" / "evaluate-point.xml";
  const std::string reference = results(point, "xml", "--stop-time 1");
  exported(quoted(point) + " --ssp evaluate-point.ssp -q");
  EXPECT_EQ(results(scratch.path() / "evaluate-point.ssp", "ssp", "--stop-time 1"), reference);
  // the learner wrote its files into the run's own folder in both runs
  const std::string paths = read_file(scratch.path() / "xml" / "paths.csv");
  EXPECT_FALSE(paths.empty());
  EXPECT_EQ(read_file(scratch.path() / "ssp" / "paths.csv"), paths);
}
#endif

}  // namespace
}  // namespace stride::cosim
