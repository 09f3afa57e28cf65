// What the FMI 2.0 and FMI 3.0 modelDescription.xml readers share: errors that name the file
// and line, and the attribute parsers both standards define alike.
#ifndef STRIDE_COSIM_SRC_MD_READER_BASE_HPP
#define STRIDE_COSIM_SRC_MD_READER_BASE_HPP

#include <tinyxml2.h>

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail {

struct md_reader_base {
  std::string origin;  ///< the file (or archive entry) named in every error

  [[noreturn]] void fail(int line, const std::string& message) const {
    std::string where = origin;
    if (line > 0) where += ":" + std::to_string(line);
    throw fmu_import_error(where + ": " + message);
  }

  /// xs:boolean ("true", "false", "1", "0"); `fallback` when the attribute is absent.
  bool parse_bool(const tinyxml2::XMLElement* e, const char* name, bool fallback = false) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return fallback;
    const std::string_view s(v);
    if (s == "true" || s == "1") return true;
    if (s == "false" || s == "0") return false;
    fail(e->GetLineNum(), std::string("attribute ") + name + "=\"" + v + "\" is not a boolean");
  }

  /// A finite number, or nullopt when the attribute is absent. xs:double would allow INF and
  /// NaN; no attribute read this way may be either.
  std::optional<double> parse_double(const tinyxml2::XMLElement* e, const char* name) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return std::nullopt;
    const auto d = text::parse_double(v);
    if (!d || !std::isfinite(*d)) {
      fail(e->GetLineNum(),
           std::string("attribute ") + name + "=\"" + v + "\" is not a finite number");
    }
    return *d;
  }
};

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_SRC_MD_READER_BASE_HPP
