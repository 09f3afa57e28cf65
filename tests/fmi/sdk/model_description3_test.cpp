// The FMI 3.0 modelDescription.xml agrees with the variable table it came from: one variable per
// scalar or array, arrays with their <Dimension>, the independent variable, the ModelStructure.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <map>
#include <set>
#include <string>

#include "stride/sdk/fmu.hpp"
#include "stride/sdk/model_description.hpp"

namespace stride::test {
namespace {

const sdk::fmu_definition& fmu() {
  return sdk::detail::registered_fmu();
}

struct parsed {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* root = nullptr;
  std::map<std::string, const tinyxml2::XMLElement*> by_name;

  parsed() {
    const std::string xml = sdk::write_model_description3(fmu(), "2026-01-01T00:00:00Z");
    if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS) throw std::runtime_error("bad XML");
    root = doc.FirstChildElement("fmiModelDescription");
    for (const auto* v = root->FirstChildElement("ModelVariables")->FirstChildElement();
         v != nullptr; v = v->NextSiblingElement()) {
      by_name[v->Attribute("name")] = v;
    }
  }
  const tinyxml2::XMLElement& var(const std::string& name) const {
    const auto it = by_name.find(name);
    if (it == by_name.end()) throw std::runtime_error("no variable " + name);
    return *it->second;
  }
};

TEST(model_description3, root_declares_fmi_3_and_the_same_token_as_the_2_0_guid) {
  parsed p;
  EXPECT_STREQ(p.root->Attribute("fmiVersion"), "3.0");
  EXPECT_STREQ(p.root->Attribute("instantiationToken"), sdk::compute_guid(fmu()).c_str());
  const auto* cs = p.root->FirstChildElement("CoSimulation");
  ASSERT_NE(cs, nullptr);
  EXPECT_STREQ(cs->Attribute("modelIdentifier"), "stride_test");
  EXPECT_STREQ(cs->Attribute("canGetAndSetFMUState"), "true");
  EXPECT_STREQ(cs->Attribute("canSerializeFMUState"), "true");
  EXPECT_STREQ(cs->Attribute("hasEventMode"), "false");
  EXPECT_EQ(p.root->FirstChildElement("ModelExchange"), nullptr);
}

TEST(model_description3, an_indexed_member_becomes_one_array_variable) {
  parsed p;
  const auto& vec = p.var("vec_in");
  EXPECT_STREQ(vec.Name(), "Float64");
  const auto* dim = vec.FirstChildElement("Dimension");
  ASSERT_NE(dim, nullptr);
  EXPECT_EQ(dim->UnsignedAttribute("start"), 3u);
  EXPECT_STREQ(vec.Attribute("causality"), "input");
  EXPECT_STREQ(vec.Attribute("start"), "0 0 0");  // one start value per element
  EXPECT_EQ(p.by_name.count("vec_in[1]"), 0u);
  // the array's value reference is its first element's
  EXPECT_EQ(vec.UnsignedAttribute("valueReference"),
            fmu().table.find("vec_in[1]")->value_reference);
}

TEST(model_description3, every_table_element_is_in_exactly_one_variable) {
  parsed p;
  std::size_t elements = 0;
  std::set<unsigned> references;
  for (const auto& [name, v] : p.by_name) {
    EXPECT_TRUE(references.insert(v->UnsignedAttribute("valueReference")).second) << name;
    if (name == "time") continue;
    const auto* dim = v->FirstChildElement("Dimension");
    elements += dim ? dim->UnsignedAttribute("start") : 1;
  }
  EXPECT_EQ(elements, fmu().table.variables().size());
}

TEST(model_description3, types_map_to_their_fmi3_kinds) {
  parsed p;
  EXPECT_STREQ(p.var("gain").Name(), "Float64");
  EXPECT_STREQ(p.var("counter").Name(), "Int32");
  EXPECT_STREQ(p.var("enable").Name(), "Boolean");
  const auto& label = p.var("label");
  EXPECT_STREQ(label.Name(), "String");
  ASSERT_NE(label.FirstChildElement("Start"), nullptr);  // String starts are child elements
  EXPECT_STREQ(label.FirstChildElement("Start")->Attribute("value"), "stride");
  EXPECT_STREQ(p.var("gain").Attribute("min"), "-1000000");
  EXPECT_STREQ(p.var("integral").Attribute("unit"), "s");
}

TEST(model_description3, time_is_the_independent_variable_with_a_reference_of_its_own) {
  parsed p;
  const auto& time = p.var("time");
  EXPECT_STREQ(time.Name(), "Float64");
  EXPECT_STREQ(time.Attribute("causality"), "independent");
  EXPECT_EQ(time.Attribute("start"), nullptr);
  for (const sdk::variable& v : fmu().table.variables()) {
    EXPECT_NE(v.value_reference, time.UnsignedAttribute("valueReference")) << v.name;
  }
}

TEST(model_description3, outputs_list_their_dependencies_by_fmi3_value_reference) {
  parsed p;
  const unsigned y = p.var("y").UnsignedAttribute("valueReference");
  const unsigned u = p.var("u").UnsignedAttribute("valueReference");
  std::set<unsigned> outputs;
  bool y_found = false;
  for (const auto* o = p.root->FirstChildElement("ModelStructure")->FirstChildElement("Output");
       o != nullptr; o = o->NextSiblingElement("Output")) {
    outputs.insert(o->UnsignedAttribute("valueReference"));
    if (o->UnsignedAttribute("valueReference") == y) {
      EXPECT_EQ(std::to_string(u), o->Attribute("dependencies"));
      EXPECT_STREQ(o->Attribute("dependenciesKind"), "dependent");
      y_found = true;
    }
  }
  EXPECT_TRUE(y_found);
  std::set<unsigned> declared;
  for (const auto& [name, v] : p.by_name) {
    if (std::string(v->Attribute("causality")) == "output") {
      declared.insert(v->UnsignedAttribute("valueReference"));
    }
  }
  EXPECT_EQ(outputs, declared);  // each output once, the array vec_out as one
}

}  // namespace
}  // namespace stride::test
