// Where messages from components (FMU loggers) and from libstride itself go.
#ifndef STRIDE_COSIM_LOG_HPP
#define STRIDE_COSIM_LOG_HPP

#include <functional>
#include <string_view>

namespace stride::cosim {

enum class log_level { debug, info, warning, error };

std::string_view to_string(log_level level) noexcept;

/// Receives one message: `source` is a component name or "stride", `category` the FMI log
/// category (may be empty).
using log_sink = std::function<void(log_level level, std::string_view source,
                                    std::string_view category, std::string_view message)>;

/// The default sink: one line on stderr, "[source] level: message", messages below
/// `min_level` dropped.
log_sink stderr_log_sink(log_level min_level = log_level::info);

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_LOG_HPP
