// Assertion kinds: what each element of a case checks on the case's recorded signals (or on other
// files of its output folder, for kinds an application adds).
#ifndef STRIDE_SUITE_ASSERTIONS_HPP
#define STRIDE_SUITE_ASSERTIONS_HPP

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "stride/suite/results.hpp"
#include "stride/suite/suite.hpp"

namespace stride::suite {

/// What a finished case offers its assertions.
struct case_output {
  std::filesystem::path dir;        ///< the run's output folder
  const recorded_signals* signals;  ///< its results CSV, read back
  std::filesystem::path suite_dir;  ///< the suite file's folder (for reference files)
};

/// How one assertion came out.
struct outcome {
  bool passed = false;
  std::string message;  ///< why it failed: signal, time, value and bound
};

/// One kind of assertion (an element name in a case).
struct assertion_kind {
  std::vector<std::string> attributes;  ///< the attributes it takes; others are errors
  /// Checks the attribute values before anything runs. \throws std::invalid_argument.
  std::function<void(const assertion_spec&, const std::filesystem::path& suite_dir)> check;
  /// The signal patterns the case must record for it.
  std::function<std::vector<std::string>(const assertion_spec&,
                                         const std::filesystem::path& suite_dir)>
      signals;
  std::function<outcome(const assertion_spec&, const case_output&)> evaluate;
};

using assertion_registry = std::map<std::string, assertion_kind>;

/// never, eventually, bounds, final, mean, rate, speed, reference (docs/regression-suites.md).
assertion_registry builtin_assertions();

}  // namespace stride::suite

#endif  // STRIDE_SUITE_ASSERTIONS_HPP
