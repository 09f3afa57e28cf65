#include "sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "commands.hpp"
#include "stop_signals.hpp"
#include "stride/common/files.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/algorithm.hpp"
#include "stride/cosim/archive.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/fmu.hpp"
#include "stride/cosim/system_builder.hpp"
#include "stride/cosim/system_import.hpp"
#include "stride/cosim/time.hpp"
#include "stride/remote/remote_placement.hpp"
#include "workers.hpp"

namespace stride::cli {

namespace fs = std::filesystem;
using cosim::validation_error;

namespace {

constexpr std::size_t k_max_points = 1000000;
constexpr const char* k_settings_file = "sweep-settings.txt";

std::string label_of(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);  // 450 + 2 * 0.1 prints as 450.2, not ...0001
  return buf;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw cosim::error(file.string() + ": cannot be read");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string duration_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[48];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, s / 60 % 60);
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ld s", s);
  }
  return buf;
}

// --- what goes in the table --------------------------------------------------------------

// One column of the table, from a point's folder.
struct column_reader {
  std::string name;
  std::function<double(const fs::path&)> read;
};

// "FILE:COLUMN[:REDUCE]" over the data rows of a CSV file in the point's folder
column_reader file_column(const std::string& spec) {
  static const std::vector<std::string> reducers{"last", "first", "mean", "min",
                                                 "max",  "sum",   "count"};
  std::string text = spec, name;
  const auto eq = text.find('='), colon = text.find(':');
  if (eq != std::string::npos && (colon == std::string::npos || eq < colon)) {
    name = text.substr(0, eq);
    text = text.substr(eq + 1);
  }
  const auto first = text.find(':');
  if (first == std::string::npos || first == 0 || first + 1 == text.size()) {
    throw validation_error("--collect '" + spec +
                           "': expected [NAME=]FILE:COLUMN[:REDUCE] or the name of a collector");
  }
  const std::string file = text.substr(0, first);
  std::string column = text.substr(first + 1);
  std::string reduce = "last";
  const auto last = column.rfind(':');
  if (last != std::string::npos &&
      std::find(reducers.begin(), reducers.end(), column.substr(last + 1)) != reducers.end()) {
    reduce = column.substr(last + 1);
    column.resize(last);
  }
  if (column.empty()) throw validation_error("--collect '" + spec + "': no COLUMN");
  if (fs::path(file).is_absolute() || file.find("..") != std::string::npos) {
    throw validation_error("--collect '" + spec + "': FILE is relative to the point's folder");
  }
  if (name.empty()) name = reduce == "last" ? column : column + "_" + reduce;
  return {name, [file, column, reduce](const fs::path& dir) {
            const fs::path path = dir / file;
            std::istringstream in(read_text(path));
            std::string line;
            if (!std::getline(in, line)) throw cosim::error(path.string() + ": empty file");
            const auto header = text::csv_fields(line);
            const auto it = std::find(header.begin(), header.end(), column);
            if (it == header.end()) {
              throw cosim::error(path.string() + ": no column '" + column + "'");
            }
            const auto index = static_cast<std::size_t>(it - header.begin());
            std::vector<double> values;
            for (int line_no = 2; std::getline(in, line); ++line_no) {
              if (line.empty() || line == "\r") continue;
              const auto fields = text::csv_fields(line);
              const auto v =
                  index < fields.size() ? text::parse_double(fields[index]) : std::nullopt;
              if (!v) {
                throw cosim::error(path.string() + ":" + std::to_string(line_no) + ": column '" +
                                   column + "' is not a number");
              }
              values.push_back(*v);
            }
            if (reduce == "count") return static_cast<double>(values.size());
            if (values.empty()) throw cosim::error(path.string() + ": no data rows");
            if (reduce == "first") return values.front();
            if (reduce == "last") return values.back();
            if (reduce == "min") return *std::min_element(values.begin(), values.end());
            if (reduce == "max") return *std::max_element(values.begin(), values.end());
            double sum = 0;
            for (double v : values) sum += v;
            return reduce == "sum" ? sum : sum / static_cast<double>(values.size());
          }};
}

// a top-level value of manifest.json (written by run_system: one "key": value per line)
std::string manifest_value(const std::string& manifest, const std::string& key) {
  const std::string tag = "\n  \"" + key + "\": ";
  const auto pos = manifest.find(tag);
  if (pos == std::string::npos) return {};
  const auto start = pos + tag.size();
  const auto end = manifest.find('\n', start);
  std::string value = manifest.substr(start, end - start);
  if (!value.empty() && value.back() == ',') value.pop_back();
  if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
  return value;
}

// "ok" for a point run to its end; "" when there is no manifest
std::string point_status(const fs::path& dir) {
  const fs::path file = dir / "manifest.json";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return {};
  return manifest_value(read_text(file), "status");
}

column_reader manifest_column(const std::string& key) {
  return {key, [key](const fs::path& dir) {
            const fs::path file = dir / "manifest.json";
            const auto v = text::parse_double(manifest_value(read_text(file), key));
            if (!v) throw cosim::error(file.string() + ": no number '" + key + "'");
            return *v;
          }};
}

// --- running points concurrently ---------------------------------------------------------

// Points done / total and the time left on stderr: redrawn in place on a terminal, a line every
// few seconds otherwise. Messages of the points' runs go through it so they do not tear the line.
class progress_line {
 public:
  progress_line(std::size_t total, std::size_t kept, std::size_t to_run, bool quiet)
      : total_(total),
        kept_(kept),
        to_run_(to_run),
        quiet_(quiet),
        terminal_(::isatty(::fileno(stderr)) != 0),
        start_(std::chrono::steady_clock::now()) {}

  void point_done(bool failed) {
    const std::lock_guard lock(mutex_);
    ++ran_;
    if (failed) ++failed_;
    draw(ran_ == to_run_);
  }
  void message(const std::string& text) {
    const std::lock_guard lock(mutex_);
    std::string line = (terminal_ && drawn_ ? "\r\033[K" : "") + text + "\n";
    std::fwrite(line.data(), 1, line.size(), stderr);
    drawn_ = false;
    if (terminal_) draw(false);
  }
  void finish() {
    const std::lock_guard lock(mutex_);
    if (terminal_ && drawn_ && !quiet_) std::fputc('\n', stderr);
    drawn_ = false;
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  void draw(bool last) {
    if (quiet_) return;
    const double t = elapsed();
    if (!terminal_ && !last && t - last_line_ < 5) return;
    last_line_ = t;
    std::string eta = "ETA -";
    if (ran_ > 0) {
      eta = last ? "done"
                 : "ETA " + duration_text(t / static_cast<double>(ran_) *
                                          static_cast<double>(to_run_ - ran_));
    }
    char buf[256];
    std::snprintf(buf, sizeof buf, "sweep: %zu/%zu points (%zu kept, %zu failed), %s elapsed, %s",
                  kept_ + ran_, total_, kept_, failed_, duration_text(t).c_str(), eta.c_str());
    const std::string line =
        (terminal_ ? "\r\033[K" : "") + std::string(buf) + (terminal_ ? "" : "\n");
    std::fwrite(line.data(), 1, line.size(), stderr);
    drawn_ = terminal_;
  }

  std::mutex mutex_;
  const std::size_t total_, kept_, to_run_;
  std::size_t ran_ = 0, failed_ = 0;
  const bool quiet_, terminal_;
  const std::chrono::steady_clock::time_point start_;
  double last_line_ = -1e9;
  bool drawn_ = false;
};

enum class point_status_kind { pending, kept, ran, failed, interrupted };

struct point_outcome {
  point_status_kind status = point_status_kind::pending;
  std::string error;
  std::vector<double> values;
};

// The settings that decide a point's result: a second sweep into the same folder must use the
// same, or its kept points would belong to another sweep.
std::string settings_text(const sweep_arguments& args) {
  std::string text = "system = " + fs::absolute(args.system).lexically_normal().string() + "\n";
  text +=
      "stop_time = " + (args.stop_time.empty() ? std::string("(the system's)") : args.stop_time) +
      "\n";
  if (args.step) text += "step = " + *args.step + "\n";
  if (args.algorithm) text += "algorithm = " + *args.algorithm + "\n";
  const auto& grids = args.grids;
  const auto& sets = args.sets;
  for (const auto& g : grids) text += "grid = " + g + "\n";
  for (const auto& s : sets) text += "set = " + s + "\n";
  return text;
}

void check_settings(const fs::path& dir, const std::string& settings) {
  const fs::path file = dir / k_settings_file;
  // a folder that is not a sweep is refused as `stride run --output` refuses it
  if (!fs::exists(file)) {
    if (fs::exists(dir) && (!fs::is_directory(dir) || !fs::is_empty(dir))) {
      throw validation_error("--output " + dir.string() + " is not empty and holds no sweep (no " +
                             k_settings_file + "): give another --output, or empty the folder");
    }
    return;
  }
  const std::string before = read_text(file);
  if (before == settings) return;
  const auto old_lines = text::split(before, '\n'), new_lines = text::split(settings, '\n');
  std::size_t i = 0;
  while (i < old_lines.size() && i < new_lines.size() && old_lines[i] == new_lines[i]) ++i;
  const std::string was = i < old_lines.size() ? std::string(old_lines[i]) : "(nothing)";
  const std::string now = i < new_lines.size() ? std::string(new_lines[i]) : "(nothing)";
  throw validation_error("--output " + dir.string() + " holds a sweep with other settings (" +
                         file.string() + ": '" + was + "'; now '" + now +
                         "'): give another --output, or remove the folder");
}

}  // namespace

sweep_target parse_sweep_grid(std::string_view text) {
  const std::string quoted = "--grid '" + std::string(text) + "'";
  const auto eq = text.find('=');
  sweep_target t;
  if (eq != std::string_view::npos) t.variable = std::string(text.substr(0, eq));
  const auto dot = t.variable.find('.');
  if (eq == std::string_view::npos || dot == std::string::npos || dot == 0 ||
      dot + 1 == t.variable.size()) {
    throw validation_error(quoted + ": expected comp.var=name:min:max:step[,name:min:max:step...]");
  }
  t.axes_text = std::string(text.substr(eq + 1));
  const auto items = text::split(t.axes_text, ',');
  for (const std::string_view item_text : items) {
    const std::string item(item_text);
    const auto fields = text::split(item, ':');
    std::vector<std::string> parts(fields.begin(), fields.end());
    if (parts.size() == 3 && items.size() == 1 && text::parse_double(parts[0])) {
      parts.insert(parts.begin(), t.variable.substr(dot + 1));
    }
    if (parts.size() != 4 || parts[0].empty()) {
      throw validation_error(quoted + ": '" + item + "' is not name:min:max:step" +
                             (items.size() == 1 ? " (or min:max:step)" : ""));
    }
    const auto lo_text = text::parse_double(parts[1]), hi_text = text::parse_double(parts[2]),
               step_text = text::parse_double(parts[3]);
    if (!lo_text || !hi_text || !step_text || !std::isfinite(*lo_text) ||
        !std::isfinite(*hi_text) || !std::isfinite(*step_text)) {
      throw validation_error(quoted + ": '" + item + "': min, max and step must be numbers");
    }
    const double lo = *lo_text, hi = *hi_text, step = *step_text;
    if (step <= 0 || hi < lo) {
      throw validation_error(quoted + ": '" + item + "': need step > 0 and max >= min");
    }
    const double count = std::round((hi - lo) / step) + 1;
    if (count > static_cast<double>(k_max_points)) {
      throw validation_error(quoted + ": '" + item + "': more than a million values");
    }
    for (const auto& a : t.axes) {
      if (a.name == parts[0]) throw validation_error(quoted + ": axis '" + a.name + "' twice");
    }
    sweep_axis axis;
    axis.name = parts[0];
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
      const double v = lo + static_cast<double>(i) * step;
      axis.labels.push_back(label_of(v));
      axis.values.push_back(v);
    }
    t.axes.push_back(std::move(axis));
  }
  return t;
}

std::vector<sweep_point> sweep_points(const std::vector<sweep_target>& targets) {
  std::vector<const sweep_axis*> axes;
  std::vector<std::size_t> target_of;
  double total = 1;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    for (const auto& a : targets[t].axes) {
      axes.push_back(&a);
      target_of.push_back(t);
      total *= static_cast<double>(a.values.size());
    }
  }
  if (total > static_cast<double>(k_max_points)) {
    throw validation_error("--grid: " + label_of(total) + " points; at most a million");
  }
  std::vector<sweep_point> points;
  if (axes.empty()) return points;
  std::vector<std::size_t> index(axes.size(), 0);
  for (;;) {
    sweep_point p;
    std::vector<std::string> values(targets.size());
    for (std::size_t k = 0; k < axes.size(); ++k) {
      const std::string& label = axes[k]->labels[index[k]];
      p.labels.push_back(label);
      p.values.push_back(axes[k]->values[index[k]]);
      auto& v = values[target_of[k]];
      v += (v.empty() ? "" : ",") + label;
      p.name += (k ? "," : "") + label;
      p.folder += (k ? "_" : "") + label;
    }
    for (std::size_t t = 0; t < targets.size(); ++t) {
      p.overrides.push_back(targets[t].variable + "=" + values[t]);
    }
    points.push_back(std::move(p));
    std::size_t k = axes.size();
    while (k > 0 && ++index[k - 1] == axes[k - 1]->values.size()) index[--k] = 0;
    if (k == 0) return points;
  }
}

int sweep(const sweep_arguments& args, const sweep_extension& extension) {
  // --- everything that can be wrong with the arguments, before anything runs
  if (args.grids.empty()) throw validation_error("--grid: give at least one");
  cosim::system_structure system = cosim::load_system_file(args.system);
  apply_stepping(system, args.step, args.algorithm);
  std::vector<sweep_target> targets;
  for (const auto& g : args.grids) {
    targets.push_back(parse_sweep_grid(g));
    for (std::size_t i = 0; i + 1 < targets.size(); ++i) {
      if (targets[i].variable == targets.back().variable) {
        throw validation_error("--grid '" + g + "': " + targets.back().variable +
                               " is swept twice");
      }
    }
  }
  for (const auto& s : args.sets) {
    for (const auto& t : targets) {
      if (s.rfind(t.variable + "=", 0) == 0) {
        throw validation_error("--set '" + s + "': " + t.variable + " is swept by --grid");
      }
    }
    cosim::system_structure checked = system;
    cosim::apply_override(checked, s);  // names the bad --set
  }
  for (const auto& t : targets) {
    cosim::system_structure checked = system;
    try {
      cosim::apply_override(checked, t.variable + "=0");
    } catch (const std::exception& e) {
      throw validation_error("--grid '" + t.variable + "=" + t.axes_text + "': " + e.what());
    }
  }
  std::optional<cosim::time_point> stop;
  if (!args.stop_time.empty()) {
    try {
      stop = cosim::time_point(cosim::parse_duration(args.stop_time));
    } catch (const std::exception& e) {
      throw validation_error(std::string("--stop-time: ") + e.what());
    }
    if (*stop <= system.start) {
      throw validation_error("--stop-time: '" + args.stop_time +
                             "' is not after the system's start time");
    }
  }

  const sweep_profile* profile = nullptr;
  std::vector<column_reader> columns;
  for (const auto& c : args.collect) {
    const auto it = std::find_if(extension.profiles.begin(), extension.profiles.end(),
                                 [&](const sweep_profile& p) { return p.name == c; });
    if (it == extension.profiles.end()) {
      columns.push_back(file_column(c));
      continue;
    }
    if (profile != nullptr) {
      throw validation_error("--collect '" + c + "': only one named collector per sweep");
    }
    profile = &*it;
  }
  std::vector<std::string> names;
  if (profile != nullptr) names = profile->columns;
  if (profile == nullptr && columns.empty()) {
    columns = {manifest_column("end_time"), manifest_column("steps")};
  }
  for (const auto& c : columns) names.push_back(c.name);
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (names[i] == names[j]) {
        throw validation_error("--collect: two columns named '" + names[i] +
                               "' (name one NAME=FILE:COLUMN)");
      }
    }
  }

  const std::vector<sweep_point> points = sweep_points(targets);
  std::vector<std::string> common = args.sets;
  if (profile != nullptr && profile->overrides) {
    for (auto& o : profile->overrides(targets)) common.push_back(std::move(o));
  }

  fs::path dir = args.output;
  if (dir.empty()) {
    cosim::system_structure named;
    named.name = system.name + "-sweep";
    dir = cosim::default_output_dir(named);
  }
  const std::string settings = settings_text(args);
  check_settings(dir, settings);
  const fs::path points_dir = dir / "points";

  std::vector<point_outcome> outcomes(points.size());
  std::vector<std::size_t> to_run;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (point_status(points_dir / points[i].folder) == "ok") {
      outcomes[i].status = point_status_kind::kept;
    } else {
      to_run.push_back(i);
    }
  }

  // the points of a process share one import of each FMU (in-process placement)
  cosim::run_options base;
  base.stop = stop;
  base.progress = false;
  base.build.threads = 1;  // the points are the parallel work
  base.overrides = common;
  const std::atomic<bool>& interrupt = catch_stop_signals();
  base.interrupt = &interrupt;

  // one point built and initialized here first: an error every point would hit (a variable the
  // system lacks, a value out of range) is reported once, before the sweep starts
  if (!to_run.empty()) {
    const sweep_point& first = points[to_run.front()];
    cosim::temp_dir scratch("stride-sweep-");
    cosim::run_options dry = base;
    dry.output_dir = scratch.path() / "run";
    dry.initialize_only = true;
    dry.build.log = cosim::stderr_log_sink(cosim::log_level::error);
    for (const auto& o : first.overrides) dry.overrides.push_back(o);
    try {
      if (extension.check) {
        cosim::system_structure checked = system;
        for (const auto& o : dry.overrides) cosim::apply_override(checked, o);
        extension.check(checked);
      }
      cosim::run_system(system, dry);
    } catch (const std::exception& e) {
      throw validation_error("point " + first.name + " cannot run: " + e.what());
    }
  }

  fs::create_directories(points_dir);
  common::write_file_atomically(dir / k_settings_file, settings);

  progress_line progress(points.size(), points.size() - to_run.size(), to_run.size(), args.quiet);
  std::atomic<std::size_t> next{0};
  remote::timeouts limits;
  limits.connect = std::chrono::milliseconds(static_cast<long>(args.worker_timeout * 1000));
  // the k-th point started runs on worker k mod n: each point a run of its own there
  auto run_one = [&](std::size_t i, std::size_t k) {
    const sweep_point& p = points[i];
    point_outcome& out = outcomes[i];
    const fs::path point_dir = points_dir / p.folder;
    std::error_code ec;
    fs::remove_all(point_dir, ec);  // what an interrupted or failed earlier run left
    cosim::run_options o = base;
    o.output_dir = point_dir;
    for (const auto& v : p.overrides) o.overrides.push_back(v);
    o.build.log = [&progress, name = p.name](cosim::log_level level, std::string_view source,
                                             std::string_view category, std::string_view text) {
      if (level < cosim::log_level::warning) return;
      std::string line = "[point " + name + "] [" + std::string(source) + "] " +
                         std::string(cosim::to_string(level));
      if (!category.empty() && category != cosim::to_string(level)) {
        line += " (" + std::string(category) + ")";
      }
      line += ": " + std::string(text);
      while (!line.empty() && line.back() == '\n') line.pop_back();
      progress.message(line);
    };
    try {
      if (extension.check) {
        cosim::system_structure checked = system;
        for (const auto& v : o.overrides) cosim::apply_override(checked, v);
        extension.check(checked);
      }
      cosim::system_structure placed = system;
      if (!args.workers.empty()) {
        placed = cosim::on_worker(system, args.workers[k % args.workers.size()]);
        o.build.placements = {std::make_shared<remote::remote_placement>(args.dds, limits)};
      }
      const cosim::run_report report = cosim::run_system(placed, o);
      if (report.result.interrupted) {
        out.status = point_status_kind::interrupted;
        return;
      }
      if (extension.report) extension.report(report);
      out.status = point_status_kind::ran;
    } catch (const std::exception& e) {
      out.status = point_status_kind::failed;
      out.error = e.what();
    }
  };
  auto worker = [&] {
    for (;;) {
      if (interrupt.load()) return;
      const std::size_t k = next.fetch_add(1);
      if (k >= to_run.size()) return;
      run_one(to_run[k], k);
      const point_outcome& out = outcomes[to_run[k]];
      if (out.status == point_status_kind::interrupted) return;
      if (out.status == point_status_kind::failed) {
        progress.message("stride sweep: point " + points[to_run[k]].name + " failed: " + out.error);
      }
      progress.point_done(out.status == point_status_kind::failed);
    }
  };
  const std::size_t threads =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(1, args.jobs)), to_run.size());
  {
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    if (threads > 0) worker();
    for (auto& t : pool) t.join();
  }
  progress.finish();

  if (interrupt.load()) {
    std::size_t done = 0;
    for (const auto& o : outcomes) {
      if (o.status == point_status_kind::kept || o.status == point_status_kind::ran) ++done;
    }
    const int signal = caught_stop_signal() == SIGTERM ? SIGTERM : SIGINT;
    std::fprintf(stderr,
                 "stride: interrupted by %s: %zu of %zu points done in %s; the same command "
                 "continues the sweep\n",
                 signal == SIGTERM ? "SIGTERM" : "SIGINT", done, points.size(),
                 dir.string().c_str());
    return 128 + signal;
  }

  // --- the table: collected from every finished point's folder, in grid order
  sweep_table table;
  for (const auto& t : targets) {
    for (const auto& a : t.axes) table.axes.push_back(a.name);
  }
  table.columns = names;
  std::size_t failed = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    point_outcome& out = outcomes[i];
    if (out.status == point_status_kind::failed) {
      ++failed;
      continue;
    }
    const fs::path point_dir = points_dir / points[i].folder;
    try {
      std::vector<double> values;
      if (profile != nullptr) values = profile->collect(point_dir);
      for (const auto& c : columns) values.push_back(c.read(point_dir));
      table.rows.push_back({points[i].labels, points[i].values, std::move(values)});
    } catch (const std::exception& e) {
      out.status = point_status_kind::failed;
      out.error = e.what();
      ++failed;
      std::fprintf(stderr, "stride sweep: point %s: %s\n", points[i].name.c_str(), e.what());
    }
  }
  const std::string base_name = profile != nullptr ? profile->table_name : "sweep";
  const fs::path csv = dir / (base_name + ".csv");
  {
    std::string text;
    for (const auto& a : table.axes) text += (text.empty() ? "" : ",") + a;
    for (const auto& c : table.columns) text += "," + c;
    text += "\n";
    for (const auto& r : table.rows) {
      std::string line;
      for (const auto& l : r.labels) line += (line.empty() ? "" : ",") + l;
      for (double v : r.values) line += "," + text::format_double(v);
      text += line + "\n";
    }
    common::write_file_atomically(csv, text);
  }
  const auto count = [&](point_status_kind k) {
    return static_cast<std::size_t>(std::count_if(outcomes.begin(), outcomes.end(),
                                                  [k](const auto& o) { return o.status == k; }));
  };
  std::printf("%s: %zu of %zu points (%zu run now, %zu kept) in %s\n", csv.string().c_str(),
              table.rows.size(), points.size(), count(point_status_kind::ran),
              count(point_status_kind::kept), duration_text(progress.elapsed()).c_str());
  const auto figure = profile != nullptr && profile->figure ? profile->figure : extension.heat_map;
  if (table.axes.size() == 2 && !table.rows.empty() && figure) {
    const fs::path png = dir / (base_name + ".png");
    try {
      figure(table, png);
      std::printf("figure: %s\n", png.string().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "stride: warning: no figure: %s\n", e.what());
    }
  }
  if (profile != nullptr && profile->summary) std::fputs(profile->summary(table).c_str(), stdout);
  std::fflush(stdout);
  if (failed > 0) {
    std::string list;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (outcomes[i].status == point_status_kind::failed) {
        list += (list.empty() ? "" : "; ") + points[i].name;
      }
    }
    std::fprintf(stderr, "stride: error: %zu of %zu points failed (%s); they are left out of %s\n",
                 failed, points.size(), list.c_str(), csv.string().c_str());
    return 1;
  }
  return 0;
}

CLI::App* add_sweep_command(CLI::App& app, sweep_extension extension) {
  auto args = std::make_shared<sweep_arguments>();
  auto ext = std::make_shared<sweep_extension>(std::move(extension));
  std::string collectors;
  for (const auto& p : ext->profiles) {
    collectors += "; '" + p.name + "': " + p.description;
  }
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run a system once per point of a parameter grid, on threads of this process (or on "
      "workers), into DIR/points/<values>/ and one CSV (and, for a 2-D grid, a heat map); "
      "points already run are kept, so an interrupted sweep continues (docs/sweep.md)");
  cmd->add_option("system", args->system, "System file (XML, SSP or OSP)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--grid", args->grids,
                  "comp.var=name:min:max:step[,name:min:max:step...]: the variable takes each "
                  "grid point's values joined by ',' (one unnamed axis: comp.var=min:max:step); "
                  "several --grid span their product")
      ->required()
      ->allow_extra_args(false);
  cmd->add_option("--set", args->sets,
                  "Parameter or input start value for every point: "
                  "comp.var=value")
      ->allow_extra_args(false);
  cmd->add_option("--collect", args->collect,
                  "What each point adds to the CSV: [NAME=]FILE:COLUMN[:REDUCE] reads COLUMN of "
                  "the CSV file FILE in the point's folder, REDUCE = last (default), first, "
                  "mean, min, max, sum or count; or a named collector" +
                      collectors + ". Default: end_time and steps of the point's manifest")
      ->allow_extra_args(false);
  cmd->add_option("--output,-o", args->output,
                  "Output folder (default ./stride-out/<system>-sweep-<YYYYmmdd-HHMMSS>)");
  cmd->add_option("--stop-time", args->stop_time, "Stop time in seconds (replaces the XML's)");
  cmd->add_option("--step", args->step, "Base step in seconds (replaces the system's)");
  cmd->add_option("--algorithm", args->algorithm, "gauss-seidel or jacobi (replaces the system's)");
  args->jobs = std::max(1, cosim::default_thread_count());
  cmd->add_option("--jobs,-j", args->jobs, "Points run at the same time (threads)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  cmd->add_flag("--quiet,-q", args->quiet, "No progress display");
  cmd->add_option("--workers", args->workers,
                  "Run the points on these `stride worker` processes in turn (names, "
                  "comma-separated or the option repeated); --jobs points at a time")
      ->delimiter(',')
      ->allow_extra_args(false);
  add_dds_options(*cmd, args->dds);
  cmd->add_option("--worker-timeout", args->worker_timeout,
                  "Seconds to wait for a worker to appear")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 3600.0));
  cmd->callback([args, ext] {
    int code = 0;
    try {
      code = sweep(*args, *ext);
    } catch (const std::exception& e) {
      std::string message = e.what();
      std::replace(message.begin(), message.end(), '\n', ' ');
      std::fprintf(stderr, "stride: error: %s\n", message.c_str());
      code = 1;
    }
    std::fflush(stdout);
    if (code != 0) throw CLI::RuntimeError(code);  // main() returns it without a message
  });
  return cmd;
}

}  // namespace stride::cli
