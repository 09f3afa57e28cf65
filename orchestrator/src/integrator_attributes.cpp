#include "integrator_attributes.hpp"

#include <cmath>
#include <string_view>

#include "stride/common/text.hpp"

namespace stride::cosim::detail {

namespace {

using me = model_exchange_options;

std::optional<double>& setting(me& o, std::string_view name) {
  return name == "rtol" ? o.rtol : name == "atol" ? o.atol : o.max_step;
}

}  // namespace

bool has_integrator_attributes(const tinyxml2::XMLElement& e) {
  for (const char* name : {"solver", "method", "rtol", "atol", "max_step"}) {
    if (e.Attribute(name) != nullptr) return true;
  }
  return false;
}

void read_integrator(const tinyxml2::XMLElement& e, component_spec& c,
                     const attribute_failure& fail) {
  if (!has_integrator_attributes(e)) return;
  if (c.kind == "co-simulation") {
    fail(
        "solver, method, rtol, atol and max_step apply to kind=\"model-exchange\" only "
        "(a Co-Simulation FMU integrates itself)");
  }
  me o;
  const std::string solver = e.Attribute("solver") ? e.Attribute("solver") : "cvode";
  if (solver == "euler") {
    o.solver = me::solver_kind::euler;
  } else if (solver != "cvode") {
    fail("solver=\"" + solver + "\" is not cvode or euler");
  }
  if (const char* method = e.Attribute("method")) {
    if (std::string_view(method) != "bdf" && std::string_view(method) != "adams") {
      fail("method=\"" + std::string(method) + "\" is not bdf or adams");
    }
    if (o.solver == me::solver_kind::euler) fail("method applies to solver=\"cvode\" only");
    o.method = std::string_view(method) == "adams" ? me::method_kind::adams : me::method_kind::bdf;
  }
  for (const char* name : {"rtol", "atol", "max_step"}) {
    const char* text = e.Attribute(name);
    if (text == nullptr) continue;
    const auto value = text::parse_double(text);
    if (!value || !std::isfinite(*value)) {
      fail(std::string(name) + "=\"" + text + "\" is not a finite number");
    }
    if (*value <= 0) fail(std::string(name) + "=\"" + text + "\" must be > 0");
    setting(o, name) = *value;
  }
  if (o.solver == me::solver_kind::euler && !o.max_step) {
    fail("solver=\"euler\" needs max_step (its fixed step in seconds)");
  }
  c.model_exchange = o;
}

void write_integrator(tinyxml2::XMLElement& e, const me& o) {
  e.SetAttribute("solver", o.solver == me::solver_kind::euler ? "euler" : "cvode");
  if (o.solver == me::solver_kind::cvode) {
    e.SetAttribute("method", o.method == me::method_kind::adams ? "adams" : "bdf");
  }
  if (o.rtol) e.SetAttribute("rtol", text::format_double(*o.rtol).c_str());
  if (o.atol) e.SetAttribute("atol", text::format_double(*o.atol).c_str());
  if (o.max_step) e.SetAttribute("max_step", text::format_double(*o.max_step).c_str());
}

}  // namespace stride::cosim::detail
