// stride-fmu-check: static FMI 2.0 (Co-Simulation and Model Exchange) and FMI 3.0 Co-Simulation
// checks of .fmu files (or bare modelDescription.xml files) from the command line.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "stride/fmi_check/fmu_check.hpp"

namespace {

constexpr std::string_view k_usage =
    "usage: stride-fmu-check [--list-rules] FILE.fmu|modelDescription.xml...\n"
    "\n"
    "Checks FMI 2.0 Co-Simulation and Model Exchange FMUs and FMI 3.0 Co-Simulation FMUs\n"
    "against the archive and modelDescription.xml rules of docs/fmi-rules.md and\n"
    "docs/fmi3-rules.md; fmiVersion chooses the rule set. For an\n"
    "FMI 3.0 FMU the binary's exported functions are read too (no code of the FMU is loaded).\n"
    "Each finding is printed as\n"
    "  FILE: error|warning: [rule] message\n"
    "A file ending in .xml is checked as a bare modelDescription.xml.\n"
    "\n"
    "options:\n"
    "  -h, --help     show this help\n"
    "  --list-rules   print every rule id with what it checks\n"
    "\n"
    "exit status: 0 when no file has an error, 1 when one has, 2 on a usage error\n";

}  // namespace

int main(int argc, char** argv) {
  namespace check = stride::fmi_check;
  std::vector<std::string> files;
  bool options_done = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (!options_done && (arg == "-h" || arg == "--help")) {
      std::cout << k_usage;
      return 0;
    }
    if (!options_done && arg == "--list-rules") {
      for (const auto& rule : check::all_rules()) {
        std::cout << rule.id << "  " << rule.summary << '\n';
      }
      return 0;
    }
    if (!options_done && arg == "--") {
      options_done = true;
      continue;
    }
    if (!options_done && arg.starts_with("-")) {
      std::cerr << "stride-fmu-check: unknown option " << arg << "\n\n" << k_usage;
      return 2;
    }
    files.emplace_back(arg);
  }
  if (files.empty()) {
    std::cerr << k_usage;
    return 2;
  }

  std::size_t errors = 0;
  std::size_t warnings = 0;
  for (const std::string& file : files) {
    std::vector<check::finding> findings;
    if (file.ends_with(".xml")) {
      std::ifstream in(file, std::ios::binary);
      if (!in) {
        std::cout << file << ": error: cannot read the file\n";
        ++errors;
        continue;
      }
      std::ostringstream text;
      text << in.rdbuf();
      findings = check::check_model_description(text.str());
    } else {
      findings = check::check_fmu(file);
    }
    for (const auto& f : findings) {
      std::cout << check::format_finding(file, f) << '\n';
      (f.level == check::finding::severity::error ? errors : warnings) += 1;
    }
  }
  std::cout.flush();
  std::cerr << "stride-fmu-check: " << files.size() << (files.size() == 1 ? " file, " : " files, ")
            << errors << (errors == 1 ? " error, " : " errors, ") << warnings
            << (warnings == 1 ? " warning\n" : " warnings\n");
  return errors == 0 ? 0 : 1;
}
