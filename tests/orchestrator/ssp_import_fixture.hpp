// What the SSP importer's tests share: SSDs written from pieces (a pair of stride_test
// components joined by one connection), FMUs that hold only their modelDescription.xml, and
// refusals checked to name the file and the line.
#ifndef STRIDE_TESTS_ORCHESTRATOR_SSP_IMPORT_FIXTURE_HPP
#define STRIDE_TESTS_ORCHESTRATOR_SSP_IMPORT_FIXTURE_HPP

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "fake_fmu.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_import.hpp"

namespace stride::cosim::test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

inline const fs::path k_data = STRIDE_TEST_DATA_DIR;

inline const std::string k_head = R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription version="1.0" name="t"
    xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues"
    xmlns:ssm="http://ssp-standard.org/SSP1/SystemStructureParameterMapping"
    xmlns:stride="https://stride-sim.org/ssp/1">
)";

// a → b: a.y feeds b.u through CONNECTION (replaced by each test); UNITS after the system
inline const std::string k_pair = R"(
  <ssd:System name="top">
    <ssd:Elements>
      <ssd:Component name="a" source="resources/stride_test.fmu">
        <ssd:Connectors><ssd:Connector name="y" kind="output">A_TYPE</ssd:Connector></ssd:Connectors>
      </ssd:Component>
      <ssd:Component name="b" source="resources/stride_test.fmu">
        <ssd:Connectors><ssd:Connector name="u" kind="input">B_TYPE</ssd:Connector></ssd:Connectors>
      </ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      CONNECTION
    </ssd:Connections>
  </ssd:System>
  UNITS
)";

inline const std::string k_units = R"(<ssd:Units>
    <ssc:Unit name="m"><ssc:BaseUnit m="1"/></ssc:Unit>
    <ssc:Unit name="km"><ssc:BaseUnit m="1" factor="1000"/></ssc:Unit>
    <ssc:Unit name="s"><ssc:BaseUnit s="1"/></ssc:Unit>
    <ssc:Unit name="degC"><ssc:BaseUnit K="1" offset="273.15"/></ssc:Unit>
    <ssc:Unit name="K"><ssc:BaseUnit K="1"/></ssc:Unit>
  </ssd:Units>)";

inline std::string replaced(std::string text, const std::string& key, const std::string& value) {
  const auto at = text.find(key);
  if (at != std::string::npos) text.replace(at, key.size(), value);
  return text;
}

// the pair with one connection element and optional connector types and units
inline std::string pair(const std::string& connection, const std::string& a_type = "",
                        const std::string& b_type = "", const std::string& units = "") {
  std::string body = replaced(k_pair, "CONNECTION", connection);
  body = replaced(body, "A_TYPE", a_type);
  body = replaced(body, "B_TYPE", b_type);
  return replaced(body, "UNITS", units);
}

inline const std::string k_plain = R"(<ssd:Connection startElement="a" startConnector="y"
                     endElement="b" endConnector="u"/>)";

// the 1-based line of the first `needle` in `text`: where a message must point
inline int line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

class ssp_import : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-ssp-test-"};
  std::vector<std::string> warnings;

  void SetUp() override {
    test::write_fake_fmu(scratch.path() / "resources" / "stride_test.fmu",
                         test::stride_test_variables());
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path file = scratch.path() / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

  // data/ssp/nested (ctrl drives the pump inside the system "engine")
  system_structure load_nested() const {
    const fs::path dir = scratch.path() / "nested";
    fs::copy(k_data / "ssp" / "nested", dir, fs::copy_options::recursive);
    test::write_fake_fmu(dir / "resources" / "stride_test.fmu", test::stride_test_variables());
    return load_system_file(dir);
  }

  std::string ssd(const std::string& body) const {
    return k_head + body + "\n</ssd:SystemStructureDescription>\n";
  }

  system_structure load(const std::string& body) {
    return load_system_file(write("t.ssd", ssd(body)),
                            [this](log_level, std::string_view, std::string_view,
                                   std::string_view message) { warnings.emplace_back(message); });
  }

  // the message of the refusal of `body`, which must point at the line of `needle`
  std::string refusal(const std::string& body, const std::string& needle,
                      const std::string& file = "t.ssd") {
    try {
      load(body);
    } catch (const validation_error& e) {
      const std::string where = (scratch.path() / file).string() + ":" +
                                std::to_string(line_of(ssd(body), needle)) + ": ";
      EXPECT_THAT(e.what(), HasSubstr(where)) << "expected the place " << where;
      return e.what();
    }
    ADD_FAILURE() << "not refused: " << needle;
    return {};
  }
};

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_SSP_IMPORT_FIXTURE_HPP
