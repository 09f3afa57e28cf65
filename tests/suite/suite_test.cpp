// The suite XML parser: what a well-formed file yields, and errors naming file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "stride/cosim/error.hpp"
#include "stride/suite/suite.hpp"

namespace stride::suite {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path k_data = STRIDE_TEST_DATA_DIR;
const fs::path k_file = "/suites/s.xml";

// the message of the validation_error that parsing `xml` throws, or "" if it parses
std::string parse_error(const std::string& xml) {
  try {
    parse_suite_text(xml, k_file);
  } catch (const cosim::validation_error& e) {
    return e.what();
  }
  return "";
}

std::string at_line(int line) {
  return k_file.string() + ":" + std::to_string(line) + ": ";
}

TEST(suite_parser, reads_cases_sets_and_assertions_with_their_lines) {
  const fs::path file = k_data / "parse.xml";
  const suite_spec s = parse_suite_file(file);
  EXPECT_EQ(s.name, "parsed");
  EXPECT_EQ(s.file, file);
  ASSERT_EQ(s.cases.size(), 2u);

  const case_spec& a = s.cases[0];
  EXPECT_EQ(a.name, "first");
  EXPECT_EQ(a.system, k_data / "systems/a.xml");  // relative to the suite's folder
  EXPECT_EQ(a.stop_time, "0.5");
  EXPECT_EQ(a.record_interval, "0.1");
  EXPECT_THAT(a.sets, ::testing::ElementsAre("a.gain=4", "b.label="));
  EXPECT_EQ(a.where.file, file.string());
  EXPECT_EQ(a.where.line, 4);
  ASSERT_EQ(a.assertions.size(), 2u);
  EXPECT_EQ(a.assertions[0].kind, "never");
  EXPECT_EQ(a.assertions[0].get("signal"), "a.fallen");
  EXPECT_EQ(a.assertions[0].get("from"), "1");
  EXPECT_EQ(a.assertions[0].get("to"), std::nullopt);
  EXPECT_EQ(a.assertions[0].where.line, 7);
  EXPECT_EQ(a.assertions[1].kind, "bounds");
  EXPECT_EQ(a.assertions[1].get("min"), "-1");
  EXPECT_EQ(a.assertions[1].get("max"), "2.5");
  EXPECT_EQ(a.assertions[1].where.line, 8);

  const case_spec& b = s.cases[1];
  EXPECT_EQ(b.name, "second-2.b");
  EXPECT_EQ(b.system, fs::path("/abs/b.xml"));  // an absolute path stays as it is
  EXPECT_FALSE(b.stop_time);
  EXPECT_FALSE(b.record_interval);
  EXPECT_TRUE(b.sets.empty());
  ASSERT_EQ(b.assertions.size(), 1u);
  EXPECT_EQ(b.assertions[0].kind, "reference");
  EXPECT_EQ(b.assertions[0].get("signals"), "a.* b.y");
  EXPECT_EQ(b.assertions[0].where.line, 11);
}

TEST(suite_parser, name_defaults_to_the_file_stem) {
  const auto s = parse_suite_text(
      "<suite><case name='c' system='x.xml'><never signal='a.b'/></case></suite>", k_file);
  EXPECT_EQ(s.name, "s");
  EXPECT_EQ(s.cases.at(0).system, fs::path("/suites/x.xml"));
}

TEST(suite_parser, missing_file_is_named) {
  try {
    parse_suite_file(k_data / "no_such_suite.xml");
    FAIL() << "no error";
  } catch (const cosim::validation_error& e) {
    EXPECT_THAT(e.what(), HasSubstr((k_data / "no_such_suite.xml").string()));
  }
}

TEST(suite_parser, malformed_xml_names_file_and_line) {
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'>\n"
                          "    <never signal=a.b/>\n"
                          "  </case>\n"
                          "</suite>\n"),
              StartsWith(at_line(3) + "malformed XML"));
  // a wrong end tag: tinyxml2 names the element left open
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'>\n"
                          "    <never signal='a.b'/>\n"
                          "  </cas>\n"
                          "</suite>\n"),
              StartsWith(at_line(2) + "malformed XML"));
  // an empty document has no line
  EXPECT_THAT(parse_error(""), StartsWith(k_file.string() + ": malformed XML"));
}

TEST(suite_parser, wrong_root_names_file_and_line) {
  EXPECT_THAT(parse_error("<?xml version='1.0'?>\n<system name='s'/>\n"),
              StartsWith(at_line(2) + "the root element must be <suite>"));
}

TEST(suite_parser, unknown_element_in_suite) {
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'><never signal='a.b'/></case>\n"
                          "  <cases name='b'/>\n"
                          "</suite>"),
              StartsWith(at_line(3) + "unknown element <cases>"));
}

TEST(suite_parser, unknown_attributes) {
  EXPECT_THAT(parse_error("<suite\n  nmae='x'>\n</suite>"),
              StartsWith(at_line(1) + "unknown attribute 'nmae' on <suite>"));
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml' stop_time='1'>\n"
                          "    <never signal='a.b'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(2) + "unknown attribute 'stop_time' on <case>"));
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'>\n"
                          "    <set variable='a.b' value='1' unit='s'/>\n"
                          "    <never signal='a.b'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(3) + "unknown attribute 'unit' on <set>"));
}

TEST(suite_parser, case_without_system_or_assertion) {
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a'>\n"
                          "    <never signal='a.b'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(2) + "<case> needs a system attribute"));
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system=''><never signal='a.b'/></case>\n"
                          "</suite>"),
              StartsWith(at_line(2) + "<case> needs a system attribute"));
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case system='x.xml'><never signal='a.b'/></case>\n"
                          "</suite>"),
              StartsWith(at_line(2) + "<case> needs a name attribute"));
  // a <set> is no assertion
  EXPECT_THAT(parse_error("<suite>\n"
                          "\n"
                          "  <case name='lonely' system='x.xml'>\n"
                          "    <set variable='a.b' value='1'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(3) + "case \"lonely\" has no assertion"));
}

TEST(suite_parser, set_needs_variable_and_value) {
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'>\n"
                          "    <set variable='a.b'/>\n"
                          "    <never signal='a.b'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(3) + "<set> needs a value attribute"));
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='a' system='x.xml'>\n"
                          "    <never signal='a.b'/>\n"
                          "    <set value='1'/>\n"
                          "  </case>\n"
                          "</suite>"),
              StartsWith(at_line(4) + "<set> needs a variable attribute"));
}

TEST(suite_parser, duplicate_case_names_point_at_the_second) {
  EXPECT_THAT(parse_error("<suite>\n"
                          "  <case name='same' system='x.xml'><never signal='a.b'/></case>\n"
                          "  <case name='other' system='x.xml'><never signal='a.b'/></case>\n"
                          "  <case name='same' system='y.xml'><never signal='a.b'/></case>\n"
                          "</suite>"),
              StartsWith(at_line(4) + "duplicate case name \"same\""));
}

TEST(suite_parser, case_names_must_be_folder_names) {
  for (const char* bad : {"a/b", ".hidden", "..", "with space", "star*"}) {
    EXPECT_THAT(parse_error(std::string("<suite>\n  <case name='") + bad +
                            "' system='x.xml'><never signal='a.b'/></case>\n</suite>"),
                StartsWith(at_line(2) + "case name \"" + bad + "\""))
        << bad;
  }
  EXPECT_EQ(parse_error("<suite><case name='ok_name-1.2' system='x.xml'><never signal='a.b'/>"
                        "</case></suite>"),
            "");
}

// the suite's name becomes the default output folder's name
TEST(suite_parser, suite_names_must_be_folder_names) {
  for (const char* bad : {"../../escape", "/tmp/x", ".."}) {
    EXPECT_THAT(parse_error(std::string("<suite name='") + bad +
                            "'>\n  <case name='a' system='x.xml'><never signal='a.b'/></case>\n"
                            "</suite>"),
                StartsWith(at_line(1) + "suite name \"" + bad + "\""))
        << bad;
  }
}

TEST(suite_parser, stop_and_interval_must_be_times) {
  const auto with = [](const std::string& attributes) {
    return parse_error("<suite>\n<case name='c' system='x.xml' " + attributes +
                       ">\n<never signal='a.b'/>\n</case>\n</suite>");
  };
  EXPECT_THAT(with("stop='ten'"), StartsWith(at_line(2) + "stop=\"ten\" is not a time"));
  EXPECT_THAT(with("stop='-1'"), StartsWith(at_line(2) + "stop=\"-1\" must be at least 0"));
  EXPECT_THAT(with("interval='0'"), StartsWith(at_line(2) + "interval=\"0\" must be positive"));
  EXPECT_THAT(with("interval='1e-12'"),
              StartsWith(at_line(2) + "interval=\"1e-12\" is not a time"));
  EXPECT_EQ(with("stop='0' interval='0.008'"), "");
}

TEST(suite_parser, unsupported_version) {
  EXPECT_THAT(parse_error("<?xml version='1.0'?>\n<suite version='2'>\n"
                          "<case name='a' system='x.xml'><never signal='a.b'/></case></suite>"),
              StartsWith(at_line(2) + "unsupported suite format version \"2\""));
  EXPECT_EQ(parse_error("<suite version='1'><case name='a' system='x.xml'><never signal='a.b'/>"
                        "</case></suite>"),
            "");
}

TEST(suite_parser, a_suite_without_cases_is_an_error) {
  EXPECT_THAT(parse_error("\n<suite name='empty'>\n</suite>"),
              StartsWith(at_line(2) + "the suite has no <case>"));
}

}  // namespace
}  // namespace stride::suite
