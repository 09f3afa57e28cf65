#include <string>

#include "instance.hpp"

namespace stride::sdk::glue {

bool fmi_logger::enabled(const char* category) const {
  if (all_) return true;
  for (const std::string& name : enabled_) {
    if (name == category) return true;
  }
  return false;
}

void fmi_logger::log(log_level level, const char* category, const std::string& message) {
  if (sink_) sink_(level, category, message);
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
