// Every system under models/ through an SSP archive and back (docs/ssp.md, "Export"): the
// archive reads back as the same system, field by field (replica groups expanded into their
// copies, recording, workers and agents from Stride's annotations); exporting what was read
// gives the same bytes; and the systems that run in this process in a few seconds run from the
// archive to the same results.csv (and learner files), byte for byte, through the built CLI.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <algorithm>
#include <map>

#include "process.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/system_export.hpp"
#include "stride/cosim/system_import.hpp"
#include "system_compare.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_file;

const fs::path k_models = fs::path(STRIDE_SOURCE_DIR) / "models";
const std::string k_cli = STRIDE_CLI;

// the system files under models/ (relative paths, sorted): XML files whose root is <system>
std::vector<std::string> model_systems() {
  std::vector<std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(k_models)) {
    if (entry.path().extension() != ".xml") continue;
    tinyxml2::XMLDocument doc;
    if (doc.LoadFile(entry.path().c_str()) != tinyxml2::XML_SUCCESS) continue;
    if (std::string_view(doc.RootElement()->Name()) != "system") continue;
    out.push_back(entry.path().lexically_relative(k_models).generic_string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// the systems run from their archive, each for a short simulated time, and the files besides
// results.csv their runs write that must match too
struct run_case {
  std::string stop_time;
  std::vector<std::string> files;
};
const std::map<std::string, run_case> k_runs = {
    {"walk.xml", {"1", {}}},
    {"walkers.xml", {"1", {}}},
    {"regression/gait_alone.xml", {"1", {}}},
    {"experiments/evaluate-point.xml", {"1", {"paths.csv"}}},
    {"experiments/demo.xml", {"2", {"steps.csv", "paths.csv", "v_table.csv", "best.txt"}}},
};

class model_export : public ::testing::TestWithParam<std::string> {
 protected:
  temp_dir scratch{"stride-model-export-"};

  // the results.csv and `files` of `stride run SYSTEM` into the folder `out`
  std::vector<std::string> run(const fs::path& system, const std::string& out,
                               const run_case& how) const {
    const auto r = test::run_command("cd " + quoted(scratch.path()) + " && '" + k_cli + "' run " +
                                         quoted(system) + " --quiet --threads 1 --stop-time " +
                                         how.stop_time + " -o " + out,
                                     scratch.path());
    EXPECT_EQ(r.exit_code, 0) << system << "\n" << r.err;
    std::vector<std::string> texts{read_file(scratch.path() / out / "results.csv")};
    EXPECT_FALSE(texts.front().empty()) << system;
    for (const auto& f : how.files) {
      texts.push_back(read_file(scratch.path() / out / f));
      EXPECT_FALSE(texts.back().empty()) << system << ": " << f;
    }
    return texts;
  }
};

TEST_P(model_export, reads_back_reexports_and_runs_as_its_system_xml) {
  const fs::path file = k_models / GetParam();
  const system_structure original = load_system_file(file);
  // named after the system, which the archive's name gives back
  const fs::path archive = scratch.path() / (original.name + ".ssp");
  export_ssp(original, archive);

  const system_structure imported = load_system_file(archive);
  const std::vector<fs::path> search = default_fmu_search_path();
  const auto expected = test::system_facts(expand_replicas(original), search).lines();
  const auto got = test::system_facts(imported, search).lines();
  EXPECT_EQ(got, expected);

  const fs::path again = scratch.path() / "again" / archive.filename();
  fs::create_directories(again.parent_path());
  export_ssp(imported, again);
  // compared whole (not printed: megabytes of FMUs)
  EXPECT_TRUE(read_file(again) == read_file(archive)) << "the export of the export differs";

  const auto runs = k_runs.find(GetParam());
  if (runs == k_runs.end()) return;  // DDS workers or hours of learning: compared above only
  EXPECT_EQ(run(archive, "ssp", runs->second), run(file, "xml", runs->second));
}

// "experiments/demo.xml" → "experiments_demo_xml"
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(models, model_export, ::testing::ValuesIn(model_systems()), test_name);

// the run list names systems that exist: a renamed model would drop out of the run silently
TEST(model_export_list, every_system_run_is_under_models) {
  const auto systems = model_systems();
  for (const auto& [name, how] : k_runs) {
    EXPECT_NE(std::find(systems.begin(), systems.end(), name), systems.end()) << name;
  }
  EXPECT_GE(systems.size(), 14U);
}

}  // namespace
}  // namespace stride::cosim
