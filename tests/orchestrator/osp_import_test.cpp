// The OSP importer (OspSystemStructure.xml) without running anything: the fixture under
// data/ssp/pair_osp/ and documents written here, FMUs that hold only their modelDescription.xml.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "fake_fmu.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_import.hpp"

namespace stride::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path k_data = STRIDE_TEST_DATA_DIR;

const std::string k_head = R"(<?xml version="1.0" encoding="UTF-8"?>
<OspSystemStructure xmlns="http://opensimulationplatform.com/MSMI/OSPSystemStructure" version="0.1">
)";

const std::string k_simulators = R"(  <Simulators>
    <Simulator name="a" source="stride_test.fmu"/>
    <Simulator name="b" source="stride_test.fmu"/>
  </Simulators>
)";

// the simulators a and b with one connection
std::string connected(const std::string& connection) {
  return k_simulators + "  <Connections>\n    " + connection + "\n  </Connections>\n";
}

class osp_import : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-osp-test-"};

  void SetUp() override {
    test::write_fake_fmu(scratch.path() / "stride_test.fmu", test::stride_test_variables());
  }

  std::string document(const std::string& body) const {
    return k_head + body + "</OspSystemStructure>\n";
  }

  system_structure load(const std::string& body) const {
    const fs::path file = scratch.path() / "OspSystemStructure.xml";
    std::ofstream(file) << document(body);
    return load_system_file(file);
  }

  // the refusal of `body`, which must name the file and the line of `needle`
  std::string refusal(const std::string& body, const std::string& needle) const {
    const std::string text = document(body);
    const auto at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    try {
      load(body);
    } catch (const validation_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("OspSystemStructure.xml:" + std::to_string(line) + ": <"));
      return e.what();
    }
    ADD_FAILURE() << "not refused: " << needle;
    return {};
  }
};

TEST_F(osp_import, the_pair_fixture_becomes_the_system_of_stride_test_pair_xml) {
  fs::copy_file(k_data / "ssp" / "pair_osp" / "OspSystemStructure.xml",
                scratch.path() / "OspSystemStructure.xml");
  const system_structure s = load_system_file(scratch.path());
  EXPECT_EQ(s.name, fs::path(scratch.path()).filename().string());
  EXPECT_EQ(s.stop, time_point(std::chrono::seconds(1)));
  EXPECT_EQ(s.base_step, std::chrono::milliseconds(10));
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[0].step_multiple, 1);  // stepSize 0.01 on a base step of 0.01
  EXPECT_EQ(s.components[0].fmu, "stride_test.fmu");
  ASSERT_EQ(s.components[0].parameters.size(), 6u);
  EXPECT_EQ(s.components[0].parameters[2].variable, "label");
  EXPECT_EQ(s.components[0].parameters[2].value, "hello");
  std::vector<std::pair<std::string, std::string>> wires;
  for (const auto& c : s.connections) wires.emplace_back(c.from, c.to);
  // each connection runs from its output, whichever Variable comes first
  EXPECT_EQ(wires,
            (std::vector<std::pair<std::string, std::string>>{{"a.y", "b.u"},
                                                              {"a.counter", "b.n"},
                                                              {"a.active", "b.enable"},
                                                              {"a.echo", "b.suffix"},
                                                              {"a.vec_out[1]", "b.vec_in[1]"},
                                                              {"a.vec_out[2]", "b.vec_in[2]"},
                                                              {"a.vec_out[3]", "b.vec_in[3]"}}));
  EXPECT_TRUE(s.record.signals.empty());  // every output recorded
}

TEST_F(osp_import, step_sizes_become_step_multiples_of_the_base_step) {
  const system_structure s = load(R"(  <StartTime>0.5</StartTime>
  <BaseStepSize>0.004</BaseStepSize>
  <Simulators>
    <Simulator name="a" source="stride_test.fmu" stepSize="0.012"/>
  </Simulators>
)");
  EXPECT_EQ(s.start, time_point(std::chrono::milliseconds(500)));
  EXPECT_FALSE(s.stop);
  EXPECT_EQ(s.components[0].step_multiple, 3);
  // without BaseStepSize libcosim steps by 0.1 s
  EXPECT_EQ(load(k_simulators).base_step, std::chrono::milliseconds(100));
}

TEST_F(osp_import, what_stride_does_not_do_is_refused_by_name) {
  EXPECT_THAT(
      refusal(
          connected(
              R"(<SignalConnection><Variable simulator="a" name="y"/><Signal function="f" name="in"/></SignalConnection>)"),
          "<SignalConnection"),
      HasSubstr("<SignalConnection>: not supported: Stride reads VariableConnection only"));
  EXPECT_THAT(
      refusal(
          connected(
              R"(<VariableGroupConnection><VariableGroup simulator="a" name="g"/><VariableGroup simulator="b" name="g"/></VariableGroupConnection>)"),
          "<VariableGroupConnection"),
      HasSubstr("not supported"));
  EXPECT_THAT(
      refusal(k_simulators + "  <Functions><Sum name=\"s\" inputCount=\"2\"/></Functions>\n",
              "<Functions"),
      HasSubstr("<Functions>: not supported"));
  EXPECT_THAT(refusal("  <Algorithm>ecco</Algorithm>\n" + k_simulators, "<Algorithm"),
              HasSubstr("<Algorithm>: algorithm \"ecco\" is not supported"));
}

TEST_F(osp_import, errors_name_file_line_and_element) {
  EXPECT_THAT(
      refusal(
          connected(
              R"(<VariableConnection><Variable simulator="a" name="nothing"/><Variable simulator="b" name="u"/></VariableConnection>)"),
          "name=\"nothing\""),
      HasSubstr("<Variable name=\"nothing\">: simulator 'a' has no variable so named"));
  EXPECT_THAT(
      refusal(
          connected(
              R"(<VariableConnection><Variable simulator="c" name="y"/><Variable simulator="b" name="u"/></VariableConnection>)"),
          "simulator=\"c\""),
      HasSubstr("no simulator is named \"c\""));
  EXPECT_THAT(
      refusal(
          connected(
              R"(<VariableConnection><Variable simulator="a" name="u"/><Variable simulator="b" name="u"/></VariableConnection>)"),
          "<VariableConnection>"),
      HasSubstr("a connection joins an output and an input"));
  EXPECT_THAT(refusal(R"(  <BaseStepSize>0.01</BaseStepSize>
  <Simulators><Simulator name="a" source="stride_test.fmu" stepSize="0.015"/></Simulators>
)",
                      "<Simulator "),
              HasSubstr("stepSize 0.015 s is not a whole multiple of the base step 0.01 s"));
  EXPECT_THAT(refusal(R"(  <Simulators><Simulator name="a" source="none.fmu"/></Simulators>
)",
                      "<Simulator "),
              HasSubstr("<Simulator name=\"a\">: FMU \"none.fmu\" not found"));
  EXPECT_THAT(refusal(R"(  <Simulators><Simulator name="a" source="stride_test.fmu">
    <InitialValues><InitialValue variable="n"><Real value="1.5"/></InitialValue></InitialValues>
  </Simulator></Simulators>
)",
                      "<Real"),
              HasSubstr("<Real>: a Real value for a.n, which is Integer"));
  EXPECT_THAT(
      refusal(
          R"(  <Simulators><Simulator name="a" source="stride_test.fmu" colour="red"/></Simulators>
)",
          "colour"),
      HasSubstr("unknown attribute 'colour'"));
  EXPECT_THAT(refusal(k_simulators + "  <EndTime>2</EndTime>\n", "<EndTime"),
              HasSubstr("out of order"));
}

}  // namespace
}  // namespace stride::cosim
