// The generated modelDescription.xml agrees with the variable table it came from.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <set>
#include <string>

#include "stride/sdk/fmu.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::test {
namespace {

const sdk::fmu_definition& fmu() {
  return sdk::detail::registered_fmu();
}

TEST(model_description, every_variable_round_trips) {
  const std::string xml = sdk::write_model_description(fmu(), "2026-01-01T00:00:00Z");
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS);
  const auto* root = doc.FirstChildElement("fmiModelDescription");
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->Attribute("guid"), sdk::compute_guid(fmu()).c_str());
  EXPECT_STREQ(root->FirstChildElement("CoSimulation")->Attribute("modelIdentifier"),
               "stride_test");
  const auto& vars = fmu().table.variables();
  std::size_t i = 0;
  std::set<unsigned> references;
  for (const auto* sv =
           root->FirstChildElement("ModelVariables")->FirstChildElement("ScalarVariable");
       sv != nullptr; sv = sv->NextSiblingElement("ScalarVariable"), ++i) {
    ASSERT_LT(i, vars.size());
    EXPECT_EQ(sv->Attribute("name"), vars[i].name);
    EXPECT_EQ(sv->UnsignedAttribute("valueReference"), vars[i].value_reference);
    EXPECT_TRUE(references.insert(vars[i].value_reference).second) << "duplicate reference";
    // the spellings are string literals, so data() is NUL-terminated
    EXPECT_STREQ(sv->Attribute("causality"), sdk::to_string(vars[i].causality_kind).data());
    EXPECT_NE(sv->FirstChildElement(sdk::to_string(vars[i].type).data()), nullptr) << vars[i].name;
  }
  EXPECT_EQ(i, vars.size());
}

TEST(model_description, outputs_list_feedthrough_dependencies) {
  const std::string xml = sdk::write_model_description(fmu(), "");
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(xml.c_str()), tinyxml2::XML_SUCCESS);
  const auto& table = fmu().table;
  const std::string y_index = std::to_string(table.index_of(*table.find("y")));
  const std::string u_index = std::to_string(table.index_of(*table.find("u")));
  bool found = false;
  for (const auto* unknown = doc.RootElement()
                                 ->FirstChildElement("ModelStructure")
                                 ->FirstChildElement("Outputs")
                                 ->FirstChildElement("Unknown");
       unknown != nullptr; unknown = unknown->NextSiblingElement("Unknown")) {
    if (y_index == unknown->Attribute("index")) {
      EXPECT_EQ(u_index, unknown->Attribute("dependencies"));
      found = true;
    }
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(xml.find("generationDateAndTime"), std::string::npos);
}

TEST(model_description, arrays_become_indexed_names) {
  const auto& table = fmu().table;
  ASSERT_NE(table.find("vec_in[1]"), nullptr);
  ASSERT_NE(table.find("vec_in[3]"), nullptr);
  EXPECT_EQ(table.find("vec_in[4]"), nullptr);
  EXPECT_EQ(table.find("vec_in[3]")->value_reference, table.find("vec_in[1]")->value_reference + 2);
}

TEST(model_description, guid_is_stable_and_reflects_the_interface) {
  EXPECT_EQ(sdk::compute_guid(fmu()), sdk::compute_guid(fmu()));
  sdk::fmu_definition changed{fmu().info, fmu().table, fmu().create};
  changed.info.version = "9.9.9";
  EXPECT_NE(sdk::compute_guid(changed), sdk::compute_guid(fmu()));
}

}  // namespace
}  // namespace stride::test
