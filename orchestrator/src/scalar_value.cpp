#include "stride/cosim/scalar_value.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "stride/common/text.hpp"

namespace stride::cosim {

// Numbers take the lexical forms of xs:double and xs:int (surrounding blanks, a leading '+'), as
// start values in modelDescription.xml do.
scalar_value parse_scalar(variable_type type, std::string_view text) {
  const std::string s(text);
  switch (type) {
    case variable_type::real: {
      const auto v = text::parse_double(s);
      if (!v || !std::isfinite(*v)) throw std::invalid_argument("'" + s + "' is not a Real");
      return *v;
    }
    case variable_type::integer:
    case variable_type::enumeration: {
      const auto v = text::parse_integer(s);
      if (!v || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max()) {
        throw std::invalid_argument("'" + s + "' is not an Integer");
      }
      return static_cast<int>(*v);
    }
    case variable_type::boolean: {
      const std::string_view b = text::trim(s);
      if (b == "true" || b == "1") return true;
      if (b == "false" || b == "0") return false;
      throw std::invalid_argument("'" + s + "' is not a Boolean (true, false, 1 or 0)");
    }
    case variable_type::string:
      return s;
  }
  throw std::invalid_argument("unknown type");
}

std::string format_scalar(const scalar_value& value) {
  struct visitor {
    std::string operator()(double d) const { return text::format_double(d); }
    std::string operator()(int i) const { return std::to_string(i); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return s; }
  };
  return std::visit(visitor{}, value);
}

}  // namespace stride::cosim
