// resources/plant.xml: what the generator writes, the FMU binary reads back, escapes included;
// a manifest that lacks something is refused naming the file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "stride/robot/plant_fmu.hpp"

namespace stride::robot {
namespace {

namespace fs = std::filesystem;

// ctest runs each test in its own process, several at once: the name must differ between them
fs::path write_temp(const std::string& text) {
  const fs::path p = fs::temp_directory_path() /
                     ("stride-plant-manifest-" + std::to_string(::getpid()) + "-" +
                      testing::UnitTest::GetInstance()->current_test_info()->name() + ".xml");
  std::ofstream(p) << text;
  return p;
}

TEST(plant_manifest, what_is_written_reads_back) {
  plant_manifest m;
  m.model_name = "arm & hand";
  m.model_identifier = "arm_hand";
  m.description = "an <arm> \"with\" a hand";
  m.urdf = "arm.urdf";
  m.profile = "arm.profile.xml";
  m.default_step = 0.004;
  m.package_path = {"packages", "more"};
  const fs::path p = write_temp(write_plant_manifest(m));
  const plant_manifest r = read_plant_manifest(p.string());
  fs::remove(p);
  EXPECT_EQ(r.model_name, m.model_name);
  EXPECT_EQ(r.model_identifier, m.model_identifier);
  EXPECT_EQ(r.description, m.description);
  EXPECT_EQ(r.urdf, m.urdf);
  EXPECT_EQ(r.profile, m.profile);
  EXPECT_EQ(r.default_step, m.default_step);
  EXPECT_EQ(r.package_path, m.package_path);
}

TEST(plant_manifest, a_manifest_lacking_something_is_refused_naming_the_file) {
  const std::pair<const char*, const char*> cases[] = {
      {"<stride_plant model_identifier=\"a\" urdf=\"a.urdf\" default_step=\"0.01\"/>",
       "<stride_plant> has no model_name"},
      {"<stride_plant model_name=\"a\" model_identifier=\"a\" default_step=\"0.01\"/>",
       "<stride_plant> has no urdf"},
      {"<stride_plant model_name=\"a\" model_identifier=\"a\" urdf=\"a.urdf\" "
       "default_step=\"-1\"/>",
       "default_step> must be a positive number"},
      {"<plant/>", "the root element must be <stride_plant>"},
      {"<stride_plant", "cannot read the plant manifest"},
  };
  for (const auto& [xml, expected] : cases) {
    const fs::path p = write_temp(xml);
    try {
      read_plant_manifest(p.string());
      ADD_FAILURE() << xml;
    } catch (const sdk::model_error& e) {
      EXPECT_NE(std::string(e.what()).find(p.string() + ": "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    fs::remove(p);
  }
}

}  // namespace
}  // namespace stride::robot
