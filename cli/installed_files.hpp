// Files that come with an installed Stride: `stride run walk.xml` finds the shipped example
// systems without the user knowing where the package put them.
#ifndef STRIDE_CLI_INSTALLED_FILES_HPP
#define STRIDE_CLI_INSTALLED_FILES_HPP

#include <CLI/CLI.hpp>

namespace stride::cli {

/// Accepts an existing file as given; a relative name that does not exist is looked up in the
/// installed models folder (<prefix>/share/stride/models) and replaced by that path. Otherwise
/// the error names the file and both places.
CLI::Validator existing_or_installed_model();

}  // namespace stride::cli

#endif
