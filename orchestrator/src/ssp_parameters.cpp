// SSP parameter bindings: inline or .ssv parameter sets, .ssm parameter mappings, units and the
// transformations they share with connections (docs/ssp.md).
#include <algorithm>
#include <cmath>

#include "ssp_model.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::detail::ssp {

using tinyxml2::XMLElement;

linear_map compose(const linear_map& first, const linear_map& then) {
  return {then.factor * first.factor, then.factor * first.offset + then.offset};
}

void read_units(const xml_file& file, const XMLElement& e, unit_table& units) {
  file.allow_attributes(e, {});
  file.children(e, {{k_ssc_ns, "Unit", 0, true}}, [&](const XMLElement& u, std::string_view) {
    file.allow_attributes(u, {"id", "description", "name"});
    const std::string name = file.required(u, "name");
    if (units.contains(name)) file.fail(u, "unit \"" + name + "\" defined twice");
    unit def;
    file.children(u, {{k_ssc_ns, "BaseUnit", 0}, {k_ssc_ns, "Annotations", 1}},
                  [&](const XMLElement& b, std::string_view local) {
                    if (local != "BaseUnit") return;
                    static constexpr const char* k_si[] = {"kg", "m",   "s",  "A",
                                                           "K",  "mol", "cd", "rad"};
                    file.allow_attributes(
                        b, {"kg", "m", "s", "A", "K", "mol", "cd", "rad", "factor", "offset"});
                    for (std::size_t k = 0; k < def.exponents.size(); ++k) {
                      const auto v = file.attribute(b, k_si[k]);
                      const auto n = v ? text::parse_integer(*v) : std::optional<long long>(0);
                      if (!n || *n < -1000 || *n > 1000) {
                        file.fail(b, std::string(k_si[k]) + "=\"" + *v + "\" is not an exponent");
                      }
                      def.exponents[k] = static_cast<int>(*n);
                    }
                    def.factor = file.real(b, "factor").value_or(1.0);
                    def.offset = file.real(b, "offset").value_or(0.0);
                    if (def.factor == 0.0) file.fail(b, "factor must not be 0");
                  });
    units.emplace(name, def);
  });
}

linear_map unit_conversion(const std::string& from_name, const unit& from,
                           const std::string& to_name, const unit& to, const std::string& where) {
  if (from.exponents != to.exponents) {
    throw validation_error(where + "units \"" + from_name + "\" and \"" + to_name +
                           "\" measure different quantities (their SI base units differ)");
  }
  // SI = factor × value + offset on both sides
  return {from.factor / to.factor, (from.offset - to.offset) / to.factor};
}

transformation read_transformation(const xml_file& file, const XMLElement& e, bool allowed_maps) {
  transformation t;
  const std::string_view local = xml_file::local(e);
  if (local == "LinearTransformation") {
    file.allow_attributes(e, {"factor", "offset"});
    t.linear = {file.real(e, "factor").value_or(1.0), file.real(e, "offset").value_or(0.0)};
    return t;
  }
  if (!allowed_maps || local == "EnumerationMappingTransformation") {
    file.fail(e, "not supported: Stride transforms " +
                     std::string(allowed_maps ? "parameter values by linear, Boolean and "
                                                "Integer mappings"
                                              : "connected values by ssc:LinearTransformation "
                                                "only (Real)"));
  }
  t.what = local == "BooleanMappingTransformation" ? transformation::kind::boolean_map
                                                   : transformation::kind::integer_map;
  file.allow_attributes(e, {});
  file.children(e, {{k_ssc_ns, "MapEntry", 0, true}}, [&](const XMLElement& m, std::string_view) {
    file.allow_attributes(m, {"source", "target"});
    const auto norm = [&](const char* name) {
      const std::string v = file.required(m, name);
      if (t.what == transformation::kind::boolean_map) {
        return std::string(file.boolean(m, name, false) ? "true" : "false");
      }
      const auto n = text::parse_integer(v);
      if (!n || *n < INT32_MIN || *n > INT32_MAX) file.fail(m, name + std::string(" is no int"));
      return std::to_string(*n);
    };
    t.table[norm("source")] = norm("target");
  });
  return t;
}

std::optional<transformation> read_transformed(
    const xml_file& file, const XMLElement& e, bool allowed_maps,
    const std::vector<child_rule>& others,
    const std::function<void(const XMLElement&, std::string_view)>& visit) {
  std::vector<child_rule> rules = {{k_ssc_ns, "LinearTransformation"},
                                   {k_ssc_ns, "BooleanMappingTransformation"},
                                   {k_ssc_ns, "IntegerMappingTransformation"},
                                   {k_ssc_ns, "EnumerationMappingTransformation"}};
  rules.insert(rules.end(), others.begin(), others.end());
  std::optional<transformation> found;
  file.children(e, rules, [&](const XMLElement& c, std::string_view local) {
    if (!local.ends_with("Transformation")) {
      if (visit) visit(c, local);
      return;
    }
    if (found) file.fail(c, "one transformation only");
    found = read_transformation(file, c, allowed_maps);
  });
  return found;
}

namespace {

struct mapping_entry {
  std::string target;
  std::optional<transformation> transform;
  bool suppress_unit_conversion = false;
  std::string origin;
};
using mapping = std::map<std::string, mapping_entry>;

// the one element inside ParameterValues / ParameterMapping (xs:any in the XSD)
const XMLElement& single_child(const xml_file& file, const XMLElement& e, std::string_view ns,
                               std::string_view local) {
  const XMLElement* only = e.FirstChildElement();
  if (only == nullptr || only->NextSiblingElement() != nullptr || !file.is(*only, ns, local)) {
    file.fail(e,
              "must hold exactly one <" + std::string(local) + "> of namespace " + std::string(ns));
  }
  return *only;
}

void check_version(const xml_file& file, const XMLElement& e) {
  const std::string version = file.required(e, "version");
  if (!version.starts_with("1.")) {
    file.fail(e, "version \"" + version + "\": Stride reads SSP 1.0 files");
  }
}

// the value of one ssv:Parameter, checked for its type
void read_value(const xml_file& file, const XMLElement& v, std::string_view type,
                parameter_value& p) {
  if (type == "Enumeration" || type == "Binary") {
    file.fail(v,
              "not supported: give enumerations as ssv:Integer values (Stride cannot map "
              "item names), binaries have no FMI 2.0 type");
  }
  file.allow_attributes(v, type == "Real" ? std::initializer_list<std::string_view>{"value", "unit"}
                                          : std::initializer_list<std::string_view>{"value"});
  const auto text = file.attribute(v, "value");
  if (!text) file.fail(v, "needs a value attribute");
  p.value = type == "String" ? *text : std::string(text::trim(*text));
  if (type == "Real") {
    p.type = variable_type::real;
    if (!file.real(v, "value")) file.fail(v, "value is not a number");
    p.unit = file.attribute(v, "unit").value_or("");
  } else if (type == "Integer") {
    p.type = variable_type::integer;
    const auto n = text::parse_integer(p.value);
    if (!n || *n < INT32_MIN || *n > INT32_MAX) file.fail(v, "value is not a 32-bit integer");
  } else if (type == "Boolean") {
    p.type = variable_type::boolean;
    p.value = file.boolean(v, "value", false) ? "true" : "false";
  } else {
    p.type = variable_type::string;
  }
}

std::vector<parameter_value> read_parameter_set(const xml_file& file, const XMLElement& set,
                                                std::vector<std::unique_ptr<unit_table>>& keep) {
  file.allow_attributes(set, {"version", "name", "id", "description", "author", "fileversion",
                              "copyright", "license", "generationTool", "generationDateAndTime"});
  check_version(file, set);
  auto units = std::make_unique<unit_table>();
  std::vector<parameter_value> values;
  const auto read_parameters = [&](const XMLElement& ps) {
    file.allow_attributes(ps, {});
    file.children(ps, {{k_ssv_ns, "Parameter", 0, true}}, [&](const XMLElement& pe, auto) {
      file.allow_attributes(pe, {"id", "description", "name"});
      parameter_value p;
      p.name = file.required(pe, "name");
      p.where = file.at(pe);
      p.origin = file.where(pe);
      p.units = units.get();
      int typed = 0;
      file.children(pe,
                    {{k_ssv_ns, "Real"},
                     {k_ssv_ns, "Integer"},
                     {k_ssv_ns, "Boolean"},
                     {k_ssv_ns, "String"},
                     {k_ssv_ns, "Enumeration"},
                     {k_ssv_ns, "Binary"},
                     {k_ssv_ns, "Annotations", 1}},
                    [&](const XMLElement& v, std::string_view type) {
                      if (type == "Annotations") return;
                      if (typed++ > 0) file.fail(v, "a parameter has one value");
                      read_value(file, v, type, p);
                    });
      if (typed == 0) file.fail(pe, "has no value (ssv:Real, ssv:Integer, ...)");
      values.push_back(std::move(p));
    });
  };
  file.children(set,
                {{k_ssv_ns, "Parameters", 0},
                 {k_ssv_ns, "Enumerations", 1},
                 {k_ssv_ns, "Units", 2},
                 {k_ssv_ns, "Annotations", 3}},
                [&](const XMLElement& c, std::string_view local) {
                  if (local == "Parameters") read_parameters(c);
                  if (local == "Units") read_units(file, c, *units);
                });
  keep.push_back(std::move(units));
  return values;
}

mapping read_mapping(const xml_file& file, const XMLElement& m) {
  file.allow_attributes(m, {"version", "id", "description", "author", "fileversion", "copyright",
                            "license", "generationTool", "generationDateAndTime"});
  check_version(file, m);
  mapping entries;
  file.children(
      m, {{k_ssm_ns, "MappingEntry", 0, true}, {k_ssm_ns, "Annotations", 1}},
      [&](const XMLElement& e, std::string_view local) {
        if (local != "MappingEntry") return;
        file.allow_attributes(e,
                              {"id", "description", "source", "target", "suppressUnitConversion"});
        mapping_entry entry;
        entry.target = file.required(e, "target");
        entry.suppress_unit_conversion = file.boolean(e, "suppressUnitConversion", false);
        entry.origin = file.where(e);
        entry.transform = read_transformed(file, e, true, {{k_ssm_ns, "Annotations", 1}}, {});
        if (!entries.emplace(file.required(e, "source"), std::move(entry)).second) {
          file.fail(e, "source mapped twice");
        }
      });
  return entries;
}

// the name and value a mapping entry makes of `p`
void apply(const mapping_entry& entry, parameter_value& p) {
  p.name = entry.target;
  p.convert_units = !entry.suppress_unit_conversion;
  if (!entry.transform) return;
  const transformation& t = *entry.transform;
  const bool fits = t.what == transformation::kind::linear ? p.type == variable_type::real
                    : t.what == transformation::kind::boolean_map
                        ? p.type == variable_type::boolean
                        : p.type == variable_type::integer;
  if (!fits) {
    throw validation_error(entry.origin + "its transformation does not fit the " +
                           std::string(to_string(p.type)) + " value of " +
                           p.origin.substr(0, p.origin.size() - 2));
  }
  if (t.what == transformation::kind::linear) {
    p.transform = t.linear;
  } else if (const auto it = t.table.find(p.value); it != t.table.end()) {
    p.value = it->second;
  }
}

std::vector<parameter_value> read_binding(const xml_file& file, const XMLElement& b,
                                          std::vector<std::unique_ptr<unit_table>>& keep) {
  file.allow_attributes(b, {"id", "description", "type", "source", "sourceBase", "prefix"});
  if (const auto type = file.attribute(b, "type");
      type && *type != "application/x-ssp-parameter-set") {
    file.fail(b, "type \"" + *type + "\" is not supported (application/x-ssp-parameter-set is)");
  }
  const auto source_base = [&](const XMLElement& e) {
    if (file.attribute(e, "sourceBase").value_or("SSD") != "SSD") {
      file.fail(e, "sourceBase=\"component\" (files inside an FMU) is not supported");
    }
  };
  source_base(b);
  std::vector<parameter_value> values;
  bool have_values = false;
  mapping map;
  std::vector<std::unique_ptr<xml_file>> files;  // the referenced files, while read
  const auto sourced = [&](const XMLElement& e, std::string_view what) -> const xml_file& {
    files.push_back(file.open(file.resolve(e, file.required(e, "source"), what)));
    return *files.back();
  };
  file.children(b,
                {{k_ssd_ns, "ParameterValues", 0},
                 {k_ssd_ns, "ParameterMapping", 1},
                 {k_ssd_ns, "Annotations", 2}},
                [&](const XMLElement& c, std::string_view local) {
                  if (local == "ParameterValues") {
                    if (file.attribute(b, "source"))
                      file.fail(c, "given beside a source attribute");
                    file.allow_attributes(c, {});
                    values = read_parameter_set(
                        file, single_child(file, c, k_ssv_ns, "ParameterSet"), keep);
                    have_values = true;
                  } else if (local == "ParameterMapping") {
                    file.allow_attributes(c, {"id", "description", "type", "source", "sourceBase"});
                    source_base(c);
                    if (const auto type = file.attribute(c, "type");
                        type && *type != "application/x-ssp-parameter-mapping") {
                      file.fail(c, "type \"" + *type + "\" is not supported");
                    }
                    if (!file.attribute(c, "source")) {
                      map = read_mapping(file, single_child(file, c, k_ssm_ns, "ParameterMapping"));
                    } else {
                      const xml_file& ssm = sourced(c, "parameter mapping");
                      if (!ssm.is(ssm.root(), k_ssm_ns, "ParameterMapping")) {
                        ssm.fail(ssm.root(), "the root element must be ssm:ParameterMapping");
                      }
                      map = read_mapping(ssm, ssm.root());
                    }
                  }
                });
  if (!have_values) {
    if (!file.attribute(b, "source")) file.fail(b, "has neither a source nor ParameterValues");
    const xml_file& ssv = sourced(b, "parameter set");
    if (!ssv.is(ssv.root(), k_ssv_ns, "ParameterSet")) {
      ssv.fail(ssv.root(), "the root element must be ssv:ParameterSet");
    }
    values = read_parameter_set(ssv, ssv.root(), keep);
  }
  // the prefix comes first, then the mapping (SSP 1.0)
  const std::string prefix = file.attribute(b, "prefix").value_or("");
  for (auto& p : values) {
    p.name = prefix + p.name;
    if (const auto it = map.find(p.name); it != map.end()) apply(it->second, p);
  }
  return values;
}

}  // namespace

void read_bindings(const xml_file& file, const XMLElement& e,
                   std::vector<std::vector<parameter_value>>& into,
                   std::vector<std::unique_ptr<unit_table>>& keep) {
  file.allow_attributes(e, {});
  file.children(
      e, {{k_ssd_ns, "ParameterBinding", 0, true}},
      [&](const XMLElement& b, std::string_view) { into.push_back(read_binding(file, b, keep)); });
}

}  // namespace stride::cosim::detail::ssp
