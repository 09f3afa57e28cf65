// `stride calibrate`: fits the gait's offsets to a static posture (docs/calibration.md).
#ifndef STRIDE_CLI_CALIBRATE_HPP
#define STRIDE_CLI_CALIBRATE_HPP

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace stride::cli {

struct calibrate_arguments {
  std::string target;
  std::string config;
  std::string output;
  std::string fit;  ///< comma-separated offsets; empty = the mode's default
  std::string mode = "joints";
  std::string ik = "darwin";
  std::vector<std::string> bounds;  ///< "offset=lo:hi"
  double loss_scale = 2.0;
  std::string system;  ///< plant mode: system XML with components gait and robot
  std::string report;  ///< also write the report to this file
  bool quiet = false;
};

/// Exit codes of `stride calibrate` besides 0 (written) and 1 (error, nothing written).
inline constexpr int calibrate_not_converged = 3;

/// Adds the `calibrate` subcommand to `app`; parsing fills `args`.
CLI::App* add_calibrate_command(CLI::App& app, calibrate_arguments& args);

/// Runs it: 0 = fitted and written, calibrate_not_converged = written but the solver did not
/// converge; throws on errors (the caller prints them and exits with 1).
int calibrate(const calibrate_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_CALIBRATE_HPP
