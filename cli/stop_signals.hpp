// SIGINT and SIGTERM as requests to stop: the first sets a flag that long-running commands check
// (so that they finish cleanly: results written, temporary files removed); a second one ends
// the process as usual.
#ifndef STRIDE_CLI_STOP_SIGNALS_HPP
#define STRIDE_CLI_STOP_SIGNALS_HPP

#include <atomic>

namespace stride::cli {

/// Installs the handlers; returns the flag they set.
const std::atomic<bool>& catch_stop_signals();

/// The signal that set the flag (SIGINT or SIGTERM), 0 if none.
int caught_stop_signal();

}  // namespace stride::cli

#endif  // STRIDE_CLI_STOP_SIGNALS_HPP
