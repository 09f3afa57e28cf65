#include "me_wire.hpp"

#include <cmath>
#include <stdexcept>

namespace stride::remote {

namespace {

using options = cosim::model_exchange_options;
constexpr const char* k_marker = "model-exchange";

void put_optional(const std::optional<double>& x, cosim::value_block& v) {
  v.reals.push_back(x.value_or(0.0));
  v.booleans.push_back(x.has_value());
}

std::optional<double> get_optional(const cosim::value_block& v, std::size_t i) {
  if (!v.booleans[i]) return std::nullopt;
  if (!std::isfinite(v.reals[i]) || v.reals[i] <= 0) {
    throw std::runtime_error("protocol: a Model Exchange tolerance or step is not positive");
  }
  return v.reals[i];
}

}  // namespace

cosim::value_block model_exchange_to_wire(const std::optional<options>& o) {
  cosim::value_block v;
  if (!o) return v;
  v.strings = {k_marker, o->solver == options::solver_kind::euler ? "euler" : "cvode",
               o->method == options::method_kind::adams ? "adams" : "bdf"};
  put_optional(o->rtol, v);
  put_optional(o->atol, v);
  put_optional(o->max_step, v);
  return v;
}

std::optional<options> model_exchange_from_wire(const cosim::value_block& v) {
  if (v.strings.empty() && v.reals.empty() && v.booleans.empty() && v.integers.empty()) {
    return std::nullopt;
  }
  const bool shaped = v.strings.size() == 3 && v.reals.size() == 3 && v.booleans.size() == 3 &&
                      v.integers.empty() && v.strings[0] == k_marker;
  const bool known = shaped && (v.strings[1] == "cvode" || v.strings[1] == "euler") &&
                     (v.strings[2] == "bdf" || v.strings[2] == "adams");
  if (!known) throw std::runtime_error("protocol: malformed Model Exchange settings");
  options o;
  o.solver = v.strings[1] == "euler" ? options::solver_kind::euler : options::solver_kind::cvode;
  o.method = v.strings[2] == "adams" ? options::method_kind::adams : options::method_kind::bdf;
  o.rtol = get_optional(v, 0);
  o.atol = get_optional(v, 1);
  o.max_step = get_optional(v, 2);
  return o;
}

}  // namespace stride::remote
