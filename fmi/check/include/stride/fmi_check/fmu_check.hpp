// Static checks of FMI 2.0 Co-Simulation and Model Exchange FMUs and FMI 3.0 Co-Simulation FMUs
// against the project's FMI rules (docs/fmi-rules.md §2, docs/fmi3-rules.md §8): archive layout,
// modelDescription.xml schema and semantic rules, ModelStructure consistency, and for 3.0 the
// functions the binary exports. The fmiVersion of the description chooses the rule set.
#ifndef STRIDE_FMI_CHECK_FMU_CHECK_HPP
#define STRIDE_FMI_CHECK_FMU_CHECK_HPP

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stride::fmi_check {

/// One problem found in an FMU. `rule` is a stable id such as "variable.start_required"
/// (see all_rules()); `message` names the entry, line or variable at fault.
struct finding {
  enum class severity { warning, error } level;
  std::string rule;
  std::string message;
};

/// Names of the entries of an FMU archive, in central-directory order.
using archive_listing = std::vector<std::string>;

/// Checks an .fmu file: reads the ZIP with libzip (nothing is extracted), checks the archive
/// rules, then the modelDescription.xml at its root together with the archive listing; for an
/// FMI 3.0 FMU also the dynamic symbols of binaries/x86_64-linux/<modelIdentifier>.so.
/// An unreadable file is reported as a finding (rule "archive.open"), never thrown.
std::vector<finding> check_fmu(const std::filesystem::path& fmu);

/// Checks the text of a modelDescription.xml. When `archive` is given, the rules that tie the
/// description to the archive content (binary named after modelIdentifier, platform folders)
/// are checked as well.
std::vector<finding> check_model_description(std::string_view xml,
                                             const archive_listing* archive = nullptr);

/// True when at least one finding is an error.
bool has_errors(std::span<const finding> findings);

/// "error" or "warning".
std::string_view to_string(finding::severity level);

/// "<file>: error: [rule] message", the line format of stride-fmu-check.
std::string format_finding(std::string_view file, const finding& f);

/// A rule id with a one-line summary of what it checks.
struct rule_description {
  std::string_view id;
  std::string_view summary;
};

/// Every rule id the checker can report, in the order of docs/fmi-rules.md, then of
/// docs/fmi3-rules.md §8.
std::span<const rule_description> all_rules();

}  // namespace stride::fmi_check

#endif  // STRIDE_FMI_CHECK_FMU_CHECK_HPP
