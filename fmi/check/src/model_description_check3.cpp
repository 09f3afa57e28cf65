// FMI 3.0 modelDescription.xml (docs/fmi3-rules.md §5): the vocabulary of the 3.0 checkers and
// the order in which they run.
#include <array>

#include "model_description_check3.hpp"
#include "xs_values.hpp"

namespace stride::fmi_check::detail {

namespace {

constexpr std::array<std::string_view, 15> k_kind_names = {
    "Float32", "Float64", "Int8",    "UInt8",  "Int16",  "UInt16",      "Int32", "UInt32",
    "Int64",   "UInt64",  "Boolean", "String", "Binary", "Enumeration", "Clock"};

constexpr std::array<std::string_view, 7> k_causality_names = {
    "parameter",   "calculatedParameter", "input", "output", "local",
    "independent", "structuralParameter"};

}  // namespace

std::optional<kind3> parse_kind3(std::string_view element) {
  for (std::size_t i = 0; i < k_kind_names.size(); ++i) {
    if (k_kind_names[i] == element) return static_cast<kind3>(i);
  }
  return std::nullopt;
}

std::string_view to_string(kind3 k) {
  return k_kind_names[static_cast<std::size_t>(k)];
}

bool is_float(kind3 k) {
  return k == kind3::float32 || k == kind3::float64;
}

bool is_integer(kind3 k) {
  return k >= kind3::int8 && k <= kind3::uint64;
}

bool is_signed(kind3 k) {
  return k == kind3::int8 || k == kind3::int16 || k == kind3::int32 || k == kind3::int64;
}

std::optional<causality3> parse_causality3(std::string_view text) {
  for (std::size_t i = 0; i < k_causality_names.size(); ++i) {
    if (k_causality_names[i] == text) return static_cast<causality3>(i);
  }
  return std::nullopt;
}

std::string_view to_string(causality3 c) {
  return k_causality_names[static_cast<std::size_t>(c)];
}

const variable3* md3_context::find(std::uint32_t vr) const {
  const auto it = by_vr.find(vr);
  return it == by_vr.end() ? nullptr : &vars[it->second];
}

std::string describe(const variable3& v) {
  return "line " + std::to_string(v.line) + ": variable " + quote(v.name) + " (index " +
         std::to_string(v.index) + ")";
}

void check_model_description3(reporter& out, const XMLElement& root, const archive_listing* archive,
                              std::string* model_identifier) {
  md3_context md(out);
  // the checkers of elements 2.0 and 3.0 define alike only report through md_context::out
  md_context shared(out);
  check_root_attributes3(md, root);
  check_child_order(
      out, root,
      {"ModelExchange", "CoSimulation", "ScheduledExecution", "UnitDefinitions", "TypeDefinitions",
       "LogCategories", "DefaultExperiment", "ModelVariables", "ModelStructure", "Annotations"});
  check_interfaces3(md, root);
  check_unit_definitions3(md, root.FirstChildElement("UnitDefinitions"));
  check_type_definitions3(md, root.FirstChildElement("TypeDefinitions"));
  check_log_categories(shared, root.FirstChildElement("LogCategories"));
  check_default_experiment(shared, root.FirstChildElement("DefaultExperiment"));
  check_model_variables3(md, root.FirstChildElement("ModelVariables"));
  check_model_structure3(md, root.FirstChildElement("ModelStructure"));
  if (archive != nullptr) {
    check_archive_ties3(out, *archive, md.model_identifier, md.me_model_identifier);
  }
  // the binary whose exports are checked: either interface's (3.0 binaries export everything)
  if (model_identifier != nullptr) {
    *model_identifier = md.model_identifier.empty() ? md.me_model_identifier : md.model_identifier;
  }
}

}  // namespace stride::fmi_check::detail
