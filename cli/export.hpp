// `stride export SYSTEM --ssp OUT.ssp | --osp DIR`: a system of any format Stride reads written
// as an SSP 1.0 archive or an OSP system structure (stride/cosim/system_export.hpp,
// docs/ssp.md "Export").
#ifndef STRIDE_CLI_EXPORT_HPP
#define STRIDE_CLI_EXPORT_HPP

#include <CLI/CLI.hpp>

#include <filesystem>

namespace stride::cli {

struct export_arguments {
  std::filesystem::path system;
  std::filesystem::path ssp;  ///< --ssp OUT.ssp (empty: not asked for)
  std::filesystem::path osp;  ///< --osp DIR
  bool force = false;
  bool quiet = false;
};

/// Adds the `export` subcommand filling `args`.
CLI::App* add_export_command(CLI::App& app, export_arguments& args);

/// Reads the system and writes it; returns the exit code. \throws validation_error.
int export_system(const export_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_EXPORT_HPP
