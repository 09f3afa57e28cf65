#include "stride/cosim/log.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace stride::cosim {

std::string_view to_string(log_level level) noexcept {
  switch (level) {
    case log_level::debug:
      return "debug";
    case log_level::info:
      return "info";
    case log_level::warning:
      return "warning";
    case log_level::error:
      return "error";
  }
  return "?";
}

log_sink stderr_log_sink(log_level min_level) {
  // on a terminal a message first clears the line the progress display may be redrawing
  const bool terminal = ::isatty(::fileno(stderr)) != 0;
  return [min_level, terminal](log_level level, std::string_view source, std::string_view category,
                               std::string_view message) {
    if (level < min_level) return;
    // one write per message so concurrent writers do not interleave within a line
    std::string line;
    line.reserve(source.size() + category.size() + message.size() + 32);
    if (terminal) line += "\r\033[K";
    line += '[';
    line += source;
    line += "] ";
    line += to_string(level);
    if (!category.empty() && category != to_string(level)) {
      line += " (";
      line += category;
      line += ')';
    }
    line += ": ";
    line += message;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    line += '\n';
    std::fwrite(line.data(), 1, line.size(), stderr);
  };
}

}  // namespace stride::cosim
