#include "stride/cosim/observers.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <utility>

#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

bool glob_match(std::string_view pattern, std::string_view text) noexcept {
  return text::glob_match(pattern, text);
}

std::vector<variable_id> find_variables(const execution& algo, std::string_view pattern) {
  const bool wildcard = pattern.find_first_of("*?") != std::string_view::npos;
  std::vector<variable_id> found;
  for (std::size_t c = 0; c < algo.component_count(); ++c) {
    const auto& comp = algo.component_at(c);
    const auto& vars = comp.model_description().variables;
    for (std::size_t v = 0; v < vars.size(); ++v) {
      if (wildcard && vars[v].causality != causality::output &&
          vars[v].causality != causality::input) {
        continue;
      }
      const std::string full = comp.name() + "." + vars[v].name;
      if (wildcard ? glob_match(pattern, full) : full == pattern) found.push_back({c, v});
    }
  }
  return found;
}

namespace {

void append_csv_field(std::string& out, std::string_view s) {
  if (s.find_first_of(",\"\n\r") == std::string_view::npos) {
    out += s;
    return;
  }
  out += '"';
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

void append_double(std::string& out, double d) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);
  if (ec == std::errc()) out.append(buf, end);
}

}  // namespace

csv_recorder::csv_recorder(std::filesystem::path file, std::vector<variable_id> variables,
                           std::optional<duration> interval)
    : file_(std::move(file)), variables_(std::move(variables)), interval_(interval) {}

std::shared_ptr<csv_recorder> csv_recorder::from_patterns(std::filesystem::path file,
                                                          const execution& algo,
                                                          const std::vector<std::string>& patterns,
                                                          std::optional<duration> interval) {
  std::vector<variable_id> vars;
  for (const auto& p : patterns) {
    const auto found = find_variables(algo, p);
    if (found.empty()) throw validation_error("record signal '" + p + "' matches no variable");
    for (const auto& v : found) {
      if (std::find(vars.begin(), vars.end(), v) == vars.end()) vars.push_back(v);
    }
  }
  if (vars.empty() && patterns.empty()) vars = find_variables(algo, "*");
  return std::make_shared<csv_recorder>(std::move(file), std::move(vars), interval);
}

csv_recorder::~csv_recorder() {
  withdraw_work(*this);
  // an unwinding run: keep what can be kept, the error that ends the run is already on its way
  if (out_ == nullptr) return;
  try {
    format_row();
  } catch (...) {  // NOLINT(bugprone-empty-catch): the row is lost, the file kept
  }
  if (!buffer_.empty()) std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
  std::fclose(out_);
}

void csv_recorder::attach(execution& ex) {
  auto& algo = ex;
  if (interval_) {
    if (*interval_ <= duration::zero() || *interval_ % algo.base_step() != duration::zero()) {
      throw validation_error("recording interval " + format_seconds(*interval_) +
                             " s is not a positive multiple of the base step " +
                             format_seconds(algo.base_step()) + " s");
    }
  }
  if (variables_.empty()) {
    // every output
    for (std::size_t c = 0; c < algo.component_count(); ++c) {
      const auto& vars = algo.component_at(c).model_description().variables;
      for (std::size_t v = 0; v < vars.size(); ++v) {
        if (vars[v].causality == causality::output) variables_.push_back({c, v});
      }
    }
  }
  observed_.clear();
  for (const auto& v : variables_) observed_.push_back(algo.observe(v));
  std::string header = "time";
  for (const auto& v : variables_) {
    header += ',';
    append_csv_field(header, algo.full_name(v));
  }
  header += '\n';
  if (continue_after_) {
    keep_rows_until(*continue_after_, header);
    out_ = std::fopen(file_.c_str(), "ab");
    if (out_ == nullptr) {
      throw error("cannot write " + file_.string() + ": " + std::strerror(errno));
    }
    last_row_ = *continue_after_;
    return;
  }
  if (!file_.parent_path().empty()) std::filesystem::create_directories(file_.parent_path());
  out_ = std::fopen(file_.c_str(), "wb");
  if (out_ == nullptr) {
    throw error("cannot write " + file_.string() + ": " + std::strerror(errno));
  }
  buffer_ = std::move(header);
}

void csv_recorder::continue_after(time_point after) {
  continue_after_ = after;
}

void csv_recorder::keep_rows_until(time_point after, const std::string& header) {
  std::ifstream in(file_, std::ios::binary);
  if (!in) throw error("cannot continue " + file_.string() + ": " + std::strerror(errno));
  std::string line;
  if (!std::getline(in, line) || in.eof() || line + '\n' != header) {
    throw validation_error("cannot continue " + file_.string() +
                           ": its header is not that of the signals recorded now");
  }
  // whole rows (ended by a newline) whose time is at most `after`, read line by line
  std::uintmax_t keep = header.size();
  while (std::getline(in, line) && !in.eof()) {
    double seconds = 0;
    const char* end = line.data() + line.size();
    const auto [ptr, ec] = std::from_chars(line.data(), end, seconds);
    if (ec != std::errc() || (ptr != end && *ptr != ',') || time_from_seconds(seconds) > after) {
      break;
    }
    keep += line.size() + 1;
  }
  in.close();
  std::error_code ec;
  std::filesystem::resize_file(file_, keep, ec);
  if (ec) throw error("cannot continue " + file_.string() + ": " + ec.message());
}

void csv_recorder::write_row(const execution& ex, time_point t) {
  if (t == last_row_ || out_ == nullptr) return;
  if (continue_after_ && t <= *continue_after_) return;  // the earlier part has these rows
  last_row_ = t;
  format_row();  // the row before, should no wait have come to format it
  copy_row(ex, t);
  defer_work(*this);
  if (buffer_.size() > (1u << 16)) flush();
}

void csv_recorder::copy_row(const execution& ex, time_point t) {
  row_.t = t;
  row_.reals.clear();
  row_.integers.clear();
  row_.booleans.clear();
  row_.strings.clear();
  for (const auto& o : observed_) {
    switch (o.type) {
      case variable_type::real:
        row_.reals.push_back(ex.real_value(o));
        break;
      case variable_type::integer:
      case variable_type::enumeration:
        row_.integers.push_back(ex.integer_value(o));
        break;
      case variable_type::boolean:
        row_.booleans.push_back(ex.boolean_value(o));
        break;
      case variable_type::string:
        row_.strings.push_back(ex.string_value(o));
        break;
    }
  }
  row_.pending = true;
  ++rows_;
}

void csv_recorder::format_row() {
  if (deferred_error_) std::rethrow_exception(std::exchange(deferred_error_, nullptr));
  if (!row_.pending) return;
  row_.pending = false;
  buffer_ += format_seconds(row_.t);
  std::size_t real = 0, integer = 0, boolean = 0, string = 0;
  for (const auto& o : observed_) {
    buffer_ += ',';
    switch (o.type) {
      case variable_type::real:
        append_double(buffer_, row_.reals[real++]);
        break;
      case variable_type::integer:
      case variable_type::enumeration:
        buffer_ += std::to_string(row_.integers[integer++]);
        break;
      case variable_type::boolean:
        buffer_ += row_.booleans[boolean++] ? '1' : '0';
        break;
      case variable_type::string:
        // always quoted so an empty string stays a field
        buffer_ += '"';
        for (char c : row_.strings[string++]) {
          if (c == '"') buffer_ += '"';
          buffer_ += c;
        }
        buffer_ += '"';
        break;
    }
  }
  buffer_ += '\n';
}

void csv_recorder::do_deferred_work() noexcept {
  try {
    format_row();
  } catch (...) {
    deferred_error_ = std::current_exception();
  }
}

void csv_recorder::flush() {
  if (out_ == nullptr) return;
  format_row();
  // a full disk must end the run with an error, not leave a silently truncated file
  const bool written =
      buffer_.empty() || std::fwrite(buffer_.data(), 1, buffer_.size(), out_) == buffer_.size();
  buffer_.clear();
  if (!written || std::fflush(out_) != 0) {
    throw error("cannot write " + file_.string() + ": " + std::strerror(errno));
  }
}

void csv_recorder::simulation_initialized(const execution& ex, time_point t) {
  write_row(ex, t);
}

void csv_recorder::step_complete(const execution& ex, std::int64_t /*step*/, time_point t) {
  if (interval_ && (t - ex.start_time()) % *interval_ != duration::zero()) return;
  write_row(ex, t);
}

void csv_recorder::simulation_ended(const execution& /*ex*/, time_point /*t*/,
                                    const std::string& /*error*/) {
  flush();
  if (out_ != nullptr) {
    const bool closed = std::fclose(out_) == 0;
    out_ = nullptr;
    if (!closed) throw error("cannot write " + file_.string() + ": " + std::strerror(errno));
  }
}

double real_time_factor(duration simulated, double wall_seconds) noexcept {
  return wall_seconds > 0 ? to_seconds(simulated) / wall_seconds : 0.0;
}

void wall_timer::start() noexcept {
  start_ = std::chrono::steady_clock::now();
  end_.reset();
}

void wall_timer::simulation_initialized(const execution& /*ex*/, time_point /*t*/) {
  if (!start_) start();
}

void wall_timer::simulation_ended(const execution& /*ex*/, time_point /*t*/,
                                  const std::string& /*error*/) {
  if (start_ && !end_) end_ = std::chrono::steady_clock::now();
}

double wall_timer::seconds() const noexcept {
  if (!start_) return 0.0;
  return std::chrono::duration<double>(end_.value_or(std::chrono::steady_clock::now()) - *start_)
      .count();
}

progress_display::progress_display(time_point stop, std::FILE* out, std::optional<bool> terminal,
                                   std::chrono::milliseconds plain_period,
                                   std::shared_ptr<wall_timer> timer)
    : stop_(stop),
      out_(out),
      terminal_(terminal ? *terminal : ::isatty(::fileno(out)) != 0),
      period_(terminal_ ? std::chrono::milliseconds(200) : plain_period),
      timer_(timer ? std::move(timer) : std::make_shared<wall_timer>()) {}

std::string progress_display::format(time_point t, double wall) const {
  const double sim = to_seconds(t - start_);
  const double total = to_seconds(stop_ - start_);
  const double rtf = real_time_factor(t - from_.value_or(start_), wall);
  const double percent = total > 0 ? 100.0 * sim / total : 100.0;
  char buf[160];
  if (rtf > 0 && sim < total && !ended_) {
    const double eta = (total - sim) / rtf;
    std::snprintf(buf, sizeof buf, "t = %.3f / %.3f s (%.1f%%), RTF %.2fx, ETA %.0f s",
                  to_seconds(t), to_seconds(stop_), percent, rtf, std::ceil(eta));
  } else {
    std::snprintf(buf, sizeof buf, "t = %.3f / %.3f s (%.1f%%), RTF %.2fx", to_seconds(t),
                  to_seconds(stop_), percent, rtf);
  }
  return buf;
}

std::string progress_display::format(time_point t, double wall, const std::string& progress_name,
                                     double progress) const {
  const double rtf = real_time_factor(t - from_.value_or(start_), wall);
  const double done_here = progress - progress_from_;
  char buf[200];
  if (done_here > 0 && progress < 1 && !ended_) {
    std::snprintf(buf, sizeof buf, "t = %.3f s, RTF %.2fx, %s %.1f%%, ETA %.0f s", to_seconds(t),
                  rtf, progress_name.c_str(), 100.0 * progress,
                  std::ceil(wall * (1 - progress) / done_here));
  } else {
    std::snprintf(buf, sizeof buf, "t = %.3f s, RTF %.2fx, %s %.1f%%", to_seconds(t), rtf,
                  progress_name.c_str(), 100.0 * std::clamp(progress, 0.0, 1.0));
  }
  return buf;
}

void progress_display::attach(execution& ex) {
  auto& algo = ex;
  for (const variable_id& id : find_variables(algo, "*.progress")) {
    const auto& v = algo.component_at(id.component).model_description().variables[id.variable];
    if (v.causality != causality::output || v.type != variable_type::real) continue;
    progress_var_ = algo.observe(id);
    progress_name_ = algo.full_name(id);
    break;
  }
}

std::string progress_display::line(const execution& ex, time_point t, double wall) const {
  // a component's own progress only when it is ahead of the clock (it will end the run early);
  // one that reports nothing (0) leaves the simulated time in charge
  if (!progress_var_) return format(t, wall);
  const double progress = ex.real_value(*progress_var_);
  const double by_time = stop_ > start_ ? to_seconds(t - start_) / to_seconds(stop_ - start_) : 0.0;
  if (!(progress > by_time)) return format(t, wall);
  return format(t, wall, progress_name_, progress);
}

void progress_display::simulation_initialized(const execution& ex, time_point t) {
  start_ = ex.start_time();
  timer_->simulation_initialized(ex, t);  // starts a timer of its own; a run's keeps its start
  last_print_ = std::chrono::steady_clock::now();
}

void progress_display::step_complete(const execution& ex, std::int64_t /*step*/, time_point t) {
  if (!from_) {
    from_ = t - ex.base_step();
    if (progress_var_) progress_from_ = ex.real_value(*progress_var_);
  }
  // look at the wall clock only every few steps
  if (countdown_ > 0) {
    --countdown_;
    return;
  }
  countdown_ = 15;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_print_ < period_) return;
  last_print_ = now;
  const std::string text = line(ex, t, timer_->seconds());
  if (terminal_) {
    std::fprintf(out_, "\r\033[K%s", text.c_str());
  } else {
    std::fprintf(out_, "stride: %s\n", text.c_str());
  }
  std::fflush(out_);
}

void progress_display::simulation_ended(const execution& ex, time_point t,
                                        const std::string& error) {
  timer_->simulation_ended(ex, t, error);  // a run's timer has stopped already: the same figure
  ended_ = true;                           // no ETA for a run that ended early
  const double wall = timer_->seconds();
  const std::string text = line(ex, t, wall);
  if (terminal_) {
    std::fprintf(out_, "\r\033[K%s, wall %.2f s\n", text.c_str(), wall);
  } else {
    std::fprintf(out_, "stride: %s, wall %.2f s\n", text.c_str(), wall);
  }
  std::fflush(out_);
}

}  // namespace stride::cosim
