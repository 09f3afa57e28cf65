// FMU archives that hold only a modelDescription.xml, made at test time: enough for the
// importers of foreign system formats, which read what an FMU declares but load no binary.
#ifndef STRIDE_TESTS_ORCHESTRATOR_FAKE_FMU_HPP
#define STRIDE_TESTS_ORCHESTRATOR_FAKE_FMU_HPP

#include <filesystem>
#include <string>
#include <vector>

#include "zip_writer.hpp"

namespace stride::cosim::test {

struct fake_variable {
  std::string name;
  std::string causality;  ///< input, output, parameter, calculatedParameter
  std::string type;       ///< Real, Integer, Boolean, String
  std::string unit;       ///< Real only; "" for none
};

/// A modelDescription.xml declaring `variables`; without `co_simulation` only ModelExchange.
inline std::string fake_model_description(const std::vector<fake_variable>& variables,
                                          bool co_simulation = true) {
  std::string md =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"fake\" guid=\"{fake}\">\n";
  md += co_simulation ? "  <CoSimulation modelIdentifier=\"fake\"/>\n"
                      : "  <ModelExchange modelIdentifier=\"fake\"/>\n";
  md += "  <ModelVariables>\n";
  int reference = 0;
  for (const auto& v : variables) {
    const bool parameter = v.causality == "parameter" || v.causality == "calculatedParameter";
    const bool real = v.type == "Real";
    std::string attributes = "name=\"" + v.name + "\" valueReference=\"" +
                             std::to_string(reference++) + "\" causality=\"" + v.causality + "\"";
    if (parameter) {
      attributes += v.causality == "parameter" ? " variability=\"fixed\""
                                               : " variability=\"fixed\" initial=\"calculated\"";
    } else if (!real) {
      attributes += " variability=\"discrete\"";
    }
    std::string type = "<" + v.type;
    if (!v.unit.empty()) type += " unit=\"" + v.unit + "\"";
    if (v.causality == "input" || v.causality == "parameter") {
      type += v.type == "Boolean"  ? " start=\"false\""
              : v.type == "String" ? " start=\"\""
                                   : " start=\"0\"";
    }
    md += "    <ScalarVariable " + attributes + ">" + type + "/></ScalarVariable>\n";
  }
  md += "  </ModelVariables>\n  <ModelStructure/>\n</fmiModelDescription>\n";
  return md;
}

inline void write_fake_fmu(const std::filesystem::path& file,
                           const std::vector<fake_variable>& variables, bool co_simulation = true) {
  std::filesystem::create_directories(file.parent_path());
  write_zip(file, {{"modelDescription.xml", fake_model_description(variables, co_simulation)}});
}

/// The interface of the stride_test FMU (components/test_fmu), as its names, kinds and types.
inline std::vector<fake_variable> stride_test_variables() {
  std::vector<fake_variable> v = {{"gain", "parameter", "Real", ""},
                                  {"offset", "parameter", "Real", ""},
                                  {"u", "input", "Real", ""},
                                  {"y", "output", "Real", ""},
                                  {"integral", "output", "Real", "s"},
                                  {"n", "input", "Integer", ""},
                                  {"counter", "output", "Integer", ""},
                                  {"enable", "input", "Boolean", ""},
                                  {"active", "output", "Boolean", ""},
                                  {"label", "parameter", "String", ""},
                                  {"suffix", "input", "String", ""},
                                  {"echo", "output", "String", ""},
                                  {"stop_after_steps", "parameter", "Integer", ""}};
  for (int i = 1; i <= 3; ++i) {
    v.push_back({"vec_in[" + std::to_string(i) + "]", "input", "Real", ""});
    v.push_back({"vec_out[" + std::to_string(i) + "]", "output", "Real", ""});
  }
  return v;
}

}  // namespace stride::cosim::test

#endif  // STRIDE_TESTS_ORCHESTRATOR_FAKE_FMU_HPP
