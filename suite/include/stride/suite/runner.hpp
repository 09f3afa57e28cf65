// Running a suite: each case is a `stride run` of its own process (a crash is that case's
// error, not the suite's), up to `jobs` at a time; then its assertions, a summary and JUnit XML.
#ifndef STRIDE_SUITE_RUNNER_HPP
#define STRIDE_SUITE_RUNNER_HPP

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "stride/suite/assertions.hpp"
#include "stride/suite/suite.hpp"

namespace stride::suite {

struct run_settings {
  std::filesystem::path stride;      ///< the executable that runs a case (`stride run ...`)
  std::filesystem::path output_dir;  ///< one folder per case below it
  int jobs = 1;
  std::string filter;  ///< glob on case names; empty = every case
  assertion_registry kinds = builtin_assertions();
  std::FILE* progress = nullptr;  ///< one line per finished case, or nothing
};

enum class case_status { passed, failed, error };

struct case_report {
  std::string name;
  case_status status = case_status::error;
  std::vector<std::string> failures;  ///< "file:line: kind: why", one per failed assertion
  std::string error;                  ///< why the case could not run
  double seconds = 0;
  std::filesystem::path dir;
};

struct suite_report {
  std::vector<case_report> cases;  ///< in the suite's order
  double seconds = 0;
  std::size_t count(case_status s) const;
};

/// Checks every case before anything runs: its system file exists; its assertions against
/// `kinds` (unknown kinds and attributes, bad values, missing reference files). \throws
/// cosim::validation_error naming file and line.
void check_suite(const suite_spec& suite, const assertion_registry& kinds);

/// Runs the cases whose names match the filter. \throws cosim::validation_error when the filter
/// matches no case.
suite_report run_suite(const suite_spec& suite, const run_settings& settings);

/// Readable summary: a line per case, each failing assertion below its case, and the closing
/// line "N passed, N failed" (errors are failed cases, also counted on their own).
std::string format_summary(const suite_report& report);

/// JUnit XML as CI systems read it: one testsuite, one testcase per case with its time, a
/// <failure> per failed case holding every failed assertion, an <error> for a case that could
/// not run. \throws std::runtime_error when the file cannot be written.
void write_junit(const std::filesystem::path& file, const suite_spec& suite,
                 const suite_report& report);

}  // namespace stride::suite

#endif  // STRIDE_SUITE_RUNNER_HPP
