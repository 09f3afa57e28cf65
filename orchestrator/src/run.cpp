#include "stride/cosim/run.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>
#include <span>
#include <sstream>

#include "run_checkpoint.hpp"
#include "run_files.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"

#ifndef STRIDE_VERSION
#define STRIDE_VERSION "0.0.0"
#endif

namespace stride::cosim {

namespace fs = std::filesystem;

std::string_view version() noexcept {
  return STRIDE_VERSION;
}

namespace {

struct manifest_data {
  const system_structure* system = nullptr;
  const built_system* built = nullptr;
  const run_report* report = nullptr;
  std::string started;
  std::string resumed_from;              ///< the --resume folder, if any
  std::optional<time_point> resumed_at;  ///< continued from a checkpoint at this time
  std::string checkpoint;                ///< file name of the checkpoint written, if any
  const std::vector<std::shared_ptr<placement_resolver>>* placements = nullptr;
};

// what the placements counted (failovers): "events": {"failovers": 1}, nothing when none counts
void write_events(std::ostream& j, const manifest_data& m) {
  if (m.placements == nullptr) return;
  std::string fields;
  for (const auto& p : *m.placements) {
    for (const auto& [what, count] : p->events()) {
      fields += (fields.empty() ? "" : ", ") + json_string(what) + ": " + std::to_string(count);
    }
  }
  if (!fields.empty()) j << "  \"events\": {" << fields << "},\n";
}

std::string manifest_json(const manifest_data& m) {
  const auto& s = *m.system;
  const auto& r = *m.report;
  std::ostringstream j;
  j << "{\n";
  j << "  \"stride_version\": " << json_string(version()) << ",\n";
  j << "  \"status\": "
    << json_string(!r.error.empty()       ? "error"
                   : r.result.interrupted ? "interrupted"
                                          : "ok")
    << ",\n";
  if (!r.error.empty()) j << "  \"error\": " << json_string(r.error) << ",\n";
  j << "  \"system\": " << json_string(s.name) << ",\n";
  j << "  \"system_file\": " << json_string(s.where.file) << ",\n";
  j << "  \"started_utc\": " << json_string(m.started) << ",\n";
  if (!m.resumed_from.empty()) j << "  \"resumed_from\": " << json_string(m.resumed_from) << ",\n";
  j << "  \"algorithm\": " << json_string(to_string(s.algorithm)) << ",\n";
  j << "  \"start_time\": " << format_seconds(s.start) << ",\n";
  if (m.built) {
    j << "  \"stop_time\": " << format_seconds(m.built->stop) << ",\n";
    j << "  \"base_step\": " << format_seconds(m.built->base_step) << ",\n";
  }
  j << "  \"end_time\": " << format_seconds(r.result.end_time) << ",\n";
  j << "  \"steps\": " << r.result.steps << ",\n";
  j << "  \"ended_by\": " << json_string(r.error.empty() ? end_reason(r.result) : "error") << ",\n";
  // the same as data: what ended the run and when
  const run_result& e = r.result;
  j << "  \"stop_reason\": {\"kind\": "
    << json_string(!r.error.empty()            ? "error"
                   : e.terminated_by_component ? "component"
                   : !e.stopped_by.empty()     ? "condition"
                   : e.interrupted             ? "interrupted"
                                               : "stop_time");
  if (r.error.empty() && e.terminated_by_component) {
    j << ", \"component\": " << json_string(e.terminated_by);
  }
  if (r.error.empty() && !e.stopped_by.empty()) {
    j << ", \"variable\": " << json_string(e.stopped_by);
  }
  j << ", \"time\": " << format_seconds(e.end_time) << "},\n";
  if (r.result.interrupted && r.error.empty()) {
    j << "  \"interrupted_at\": " << format_seconds(r.result.end_time) << ",\n";
  }
  if (!m.checkpoint.empty()) j << "  \"checkpoint\": " << json_string(m.checkpoint) << ",\n";
  if (m.resumed_at) j << "  \"resumed_at\": " << format_seconds(*m.resumed_at) << ",\n";
  write_events(j, m);
  j << "  \"wall_time_s\": " << json_number(r.wall_seconds) << ",\n";
  j << "  \"real_time_factor\": " << json_number(r.real_time_factor) << ",\n";
  // every value the system sets, so that a run can be told apart from another (seeds included)
  j << "  \"parameters\": {";
  bool first_parameter = true;
  for (const auto& c : s.components) {
    for (const auto& p : c.parameters) {
      j << (first_parameter ? "\n    " : ",\n    ") << json_string(c.name + "." + p.variable)
        << ": " << json_string(p.value);
      first_parameter = false;
    }
  }
  j << (first_parameter ? "},\n" : "\n  },\n");
  j << "  \"results\": " << json_string(r.results_file.filename().string()) << ",\n";
  j << "  \"components\": [";
  if (m.built) {
    for (std::size_t i = 0; i < m.built->components.size(); ++i) {
      const auto& c = m.built->components[i];
      j << (i ? ",\n" : "\n") << "    {\"name\": " << json_string(c.name)
        << ", \"fmu\": " << json_string(c.fmu.string()) << ", \"guid\": " << json_string(c.guid)
        << ", \"model_name\": " << json_string(c.model_name)
        << ", \"generation_tool\": " << json_string(c.generation_tool)
        << ", \"step_multiple\": " << c.step_multiple << "}";
    }
    if (!m.built->components.empty()) j << "\n  ";
  }
  j << "]\n}\n";
  return j.str();
}

}  // namespace

fs::path checkpoint_file(const fs::path& run_dir) {
  return run_dir / "checkpoint.stride";
}

run_status read_run_status(const fs::path& run_dir) {
  const fs::path manifest = run_dir / "manifest.json";
  run_status s;
  if (!fs::is_regular_file(manifest)) return s;
  s.status = read_manifest_field(manifest, "status");
  s.end_time = read_manifest_field(manifest, "end_time");
  s.ended_by = read_manifest_field(manifest, "ended_by");
  return s;
}

std::string end_reason(const run_result& result) {
  if (result.terminated_by_component) {
    return "component " + result.terminated_by + " requested termination";
  }
  if (!result.stopped_by.empty()) return result.stopped_by;
  return result.interrupted ? "interrupted" : "stop time";
}

fs::path default_output_dir(const system_structure& system) {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  const fs::path base = fs::path("stride-out") / (system.name + "-" + stamp);
  fs::path candidate = base;
  for (int n = 2; fs::exists(candidate); ++n) {
    candidate = base.string() + "-" + std::to_string(n);
  }
  return candidate;
}

std::string fresh_results_name(const fs::path& dir, const std::string& name) {
  const fs::path first = name;
  fs::path file = first;
  for (int n = 1; fs::exists(dir / file); ++n) {
    file =
        first.parent_path() / (first.stem().string() + "-resumed" +
                               (n > 1 ? "-" + std::to_string(n) : "") + first.extension().string());
  }
  return file.string();
}

std::size_t substitute_placeholders(system_structure& system, const fs::path& output_dir,
                                    const fs::path& resume_dir,
                                    const std::map<std::string, std::string>& more) {
  static constexpr std::string_view k_output = "${output_dir}", k_resume = "${resume}";
  std::size_t resume_uses = 0;
  for (auto& c : system.components) {
    for (auto& p : c.parameters) {
      std::string out;
      std::string_view rest = p.value;
      for (auto pos = rest.find("${"); pos != std::string_view::npos; pos = rest.find("${")) {
        out += rest.substr(0, pos);
        rest.remove_prefix(pos);
        if (rest.starts_with(k_output)) {
          out += output_dir.string();
          rest.remove_prefix(k_output.size());
        } else if (rest.starts_with(k_resume)) {
          out += resume_dir.string();
          rest.remove_prefix(k_resume.size());
          ++resume_uses;
        } else {
          const auto close = rest.find('}');
          const auto it = close == std::string_view::npos
                              ? more.end()
                              : more.find(std::string(rest.substr(2, close - 2)));
          if (it == more.end()) {
            std::string known = "${output_dir}, ${resume}";
            for (const auto& [name, value] : more) known += ", ${" + name + "}";
            const std::string where = p.where.str();
            throw validation_error((where.empty() ? "" : where + ": ") + "parameter '" + c.name +
                                   "." + p.variable + "': unknown placeholder in '" + p.value +
                                   "' (known: " + known + ")");
          }
          out += it->second;
          rest.remove_prefix(close + 1);
        }
      }
      out += rest;
      p.value = std::move(out);
    }
  }
  return resume_uses;
}

void check_output_folder_free(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) {
    throw validation_error("output folder " + dir.string() + " is a file, not a folder");
  }
  if (fs::exists(dir / "system.xml")) {
    throw validation_error("output folder " + dir.string() +
                           " holds an earlier run (its system.xml): choose another --output, "
                           "remove it, continue it with --resume, or replace its files with "
                           "--force");
  }
  fs::directory_iterator entries(dir, ec);
  if (ec) throw validation_error("output folder " + dir.string() + ": " + ec.message());
  if (entries != fs::directory_iterator()) {
    throw validation_error("output folder " + dir.string() + " is not empty (it holds " +
                           entries->path().filename().string() +
                           "): choose another --output, empty it, or write into it anyway with "
                           "--force");
  }
}

std::map<std::string, std::string> single_run_placeholders() {
  return {{"agent", "1"}, {"shared_table", ""}};
}

run_report run_system(system_structure system, const run_options& options) {
  std::map<std::string, std::string> placeholders = options.placeholders;
  const bool as_agent = placeholders.contains("agent");
  placeholders.merge(single_run_placeholders());  // keeps the given ones
  if (system.agents.count > 0 && !as_agent && !options.initialize_only) {
    const std::string where = system.agents.where.str();
    throw validation_error((where.empty() ? "" : where + ": ") + "system '" + system.name +
                           "' has <agents>: run it with run_agents");
  }
  system.agents = {};
  for (const auto& o : options.overrides) apply_override(system, o);
  if (options.stop) system.stop = *options.stop;
  // what is recorded belongs to the run as written: a resumed run records the same
  if (!options.record_signals.empty()) {
    system.record.enabled = true;
    system.record.signals = options.record_signals;
    system.record.signal_locations.assign(options.record_signals.size(),
                                          source_location{"--record", 0});
  }
  if (options.record_interval) system.record.interval = *options.record_interval;
  // the copies of replica groups get their own names and ${copy} values before the run's
  // placeholders are substituted; system.xml keeps the groups
  const system_structure as_written = system;
  system = expand_replicas(system);

  run_report report;
  const bool resuming = !options.resume_dir.empty();
  if (resuming) {
    if (!fs::is_directory(options.resume_dir)) {
      throw validation_error("--resume: " + options.resume_dir.string() + " is not a folder");
    }
    report.output_dir = options.resume_dir;
  } else {
    report.output_dir =
        options.output_dir.empty() ? default_output_dir(system) : options.output_dir;
    if (!options.initialize_only && !options.force_output) {
      check_output_folder_free(report.output_dir);
    }
  }
  // system.xml keeps the placeholders (as_written above), so it can be run (resumed) again
  const std::size_t resume_uses = substitute_placeholders(
      system, fs::absolute(report.output_dir),
      resuming ? fs::absolute(options.resume_dir) : fs::path(), placeholders);
  // a run interrupted between two steps left the state of the whole system: go on from there
  std::optional<detail::checkpoint_data> saved;
  if (resuming && !as_agent && fs::exists(checkpoint_file(options.resume_dir))) {
    saved = detail::read_checkpoint(checkpoint_file(options.resume_dir));
  }
  if (resuming && resume_uses == 0 && !saved) {
    throw validation_error("--resume: " + options.resume_dir.string() +
                           " holds no checkpoint of an interrupted run (" +
                           checkpoint_file({}).string() + ") and no parameter of system '" +
                           system.name + "' uses ${resume}, so nothing would continue from it");
  }
  if (options.record_file) system.record.file = *options.record_file;

  report.system = system;
  built_system built = build_system(system, options.build);
  auto& ex = *built.execution;

  // what to record and when to stop, checked before anything is written
  std::vector<variable_id> recorded;
  if (system.record.enabled) {
    for (std::size_t i = 0; i < system.record.signals.size(); ++i) {
      const auto& pattern = system.record.signals[i];
      const auto found = find_variables(ex, pattern);
      if (found.empty()) {
        const std::string where = i < system.record.signal_locations.size()
                                      ? system.record.signal_locations[i].str()
                                      : system.where.str();
        throw validation_error((where.empty() ? "" : where + ": ") + "record signal '" + pattern +
                               "' matches no variable");
      }
      for (const auto& v : found) {
        if (std::find(recorded.begin(), recorded.end(), v) == recorded.end()) recorded.push_back(v);
      }
    }
    if (const auto& interval = system.record.interval;
        interval && (*interval <= duration::zero() || *interval % built.base_step != duration{})) {
      const std::string where =
          options.record_interval ? std::string("--record-interval") : system.record.where.str();
      throw validation_error((where.empty() ? "" : where + ": ") + "recording interval " +
                             format_seconds(*interval) +
                             " s is not a positive multiple of the base step " +
                             format_seconds(built.base_step) + " s");
    }
  }
  // further recordings: resolved and checked with the results' signals, before anything is
  // written
  std::vector<std::pair<std::vector<variable_id>, std::optional<duration>>> extras;
  for (const extra_record& e : options.extra_records) {
    const std::string what = e.origin.empty() ? e.file : e.origin;
    if (e.file.empty() || e.file == "system.xml" || e.file == "manifest.json" ||
        (system.record.enabled && e.file == system.record.file)) {
      throw validation_error(what + ": '" + e.file + "' is not a free file name in the run folder");
    }
    std::vector<variable_id> vars;
    for (const auto& pattern : e.signals) {
      for (const auto& v : find_variables(ex, pattern)) {
        if (std::find(vars.begin(), vars.end(), v) == vars.end()) vars.push_back(v);
      }
    }
    if (vars.empty()) throw validation_error(what + ": no variable of the system to record");
    std::optional<duration> interval;
    if (e.interval) {
      const auto steps = std::max<std::int64_t>(
          1, (e.interval->count() + built.base_step.count() / 2) / built.base_step.count());
      interval = built.base_step * steps;
    }
    extras.emplace_back(std::move(vars), interval);
  }
  for (const auto& pattern : options.stop_when) {
    const std::string what = "--stop-when '" + pattern + "': ";
    const auto found = find_variables(ex, pattern);
    if (found.empty()) throw validation_error(what + "names no variable");
    const bool wildcard = pattern.find_first_of("*?") != std::string::npos;
    std::size_t conditions = 0;
    for (const auto& v : found) {
      const auto& var = ex.component_at(v.component).model_description().variables[v.variable];
      // a wildcard takes the outputs it matches that can be conditions
      if (wildcard && (var.causality != causality::output ||
                       exchange_type(var.type) == variable_type::string)) {
        continue;
      }
      try {
        ex.stop_when(v);
        ++conditions;
      } catch (const validation_error& e) {
        throw validation_error(what + e.what());
      }
    }
    if (conditions == 0) {
      throw validation_error(what + "matches no Boolean, Integer or Real output");
    }
  }

  create_output_folder(report.output_dir);
  write_file(report.output_dir / "system.xml", to_xml(as_written));
  report.manifest_file = report.output_dir / "manifest.json";

  // the run's wall clock, told first of all observers that the simulation ended
  const auto timer = std::make_shared<wall_timer>();
  ex.add_observer(timer);
  std::vector<std::shared_ptr<csv_recorder>> recorders;  // flushed before a checkpoint
  if (system.record.enabled) {
    report.results_file = report.output_dir / system.record.file;
    try {
      auto recorder =
          std::make_shared<csv_recorder>(report.results_file, recorded, system.record.interval);
      if (saved) recorder->continue_after(saved->time);  // the rows so far stay
      recorders.push_back(recorder);
      ex.add_observer(std::move(recorder));
    } catch (const validation_error& e) {
      const std::string where = system.record.where.str();
      throw validation_error((where.empty() ? "" : where + ": ") + e.what());
    }
  }
  for (std::size_t i = 0; i < extras.size(); ++i) {
    report.extra_files.push_back(report.output_dir / options.extra_records[i].file);
    auto recorder = std::make_shared<csv_recorder>(report.extra_files.back(), extras[i].first,
                                                   extras[i].second);
    if (saved) recorder->continue_after(saved->time);
    recorders.push_back(recorder);
    ex.add_observer(std::move(recorder));
  }
  if (options.progress) {
    ex.add_observer(std::make_shared<progress_display>(built.stop, stderr, std::nullopt,
                                                       std::chrono::seconds(5), timer));
  }

  manifest_data m;
  m.system = &system;
  m.built = &built;
  m.report = &report;
  m.started = utc_now();
  m.placements = &options.build.placements;
  if (resuming) m.resumed_from = fs::absolute(options.resume_dir).string();
  if (saved) m.resumed_at = saved->time;
  // the figures the progress display showed last: one timer, one definition
  auto finish_report = [&] {
    report.wall_seconds = timer->seconds();
    report.real_time_factor = real_time_factor(
        report.result.end_time - (saved ? saved->time : system.start), report.wall_seconds);
  };
  if (options.initialize_only) {
    ex.initialize(built.stop);
    ex.end();
    return report;
  }
  timer->start();  // initialization is part of the run's wall time
  try {
    if (saved) {
      ex.initialize(built.stop);
      ex.restore_state_bytes(saved->state);
      if (ex.current_time() != saved->time) {
        throw validation_error(checkpoint_file(options.resume_dir).string() +
                               ": damaged (its time is not that of its state)");
      }
    }
    // a checkpoint now and then: the rows up to it are on disk before it is
    const auto save_now = [&] {
      for (const auto& r : recorders) r->flush();
      detail::write_checkpoint(checkpoint_file(report.output_dir), ex.current_time(),
                               ex.save_state_bytes());
    };
    const auto cannot_save = [&](const std::string& why) {
      if (options.build.log) {
        options.build.log(log_level::warning, "stride", "",
                          "no more checkpoints (--checkpoint-every): " + why);
      }
    };
    report.result =
        detail::simulate_saving(ex, built.stop, as_agent ? std::nullopt : options.checkpoint_every,
                                options.interrupt, save_now, cannot_save);
    if (report.result.interrupted && !as_agent) {
      // between two steps: every component can be saved as it is now (agents are resumed
      // from their journal instead, stride/cosim/run_agents.hpp)
      try {
        detail::write_checkpoint(checkpoint_file(report.output_dir), ex.current_time(),
                                 ex.save_state_bytes());
        m.checkpoint = checkpoint_file({}).string();
      } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove(checkpoint_file(report.output_dir), ec);  // not one of an earlier moment
        if (options.build.log) {
          options.build.log(log_level::warning, "stride", "",
                            std::string("no checkpoint to resume from: ") + e.what());
        }
      }
    } else if (!report.result.interrupted) {
      std::error_code ec;
      fs::remove(checkpoint_file(report.output_dir), ec);  // finished: nothing to resume
    }
    ex.end();
  } catch (const std::exception& e) {
    report.error = e.what();
    report.result.end_time = ex.current_time();
    report.result.steps = ex.step_count();
    finish_report();
    try {
      write_file(report.manifest_file, manifest_json(m));
    } catch (const std::exception& manifest_failure) {
      // e.g. a full disk: the first error is the one to report
      throw error(report.error + " (" + manifest_failure.what() + ")");
    }
    throw;
  }
  finish_report();
  write_file(report.manifest_file, manifest_json(m));
  return report;
}

}  // namespace stride::cosim
