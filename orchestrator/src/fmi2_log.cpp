#include "fmi2_log.hpp"

#include <cstdio>

namespace stride::cosim::detail {

namespace {

log_level level_of(fmi2Status status) {
  switch (status) {
    case fmi2Warning:
      return log_level::warning;
    case fmi2Discard:
    case fmi2Error:
    case fmi2Fatal:
      return log_level::error;
    default:
      return log_level::info;
  }
}

}  // namespace

void forward_fmi2_log(const log_sink& sink, const std::string& component, fmi2Status status,
                      fmi2String category, fmi2String message, std::va_list args) noexcept {
  if (message == nullptr) return;
  try {
    std::va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, message, copy);
    va_end(copy);
    std::string text;
    if (n > 0) {
      text.resize(static_cast<std::size_t>(n) + 1);
      std::vsnprintf(text.data(), text.size(), message, args);
      text.resize(static_cast<std::size_t>(n));
    }
    sink(level_of(status), component, category ? category : "", text);
  } catch (...) {
    // a throwing sink (or a failed allocation) must not unwind through the FMU's C code
  }
}

}  // namespace stride::cosim::detail
