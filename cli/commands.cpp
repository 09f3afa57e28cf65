#include "commands.hpp"

#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "stop_signals.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/model_description.hpp"
#include "stride/cosim/run.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_import.hpp"
#include "stride/cosim/system_structure.hpp"
#include "stride/remote/remote_placement.hpp"
#include "stride/suite/runner.hpp"
#include "stride/suite/suite.hpp"

#ifdef STRIDE_HAVE_FMI_CHECK
#include "stride/fmi_check/fmu_check.hpp"
#endif

namespace stride::cli {

namespace fs = std::filesystem;
using namespace stride::cosim;

namespace {

cosim::time_point parse_stop(const std::string& text) {
  try {
    return cosim::time_point(parse_duration(text));
  } catch (const std::exception& e) {
    throw validation_error(std::string("--stop-time: ") + e.what());
  }
}

system_structure load_system(const std::optional<fs::path>& file, const run_extension& ext,
                             const log_sink& log) {
  if (file) return load_system_file(*file, log);
  if (ext.default_system_xml.empty()) throw validation_error("no system file given");
  return parse_system_text(ext.default_system_xml,
                           "(embedded) " + std::string(ext.default_system_name));
}

const char* yes_no(bool b) {
  return b ? "true" : "false";
}

// where each component of `system` (replicas expanded) runs, one line per component
// "model-exchange cvode bdf rtol=1e-08": how a component with kind or solver settings runs
std::string kind_column(const component_spec& c) {
  if (c.kind.empty() && !c.model_exchange) return "";
  std::string text = c.kind.empty() ? "model-exchange if the FMU is ME-only" : c.kind;
  if (!c.model_exchange) return text;
  using me = model_exchange_options;
  const auto& o = *c.model_exchange;
  text += o.solver == me::solver_kind::euler   ? " euler"
          : o.method == me::method_kind::adams ? " cvode adams"
                                               : " cvode bdf";
  const auto number = [](const char* name, const std::optional<double>& v) {
    return v ? std::string(" ") + name + "=" + text::format_double(*v) : std::string();
  };
  return text + number("rtol", o.rtol) + number("atol", o.atol) + number("max_step", o.max_step);
}

std::string placement_table(const system_structure& system) {
  const system_structure expanded = expand_replicas(system);
  std::size_t width = 9;
  for (const auto& c : expanded.components) width = std::max(width, c.name.size());
  std::string table;
  char line[512];
  for (const auto& c : expanded.components) {
    const std::string where = c.worker.empty() ? "this process" : "worker " + c.worker;
    std::snprintf(line, sizeof line, "  %-*s  %-24s  %s", static_cast<int>(width), c.name.c_str(),
                  where.c_str(), c.fmu.c_str());
    table += line;
    const std::string kind = kind_column(c);
    table += (kind.empty() ? "" : "  (" + kind + ")") + "\n";
  }
  if (!system.failover.standby.empty()) {
    table +=
        "  standby workers: " + text::join(system.failover.standby, ", ") +
        " (a state image every " +
        std::to_string(system.failover.snapshot_every.value_or(remote::k_default_snapshot_every)) +
        " steps)\n";
  }
  return table;
}

bool has_workers(const system_structure& system) {
  for (const auto& c : system.components) {
    if (!c.worker.empty()) return true;
  }
  return false;
}

// where step and algorithm came from, and what of a foreign file was not read (docs/ssp.md)
void print_import_notes(const system_structure& system) {
  const import_notes& notes = system.notes;
  const std::string step = system.base_step ? format_seconds(*system.base_step) + " s"
                                            : "the smallest DefaultExperiment stepSize of its FMUs";
  std::printf("Base step %s, %s, from %s (--step and --algorithm replace them)\n\n", step.c_str(),
              std::string(to_string(system.algorithm)).c_str(),
              notes.stepping_from.empty() ? "the system file" : notes.stepping_from.c_str());
  if (notes.descriptions.size() > 1) {
    std::printf("System structure descriptions (pick one with --ssd NAME):\n");
    for (const auto& d : notes.descriptions) {
      const bool read = system.where.file.ends_with("/" + d);
      std::printf("  %s%s\n", d.c_str(), read ? "  (read)" : "");
    }
    std::printf("\n");
  }
  if (!notes.ignored_annotations.empty()) {
    std::printf("Annotations of other tools, not read:\n");
    for (const auto& a : notes.ignored_annotations) std::printf("  %s\n", a.c_str());
    std::printf("\n");
  }
}

int inspect_system(const fs::path& file) {
  const system_structure system = load_system_file(file);
  const system_structure expanded = expand_replicas(system);
  std::printf("System '%s' (%s): %zu components, %zu connections, %s\n\n", system.name.c_str(),
              file.string().c_str(), expanded.components.size(), expanded.connections.size(),
              std::string(to_string(system.algorithm)).c_str());
  print_import_notes(system);
  if (system.agents.count > 0) {
    std::printf("Agents: %d copies of the system at once, %s (docs/swarm.md)\n\n",
                system.agents.count,
                system.agents.synchronous ? "synchronous rounds" : "asynchronous");
  }
  std::printf("Placement\n\n%s", placement_table(system).c_str());
  if (has_workers(system)) {
    std::printf("\n`stride workers` lists the workers visible on a DDS domain.\n");
  }
  return 0;
}

}  // namespace

// --step and --algorithm: the base step and master algorithm, whatever the system says
void apply_stepping(system_structure& system, const std::optional<std::string>& step,
                    const std::optional<std::string>& algorithm) {
  if (step) {
    try {
      system.base_step = parse_duration(*step);
    } catch (const std::exception& e) {
      throw validation_error(std::string("--step: ") + e.what());
    }
    if (*system.base_step <= duration::zero()) throw validation_error("--step must be positive");
  }
  if (algorithm) {
    if (*algorithm != "gauss-seidel" && *algorithm != "jacobi") {
      throw validation_error("--algorithm " + *algorithm + ": not gauss-seidel or jacobi");
    }
    system.algorithm =
        *algorithm == "jacobi" ? algorithm_kind::jacobi : algorithm_kind::gauss_seidel;
  }
}

void apply_failover(system_structure& system, const std::vector<std::string>& standby,
                    std::optional<int> snapshot_every) {
  if (!standby.empty()) {
    system.failover.standby.clear();
    for (const auto& w : standby) {
      if (w.empty()) throw validation_error("--standby: an empty worker name");
      system.failover.standby.push_back(w);
    }
  }
  if (snapshot_every) {
    if (system.failover.standby.empty()) {
      throw validation_error("--snapshot-every: no standby worker (--standby or <failover>)");
    }
    system.failover.snapshot_every = snapshot_every;
  }
}

remote::timeouts worker_limits(const run_arguments& args) {
  remote::timeouts limits;
  limits.connect = std::chrono::milliseconds(std::lround(args.worker_timeout * 1000));
  limits.stall = std::chrono::milliseconds(std::lround(args.stall * 1000));
  return limits;
}

std::vector<std::string> record_patterns(const std::vector<std::string>& values) {
  std::vector<std::string> patterns;
  for (const auto& value : values) {
    std::string pattern;
    for (const char c : value + ",") {
      if (c == ',' || std::isspace(static_cast<unsigned char>(c)) != 0) {
        if (!pattern.empty()) patterns.push_back(std::move(pattern));
        pattern.clear();
      } else {
        pattern += c;
      }
    }
  }
  if (patterns.empty() && !values.empty()) {
    throw validation_error("--record: no signal pattern given (e.g. --record 'robot.base_*')");
  }
  return patterns;
}

int run(const run_arguments& args, const run_extension& extension) {
  run_options options;
  options.output_dir = args.output;
  options.overrides = args.sets;
  if (args.stop_time) options.stop = parse_stop(*args.stop_time);
  options.progress = !args.quiet;
  options.build.log = stderr_log_sink(args.quiet ? log_level::warning : log_level::info);
  options.build.fmu_debug_logging = args.fmu_debug_log;
  options.build.threads = args.threads;
  // joins the DDS domain only when a component has a worker
  options.build.placements.push_back(
      std::make_shared<remote::remote_placement>(args.dds, worker_limits(args)));
  options.record_signals = record_patterns(args.signals);
  options.stop_when = args.stop_when;
  options.extra_records = args.extra_records;
  options.force_output = args.force;
  options.interrupt = &catch_stop_signals();
  if (args.record_interval) {
    try {
      options.record_interval = parse_duration(*args.record_interval);
    } catch (const std::exception& e) {
      throw validation_error(std::string("--record-interval: ") + e.what());
    }
  }
  if (args.checkpoint_every) {
    try {
      options.checkpoint_every = parse_duration(*args.checkpoint_every);
    } catch (const std::exception& e) {
      throw validation_error(std::string("--checkpoint-every: ") + e.what());
    }
    if (*options.checkpoint_every <= duration::zero()) {
      throw validation_error("--checkpoint-every: " + *args.checkpoint_every +
                             " is not a positive number of seconds");
    }
  }
  std::optional<fs::path> system_file = args.system;
  if (!args.resume.empty()) {
    // resume the system as it was run (overrides included), unless another one is given
    options.resume_dir = args.resume;
    if (!system_file) system_file = args.resume / "system.xml";
    if (!args.output.empty()) throw validation_error("--resume and --output exclude each other");
  }
  system_structure system = load_system(system_file, extension, options.build.log);
  apply_stepping(system, args.step, args.algorithm);
  apply_failover(system, args.standby, args.snapshot_every);
  if (!options.resume_dir.empty() && system.agents.count == 0 &&
      !fs::exists(checkpoint_file(options.resume_dir))) {
    // starting over: the results of the interrupted run stay as they are
    options.record_file = fresh_results_name(options.resume_dir, system.record.file);
  }
  if (extension.check) {
    system_structure checked = system;
    for (const auto& o : options.overrides) apply_override(checked, o);
    extension.check(checked);
  }
  if (args.agents > 0) {
    if (!options.resume_dir.empty() && args.agents != system.agents.count) {
      throw validation_error("--agents " + std::to_string(args.agents) + ": the run in " +
                             options.resume_dir.string() + " has " +
                             std::to_string(system.agents.count) + " agents");
    }
    system.agents.count = args.agents;
  }
  if (!options.resume_dir.empty()) {
    // a finished run stays as it is
    const run_status before = read_run_status(options.resume_dir);
    if (before.status == "ok") {
      std::string how;
      if (!before.ended_by.empty()) {
        how = " (" + before.ended_by +
              (before.end_time.empty() ? "" : " at t = " + before.end_time + " s") + ")";
      }
      std::printf("%s: the run has finished%s: nothing to resume\n",
                  options.resume_dir.string().c_str(), how.c_str());
      return 0;
    }
  }
  if (system.agents.count > 0) {
    if (options.checkpoint_every) {
      throw validation_error(
          "--checkpoint-every: a run of agents is resumed from its shared table's journal and "
          "the learners' own checkpoints (docs/swarm.md), not from checkpoint.stride");
    }
    return run_agents(std::move(system), options, args, extension);
  }
  const run_report report = run_system(std::move(system), options);
  if (!args.save_reference.empty()) {
    if (report.results_file.empty()) throw validation_error("--save-reference: nothing recorded");
    if (args.save_reference.has_parent_path()) {
      fs::create_directories(args.save_reference.parent_path());
    }
    fs::copy_file(report.results_file, args.save_reference, fs::copy_options::overwrite_existing);
    if (!args.quiet) std::printf("reference: %s\n", args.save_reference.string().c_str());
  }
  if (extension.report) extension.report(report, args);
  if (report.result.interrupted) {
    const int signal = caught_stop_signal();
    std::fprintf(stderr,
                 "stride: interrupted by %s at t = %s s after %lld steps; what was recorded is "
                 "in %s\n",
                 signal == SIGTERM ? "SIGTERM" : "SIGINT",
                 format_seconds(report.result.end_time).c_str(),
                 static_cast<long long>(report.result.steps), report.output_dir.string().c_str());
    return 128 + (signal == SIGTERM ? SIGTERM : SIGINT);
  }
  if (!args.quiet) {
    // why and when it ended; the wall time and real-time factor are the progress display's
    const bool early = report.result.terminated_by_component || !report.result.stopped_by.empty();
    std::printf("%s at t = %s s after %lld steps (%.2f s wall, real-time factor %.2f)\n",
                early ? ("stopped: " + end_reason(report.result)).c_str() : "finished",
                format_seconds(report.result.end_time).c_str(),
                static_cast<long long>(report.result.steps), report.wall_seconds,
                report.real_time_factor);
    std::printf("output: %s\n", report.output_dir.string().c_str());
  }
  return 0;
}

int test(const test_arguments& args, const stride::suite::assertion_registry& kinds) {
  const stride::suite::suite_spec suite = stride::suite::parse_suite_file(args.suite);
  stride::suite::check_suite(suite, kinds);
  stride::suite::run_settings settings;
  settings.stride = fs::read_symlink("/proc/self/exe");
  settings.output_dir = args.output;
  if (settings.output_dir.empty()) {
    system_structure named;
    named.name = suite.name;
    settings.output_dir = default_output_dir(named);
  }
  settings.jobs = args.jobs;
  settings.filter = args.filter;
  settings.kinds = kinds;
  settings.progress = args.quiet ? nullptr : stdout;
  const stride::suite::suite_report report = stride::suite::run_suite(suite, settings);
  if (!args.junit.empty()) stride::suite::write_junit(args.junit, suite, report);
  const std::string summary = stride::suite::format_summary(report);
  if (args.quiet) {
    std::fputs(summary.substr(summary.rfind('\n', summary.size() - 2) + 1).c_str(), stdout);
  } else {
    std::printf("\n%s", summary.c_str());
    std::printf("output: %s\n", settings.output_dir.string().c_str());
  }
  const bool all_passed = report.count(stride::suite::case_status::passed) == report.cases.size();
  return all_passed ? 0 : 1;
}

int inspect(const fs::path& file) {
  if (file.extension() != ".fmu") return inspect_system(file);
  const fs::path& fmu_file = file;
  const model_description md = read_archive_description(fmu_file);
  std::ostringstream out;
  int key_width = 22;
  auto row = [&](const char* key, const std::string& value) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "  %-*s", key_width, key);
    out << buf << value << "\n";
  };
  out << "Model Info\n\n";
  row("FMI Version", md.fmi_version);
  std::string type = md.co_simulation ? "Co-Simulation" : "";
  if (md.has_model_exchange) type += type.empty() ? "Model Exchange" : ", Model Exchange";
  row("FMI Type", type);
  row("Model Name", md.model_name);
  row("Description", md.description);
  row("GUID", md.guid);
  row("Author", md.author);
  row("Version", md.version);
  row("Generation Tool", md.generation_tool);
  row("Generation Date", md.generation_date_and_time);
  if (md.co_simulation) {
    const auto& cs = *md.co_simulation;
    out << "\nCo-Simulation Capabilities\n\n";
    key_width = 40;
    row("modelIdentifier", cs.model_identifier);
    row("canHandleVariableCommunicationStepSize",
        yes_no(cs.can_handle_variable_communication_step_size));
    row("canInterpolateInputs", yes_no(cs.can_interpolate_inputs));
    row("maxOutputDerivativeOrder", std::to_string(cs.max_output_derivative_order));
    row("canBeInstantiatedOnlyOncePerProcess",
        yes_no(cs.can_be_instantiated_only_once_per_process));
    row("canNotUseMemoryManagementFunctions", yes_no(cs.can_not_use_memory_management_functions));
    row("canGetAndSetFMUstate", yes_no(cs.can_get_and_set_fmu_state));
    row("canSerializeFMUstate", yes_no(cs.can_serialize_fmu_state));
    row("providesDirectionalDerivative", yes_no(cs.provides_directional_derivative));
  }
  if (md.model_exchange) {
    const auto& me = *md.model_exchange;
    out << "\nModel Exchange Capabilities\n\n";
    key_width = 40;
    row("modelIdentifier", me.model_identifier);
    row("continuous states", std::to_string(md.derivatives.size()));
    row("numberOfEventIndicators", std::to_string(md.number_of_event_indicators));
    row("completedIntegratorStepNotNeeded", yes_no(me.completed_integrator_step_not_needed));
    row("canGetAndSetFMUstate", yes_no(me.can_get_and_set_fmu_state));
    row("canSerializeFMUstate", yes_no(me.can_serialize_fmu_state));
    row("providesDirectionalDerivative", yes_no(me.provides_directional_derivative));
  }
  const auto& de = md.default_experiment;
  auto opt = [](const std::optional<double>& d) {
    if (!d) return std::string("-");
    std::ostringstream s;
    s << *d;
    return s.str();
  };
  key_width = 22;
  out << "\nDefault Experiment\n\n";
  row("Start Time", opt(de.start_time));
  row("Stop Time", opt(de.stop_time));
  row("Tolerance", opt(de.tolerance));
  row("Step Size", opt(de.step_size));

  out << "\nVariables (" << md.variables.size() << ")\n\n";
  std::size_t width = 4;
  for (const auto& v : md.variables) width = std::max(width, v.name.size());
  char head[256];
  std::snprintf(head, sizeof head, "%-*s  %-19s  %-11s  %-11s  %-12s  %-8s  %s\n",
                static_cast<int>(width), "Name", "Causality", "Variability", "Type", "Start",
                "Unit", "Description");
  out << head;
  for (const auto& v : md.variables) {
    std::string start = v.start.value_or("");
    if (v.type == variable_type::string && v.start) start = "\"" + start + "\"";
    std::string unit = v.unit;
    char line[512];
    std::snprintf(
        line, sizeof line, "%-*s  %-19s  %-11s  %-11s  %-12s  %-8s  %s\n", static_cast<int>(width),
        v.name.c_str(), std::string(to_string(v.causality)).c_str(),
        std::string(to_string(v.variability)).c_str(), std::string(to_string(v.type)).c_str(),
        start.c_str(), unit.c_str(), v.description.c_str());
    out << line;
  }
  std::fputs(out.str().c_str(), stdout);
  return 0;
}

int validate(const validate_arguments& args) {
  const bool is_fmu = args.file.extension() == ".fmu";
  if (!is_fmu) {
    const log_sink log = stderr_log_sink(args.quiet ? log_level::warning : log_level::info);
    system_structure system = load_system_file(args.file, log);
    apply_stepping(system, args.step, args.algorithm);
    for (const auto& s : args.sets) apply_override(system, s);
    if (args.stop_time) system.stop = parse_stop(*args.stop_time);
    build_options options;
    options.log = log;
    // components placed on workers are checked here with the same FMU: validation needs no
    // worker to be running
    system_structure local = system;
    for (auto& c : local.components) c.worker.clear();
    for (auto& g : local.groups) {
      for (auto& c : g.components) c.worker.clear();
    }
    temp_dir scratch("stride-validate-");
    // the placeholders as a run of one substitutes them
    system_structure substituted = expand_replicas(local);
    substitute_placeholders(substituted, scratch.path() / "run", {}, single_run_placeholders());
    const built_system built = build_system(substituted, options);
    // and everything a run checks before its first step: records, start values, initialization
    {
      run_options dry;
      dry.output_dir = scratch.path() / "run";
      dry.progress = false;
      dry.build.log = stderr_log_sink(log_level::warning);  // the run of no steps says nothing
      dry.initialize_only = true;
      run_system(local, dry);
    }
    if (!args.quiet) {
      const execution& ex = *built.execution;
      std::string order;
      for (std::size_t i : ex.order()) {
        order += (order.empty() ? "" : " -> ") + ex.component_at(i).name();
      }
      std::printf(
          "%s: OK: system '%s', %zu components, %zu connections (%zu variable pairs), "
          "%s order %s, base step %s s, %s .. %s s\n",
          args.file.string().c_str(), system.name.c_str(), ex.component_count(),
          expand_replicas(system).connections.size(), ex.connections().size(),
          ex.algorithm_name().c_str(), order.c_str(), format_seconds(built.base_step).c_str(),
          format_seconds(built.start).c_str(), format_seconds(built.stop).c_str());
      if (has_workers(system)) {
        std::printf("placement:\n%s", placement_table(system).c_str());
        std::vector<std::string> workers;
        for (const auto& c : expand_replicas(system).components) workers.push_back(c.worker);
        for (const auto& g : worker_groups(ex, workers, system.algorithm)) {
          std::string names;
          for (std::size_t i : g) names += (names.empty() ? "" : ", ") + ex.component_at(i).name();
          std::printf("  %s step together on worker %s\n", names.c_str(), workers[g[0]].c_str());
        }
      }
    }
    return 0;
  }

  int errors = 0;
#ifdef STRIDE_HAVE_FMI_CHECK
  const auto findings = stride::fmi_check::check_fmu(args.file);
  for (const auto& f : findings) {
    std::fprintf(stderr, "%s\n", stride::fmi_check::format_finding(args.file.string(), f).c_str());
    if (f.level == stride::fmi_check::finding::severity::error) ++errors;
  }
#endif
  // import and a full initialization, to catch binary, symbol and GUID problems
  try {
    auto f = fmu::load(args.file);
    instance_options io;
    io.log = stderr_log_sink(log_level::warning);
    auto c = f->instantiate("validate", io);
    const auto& de = f->model_description().default_experiment;
    c->setup(time_from_seconds(de.start_time.value_or(0.0)), std::nullopt);
    c->enter_initialization();
    c->exit_initialization();
    c->terminate();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: [import] %s\n", args.file.string().c_str(), e.what());
    ++errors;
  }
  if (errors > 0) {
    std::fprintf(stderr, "stride: error: %s: %d error(s)\n", args.file.string().c_str(), errors);
    return 1;
  }
  if (!args.quiet) std::printf("%s: OK\n", args.file.string().c_str());
  return 0;
}

}  // namespace stride::cli
