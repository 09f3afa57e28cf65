#include "stride/cosim/scalar_value.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace stride::cosim {

scalar_value parse_scalar(variable_type type, std::string_view text) {
  const std::string s(text);
  const char* first = s.data();
  const char* last = s.data() + s.size();
  switch (type) {
    case variable_type::real: {
      double v = 0;
      auto [end, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || end != last || !std::isfinite(v)) {
        throw std::invalid_argument("'" + s + "' is not a Real");
      }
      return v;
    }
    case variable_type::integer:
    case variable_type::enumeration: {
      int v = 0;
      auto [end, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || end != last) {
        throw std::invalid_argument("'" + s + "' is not an Integer");
      }
      return v;
    }
    case variable_type::boolean:
      if (s == "true" || s == "1") return true;
      if (s == "false" || s == "0") return false;
      throw std::invalid_argument("'" + s + "' is not a Boolean (true, false, 1 or 0)");
    case variable_type::string:
      return s;
  }
  throw std::invalid_argument("unknown type");
}

std::string format_scalar(const scalar_value& value) {
  struct visitor {
    std::string operator()(double d) const {
      char buf[32];
      auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
      return ec == std::errc() ? std::string(buf, end) : std::to_string(d);
    }
    std::string operator()(int i) const { return std::to_string(i); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(visitor{}, value);
}

}  // namespace stride::cosim
