// The FMI 3.0 modelDescription.xml reader: kinds, arrays and their port names, structural
// sizes, ModelStructure by value reference, and every refusal naming the file and the variable.
#include "fmi3_model_description.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "stride/cosim/error.hpp"

namespace stride::cosim::fmi3 {
namespace {

using ::testing::HasSubstr;

std::string kinds_xml() {
  std::ifstream in(FMI3_KINDS_MODEL_DESCRIPTION);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A minimal model description around `variables` (and `structure`).
std::string md(const std::string& variables, const std::string& structure = "",
               const std::string& root_attributes =
                   R"(fmiVersion="3.0" modelName="m" instantiationToken="{t}")") {
  return "<?xml version=\"1.0\"?>\n<fmiModelDescription " + root_attributes +
         ">\n<CoSimulation modelIdentifier=\"m\"/>\n<ModelVariables>\n" + variables +
         "</ModelVariables>\n<ModelStructure>" + structure +
         "</ModelStructure>\n</fmiModelDescription>\n";
}

std::string error_of(const std::string& xml) {
  try {
    parse_description(xml, "m.fmu!modelDescription.xml");
  } catch (const fmu_import_error& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(fmi3_model_description, reads_every_kind_of_the_test_fmu) {
  const auto d = parse_description(kinds_xml(), "kinds");
  EXPECT_EQ(d.scalar.fmi_version, "3.0");
  EXPECT_EQ(d.scalar.guid, "{fmi3-kinds-7d1c}");
  ASSERT_TRUE(d.scalar.co_simulation);
  EXPECT_EQ(d.scalar.co_simulation->model_identifier, "fmi3_kinds");
  EXPECT_TRUE(d.scalar.co_simulation->can_get_and_set_fmu_state);
  EXPECT_TRUE(d.scalar.co_simulation->can_serialize_fmu_state);
  EXPECT_TRUE(d.has_event_mode);
  const std::vector<std::pair<const char*, kind>> expected = {
      {"f32_in", kind::float32}, {"f64_in", kind::float64}, {"i8_in", kind::int8},
      {"u8_in", kind::uint8},    {"i16_in", kind::int16},   {"u16_in", kind::uint16},
      {"i32_in", kind::int32},   {"u32_in", kind::uint32},  {"i64_in", kind::int64},
      {"u64_in", kind::uint64},  {"b_in", kind::boolean},   {"s_in", kind::string},
      {"bin_in", kind::binary}};
  for (const auto& [name, k] : expected) {
    const std::string& wanted = name;  // a structured binding cannot be captured (C++20)
    const auto it = std::find_if(d.variables.begin(), d.variables.end(),
                                 [&](const variable& v) { return v.name == wanted; });
    ASSERT_NE(it, d.variables.end()) << name;
    EXPECT_EQ(it->kind, k) << name;
  }
  // the channels: floats real, integers integer, Binary as (hex) string
  EXPECT_EQ(d.scalar.find("f32_in")->type, variable_type::real);
  EXPECT_EQ(d.scalar.find("u64_in")->type, variable_type::integer);
  EXPECT_EQ(d.scalar.find("b_in")->type, variable_type::boolean);
  EXPECT_EQ(d.scalar.find("bin_in")->type, variable_type::string);
  EXPECT_EQ(d.scalar.find("bin_in")->start, "cafe");
  EXPECT_EQ(d.scalar.find("s_in")->start, "stride");
  EXPECT_EQ(d.scalar.find("gain")->causality, causality::parameter);
  EXPECT_EQ(d.scalar.find("f64_out")->causality, causality::output);
}

TEST(fmi3_model_description, arrays_become_one_port_per_element_named_like_fmi2_elements) {
  const auto d = parse_description(kinds_xml(), "kinds");
  EXPECT_EQ(d.scalar.find("i16_ain"), nullptr);  // the array itself is no port
  for (int i = 1; i <= 3; ++i) {
    const auto* p = d.scalar.find("i16_ain[" + std::to_string(i) + "]");
    ASSERT_NE(p, nullptr) << i;
    EXPECT_EQ(p->start, std::to_string(10 * i));
    EXPECT_EQ(p->causality, causality::input);
    const auto& port = d.ports[p->reference];
    EXPECT_EQ(d.variables[port.variable].name, "i16_ain");
    EXPECT_EQ(port.element, static_cast<std::size_t>(i - 1));
  }
  EXPECT_EQ(d.scalar.find("i16_ain[4]"), nullptr);
  // the size of series_* comes from the structural parameter n = 4
  EXPECT_NE(d.scalar.find("series_out[4]"), nullptr);
  EXPECT_EQ(d.scalar.find("series_out[5]"), nullptr);
  // ports are numbered densely: the reference is the index
  for (std::size_t i = 0; i < d.scalar.variables.size(); ++i) {
    EXPECT_EQ(d.scalar.variables[i].reference, i);
  }
  EXPECT_EQ(d.ports.size(), d.scalar.variables.size());
}

TEST(fmi3_model_description, two_dimensions_are_row_major_and_comma_separated) {
  const auto d = parse_description(
      md(R"(<Float64 name="A" valueReference="1" causality="parameter" start="1 2 3 4 5 6">
  <Dimension start="2"/><Dimension start="3"/></Float64>
)"),
      "m");
  ASSERT_EQ(d.scalar.variables.size(), 6u);
  EXPECT_EQ(d.scalar.variables[0].name, "A[1,1]");
  EXPECT_EQ(d.scalar.variables[2].name, "A[1,3]");
  EXPECT_EQ(d.scalar.variables[3].name, "A[2,1]");
  EXPECT_EQ(d.scalar.variables[5].start, "6");
}

TEST(fmi3_model_description, output_dependencies_are_mapped_to_element_ports) {
  const auto d = parse_description(kinds_xml(), "kinds");
  const auto out = *d.scalar.index_of("series_out[2]");
  const auto in1 = *d.scalar.index_of("series_in[1]");
  const auto in4 = *d.scalar.index_of("series_in[4]");
  const auto b_in = *d.scalar.index_of("b_in");
  EXPECT_TRUE(d.scalar.has_feedthrough(out, in1));
  EXPECT_TRUE(d.scalar.has_feedthrough(out, in4));
  EXPECT_FALSE(d.scalar.has_feedthrough(out, b_in));
  // dependencies="" : steps depends on no input
  EXPECT_FALSE(d.scalar.has_feedthrough(*d.scalar.index_of("steps"), in1));
}

TEST(fmi3_model_description, structural_parameters_are_fixed_locals) {
  const auto d = parse_description(kinds_xml(), "kinds");
  const auto* n = d.scalar.find("n");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->causality, causality::local);
  EXPECT_EQ(n->variability, variability::fixed);
}

TEST(fmi3_model_description, wrong_fmi_version_text_is_refused) {
  const auto e =
      error_of(md("", "", R"(fmiVersion="3.0-beta.2" modelName="m" instantiationToken="{t}")"));
  EXPECT_THAT(e, HasSubstr("m.fmu!modelDescription.xml:2"));
  EXPECT_THAT(e, HasSubstr("fmiVersion is \"3.0-beta.2\", not \"3.0\""));
}

TEST(fmi3_model_description, missing_instantiation_token_is_refused) {
  EXPECT_THAT(error_of(md("", "", R"(fmiVersion="3.0" modelName="m")")),
              HasSubstr("missing or empty instantiationToken"));
}

TEST(fmi3_model_description, a_dimension_naming_a_non_structural_variable_is_refused) {
  const auto e =
      error_of(md(R"(<UInt64 name="k" valueReference="1" causality="parameter" start="3"/>
<Float64 name="x" valueReference="2" causality="input" start="0 0 0"><Dimension valueReference="1"/></Float64>
)"));
  EXPECT_THAT(e, HasSubstr("m.fmu!modelDescription.xml:6"));
  EXPECT_THAT(e, HasSubstr("variable \"x\""));
  EXPECT_THAT(e, HasSubstr("names \"k\", which is not a structural or constant UInt64"));
  // the same with the structural causality is read
  EXPECT_NO_THROW(parse_description(
      md(R"(<UInt64 name="k" valueReference="1" causality="structuralParameter" variability="fixed" start="3"/>
<Float64 name="x" valueReference="2" causality="input" start="0 0 0"><Dimension valueReference="1"/></Float64>
)"),
      "m"));
}

TEST(fmi3_model_description, a_dimension_naming_no_variable_is_refused) {
  EXPECT_THAT(
      error_of(md(R"(<Float64 name="x" valueReference="2"><Dimension valueReference="9"/></Float64>
)")),
      HasSubstr("variable \"x\": <Dimension valueReference=\"9\"> names no variable"));
}

TEST(fmi3_model_description, duplicate_value_references_are_refused) {
  const auto e = error_of(md(R"(<Float64 name="a" valueReference="7"/>
<Int32 name="b" valueReference="7"/>
)"));
  EXPECT_THAT(e, HasSubstr(":6: variable \"b\" has value reference 7, already used by \"a\""));
}

TEST(fmi3_model_description, a_start_count_not_matching_the_array_size_is_refused) {
  const auto e = error_of(md(
      R"(<Int8 name="v" valueReference="1" causality="input" start="1 2"><Dimension start="3"/></Int8>
)"));
  EXPECT_THAT(e, HasSubstr("variable \"v\" has 2 start values for 3 elements"));
  EXPECT_THAT(error_of(md(R"(<Float64 name="s" valueReference="1" causality="input" start="1 2"/>
)")),
              HasSubstr("variable \"s\" has 2 start values for 1 elements"));
}

TEST(fmi3_model_description, a_start_value_outside_its_kind_is_refused) {
  EXPECT_THAT(error_of(md(R"(<UInt8 name="u" valueReference="1" causality="input" start="256"/>
)")),
              HasSubstr("variable \"u\": start value \"256\" is not a valid UInt8"));
  EXPECT_THAT(
      error_of(
          md(R"(<Binary name="b" valueReference="1" causality="input"><Start value="xyz"/></Binary>
)")),
      HasSubstr("start value \"xyz\" is not a valid Binary"));
}

TEST(fmi3_model_description, an_unknown_type_element_is_refused) {
  EXPECT_THAT(error_of(md(R"(<Real name="r" valueReference="1"/>
)")),
              HasSubstr(":5: variable \"r\": unknown variable type element <Real>"));
}

TEST(fmi3_model_description, a_clock_is_refused_naming_the_feature) {
  EXPECT_THAT(
      error_of(md(
          R"(<Clock name="tick" valueReference="1" causality="input" intervalVariability="constant"/>
)")),
      HasSubstr("variable \"tick\" is a Clock: clocks (and the event mode they need) are not "
                "supported"));
}

TEST(fmi3_model_description, output_naming_an_unknown_value_reference_is_refused) {
  EXPECT_THAT(error_of(md(R"(<Float64 name="y" valueReference="1" causality="output"/>
)",
                          R"(<Output valueReference="2"/>)")),
              HasSubstr("ModelStructure names value reference 2, which no variable has"));
}

TEST(fmi3_model_description, malformed_xml_names_the_file) {
  EXPECT_THAT(error_of("<fmiModelDescription fmiVersion=\"3.0\""),
              HasSubstr("m.fmu!modelDescription.xml"));
}

TEST(fmi3_model_description, declared_version_is_read_without_parsing_the_rest) {
  EXPECT_EQ(declared_fmi_version(kinds_xml()), "3.0");
  EXPECT_EQ(declared_fmi_version("<fmiModelDescription fmiVersion=\"2.0\"/>"), "2.0");
  EXPECT_EQ(declared_fmi_version("not xml"), "");
}

TEST(fmi3_model_description, the_generic_reader_hands_3_0_to_the_fmi3_reader) {
  // what `stride inspect`, SSP import and remote placement read
  const auto md = parse_model_description_text(kinds_xml(), "kinds");
  EXPECT_EQ(md.fmi_version, "3.0");
  EXPECT_NE(md.find("u8_ain[3]"), nullptr);
  EXPECT_EQ(md.variables.size(), parse_description(kinds_xml(), "kinds").ports.size());
  EXPECT_EQ(parse_model_description(FMI3_KINDS_MODEL_DESCRIPTION).guid, "{fmi3-kinds-7d1c}");
}

}  // namespace
}  // namespace stride::cosim::fmi3
