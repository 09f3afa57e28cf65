#include "stride/learner/artefacts.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "stride/common/bytes.hpp"
#include "stride/common/files.hpp"

namespace stride::learner {

namespace fs = std::filesystem;

namespace {

// format 2: the session state encoded field by field (format 1 copied it from memory)
constexpr char k_magic[8] = {'S', 'T', 'R', 'L', 'C', 'K', 'P', '2'};
constexpr char k_magic_v1[8] = {'S', 'T', 'R', 'L', 'C', 'K', 'P', '1'};

std::string errno_text() {
  return std::strerror(errno);
}

// fails naming the checkpoint file
using byte_reader = common::byte_reader<learner_error>;

std::map<std::string, std::string> parse_lines(const std::string& text) {
  std::map<std::string, std::string> m;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return m;
}

std::string csv_header(const state_grid& grid, const std::string& prefix) {
  std::string h;
  for (const auto& d : grid.dimensions()) h += (h.empty() ? "" : ",") + prefix + d.name;
  return h;
}

std::string csv_values(const std::vector<double>& values) {
  std::string row;
  for (double v : values) row += (row.empty() ? "" : ",") + format_number(v);
  return row;
}

std::string csv_values(const state_grid& grid, std::size_t s) {
  return csv_values(grid.values(s));
}

}  // namespace

std::vector<std::byte> checkpoint_bytes(const checkpoint& c) {
  common::byte_writer w;
  w.put_raw(std::as_bytes(std::span(k_magic)));
  w.put_string(c.config);
  w.put_bytes(c.state);
  w.put(static_cast<std::uint64_t>(c.values.size()));
  for (double v : c.values) w.put(v);
  w.put(static_cast<std::uint64_t>(c.traces.size()));
  for (const auto& e : c.traces) {
    w.put(static_cast<std::uint64_t>(e.state));
    w.put(e.z);
    w.put(e.v_start);
  }
  w.put(static_cast<std::uint64_t>(c.file_sizes.size()));
  for (const auto& [name, size] : c.file_sizes) {
    w.put_string(name);
    w.put(size);
  }
  if (c.shared) {  // an optional trailing section: checkpoints without it read as before
    const shared_checkpoint& sh = *c.shared;
    w.put(sh.round);
    w.put(static_cast<std::uint64_t>(sh.entries.size()));
    for (std::size_t i = 0; i < sh.entries.size(); ++i) {
      w.put(sh.entries[i]);
      w.put(sh.increments[i]);
    }
    w.put(sh.merged_updates);
    w.put(sh.snapshots_written);
  }
  return w.take();
}

checkpoint checkpoint_from_bytes(std::span<const std::byte> bytes, const std::string& what) {
  if (bytes.size() >= sizeof k_magic &&
      std::memcmp(bytes.data(), k_magic_v1, sizeof k_magic_v1) == 0) {
    throw learner_error(what +
                        ": a checkpoint of an earlier Stride (format 1, its state in its host's "
                        "memory layout), which this version does not read; start the run again");
  }
  if (bytes.size() < sizeof k_magic || std::memcmp(bytes.data(), k_magic, sizeof k_magic) != 0) {
    throw learner_error(what + ": not a learner checkpoint");
  }
  byte_reader r(bytes.subspan(sizeof k_magic), what + ": checkpoint is truncated");
  checkpoint c;
  c.config = r.get_string();
  const auto state = r.get_bytes();
  c.state.assign(state.begin(), state.end());
  const auto n = r.get<std::uint64_t>();
  r.need(n, sizeof(double));
  c.values.resize(n);
  for (auto& v : c.values) v = r.get<double>();
  const auto nt = r.get<std::uint64_t>();
  r.need(nt, 24);
  for (std::uint64_t i = 0; i < nt; ++i) {
    eligibility_traces::entry e;
    e.state = static_cast<std::size_t>(r.get<std::uint64_t>());
    e.z = r.get<double>();
    e.v_start = r.get<double>();
    c.traces.push_back(e);
  }
  const auto nf = r.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < nf; ++i) {
    std::string name = r.get_string();
    c.file_sizes[name] = r.get<std::uint64_t>();
  }
  if (!r.at_end()) {
    shared_checkpoint sh;
    sh.round = r.get<std::int64_t>();
    const auto ne = r.get<std::uint64_t>();
    r.need(ne, sizeof(std::uint32_t) + sizeof(double));
    for (std::uint64_t i = 0; i < ne; ++i) {
      sh.entries.push_back(r.get<std::uint32_t>());
      sh.increments.push_back(r.get<double>());
    }
    sh.merged_updates = r.get<std::int64_t>();
    sh.snapshots_written = r.get<std::uint64_t>();
    c.shared = std::move(sh);
  }
  if (!r.at_end()) throw learner_error(what + ": trailing bytes after the checkpoint");
  return c;
}

void write_checkpoint(const fs::path& file, const checkpoint& c) {
  const std::vector<std::byte> bytes = checkpoint_bytes(c);
  try {
    common::write_file_atomically(
        file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } catch (const std::runtime_error& e) {
    throw learner_error(e.what());
  }
}

checkpoint read_checkpoint(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw learner_error(file.string() + ": cannot read the checkpoint");
  std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return checkpoint_from_bytes(std::as_bytes(std::span(raw)), file.string());
}

void check_checkpoint_config(const std::string& saved, const std::string& current,
                             const fs::path& file) {
  const auto a = parse_lines(saved);
  const auto b = parse_lines(current);
  for (const auto& [key, value] : b) {
    const auto it = a.find(key);
    const std::string old = it == a.end() ? "(absent)" : it->second;
    if (old != value) {
      throw learner_error(file.string() + ": the checkpoint was written with " + key + " = " + old +
                          ", this run has " + key + " = " + value);
    }
  }
}

void write_value_table(const fs::path& file, const state_grid& grid, const value_table& v) {
  std::string text = csv_header(grid, "") + ",V\n";
  for (std::size_t s = 0; s < grid.size(); ++s) {
    text += csv_values(grid, s) + "," + format_number(v.get(s)) + "\n";
  }
  try {
    common::write_file_atomically(file, text);
  } catch (const std::runtime_error& e) {
    throw learner_error(e.what());
  }
}

artefact_writer::artefact_writer(fs::path dir, const state_grid& grid, bool log_steps,
                                 const std::map<std::string, std::uint64_t>* resume_sizes)
    : dir_(std::move(dir)), grid_(&grid) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw learner_error("cannot create output_dir " + dir_.string() + ": " + ec.message());
  episodes_ = open(run_files::episodes,
                   "episode,steps,falls,reward,sum_abs_dv," + csv_header(grid, "start_") +
                       ",rl_step,time,complete",
                   resume_sizes);
  if (log_steps) {
    steps_ = open(run_files::steps,
                  "rl_step,episode,step," + csv_header(grid, "") +
                      ",action,fell,distance,duration,speed,reward,delta,V",
                  resume_sizes);
  }
  paths_ = open(run_files::paths, "episode,rl_step,time,x,y,fallen", resume_sizes);
}

artefact_writer::~artefact_writer() {
  close();
}

artefact_writer::artefact_writer(artefact_writer&& other) noexcept {
  *this = std::move(other);
}

artefact_writer& artefact_writer::operator=(artefact_writer&& other) noexcept {
  if (this != &other) {
    close();
    dir_ = std::move(other.dir_);
    grid_ = other.grid_;
    files_ = std::move(other.files_);
    steps_ = other.steps_;
    episodes_ = other.episodes_;
    paths_ = other.paths_;
    other.files_.clear();
    other.dir_.clear();
    other.steps_ = other.episodes_ = other.paths_ = nullptr;
  }
  return *this;
}

std::FILE* artefact_writer::open(const std::string& name, const std::string& header,
                                 const std::map<std::string, std::uint64_t>* resume_sizes) {
  const fs::path file = dir_ / name;
  std::FILE* f = nullptr;
  std::optional<std::uint64_t> cut;
  if (resume_sizes != nullptr && fs::exists(file)) {
    if (resume_sizes->count(name)) {
      cut = resume_sizes->at(name);  // what the checkpoint had: rows after it are written again
    } else {
      std::ifstream in(file, std::ios::binary);
      std::string first;
      std::getline(in, first);
      if (first == header) cut = header.size() + 1;  // no checkpoint yet: the header alone
    }
  }
  // a new file is emptied and gets its header only at the first cut (see the class comment)
  std::string pending_header;
  if (!cut) {
    cut = 0;
    pending_header = header + "\n";
  }
  f = std::fopen(file.c_str(), "ab");
  if (f == nullptr) throw learner_error("cannot write " + file.string() + ": " + errno_text());
  files_.push_back({name, f, cut, std::move(pending_header)});
  return f;
}

void artefact_writer::apply_cuts() {
  for (auto& lf : files_) {
    if (!lf.cut || lf.f == nullptr) continue;
    const fs::path file = dir_ / lf.name;
    struct stat st {};
    if (std::fflush(lf.f) != 0 || ::fstat(::fileno(lf.f), &st) != 0) {
      throw learner_error("cannot write " + file.string() + ": " + errno_text());
    }
    if (static_cast<std::uint64_t>(st.st_size) < *lf.cut) {
      throw learner_error("cannot continue " + file.string() + ": it has " +
                          std::to_string(st.st_size) + " bytes, the checkpoint expects " +
                          std::to_string(*lf.cut));
    }
    if (::ftruncate(::fileno(lf.f), static_cast<off_t>(*lf.cut)) != 0) {
      throw learner_error("cannot truncate " + file.string() + ": " + errno_text());
    }
    lf.cut.reset();
    if (!lf.header.empty() &&
        std::fwrite(lf.header.data(), 1, lf.header.size(), lf.f) != lf.header.size()) {
      throw learner_error("cannot write " + file.string() + ": " + errno_text());
    }
    lf.header.clear();
  }
}

void artefact_writer::cut_back(const std::map<std::string, std::uint64_t>& sizes) {
  for (auto& lf : files_) {
    if (const auto it = sizes.find(lf.name); it != sizes.end()) {
      lf.cut = it->second;
      lf.header.clear();  // the saved size includes it
    }
  }
}

void artefact_writer::write(std::FILE* f, const std::string& line) {
  if (f == nullptr) return;
  apply_cuts();
  if (std::fwrite(line.data(), 1, line.size(), f) != line.size()) {
    throw learner_error("cannot write to " + dir_.string() + ": " + errno_text());
  }
}

void artefact_writer::step(const step_record& s) {
  if (steps_ == nullptr) return;
  std::string line = std::to_string(s.rl_step) + "," + std::to_string(s.episode) + "," +
                     std::to_string(s.step_in_episode) + "," + csv_values(s.values) + "," +
                     std::to_string(s.action) + "," + (s.fell ? "1" : "0") + "," +
                     format_number(s.distance) + "," + format_number(s.duration) + "," +
                     format_number(s.speed) + "," + format_number(s.reward) + "," +
                     format_number(s.delta) + "," + format_number(s.value) + "\n";
  write(steps_, line);
}

void artefact_writer::episode(const episode_record& e) {
  std::string line = std::to_string(e.episode) + "," + std::to_string(e.steps) + "," +
                     std::to_string(e.falls) + "," + format_number(e.reward) + "," +
                     format_number(e.sum_abs_dv) + "," + csv_values(*grid_, e.first_state) + "," +
                     std::to_string(e.rl_step) + "," + format_number(e.time) + "," +
                     (e.complete ? "1" : "0") + "\n";
  write(episodes_, line);
}

void artefact_writer::path_point(std::int64_t episode, std::int64_t rl_step, double time, double x,
                                 double y, bool fallen) {
  std::string line = std::to_string(episode) + "," + std::to_string(rl_step) + "," +
                     format_number(time) + "," + format_number(x) + "," + format_number(y) + "," +
                     (fallen ? "1" : "0") + "\n";
  write(paths_, line);
}

std::map<std::string, std::uint64_t> artefact_writer::flush() {
  apply_cuts();
  std::map<std::string, std::uint64_t> sizes;
  for (const auto& lf : files_) {
    struct stat st {};
    if (std::fflush(lf.f) != 0 || ::fstat(::fileno(lf.f), &st) != 0) {
      throw learner_error("cannot write " + (dir_ / lf.name).string() + ": " + errno_text());
    }
    sizes[lf.name] = static_cast<std::uint64_t>(st.st_size);
  }
  return sizes;
}

void artefact_writer::close() {
  try {
    apply_cuts();
  } catch (const learner_error&) {
    // closing (also from the destructor) must not throw: the logs stay as they are
  }
  for (auto& lf : files_) {
    if (lf.f != nullptr) std::fclose(lf.f);
  }
  files_.clear();
  steps_ = episodes_ = paths_ = nullptr;
}

std::string describe_point(const state_grid& grid, const std::vector<double>& values) {
  std::string s;
  for (std::size_t d = 0; d < grid.dimension_count() && d < values.size(); ++d) {
    s += (s.empty() ? "" : ", ") + grid.dimensions()[d].name + " = " + format_number(values[d]);
  }
  return s;
}

best_summary summarize_best(const state_grid& grid, const value_table& v, std::size_t top) {
  best_summary b;
  b.best = best_state(v);
  b.best_value = v.get(b.best);
  b.best_values = grid.values(b.best);
  // the `top` states with the largest V (ties by index), as a bounding box
  std::vector<std::size_t> order(v.size());
  for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
  top = std::min(top, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(top), order.end(),
                    [&v](std::size_t a, std::size_t c) {
                      return v.get(a) > v.get(c) || (v.get(a) == v.get(c) && a < c);
                    });
  b.region.assign(grid.dimension_count(), {0.0, 0.0});
  for (std::size_t k = 0; k < top; ++k) {
    const auto vals = grid.values(order[k]);
    for (std::size_t d = 0; d < vals.size(); ++d) {
      if (k == 0) {
        b.region[d] = {vals[d], vals[d]};
      } else {
        b.region[d].first = std::min(b.region[d].first, vals[d]);
        b.region[d].second = std::max(b.region[d].second, vals[d]);
      }
    }
  }
  b.region_states = top;
  std::ostringstream t;
  t << "best state: " << describe_point(grid, b.best_values)
    << " (V = " << format_number(std::round(b.best_value * 1000) / 1000) << ")\n";
  t << "best region (the " << top << " states with the largest V):";
  for (std::size_t d = 0; d < b.region.size(); ++d) {
    t << (d ? "," : "") << " " << grid.dimensions()[d].name << " "
      << format_number(b.region[d].first) << ".." << format_number(b.region[d].second);
  }
  t << "\n";
  b.text = t.str();
  return b;
}

namespace run_files {

std::string snapshot(std::int64_t rl_step) {
  return "v_snapshot_" + std::to_string(rl_step) + ".csv";
}

std::int64_t snapshot_step(const std::string& name) {
  static constexpr std::string_view prefix = "v_snapshot_", suffix = ".csv";
  if (!name.starts_with(prefix) || !name.ends_with(suffix)) return -1;
  const std::string_view digits(name.data() + prefix.size(),
                                name.size() - prefix.size() - suffix.size());
  std::int64_t n = -1;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  return ec == std::errc() && end == digits.data() + digits.size() ? n : -1;
}

}  // namespace run_files

namespace {

void write_whole_file(const fs::path& file, const std::string& text) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr) throw learner_error("cannot write " + file.string() + ": " + errno_text());
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) {
    throw learner_error("cannot write " + file.string() + ": " + errno_text());
  }
}

std::string read_whole_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw learner_error("cannot read " + file.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

protocol protocol_named(const std::string& name, const fs::path& file) {
  const auto p = parse_protocol(name);
  if (!p) throw learner_error(file.string() + ": unknown protocol '" + name + "'");
  return *p;
}

}  // namespace

void write_best(const fs::path& dir, const best_summary& best, protocol rules,
                std::int64_t rl_steps, std::int64_t episodes, std::int64_t falls) {
  write_whole_file(dir / run_files::best, best.text + "protocol: " + std::string(to_string(rules)) +
                                              "\nRL steps: " + std::to_string(rl_steps) +
                                              ", episodes: " + std::to_string(episodes) +
                                              ", falls: " + std::to_string(falls) + "\n");
}

best_record read_best(const fs::path& file) {
  best_record b;
  b.text = read_whole_file(file);
  std::istringstream in(b.text);
  bool counts = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("protocol: ")) b.rules = protocol_named(line.substr(10), file);
    long long steps = 0, episodes = 0, falls = 0;
    if (std::sscanf(line.c_str(), "RL steps: %lld, episodes: %lld, falls: %lld", &steps, &episodes,
                    &falls) == 3) {
      b.rl_steps = steps;
      b.episodes = episodes;
      b.falls = falls;
      counts = true;
    }
  }
  if (!counts) throw learner_error(file.string() + ": no 'RL steps: ...' line");
  return b;
}

void write_evaluation(const fs::path& dir, const evaluation_result& r) {
  std::string header, row;
  for (const auto& [name, value] : r.point) {
    header += name + ",";
    row += format_number(value) + ",";
  }
  write_whole_file(
      dir / run_files::evaluation,
      header +
          "windows,falls,distance,measured_time,mean_speed,sim_time,physical_speed,protocol\n" +
          row + std::to_string(r.windows) + "," + std::to_string(r.falls) + "," +
          format_number(r.distance) + "," + format_number(r.measured_time) + "," +
          format_number(r.mean_speed) + "," + format_number(r.sim_time) + "," +
          format_number(r.physical_speed) + "," + std::string(to_string(r.rules)) + "\n");
}

evaluation_result read_evaluation(const fs::path& file) {
  std::istringstream in(read_whole_file(file));
  std::string header_line, row_line;
  std::getline(in, header_line);
  std::getline(in, row_line);
  const auto header = split_csv_line(header_line);
  const auto row = split_csv_line(row_line);
  const auto at = [&](const char* name) -> const std::string& {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end() || static_cast<std::size_t>(it - header.begin()) >= row.size()) {
      throw learner_error(file.string() + ": no column '" + name + "'");
    }
    return row[static_cast<std::size_t>(it - header.begin())];
  };
  const auto number = [&](const char* name) { return parse_number(at(name), file.string()); };
  evaluation_result r;
  const auto first = std::find(header.begin(), header.end(), "windows");
  for (auto it = header.begin(); it != first; ++it) {
    const std::size_t i = static_cast<std::size_t>(it - header.begin());
    r.point.emplace_back(*it, parse_number(i < row.size() ? row[i] : "", file.string()));
  }
  r.windows = static_cast<std::int64_t>(number("windows"));
  r.falls = static_cast<std::int64_t>(number("falls"));
  r.distance = number("distance");
  r.measured_time = number("measured_time");
  r.mean_speed = number("mean_speed");
  r.sim_time = number("sim_time");
  r.physical_speed = number("physical_speed");
  r.rules = protocol_named(at("protocol"), file);
  return r;
}

int csv_columns::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

csv_columns read_csv_log(const fs::path& file) {
  std::istringstream in(read_whole_file(file));
  csv_columns t;
  bool first = true;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto cells = split_csv_line(line);
    if (first) {
      t.header = cells;
      first = false;
      continue;
    }
    if (cells.size() != t.header.size()) continue;  // a row cut by a kill
    std::vector<double> values;
    for (const auto& c : cells) {
      double v = std::nan("");
      std::from_chars(c.data(), c.data() + c.size(), v);
      values.push_back(v);
    }
    t.rows.push_back(std::move(values));
  }
  return t;
}

}  // namespace stride::learner
