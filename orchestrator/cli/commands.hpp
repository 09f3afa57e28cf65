// The stride subcommands; each returns the process exit code and throws on errors.
#ifndef STRIDE_CLI_COMMANDS_HPP
#define STRIDE_CLI_COMMANDS_HPP

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::cli {

struct run_arguments {
  std::optional<std::filesystem::path> system;  ///< nullopt = embedded default scenario
  std::optional<std::string> stop_time;
  std::filesystem::path output;
  std::vector<std::string> sets;
  bool quiet = false;
  bool fmu_debug_log = false;
  std::filesystem::path resume;  ///< --resume DIR (empty: a new run)
  bool no_plots = false;         ///< skip the figures after a learner run
  int threads = 1;               ///< --threads
};

struct validate_arguments {
  std::filesystem::path file;
  std::optional<std::string> stop_time;
  std::vector<std::string> sets;
  bool quiet = false;
};

int run(const run_arguments& args);
int inspect(const std::filesystem::path& fmu_file);
int validate(const validate_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_COMMANDS_HPP
