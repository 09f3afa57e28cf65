// The run settings Stride's system annotation carries besides step and algorithm (docs/ssp.md,
// "Stride's annotations"): what to record and how many agents run the system. Their attributes
// are those of <record> and <agents> in the system XML, so that an exported system reads back
// exactly as it was written.
#include <charconv>
#include <sstream>

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

}  // namespace stride::cosim::detail::ssp
