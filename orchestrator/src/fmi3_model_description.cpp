#include "fmi3_model_description.hpp"

#include <tinyxml2.h>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "md_reader_base.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "xml_util.hpp"

namespace stride::cosim::fmi3 {

namespace {

constexpr std::array<std::pair<kind, std::string_view>, 14> kind_names{{
    {kind::float32, "Float32"},
    {kind::float64, "Float64"},
    {kind::int8, "Int8"},
    {kind::uint8, "UInt8"},
    {kind::int16, "Int16"},
    {kind::uint16, "UInt16"},
    {kind::int32, "Int32"},
    {kind::uint32, "UInt32"},
    {kind::int64, "Int64"},
    {kind::uint64, "UInt64"},
    {kind::boolean, "Boolean"},
    {kind::string, "String"},
    {kind::binary, "Binary"},
    {kind::enumeration, "Enumeration"},
}};

std::optional<kind> parse_kind(std::string_view name) {
  for (const auto& [k, n] : kind_names) {
    if (n == name) return k;
  }
  return std::nullopt;
}

bool is_float(kind k) {
  return k == kind::float32 || k == kind::float64;
}

variable_type exchange_of(kind k) {
  switch (k) {
    case kind::float32:
    case kind::float64:
      return variable_type::real;
    case kind::boolean:
      return variable_type::boolean;
    case kind::string:
    case kind::binary:
      return variable_type::string;
    case kind::enumeration:
      return variable_type::enumeration;
    default:
      return variable_type::integer;
  }
}

// The closed range of an integer kind, as the widest signed/unsigned pair.
struct int_range {
  long double low;
  long double high;
};
int_range range_of(kind k) {
  switch (k) {
    case kind::int8:
      return {-128.0L, 127.0L};
    case kind::uint8:
      return {0.0L, 255.0L};
    case kind::int16:
      return {-32768.0L, 32767.0L};
    case kind::uint16:
      return {0.0L, 65535.0L};
    case kind::int32:
      return {-2147483648.0L, 2147483647.0L};
    case kind::uint32:
      return {0.0L, 4294967295.0L};
    case kind::uint64:
      return {0.0L, 18446744073709551615.0L};
    default:
      return {-9223372036854775808.0L, 9223372036854775807.0L};
  }
}

// One start token checked against its kind: a number in range, a boolean, hex bytes.
bool valid_start(kind k, std::string_view text) {
  switch (k) {
    case kind::float32:
    case kind::float64:
      return text::parse_double(text).has_value();
    case kind::boolean:
      return text == "true" || text == "false" || text == "1" || text == "0";
    case kind::string:
      return true;
    case kind::binary:
      return text.size() % 2 == 0 &&
             text.find_first_not_of("0123456789abcdefABCDEF") == std::string_view::npos;
    default: {
      long double v = 0;
      if (text.starts_with('-')) {
        long long s = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), s);
        if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return false;
        v = static_cast<long double>(s);
      } else {
        unsigned long long u = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), u);
        if (r.ec != std::errc() || r.ptr != text.data() + text.size()) return false;
        v = static_cast<long double>(u);
      }
      const auto range = range_of(k);
      return v >= range.low && v <= range.high;
    }
  }
}

using detail::attribute;
using detail::attribute_or;

// every element is a port with its own name: far larger arrays are not signals to connect
constexpr std::size_t max_elements = std::size_t{1} << 20;

struct reader : detail::md_reader_base {
  value_reference parse_reference(const std::string& text, int line,
                                  const std::string& what) const {
    value_reference vr = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), vr);
    if (ec != std::errc() || end != text.data() + text.size()) {
      fail(line, what + ": value reference \"" + text + "\" is not an unsigned 32-bit integer");
    }
    return vr;
  }

  description read(const tinyxml2::XMLDocument& doc) const {
    const auto* root = doc.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "fmiModelDescription") {
      fail(root ? root->GetLineNum() : 0, "root element is not <fmiModelDescription>");
    }
    description d;
    auto& md = d.scalar;
    md.fmi_version = attribute_or(root, "fmiVersion");
    if (md.fmi_version != "3.0") {
      fail(root->GetLineNum(), "fmiVersion is \"" + md.fmi_version + "\", not \"3.0\"");
    }
    md.model_name = attribute_or(root, "modelName");
    md.guid = attribute_or(root, "instantiationToken");
    if (md.guid.empty()) fail(root->GetLineNum(), "missing or empty instantiationToken");
    md.description = attribute_or(root, "description");
    md.author = attribute_or(root, "author");
    md.version = attribute_or(root, "version");
    md.generation_tool = attribute_or(root, "generationTool");
    md.generation_date_and_time = attribute_or(root, "generationDateAndTime");
    md.has_model_exchange = root->FirstChildElement("ModelExchange") != nullptr;
    if (const auto* cs = root->FirstChildElement("CoSimulation")) read_cosimulation(cs, d);
    if (const auto* me = root->FirstChildElement("ModelExchange")) read_model_exchange(me, d);
    if (const auto* de = root->FirstChildElement("DefaultExperiment")) {
      md.default_experiment.start_time = parse_double(de, "startTime");
      md.default_experiment.stop_time = parse_double(de, "stopTime");
      md.default_experiment.tolerance = parse_double(de, "tolerance");
      md.default_experiment.step_size = parse_double(de, "stepSize");
    }
    const auto* mv = root->FirstChildElement("ModelVariables");
    if (mv == nullptr) fail(root->GetLineNum(), "missing <ModelVariables>");
    std::vector<const tinyxml2::XMLElement*> elements;
    for (auto* e = mv->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      elements.push_back(e);
      d.variables.push_back(read_variable(e));
    }
    check_unique(d.variables);
    for (std::size_t i = 0; i < d.variables.size(); ++i) {
      resolve_dimensions(elements[i], d.variables, d.variables[i]);
    }
    for (std::size_t i = 0; i < d.variables.size(); ++i) {
      check_start(d.variables[i]);
      add_ports(elements[i], i, d);
    }
    if (const auto* ms = root->FirstChildElement("ModelStructure")) {
      read_outputs(ms, d);
      read_continuous_structure(ms, d);
    }
    return d;
  }

  void read_cosimulation(const tinyxml2::XMLElement* cs, description& d) const {
    cosim_capabilities cap;
    cap.model_identifier = attribute_or(cs, "modelIdentifier");
    if (cap.model_identifier.empty()) {
      fail(cs->GetLineNum(), "<CoSimulation> has no modelIdentifier");
    }
    cap.needs_execution_tool = parse_bool(cs, "needsExecutionTool");
    cap.can_handle_variable_communication_step_size =
        parse_bool(cs, "canHandleVariableCommunicationStepSize");
    cap.max_output_derivative_order = cs->IntAttribute("maxOutputDerivativeOrder", 0);
    cap.can_be_instantiated_only_once_per_process =
        parse_bool(cs, "canBeInstantiatedOnlyOncePerProcess");
    cap.can_get_and_set_fmu_state = parse_bool(cs, "canGetAndSetFMUState");
    cap.can_serialize_fmu_state = parse_bool(cs, "canSerializeFMUState");
    cap.provides_directional_derivative = parse_bool(cs, "providesDirectionalDerivatives");
    d.has_event_mode = parse_bool(cs, "hasEventMode");
    d.scalar.co_simulation = cap;
  }

  void read_model_exchange(const tinyxml2::XMLElement* me, description& d) const {
    model_exchange_capabilities cap;
    cap.model_identifier = attribute_or(me, "modelIdentifier");
    if (cap.model_identifier.empty()) {
      fail(me->GetLineNum(), "<ModelExchange> has no modelIdentifier");
    }
    cap.needs_execution_tool = parse_bool(me, "needsExecutionTool");
    // 3.0 asks for the call when needed; 2.0 said when it was not
    cap.completed_integrator_step_not_needed = !parse_bool(me, "needsCompletedIntegratorStep");
    cap.can_be_instantiated_only_once_per_process =
        parse_bool(me, "canBeInstantiatedOnlyOncePerProcess");
    cap.can_get_and_set_fmu_state = parse_bool(me, "canGetAndSetFMUState");
    cap.can_serialize_fmu_state = parse_bool(me, "canSerializeFMUState");
    cap.provides_directional_derivative = parse_bool(me, "providesDirectionalDerivatives");
    d.scalar.model_exchange = cap;
  }

  // The continuous-state derivatives in the order of the state vector, and the event
  // indicators; both are Float64 and an array counts element by element.
  void read_continuous_structure(const tinyxml2::XMLElement* ms, description& d) const {
    const auto float64_ports = [&](const tinyxml2::XMLElement* e, const char* tag) {
      const auto vr = attribute(e, "valueReference");
      if (!vr) fail(e->GetLineNum(), std::string("<") + tag + "> without valueReference");
      const auto ports = ports_of(d, parse_reference(*vr, e->GetLineNum(), tag), e->GetLineNum());
      const variable& v = d.variables[d.ports[ports.front()].variable];
      if (v.kind != kind::float64) {
        fail(e->GetLineNum(), std::string("<") + tag + "> names variable \"" + v.name + "\", a " +
                                  std::string(to_string(v.kind)) + ", not a Float64");
      }
      return ports;
    };
    for (auto* e = ms->FirstChildElement("ContinuousStateDerivative"); e != nullptr;
         e = e->NextSiblingElement("ContinuousStateDerivative")) {
      const auto ports = float64_ports(e, "ContinuousStateDerivative");
      d.scalar.derivatives.insert(d.scalar.derivatives.end(), ports.begin(), ports.end());
    }
    for (auto* e = ms->FirstChildElement("EventIndicator"); e != nullptr;
         e = e->NextSiblingElement("EventIndicator")) {
      d.scalar.number_of_event_indicators += float64_ports(e, "EventIndicator").size();
    }
  }

  variable read_variable(const tinyxml2::XMLElement* e) const {
    variable v;
    v.line = e->GetLineNum();
    v.name = attribute_or(e, "name");
    const std::string tag = e->Name();
    const std::string what = "variable \"" + v.name + "\"";
    if (v.name.empty()) fail(v.line, "<" + tag + "> without name");
    if (tag == "Clock") {
      fail(v.line, what + " is a Clock: clocks (and the event mode they need) are not supported");
    }
    const auto k = parse_kind(tag);
    if (!k) fail(v.line, what + ": unknown variable type element <" + tag + ">");
    v.kind = *k;
    const auto vr = attribute(e, "valueReference");
    if (!vr) fail(v.line, what + " has no valueReference");
    v.reference = parse_reference(*vr, v.line, what);
    v.structural = attribute_or(e, "causality") == "structuralParameter";
    v.constant = attribute_or(e, "variability") == "constant";
    if (v.kind == kind::string || v.kind == kind::binary) {
      for (auto* s = e->FirstChildElement("Start"); s != nullptr;
           s = s->NextSiblingElement("Start")) {
        v.start.push_back(attribute_or(s, "value"));
      }
    }
    if (const auto start = attribute(e, "start")) {
      std::istringstream in(*start);
      for (std::string token; in >> token;) v.start.push_back(token);
      if (v.start.empty()) fail(v.line, what + " has an empty start attribute");
    }
    return v;
  }

  void check_unique(const std::vector<variable>& variables) const {
    std::map<value_reference, const variable*> refs;
    std::set<std::string> names;
    for (const auto& v : variables) {
      if (!names.insert(v.name).second) {
        fail(v.line, "duplicate variable name \"" + v.name + "\"");
      }
      const auto [it, added] = refs.emplace(v.reference, &v);
      if (!added) {
        fail(v.line, "variable \"" + v.name + "\" has value reference " +
                         std::to_string(v.reference) + ", already used by \"" + it->second->name +
                         "\"");
      }
    }
  }

  // A size comes from start="n" or from a constant or structural UInt64 parameter; structural
  // parameters keep their start values (Stride does not use configuration mode).
  void resolve_dimensions(const tinyxml2::XMLElement* e, const std::vector<variable>& all,
                          variable& v) const {
    const std::string what = "variable \"" + v.name + "\"";
    for (auto* dim = e->FirstChildElement("Dimension"); dim != nullptr;
         dim = dim->NextSiblingElement("Dimension")) {
      const auto start = attribute(dim, "start");
      const auto ref = attribute(dim, "valueReference");
      if (start.has_value() == ref.has_value()) {
        fail(dim->GetLineNum(),
             what + ": a <Dimension> needs exactly one of start and valueReference");
      }
      std::string size_text;
      if (start) {
        size_text = *start;
      } else {
        const value_reference vr = parse_reference(*ref, dim->GetLineNum(), what);
        const variable* target = nullptr;
        for (const auto& w : all) {
          if (w.reference == vr) target = &w;
        }
        if (target == nullptr) {
          fail(dim->GetLineNum(),
               what + ": <Dimension valueReference=\"" + *ref + "\"> names no variable");
        }
        if (target->kind != kind::uint64 || !(target->structural || target->constant) ||
            target->start.size() != 1) {
          fail(dim->GetLineNum(), what + ": <Dimension valueReference=\"" + *ref + "\"> names \"" +
                                      target->name +
                                      "\", which is not a structural or constant UInt64 "
                                      "parameter with one start value");
        }
        size_text = target->start.front();
      }
      const auto n = text::parse_integer(size_text);
      if (!n || *n < 1) {
        fail(dim->GetLineNum(), what + ": array size \"" + size_text + "\" is not positive");
      }
      v.dimensions.push_back(static_cast<std::size_t>(*n));
      if (static_cast<std::size_t>(*n) > max_elements || v.size() > max_elements) {
        fail(dim->GetLineNum(),
             what + " has more than " + std::to_string(max_elements) + " elements (one port each)");
      }
    }
  }

  void check_start(const variable& v) const {
    if (v.start.empty()) return;
    const std::string what = "variable \"" + v.name + "\"";
    if (v.start.size() != v.size()) {
      fail(v.line, what + " has " + std::to_string(v.start.size()) + " start values for " +
                       std::to_string(v.size()) + " elements");
    }
    for (const auto& s : v.start) {
      if (!valid_start(v.kind, s)) {
        fail(v.line,
             what + ": start value \"" + s + "\" is not a valid " + std::string(to_string(v.kind)));
      }
    }
  }

  // Row-major element name: name[i] or name[i,j], 1-based.
  static std::string element_name(const variable& v, std::size_t element) {
    std::vector<std::size_t> index(v.dimensions.size());
    for (std::size_t d = v.dimensions.size(); d-- > 0;) {
      index[d] = element % v.dimensions[d] + 1;
      element /= v.dimensions[d];
    }
    std::string name = v.name + "[";
    for (std::size_t d = 0; d < index.size(); ++d) {
      if (d > 0) name += ",";
      name += std::to_string(index[d]);
    }
    return name + "]";
  }

  void add_ports(const tinyxml2::XMLElement* e, std::size_t index, description& d) const {
    const variable& v = d.variables[index];
    variable_description base;
    base.line = v.line;
    base.type = exchange_of(v.kind);
    base.description = attribute_or(e, "description");
    base.unit = attribute_or(e, "unit");
    base.declared_type = attribute_or(e, "declaredType");
    base.min = attribute(e, "min");
    base.max = attribute(e, "max");
    read_causality(e, v, base);
    for (std::size_t k = 0; k < v.size(); ++k) {
      variable_description p = base;
      p.name = v.dimensions.empty() ? v.name : element_name(v, k);
      p.reference = static_cast<value_reference>(d.ports.size());
      if (!v.start.empty()) p.start = v.start[k];
      d.scalar.variables.push_back(std::move(p));
      d.ports.push_back({index, k});
    }
  }

  void read_causality(const tinyxml2::XMLElement* e, const variable& v,
                      variable_description& p) const {
    const std::string what = "variable \"" + v.name + "\"";
    const std::string c = attribute_or(e, "causality", "local");
    const bool parameter_like =
        c == "parameter" || c == "calculatedParameter" || c == "structuralParameter";
    // structural parameters keep their start values: they are fixed locals to the system
    if (v.structural) {
      p.causality = causality::local;
    } else if (const auto parsed = fmi2::parse_causality(c)) {
      p.causality = *parsed;
    } else {
      fail(v.line, what + ": unknown causality \"" + c + "\"");
    }
    const std::string fallback = parameter_like     ? "fixed"
                                 : is_float(v.kind) ? "continuous"
                                                    : "discrete";
    const std::string var = attribute_or(e, "variability", fallback);
    const auto parsed_var = fmi2::parse_variability(var);
    if (!parsed_var) fail(v.line, what + ": unknown variability \"" + var + "\"");
    p.variability = *parsed_var;
    if (v.structural) p.variability = variability::fixed;
    if (const auto init = attribute(e, "initial")) {
      const auto parsed = fmi2::parse_initial_kind(*init);
      if (!parsed) fail(v.line, what + ": unknown initial \"" + *init + "\"");
      p.initial = *parsed;
    }
  }

  void read_outputs(const tinyxml2::XMLElement* ms, description& d) const {
    for (auto* o = ms->FirstChildElement("Output"); o != nullptr;
         o = o->NextSiblingElement("Output")) {
      const auto vr = attribute(o, "valueReference");
      if (!vr) fail(o->GetLineNum(), "<Output> without valueReference");
      const auto out_ports =
          ports_of(d, parse_reference(*vr, o->GetLineNum(), "<Output>"), o->GetLineNum());
      std::optional<std::vector<std::size_t>> deps;
      if (const auto list = attribute(o, "dependencies")) {
        deps.emplace();
        std::istringstream in(*list);
        for (std::string token; in >> token;) {
          const auto p = ports_of(d, parse_reference(token, o->GetLineNum(), "<Output> dependency"),
                                  o->GetLineNum());
          deps->insert(deps->end(), p.begin(), p.end());
        }
      }
      // an array depends as a whole: each element on every element of its dependencies
      for (const std::size_t p : out_ports) d.scalar.outputs.push_back({p, deps});
    }
  }

  std::vector<std::size_t> ports_of(const description& d, value_reference vr, int line) const {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < d.ports.size(); ++i) {
      if (d.variables[d.ports[i].variable].reference == vr) out.push_back(i);
    }
    if (out.empty()) {
      fail(line, "ModelStructure names value reference " + std::to_string(vr) +
                     ", which no variable has");
    }
    return out;
  }
};

}  // namespace

std::string_view to_string(kind k) noexcept {
  for (const auto& [kk, n] : kind_names) {
    if (kk == k) return n;
  }
  return "?";
}

std::size_t variable::size() const noexcept {
  std::size_t n = 1;
  for (const std::size_t d : dimensions) n *= d;
  return n;
}

std::string declared_fmi_version(std::string_view xml) {
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  const auto* root = doc.RootElement();
  if (doc.Error() || root == nullptr) return "";
  return attribute_or(root, "fmiVersion");
}

description parse_description(std::string_view xml, const std::string& origin) {
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  const reader r{{origin}};
  if (doc.Error()) r.fail(doc.ErrorLineNum(), "malformed XML: " + detail::describe_error(doc));
  return r.read(doc);
}

}  // namespace stride::cosim::fmi3
