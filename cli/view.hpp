// `stride view RUN_DIR`: the run viewer's page (stride/viewer/view.hpp).
#ifndef STRIDE_CLI_VIEW_HPP
#define STRIDE_CLI_VIEW_HPP

#include <CLI/CLI.hpp>

#include "stride/viewer/view.hpp"

namespace stride::cli {

struct view_arguments {
  viewer::view_options options;
  bool open = false;
  bool quiet = false;
};

/// Adds the `view` subcommand filling `args`.
CLI::App* add_view_command(CLI::App& app, view_arguments& args);

/// Writes the page (and opens it with --open); returns the exit code.
int view(const view_arguments& args);

}  // namespace stride::cli

#endif  // STRIDE_CLI_VIEW_HPP
