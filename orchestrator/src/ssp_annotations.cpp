// What Stride's annotations carry besides step and algorithm (docs/ssp.md, "Stride's
// annotations"): what to record and how many agents run the system; where a component runs, its
// step multiple, integrator and the values no SSP type holds. Their attributes are those of the
// system XML's, so that an exported system reads back exactly as it was written.
#include <charconv>
#include <sstream>

#include "integrator_attributes.hpp"
#include "ssp_model.hpp"
#include "xml_util.hpp"

namespace stride::cosim::detail::ssp {

using tinyxml2::XMLElement;

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
  const std::string count = file.required(e, "count");
  const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), a.count);
  if (error != std::errc() || end != count.data() + count.size() || a.count < 1) {
    file.fail(e, "count=\"" + count + "\" is not a positive integer");
  }
  if (const auto mode = file.attribute(e, "mode")) {
    if (*mode != "synchronous" && *mode != "asynchronous") {
      file.fail(e, "mode \"" + *mode + "\" is not synchronous or asynchronous");
    }
    a.synchronous = *mode == "synchronous";
  }
  if (const auto workers = file.attribute(e, "workers")) {
    std::istringstream names(*workers);
    for (std::string name; names >> name;) a.workers.push_back(name);
    if (a.workers.empty()) file.fail(e, "workers=\"\" names no worker");
  }
  return a;
}

void read_component_annotation(const xml_file& file, const XMLElement& s, element& c) {
  file.allow_attributes(
      s, {"worker", "step_multiple", "solver", "method", "rtol", "atol", "max_step"});
  if (file.attribute(s, "worker")) c.worker = file.required(s, "worker");
  if (const auto m = file.attribute(s, "step_multiple")) {
    const auto [end, error] = std::from_chars(m->data(), m->data() + m->size(), c.step_multiple);
    if (error != std::errc() || end != m->data() + m->size() || c.step_multiple < 1) {
      file.fail(s, "step_multiple=\"" + *m + "\" is not a positive integer");
    }
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
