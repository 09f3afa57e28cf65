#include "lifecycle.hpp"

namespace stride::sdk::glue {

const char* state_name(std::uint32_t s) {
  switch (s) {
    case instantiated:
      return "instantiated";
    case initialization_mode:
      return "initializationMode";
    case step_complete:
      return "stepComplete";
    case step_in_progress:
      return "stepInProgress";
    case step_failed:
      return "stepFailed";
    case step_canceled:
      return "stepCanceled";
    case terminated:
      return "terminated";
    case error:
      return "error";
    case fatal:
      return "fatal";
    default:
      return "?";
  }
}

std::string state_list(std::uint32_t mask) {
  std::string out;
  for (std::uint32_t bit = 1; bit <= fatal; bit <<= 1) {
    if ((mask & bit) == 0) continue;
    if (!out.empty()) out += ", ";
    out += state_name(bit);
  }
  return out.empty() ? "none" : out;
}

}  // namespace stride::sdk::glue
