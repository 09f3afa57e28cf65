// A regression suite: cases, each a system run with overrides and assertions on what it
// recorded (docs/regression-suites.md, schema docs/stride-suite.xsd).
#ifndef STRIDE_SUITE_SUITE_HPP
#define STRIDE_SUITE_SUITE_HPP

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "stride/cosim/system_structure.hpp"

namespace stride::suite {

/// One assertion as written: its element name (the kind), its attributes and where it stands.
struct assertion_spec {
  std::string kind;
  std::map<std::string, std::string> attributes;
  cosim::source_location where;

  /// The attribute's text, or nullopt.
  std::optional<std::string> get(const std::string& name) const;
};

/// One case: a system run and what must hold for it to pass.
struct case_spec {
  std::string name;
  std::filesystem::path system;                ///< resolved against the suite file's folder
  std::optional<std::string> stop_time;        ///< seconds, replaces the system's
  std::optional<std::string> record_interval;  ///< seconds; default: the system's
  std::vector<std::string> sets;               ///< "comp.var=value", in order
  std::vector<assertion_spec> assertions;
  cosim::source_location where;
};

struct suite_spec {
  std::string name;
  std::filesystem::path file;
  std::vector<case_spec> cases;
};

/// Reads a suite file. Errors (malformed XML, unknown elements or attributes, a case without a
/// system or without assertions, duplicate case names) name the file and line.
/// \throws cosim::validation_error
suite_spec parse_suite_file(const std::filesystem::path& file);
suite_spec parse_suite_text(const std::string& xml, const std::filesystem::path& file);

}  // namespace stride::suite

#endif  // STRIDE_SUITE_SUITE_HPP
