// The units of the gait parameters a study axis is named after, for figure labels.
#ifndef STRIDE_STUDY_SRC_AXIS_UNITS_HPP
#define STRIDE_STUDY_SRC_AXIS_UNITS_HPP

#include <string>

namespace stride::study {

/// " (ms)" / " (mm)" for the gait parameters a study axis is named after, else "".
inline std::string unit_of(const std::string& parameter) {
  if (parameter == "period_time") return " (ms)";
  if (parameter.find("swing") != std::string::npos ||
      parameter.find("height") != std::string::npos ||
      parameter.find("offset") != std::string::npos)
    return " (mm)";
  return "";
}

}  // namespace stride::study

#endif  // STRIDE_STUDY_SRC_AXIS_UNITS_HPP
