// Observers shipped with libstride: CSV recorder and progress display.
#ifndef STRIDE_COSIM_OBSERVERS_HPP
#define STRIDE_COSIM_OBSERVERS_HPP

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stride/cosim/deferred_work.hpp"
#include "stride/cosim/execution.hpp"

namespace stride::cosim {

/// Glob match with `*` (any run of characters) and `?` (one character).
bool glob_match(std::string_view pattern, std::string_view text) noexcept;

/// Variables whose full name "comp.var" matches `pattern`. A pattern without wildcards names
/// exactly one variable of any causality; a wildcard pattern matches inputs and outputs only.
/// Results are in component order, then model description order.
std::vector<variable_id> find_variables(const execution& ex, std::string_view pattern);

/// Writes one CSV row per recording interval: `time` first, then one column per variable,
/// headed by its full name "comp.var" (FMPy/cosim style; Booleans as 0/1, strings quoted,
/// doubles in shortest round-trip form). A row's values are copied when it is recorded and
/// turned into text as deferred work (stride/cosim/deferred_work.hpp): while the run waits for
/// a worker's reply to the next step, or else when the next row comes.
class csv_recorder : public observer, private deferred_work {
 public:
  /// Records `variables` (an empty list records every output) every `interval` (nullopt = every
  /// base step; must be a multiple of the base step).
  csv_recorder(std::filesystem::path file, std::vector<variable_id> variables,
               std::optional<duration> interval = std::nullopt);
  /// Records the variables matching any of `patterns`.
  static std::shared_ptr<csv_recorder> from_patterns(std::filesystem::path file,
                                                     const execution& ex,
                                                     const std::vector<std::string>& patterns,
                                                     std::optional<duration> interval = {});
  ~csv_recorder() override;

  /// Continues `file` as an earlier part of the same run left it, instead of starting it anew:
  /// its header must be the one this recorder writes, its rows up to `after` are kept (any later
  /// or incomplete row is cut), and no row at or before `after` is written again. Call before
  /// the execution is initialized. (A resumed run: stride/cosim/run.hpp.)
  void continue_after(time_point after);

  void attach(execution& ex) override;
  void simulation_initialized(const execution& ex, time_point t) override;
  void step_complete(const execution& ex, std::int64_t step, time_point t) override;
  void simulation_ended(const execution& ex, time_point t, const std::string& error) override;

  const std::filesystem::path& file() const noexcept { return file_; }
  /// Rows recorded so far, the one not yet formatted included.
  std::size_t rows_written() const noexcept { return rows_; }
  /// Writes the buffered rows (before a checkpoint); \throws error naming the file when the
  /// write fails.
  void flush();

 private:
  // the latest row's values, as they were when it was recorded
  struct row_values {
    bool pending = false;
    time_point t{};
    std::vector<double> reals;
    std::vector<int> integers;
    std::vector<bool> booleans;
    std::vector<std::string> strings;
  };

  void write_row(const execution& ex, time_point t);
  void copy_row(const execution& ex, time_point t);
  void format_row();
  void do_deferred_work() noexcept override;
  void keep_rows_until(time_point after, const std::string& header);

  std::filesystem::path file_;
  std::vector<variable_id> variables_;
  std::optional<duration> interval_;
  std::vector<observed_variable> observed_;
  std::FILE* out_ = nullptr;
  std::string buffer_;
  row_values row_;
  std::exception_ptr deferred_error_;  // of formatting as deferred work, thrown by the next call
  std::size_t rows_ = 0;
  time_point last_row_{duration::min()};
  std::optional<time_point> continue_after_;
};

/// Simulated seconds per wall-clock second (0 while no wall time has passed): the one definition
/// of the real-time factor, shown live by progress_display and at the end by run_system's report.
double real_time_factor(duration simulated, double wall_seconds) noexcept;

/// The wall time of a run on the steady clock: from start() (or, without it, the end of
/// initialization) to the end of the simulation. run_system's report and its progress display
/// read one timer, so that the live real-time factor and the final one are the same figure.
class wall_timer : public observer {
 public:
  /// Starts the clock now (e.g. before initialization, so that it counts).
  void start() noexcept;
  void simulation_initialized(const execution& ex, time_point t) override;
  void simulation_ended(const execution& ex, time_point t, const std::string& error) override;
  /// Seconds from the start to the end of the simulation, or to now while it runs; 0 before the
  /// start.
  double seconds() const noexcept;

 private:
  std::optional<std::chrono::steady_clock::time_point> start_;
  std::optional<std::chrono::steady_clock::time_point> end_;
};

/// Prints simulated time, real-time factor and ETA on a stream (stderr by default). On a
/// terminal one line is redrawn a few times per second; otherwise a plain line is printed every
/// `plain_period` of wall time. When a component has a Real output named `progress` (a fraction
/// 0..1 of its work, e.g. the learner's RL steps) that is ahead of the simulated time, the
/// percentage and the ETA come from it (a run that a component ends early). The real-time factor
/// and ETA count from the first step this process took, so a resumed run shows its own speed.
class progress_display : public observer {
 public:
  /// `timer`: the run's wall clock (add it to the execution before the display); none: the
  /// display keeps its own, from the end of initialization.
  progress_display(time_point stop, std::FILE* out = stderr, std::optional<bool> terminal = {},
                   std::chrono::milliseconds plain_period = std::chrono::seconds(5),
                   std::shared_ptr<wall_timer> timer = nullptr);

  void attach(execution& ex) override;

  void simulation_initialized(const execution& ex, time_point t) override;
  void step_complete(const execution& ex, std::int64_t step, time_point t) override;
  void simulation_ended(const execution& ex, time_point t, const std::string& error) override;

  /// The line that would be printed for simulated time `t` after `wall` seconds.
  std::string format(time_point t, double wall_seconds) const;
  /// The same with a component's progress fraction (0..1) named `progress_name`.
  std::string format(time_point t, double wall_seconds, const std::string& progress_name,
                     double progress) const;

 private:
  std::string line(const execution& ex, time_point t, double wall_seconds) const;
  std::optional<observed_variable> progress_var_;
  std::string progress_name_;
  time_point stop_;
  time_point start_{};
  // where this process's stepping began (later than start_ for a run resumed from a saved
  // state) and the component's progress there: speed and ETA count only what was done here
  std::optional<time_point> from_;
  double progress_from_ = 0.0;
  std::FILE* out_;
  bool terminal_;
  std::chrono::milliseconds period_;
  std::shared_ptr<wall_timer> timer_;
  std::chrono::steady_clock::time_point last_print_{};
  std::uint32_t countdown_ = 0;
  bool ended_ = false;
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_OBSERVERS_HPP
