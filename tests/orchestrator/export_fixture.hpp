// What the SSP and OSP export tests share: a scratch folder with a stride_test FMU that holds
// only its modelDescription.xml, a system XML using it with every kind of value and connection,
// and one-line summaries of systems to compare what an importer reads back.
#ifndef STRIDE_TESTS_ORCHESTRATOR_EXPORT_FIXTURE_HPP
#define STRIDE_TESTS_ORCHESTRATOR_EXPORT_FIXTURE_HPP

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fake_fmu.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_export.hpp"
#include "stride/cosim/system_import.hpp"

namespace stride::cosim::test {

/// a → b through every value type, a transformed and a delayed connection, a group connection
/// and values needing canonical text ("1" for a Boolean, "+7") or escaping
inline const std::string k_export_system = R"(<?xml version="1.0" encoding="UTF-8"?>
<system name="pair" description="two of stride_test" version="1">
  <simulation start="0.5" stop="2" step="0.01" algorithm="jacobi"/>
  <component name="a" fmu="fmus/stride_test.fmu">
    <parameter name="gain" value="3"/>
    <parameter name="enable" value="1"/>
    <parameter name="label" value="a &amp; &lt;b&gt; &quot;c&quot;"/>
    <parameter name="n" value="+7"/>
  </component>
  <component name="b" fmu="fmus/stride_test.fmu"/>
  <connection from="a.y" to="b.u" factor="2" offset="1"/>
  <connection from="a.counter" to="b.n" delay="true"/>
  <connection from="a.vec_out[*]" to="b.vec_in[*]"/>
  <connection from="a.echo" to="b.suffix"/>
</system>
)";

class export_fixture : public ::testing::Test {
 protected:
  temp_dir scratch{"stride-export-test-"};
  export_options options;

  void SetUp() override {
    write_fake_fmu(scratch.path() / "fmus" / "stride_test.fmu", stride_test_variables());
  }

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = scratch.path() / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

  system_structure system_xml(const std::string& text = k_export_system) const {
    return load_system_file(write("pair.xml", text));
  }

  // The message with which `export_to` (export_ssp or export_osp) refuses `s` when writing to
  // `target` in the scratch folder; nothing may be written.
  template <class Export>
  std::string refusal(Export export_to, const system_structure& s,
                      const std::string& target) const {
    const std::filesystem::path path = scratch.path() / target;
    try {
      export_to(s, path, options);
    } catch (const validation_error& e) {
      EXPECT_FALSE(std::filesystem::exists(path)) << e.what();
      return e.what();
    }
    ADD_FAILURE() << "exported";
    return {};
  }

  // a system built in code: a and b of the fake FMU (no file and line in messages)
  system_structure in_code() const {
    system_structure s;
    s.base_dir = scratch.path();
    s.base_step = duration_from_seconds(0.01);
    s.add_component("a", "fmus/stride_test.fmu");
    s.add_component("b", "fmus/stride_test.fmu");
    return s;
  }
};

/// The components (name, FMU file name, values) and connections of `s`, one line each, and its
/// times and algorithm: what an export must keep.
inline std::vector<std::string> summary(const system_structure& s) {
  const auto number = [](double x) {
    std::ostringstream text;
    text << x;
    return text.str();
  };
  std::vector<std::string> out;
  out.push_back("start " + format_seconds(s.start) + " stop " +
                (s.stop ? format_seconds(*s.stop) : "-") + " step " +
                (s.base_step ? format_seconds(*s.base_step) : "-") + " " +
                std::string(to_string(s.algorithm)));
  for (const auto& c : s.components) {
    std::string line = "component " + c.name + " " +
                       std::filesystem::path(c.fmu).filename().string() + " x" +
                       std::to_string(c.step_multiple);
    for (const auto& p : c.parameters) line += " " + p.variable + "=" + p.value;
    out.push_back(line);
  }
  for (const auto& c : s.connections) {
    out.push_back("connection " + c.from + " -> " + c.to + (c.delayed ? " delayed" : "") +
                  (c.transforms() ? " * " + number(c.factor) + " + " + number(c.offset) : ""));
  }
  return out;
}

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_EXPORT_FIXTURE_HPP
