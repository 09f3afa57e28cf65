// What Stride's annotations carry besides step and algorithm (docs/ssp.md, "Stride's
// annotations"): what to record, how many agents run the system and its standby workers; where a
// component runs, its
// step multiple, integrator and the values no SSP type holds. Their attributes are those of the
// system XML's, so that an exported system reads back exactly as it was written.
#include <charconv>
#include <sstream>

#include "integrator_attributes.hpp"
#include "ssp_model.hpp"
#include "xml_util.hpp"

namespace stride::cosim::detail::ssp {

using tinyxml2::XMLElement;

namespace {

// the attribute `name` of `e` as an integer of at least 1
int positive_integer(const xml_file& file, const XMLElement& e, const char* name,
                     const std::string& text) {
  int n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 1) {
    file.fail(e, std::string(name) + "=\"" + text + "\" is not a positive integer");
  }
  return n;
}

// names separated by blanks; at least one
std::vector<std::string> worker_names(const xml_file& file, const XMLElement& e, const char* name,
                                      const std::string& text) {
  std::vector<std::string> names;
  std::istringstream in(text);
  for (std::string w; in >> w;) names.push_back(w);
  if (names.empty()) file.fail(e, std::string(name) + "=\"\" names no worker");
  return names;
}

}  // namespace

record_spec read_record_annotation(const xml_file& file, const XMLElement& e) {
  file.allow_attributes(e, {"enabled", "interval", "file"});
  record_spec r;
  r.where = file.at(e);
  r.enabled = file.boolean(e, "enabled", true);
  if (const auto interval = file.attribute(e, "interval")) {
    r.interval = file.seconds(e, *interval, "interval");
    if (*r.interval <= duration::zero()) file.fail(e, "interval must be positive");
  }
  if (const auto f = file.attribute(e, "file")) {
    if (const std::string problem = record_file_problem(*f); !problem.empty()) {
      file.fail(e, problem);
    }
    r.file = *f;
  }
  file.children(e, {{k_stride_ns, "Signal", 0, true}}, [&](const XMLElement& s, auto) {
    file.allow_attributes(s, {"name"});
    r.signals.push_back(file.required(s, "name"));
    r.signal_locations.push_back(file.at(s));
  });
  return r;
}

agents_spec read_agents_annotation(const xml_file& file, const XMLElement& e) {
  file.allow_attributes(e, {"count", "mode", "workers"});
  agents_spec a;
  a.where = file.at(e);
  a.count = positive_integer(file, e, "count", file.required(e, "count"));
  if (const auto mode = file.attribute(e, "mode")) {
    if (*mode != "synchronous" && *mode != "asynchronous") {
      file.fail(e, "mode \"" + *mode + "\" is not synchronous or asynchronous");
    }
    a.synchronous = *mode == "synchronous";
  }
  if (const auto workers = file.attribute(e, "workers")) {
    a.workers = worker_names(file, e, "workers", *workers);
  }
  return a;
}

failover_spec read_failover_annotation(const xml_file& file, const XMLElement& e) {
  file.allow_attributes(e, {"standby", "snapshot-every"});
  failover_spec f;
  f.where = file.at(e);
  f.standby = worker_names(file, e, "standby", file.required(e, "standby"));
  if (const auto every = file.attribute(e, "snapshot-every")) {
    f.snapshot_every = positive_integer(file, e, "snapshot-every", *every);
  }
  return f;
}

void read_component_annotation(const xml_file& file, const XMLElement& s, element& c) {
  file.allow_attributes(
      s, {"worker", "step_multiple", "solver", "method", "rtol", "atol", "max_step"});
  if (file.attribute(s, "worker")) c.worker = file.required(s, "worker");
  if (const auto m = file.attribute(s, "step_multiple")) {
    c.step_multiple = positive_integer(file, s, "step_multiple", *m);
  }
  component_spec integrated;
  integrated.kind = c.kind;
  read_integrator(s, integrated, [&](const std::string& message) { file.fail(s, message); });
  c.model_exchange = integrated.model_exchange;
  file.children(s, {{k_stride_ns, "Value", 0, true}}, [&](const XMLElement& v, auto) {
    file.allow_attributes(v, {"name", "value"});
    const std::string name = file.required(v, "name");
    if (c.description->find(name) == nullptr) {
      file.fail(v, "the FMU of '" + c.path + "' has no variable \"" + name + "\"");
    }
    c.stride_values.push_back({name, file.required(v, "value"), file.at(v)});
  });
}

}  // namespace stride::cosim::detail::ssp
