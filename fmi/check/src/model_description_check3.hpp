// What the FMI 3.0 checkers of one modelDescription.xml share (docs/fmi3-rules.md §5, §6).
// model_description_check.cpp dispatches here when fmiVersion starts with "3."; the elements
// both versions define alike (LogCategories, DefaultExperiment, the child order) are checked by
// the 2.0 functions of model_description_check.hpp.
#ifndef STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK3_HPP
#define STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK3_HPP

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "model_description_check.hpp"

namespace stride::fmi_check::detail {

/// The variable elements of FMI 3.0, named as in the schema.
enum class kind3 : std::uint8_t {
  float32,
  float64,
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  int64,
  uint64,
  boolean,
  string,
  binary,
  enumeration,
  clock
};
std::optional<kind3> parse_kind3(std::string_view element);
std::string_view to_string(kind3 k);
bool is_float(kind3 k);
/// The eight integer kinds (Enumeration aside).
bool is_integer(kind3 k);
bool is_signed(kind3 k);

/// FMI 2.0's causalities plus structuralParameter.
enum class causality3 : std::uint8_t {
  parameter,
  calculated_parameter,
  input,
  output,
  local,
  independent,
  structural_parameter
};
std::optional<causality3> parse_causality3(std::string_view text);
std::string_view to_string(causality3 c);

/// One variable element as far as it could be read.
struct variable3 {
  std::size_t index = 0;  // 1-based position in ModelVariables
  int line = 0;
  std::string name;
  std::optional<std::uint32_t> vr;
  std::optional<kind3> kind;
  const XMLElement* element = nullptr;
  std::optional<causality3> caus;
  std::optional<fmi2::variability> var;
  std::optional<fmi2::initial_kind> initial;   // effective value (given or default)
  bool has_start = false;                      // start attribute or <Start> children
  std::optional<std::uint32_t> derivative_of;  // valueReference of the state, when valid
};

/// Where findings go and what earlier checkers learnt, for the later ones.
struct md3_context {
  explicit md3_context(reporter& r) : out(r) {}

  reporter& out;
  std::string model_identifier;     // of <CoSimulation>, when a C identifier
  std::string me_model_identifier;  // of <ModelExchange>, when a C identifier
  /// Unit name -> its DisplayUnit names.
  std::map<std::string, std::set<std::string, std::less<>>, std::less<>> units;
  /// TypeDefinitions name -> element (Float64Type, EnumerationType, ...).
  std::map<std::string, const XMLElement*, std::less<>> types;
  std::vector<variable3> vars;
  /// valueReference -> position in vars (the first variable with it).
  std::map<std::uint32_t, std::size_t> by_vr;

  const variable3* find(std::uint32_t vr) const;
};

std::string describe(const variable3& v);

/// The checks of an FMI 3.0 description; `model_identifier` receives CoSimulation's, if valid.
void check_model_description3(reporter& out, const XMLElement& root, const archive_listing* archive,
                              std::string* model_identifier);

// --- root attributes, interface types, UnitDefinitions, TypeDefinitions (root_check3.cpp)
void check_root_attributes3(md3_context& md, const XMLElement& root);
void check_interfaces3(md3_context& md, const XMLElement& root);
void check_unit_definitions3(md3_context& md, const XMLElement* ud);
void check_type_definitions3(md3_context& md, const XMLElement* td);

// --- variable elements and their combinations (variables_check3.cpp)
void check_model_variables3(md3_context& md, const XMLElement* mv);

// --- start values, ranges, units, dimensions (start_values_check3.cpp)
/// Whether `v` must or must not have a start; `initial_given` tells whether initial was written.
void check_start_presence3(md3_context& md, const variable3& v, bool initial_given);
/// start, min, max, nominal parse as the variable's kind and fit together; unit and declaredType.
void check_values3(md3_context& md, const variable3& v);
/// Dimensions and the number of start values; needs every variable, so it runs after all.
void check_dimensions3(md3_context& md, const variable3& v);

// --- ModelStructure (model_structure_check3.cpp)
void check_model_structure3(md3_context& md, const XMLElement* ms);

// --- the archive next to the description (archive_check3.cpp)
/// binaries/x86_64-linux/<modelIdentifier>.so, and no FMI 2.0 platform folder.
void check_archive_ties3(reporter& out, const archive_listing& archive,
                         std::string_view model_identifier, std::string_view me_model_identifier);
/// The dynamic symbols of the binary `entry` (the bytes of an ELF shared object) include every
/// function of the FMI 3.0 C API, as functions.
void check_exports3(reporter& out, std::string_view entry, std::string_view bytes);

}  // namespace stride::fmi_check::detail

#endif  // STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK3_HPP
