// `stride security init|add|show`: DDS Security keystores for Stride's workers
// (docs/distributed.md; stride/remote/keystore.hpp).
#ifndef STRIDE_CLI_SECURITY_HPP
#define STRIDE_CLI_SECURITY_HPP

#include <CLI/CLI.hpp>

#include <string>

namespace stride::cli {

struct security_arguments {
  std::string dir;   ///< the keystore (init, add), or a keystore or identity folder (show)
  std::string name;  ///< add: the identity
  std::string domains = "0";
  std::string protection = "encrypt";
  int ca_valid_days = 3650;
  int identity_valid_days = 365;
  CLI::App* init = nullptr;
  CLI::App* add = nullptr;
  CLI::App* show = nullptr;
};

CLI::App* add_security_command(CLI::App& app, security_arguments& args);

/// Runs the chosen subcommand; errors are thrown (std::runtime_error naming the file).
int security(const security_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_SECURITY_HPP
