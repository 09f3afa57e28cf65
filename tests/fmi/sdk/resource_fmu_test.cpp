// An FMU whose interface is read from its resources (STRIDE_FMU_FROM_RESOURCES), driven through
// the FMI functions of the glue linked into this test: one definition per resources folder,
// each with its own GUID, and a clear error when the resources do not define one.
#include <gtest/gtest.h>

#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "stride/fmi2/fmi2_api.h"
#include "stride/sdk/fmu.hpp"
#include "stride/sdk/model_description.hpp"

namespace {

namespace fs = std::filesystem;
namespace sdk = stride::sdk;

// y[i] = gain * u[i] for a width read from resources/width.txt
class doubler final : public sdk::buffer_model {
 public:
  doubler(const sdk::variable_table& t, std::size_t width) : buffer_model(t), width_(width) {}
  sdk::step_result do_step(sdk::time_ns, sdk::time_ns) override {
    for (std::size_t i = 0; i < width_; ++i) {
      value<double>((width_ + i) * sizeof(double)) =
          value<double>(2 * width_ * sizeof(double)) * value<double>(i * sizeof(double));
    }
    return sdk::step_result::ok;
  }

 private:
  std::size_t width_;
};

std::shared_ptr<const sdk::fmu_definition> load(const std::string& resource_dir) {
  std::ifstream in(fs::path(resource_dir) / "width.txt");
  std::size_t width = 0;
  if (!(in >> width) || width == 0) {
    throw sdk::model_error(resource_dir + "/width.txt: no positive width");
  }
  sdk::buffer_table_builder b;
  b.declare<double>("u", b.reserve<double>(width, 0.0), width, true).input();
  b.declare<double>("y", b.reserve<double>(width, 0.0), width, true).output();
  b.add<double>("gain", 2.0).parameter();
  sdk::model_info info;
  info.model_name = "doubler";
  info.model_identifier = "doubler";
  auto def = std::make_shared<sdk::fmu_definition>(
      sdk::fmu_definition{std::move(info), b.finish(), nullptr});
  const sdk::variable_table* table = &def->table;
  def->create = [table, width](const sdk::instance_context&) {
    return std::unique_ptr<sdk::model>(new doubler(*table, width));
  };
  return def;
}

std::vector<std::string> g_messages;
void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String message, ...) {
  g_messages.emplace_back(message);
}
const fmi2CallbackFunctions k_callbacks{logger, nullptr, nullptr, nullptr, nullptr};

fs::path resources_with_width(const std::string& name, const std::string& width) {
  const fs::path dir = fs::temp_directory_path() / ("stride-resource-fmu-" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "width.txt") << width;
  return dir;
}

std::string uri(const fs::path& p) {
  return "file://" + p.string();
}

TEST(resource_fmu, each_resources_folder_gives_its_own_interface_and_guid) {
  const fs::path two = resources_with_width("two", "2");
  const fs::path three = resources_with_width("three", "3");
  const auto def2 = sdk::detail::fmu_for(two.string());
  const auto def3 = sdk::detail::fmu_for(three.string());
  EXPECT_EQ(def2->table.variables().size(), 5u);
  EXPECT_EQ(def3->table.variables().size(), 7u);
  const std::string guid2 = sdk::compute_guid(*def2);
  const std::string guid3 = sdk::compute_guid(*def3);
  EXPECT_NE(guid2, guid3);

  // through the FMI functions: the GUID of the folder's interface is the one accepted
  EXPECT_EQ(fmi2Instantiate("a", fmi2CoSimulation, guid2.c_str(), uri(three).c_str(), &k_callbacks,
                            fmi2False, fmi2False),
            nullptr);
  fmi2Component c = fmi2Instantiate("b", fmi2CoSimulation, guid3.c_str(), uri(three).c_str(),
                                    &k_callbacks, fmi2False, fmi2False);
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(fmi2SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0), fmi2OK);
  ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
  const fmi2ValueReference u[] = {0, 1, 2};
  const fmi2Real values[] = {1.5, -2.0, 4.0};
  ASSERT_EQ(fmi2SetReal(c, u, 3, values), fmi2OK);
  const fmi2ValueReference gain = 6;
  const fmi2Real three_times = 3.0;
  ASSERT_EQ(fmi2SetReal(c, &gain, 1, &three_times), fmi2OK);
  ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
  ASSERT_EQ(fmi2DoStep(c, 0.0, 0.1, fmi2True), fmi2OK);
  const fmi2ValueReference y[] = {3, 4, 5};
  fmi2Real out[3] = {};
  ASSERT_EQ(fmi2GetReal(c, y, 3, out), fmi2OK);
  EXPECT_EQ(out[0], 4.5);
  EXPECT_EQ(out[1], -6.0);
  EXPECT_EQ(out[2], 12.0);
  // a state of this interface does not fit an instance of the other
  fmi2FMUstate state = nullptr;
  ASSERT_EQ(fmi2GetFMUstate(c, &state), fmi2OK);
  size_t size = 0;
  ASSERT_EQ(fmi2SerializedFMUstateSize(c, state, &size), fmi2OK);
  std::vector<fmi2Byte> bytes(size);
  ASSERT_EQ(fmi2SerializeFMUstate(c, state, bytes.data(), size), fmi2OK);
  fmi2Component other = fmi2Instantiate("c", fmi2CoSimulation, guid2.c_str(), uri(two).c_str(),
                                        &k_callbacks, fmi2False, fmi2False);
  ASSERT_NE(other, nullptr);
  fmi2FMUstate foreign = nullptr;
  g_messages.clear();
  EXPECT_EQ(fmi2DeSerializeFMUstate(other, bytes.data(), size, &foreign), fmi2Error);
  ASSERT_FALSE(g_messages.empty());
  EXPECT_NE(g_messages.back().find("another FMU"), std::string::npos) << g_messages.back();
  fmi2FreeFMUstate(c, &state);
  fmi2FreeInstance(other);
  fmi2FreeInstance(c);
}

TEST(resource_fmu, resources_that_define_no_fmu_fail_instantiation_with_the_reason) {
  const fs::path bad = resources_with_width("bad", "zero");
  g_messages.clear();
  EXPECT_EQ(fmi2Instantiate("d", fmi2CoSimulation, "{whatever}", uri(bad).c_str(), &k_callbacks,
                            fmi2False, fmi2False),
            nullptr);
  ASSERT_FALSE(g_messages.empty());
  EXPECT_NE(g_messages.back().find("width.txt: no positive width"), std::string::npos)
      << g_messages.back();
}

TEST(resource_fmu, the_resource_uri_is_percent_decoded_and_a_bad_escape_is_named) {
  const fs::path spaced = resources_with_width("with space", "2");
  std::string encoded = uri(spaced);
  encoded.replace(encoded.find(' '), 1, "%20");
  const std::string guid = sdk::compute_guid(*sdk::detail::fmu_for(spaced.string()));
  fmi2Component c = fmi2Instantiate("e", fmi2CoSimulation, guid.c_str(), encoded.c_str(),
                                    &k_callbacks, fmi2False, fmi2False);
  EXPECT_NE(c, nullptr);
  fmi2FreeInstance(c);

  for (const std::string& broken : {uri(spaced) + "%zz", uri(spaced) + "%4"}) {
    g_messages.clear();
    EXPECT_EQ(fmi2Instantiate("f", fmi2CoSimulation, guid.c_str(), broken.c_str(), &k_callbacks,
                              fmi2False, fmi2False),
              nullptr);
    ASSERT_FALSE(g_messages.empty());
    // the logger's message is a format string: a literal '%' arrives doubled
    EXPECT_NE(g_messages.back().find("resource location '" + uri(spaced) + "%%"), std::string::npos)
        << g_messages.back();
    EXPECT_NE(g_messages.back().find("is not a percent-encoded byte"), std::string::npos)
        << g_messages.back();
  }
  g_messages.clear();
  EXPECT_EQ(fmi2Instantiate("g", fmi2CoSimulation, guid.c_str(), "file://host", &k_callbacks,
                            fmi2False, fmi2False),
            nullptr);
  ASSERT_FALSE(g_messages.empty());
  EXPECT_NE(g_messages.back().find("no path after the host"), std::string::npos)
      << g_messages.back();
}

}  // namespace

STRIDE_FMU_FROM_RESOURCES(load)
