#include "lifecycle.hpp"

#include "lifecycle3.hpp"

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

const char* state_name3(std::uint32_t s) {
  switch (s) {
    case instantiated:
      return "Instantiated";
    case initialization_mode:
      return "Initialization Mode";
    case step_complete:
      return "Step Mode";
    case step_failed:
      return "Step Discarded";
    case terminated:
      return "Terminated";
    default:
      return state_name(s);
  }
}

namespace {
std::string list_states(std::uint32_t mask, const char* (*name)(std::uint32_t)) {
  std::string out;
  for (std::uint32_t bit = 1; bit <= fatal; bit <<= 1) {
    if ((mask & bit) == 0) continue;
    if (!out.empty()) out += ", ";
    out += name(bit);
  }
  return out.empty() ? "none" : out;
}
}  // namespace

std::string state_list(std::uint32_t mask) {
  return list_states(mask, state_name);
}

std::string state_list3(std::uint32_t mask) {
  return list_states(mask, state_name3);
}

}  // namespace stride::sdk::glue
