// Collects findings; every rule id must be listed in all_rules().
#ifndef STRIDE_FMI_CHECK_REPORTER_HPP
#define STRIDE_FMI_CHECK_REPORTER_HPP

#include <string>
#include <string_view>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"

namespace stride::fmi_check::detail {

class reporter {
 public:
  /// Throws std::logic_error for a rule id missing from all_rules(): a checker bug.
  void error(std::string_view rule, std::string message);
  void warning(std::string_view rule, std::string message);
  void append(std::vector<finding> more);

  std::vector<finding> take() { return std::move(findings_); }

 private:
  void add(finding::severity level, std::string_view rule, std::string message);

  std::vector<finding> findings_;
};

}  // namespace stride::fmi_check::detail

#endif  // STRIDE_FMI_CHECK_REPORTER_HPP
