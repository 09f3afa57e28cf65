// Loading FMI 3.0 archives through fmu::load: the dispatch on fmiVersion, the binary folder,
// and the refusals (no interface Stride runs, missing functions, clocks, missing binary) naming the
// FMU file and the feature.
#include "fmi3_fmu.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fmi3_fixture.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class fmi3_fmu_test : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-fmi3-fmu-test-"};

  std::string load_error(const fs::path& file) {
    try {
      fmu::load(file, test::extract_into(scratch.path()));
    } catch (const fmu_import_error& e) {
      return e.what();
    }
    return "<no error>";
  }
};

TEST_F(fmi3_fmu_test, a_3_0_archive_is_read_as_fmi3) {
  const auto f = fmu::load(test::k_fmi3_kinds, test::extract_into(scratch.path()));
  EXPECT_EQ(f->model_description().fmi_version, "3.0");
  EXPECT_EQ(f->model_description().guid, "{fmi3-kinds-7d1c}");
  EXPECT_NE(f->model_description().find("u64_aout[3]"), nullptr);
  const auto c = f->instantiate("k");
  EXPECT_EQ(c->name(), "k");
  EXPECT_EQ(&c->model_description(), &c->model_description());
  EXPECT_EQ(c->model_description().variables.size(), f->model_description().variables.size());
}

TEST_F(fmi3_fmu_test, the_extraction_lives_as_long_as_an_instance) {
  auto f = fmu::load(test::k_fmi3_kinds, test::extract_into(scratch.path()));
  const fs::path dir = f->extracted_dir();
  auto c = f->instantiate("k");
  f.reset();
  EXPECT_TRUE(fs::exists(dir));  // the instance keeps the binary loaded
  c->setup(time_point{}, std::nullopt);
  c->enter_initialization();
  c->exit_initialization();
  c.reset();
  EXPECT_FALSE(fs::exists(dir));
}

// the kinds FMU's binary offers Co-Simulation only: declared as Model Exchange, it loads (it
// exports every 3.0 function, the Model Exchange ones as refusals) and its refusal to
// instantiate stops the run naming the component and the file
TEST_F(fmi3_fmu_test, model_exchange_refused_by_the_binary_names_the_component) {
  const fs::path file = scratch.path() / "me_only.fmu";
  auto xml = test::fmi3_kinds_xml();
  xml = test::replaced(xml, "<CoSimulation ", "<ModelExchange ");
  xml = test::replaced(xml, " hasEventMode=\"true\"", "");
  test::write_fmi3_kinds_variant(file, xml);
  const auto f = fmu::load(file, test::extract_into(scratch.path()));
  try {
    f->instantiate("k");
    FAIL() << "a Co-Simulation binary instantiated as Model Exchange";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'k': fmi3InstantiateModelExchange of " +
                                    fs::absolute(file).string() + " failed"));
  }
}

TEST_F(fmi3_fmu_test, neither_interface_is_refused_naming_the_file) {
  const fs::path file = scratch.path() / "scheduled.fmu";
  auto xml = test::fmi3_kinds_xml();
  xml = test::replaced(xml, "<CoSimulation ", "<ScheduledExecution ");
  xml = test::replaced(xml, " hasEventMode=\"true\"", "");
  test::write_fmi3_kinds_variant(file, xml);
  const auto e = load_error(file);
  EXPECT_THAT(e, HasSubstr(file.string() + ": neither <CoSimulation> nor <ModelExchange>"));
  EXPECT_THAT(e, HasSubstr("Scheduled Execution is not supported"));
}

TEST_F(fmi3_fmu_test, a_clock_is_refused_naming_the_file_and_the_variable) {
  const fs::path file = scratch.path() / "clocked.fmu";
  test::write_fmi3_kinds_variant(
      file, test::replaced(test::fmi3_kinds_xml(), "  </ModelVariables>",
                           "    <Clock name=\"tick\" valueReference=\"500\" causality=\"input\" "
                           "intervalVariability=\"triggered\"/>\n  </ModelVariables>"));
  const auto e = load_error(file);
  EXPECT_THAT(e, HasSubstr(file.string() + "!modelDescription.xml:"));
  EXPECT_THAT(e, HasSubstr("variable \"tick\" is a Clock: clocks"));
}

TEST_F(fmi3_fmu_test, offered_event_mode_is_accepted_and_declined) {
  // the test FMU declares hasEventMode="true" and refuses instantiation with eventModeUsed:
  // it instantiates, so Stride declined event mode
  const auto f = fmu::load(test::k_fmi3_kinds, test::extract_into(scratch.path()));
  EXPECT_NO_THROW(f->instantiate("k"));
}

TEST_F(fmi3_fmu_test, a_binary_only_in_the_2_0_folder_is_not_found) {
  const fs::path file = scratch.path() / "old_folder.fmu";
  test::write_zip(file, {{"modelDescription.xml", test::fmi3_kinds_xml()},
                         {"binaries/linux64/fmi3_kinds.so", test::read_whole(FMI3_KINDS_BINARY)}});
  EXPECT_THAT(load_error(file),
              HasSubstr(file.string() + ": missing binary binaries/x86_64-linux/fmi3_kinds.so"));
}

TEST_F(fmi3_fmu_test, a_path_as_model_identifier_is_refused) {
  const fs::path file = scratch.path() / "path.fmu";
  test::write_fmi3_kinds_variant(
      file, test::replaced(test::fmi3_kinds_xml(), "modelIdentifier=\"fmi3_kinds\"",
                           "modelIdentifier=\"../fmi3_kinds\""));
  EXPECT_THAT(load_error(file),
              HasSubstr("modelIdentifier \"../fmi3_kinds\" is not a C identifier"));
}

TEST_F(fmi3_fmu_test, a_wrong_version_text_goes_to_the_fmi3_reader_and_is_refused) {
  const fs::path file = scratch.path() / "beta.fmu";
  test::write_fmi3_kinds_variant(file, test::replaced(test::fmi3_kinds_xml(), "fmiVersion=\"3.0\"",
                                                      "fmiVersion=\"3.0-beta\""));
  EXPECT_THAT(load_error(file),
              HasSubstr(file.string() + "!modelDescription.xml:2: fmiVersion is \"3.0-beta\""));
}

TEST_F(fmi3_fmu_test, a_wrong_instantiation_token_fails_at_instantiation) {
  const fs::path file = scratch.path() / "token.fmu";
  test::write_fmi3_kinds_variant(
      file, test::replaced(test::fmi3_kinds_xml(), "{fmi3-kinds-7d1c}", "{another-token}"));
  const auto f = fmu::load(file, test::extract_into(scratch.path()));
  test::log_lines log;
  try {
    f->instantiate("k", {log.sink(), true});
    FAIL() << "instantiated";
  } catch (const component_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("component 'k': fmi3InstantiateCoSimulation of"));
    EXPECT_THAT(e.what(), HasSubstr("{another-token}"));
  }
  ASSERT_EQ(log.lines.size(), 1u);  // the FMU's own message reaches the instance's sink
  EXPECT_EQ(log.lines[0], "error k: wrong instantiationToken");
}

}  // namespace
}  // namespace stride::cosim
