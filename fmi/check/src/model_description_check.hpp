// What the checkers of one modelDescription.xml share. model_description_check.cpp parses the
// text and calls the checkers in document order; each rule family lives in its own file.
#ifndef STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK_HPP
#define STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK_HPP

#include <tinyxml2.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reporter.hpp"
#include "stride/fmi2/vocabulary.hpp"
#include "stride/fmi_check/fmu_check.hpp"

namespace stride::fmi_check::detail {

using tinyxml2::XMLElement;

/// One ScalarVariable as far as it could be read.
struct variable {
  std::size_t index = 0;  // 1-based position in ModelVariables
  int line = 0;
  std::string name;
  std::optional<std::uint32_t> vr;
  std::optional<fmi2::value_type> type;  // empty when the type child is broken
  const XMLElement* type_element = nullptr;
  std::optional<fmi2::causality> caus;
  std::optional<fmi2::variability> var;
  std::optional<fmi2::initial_kind> initial;  // effective value (given or default)
  bool has_start = false;
  std::optional<std::size_t> derivative_of;  // Real@derivative, when valid
};

struct simple_type {
  std::string type;  // base type element name, as written
  const XMLElement* element = nullptr;
};

/// Where findings go and what earlier checkers learnt, for the later ones.
struct md_context {
  explicit md_context(reporter& r) : out(r) {}

  reporter& out;
  std::string model_identifier;     // set by check_co_simulation when valid
  bool model_exchange = false;      // a <ModelExchange> element is present
  std::string me_model_identifier;  // set by check_model_exchange when valid
  std::map<std::string, simple_type, std::less<>> simple_types;  // by check_type_definitions
  std::vector<variable> vars;                                    // by check_model_variables
};

// --- shared helpers (model_description_check.cpp)
std::string at(const XMLElement& e);
std::string describe(const variable& v);
/// Reports every attribute of `e` the schema of `version` ("2.0" or "3.0") does not define
/// ("schema.attribute").
void check_attributes(reporter& out, const XMLElement& e, const std::set<std::string_view>& allowed,
                      std::string_view version = "2.0");
/// Reports unknown, repeated and misplaced children of `parent` ("structure.child_order").
void check_child_order(reporter& out, const XMLElement& parent,
                       std::initializer_list<std::string_view> sequence);

/// check_model_description, telling also the major FMI version (2 or 3, when the root element
/// is readable) and the CoSimulation modelIdentifier ("" if invalid); either may be null.
std::vector<finding> check_description(std::string_view xml, const archive_listing* archive,
                                       int* major_version, std::string* model_identifier);

// --- fmiModelDescription attributes, CoSimulation, LogCategories, DefaultExperiment
// (root_check.cpp)
void check_root_attributes(md_context& md, const XMLElement& root);
/// <CoSimulation> and <ModelExchange>: at least one of them, each checked when present.
void check_interfaces(md_context& md, const XMLElement& root);
/// The rules <CoSimulation> and <ModelExchange> share: allowed attributes, xs:boolean `flags`
/// (rule `<rule>.flag`), a C-identifier modelIdentifier (`<rule>.model_identifier`). Returns the
/// identifier, or "" when it is missing or not valid.
std::string check_interface_element(md_context& md, const XMLElement& element,
                                    const std::string& rule,
                                    std::initializer_list<std::string_view> flags,
                                    std::initializer_list<std::string_view> other_attributes);
void check_co_simulation(md_context& md, const XMLElement& cs);
void check_log_categories(md_context& md, const XMLElement* lc);
void check_default_experiment(md_context& md, const XMLElement* de);

// --- SimpleTypes and the type element of each variable (type_definitions_check.cpp)
void check_type_definitions(md_context& md, const XMLElement* td);
/// Attributes and declaredType of `v.type_element`; sets `v.has_start`.
void check_type_element(md_context& md, variable& v);

// --- ScalarVariables and their combinations (variables_check.cpp)
void check_model_variables(md_context& md, const XMLElement* mv);

// --- start values and ranges (start_values_check.cpp)
/// Whether `v` must or must not have a start; `initial_given` tells whether initial was written.
void check_start_presence(md_context& md, const variable& v, bool initial_given);
/// start, min, max, nominal and the other value attributes parse and fit together.
void check_values(md_context& md, const variable& v);

// --- ModelStructure (model_structure_check.cpp)
void check_model_structure(md_context& md, const XMLElement* ms);

// --- Model Exchange (model_exchange_check.cpp)
/// The attributes of <ModelExchange>; sets `md.model_exchange` and `md.me_model_identifier`.
void check_model_exchange(md_context& md, const XMLElement& me);
/// The continuous states of an FMU with <ModelExchange>, as <ModelStructure><Derivatives>
/// defines them; run after check_model_structure.
void check_model_exchange_states(md_context& md, const XMLElement* ms);

// --- the archive next to the description (archive_check.cpp)
/// How one FMI version lays out its binaries, for check_binary_layout.
struct binary_layout {
  std::string_view platform_dir;  ///< "linux64" (2.0) or "x86_64-linux" (3.0)
  /// the other version's folder names that this version's importers do not look into, each
  /// with this version's name for the same platform
  const std::map<std::string_view, std::string_view>& foreign_dirs;
  std::string_view foreign_kind;  ///< what those folders are, for the message
  std::string_view version;       ///< "FMI 2" or "FMI 3.0", for the message
  std::string_view rule_prefix;   ///< "" (2.0) or "fmi3." (3.0)
};
/// A binary the description names: the modelIdentifier ("" if invalid) of one interface element.
struct binary_name {
  std::string_view model_identifier;
  std::string_view element;  ///< "CoSimulation" or "ModelExchange"
};
/// Platform folders, and one binary per distinct modelIdentifier of `binaries`.
void check_binary_layout(reporter& out, const archive_listing& archive,
                         std::span<const binary_name> binaries, const binary_layout& layout);
/// The FMI 2.0 ties; `me_model_identifier` is "" without a valid <ModelExchange>.
void check_archive_ties(reporter& out, const archive_listing& archive,
                        std::string_view model_identifier, std::string_view me_model_identifier);

}  // namespace stride::fmi_check::detail

#endif  // STRIDE_FMI_CHECK_MODEL_DESCRIPTION_CHECK_HPP
