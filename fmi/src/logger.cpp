#include <string>

#include "instance.hpp"

namespace stride::sdk::glue {
namespace {

// the FMI logger treats the message as a printf format: escape '%'
std::string escape_percent(const std::string& message) {
  std::string out;
  out.reserve(message.size());
  for (char c : message) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

}  // namespace

bool fmi_logger::enabled(const char* category) const {
  if (all_) return true;
  for (const std::string& name : enabled_) {
    if (name == category) return true;
  }
  return false;
}

void fmi_logger::log(log_level level, const char* category, const std::string& message) {
  if (callback_ == nullptr) return;
  const fmi2Status status = level == log_level::error     ? fmi2Error
                            : level == log_level::warning ? fmi2Warning
                                                          : fmi2OK;
  callback_(environment_, instance_name_.c_str(), status, category,
            escape_percent(message).c_str());
}

std::string fmi_logger::set_debug_logging(bool on, const std::vector<std::string>& categories,
                                          const std::vector<std::string>& known) {
  if (categories.empty()) {
    enable_all(on);
    return {};
  }
  for (const std::string& c : categories) {
    bool is_known = c == "logAll";
    for (const std::string& k : known) is_known = is_known || k == c;
    if (!is_known) return c;
  }
  for (const std::string& c : categories) {
    if (c == "logAll") {
      enable_all(on);
    } else {
      std::erase(enabled_, c);
      if (on) enabled_.push_back(c);
    }
  }
  calls_ = enabled("logCalls");
  return {};
}

void fmi_logger::enable_all(bool on) {
  all_ = on;
  if (!on) enabled_.clear();
  calls_ = on;
}

}  // namespace stride::sdk::glue
