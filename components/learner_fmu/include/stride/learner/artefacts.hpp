// What a learner run leaves in its output folder, written and read here only (the FMU writes,
// tools such as `stride plot` read):
//
//   v_table.csv            grid coordinates + V, one row per state (index order); at the end
//   v_snapshot_<N>.csv     the same after RL step N (snapshot_steps)
//   episodes.csv           one row per episode: reward, Σ|ΔV|, falls, start/end state
//   steps.csv              one row per RL step (log_steps): state, action, speed, reward, δ
//   paths.csv              torso x-y at every footstep and fall (path_every)
//   best.txt               the best state and region, the protocol, the run's counts
//   evaluation.csv         evaluate mode: distance, mean speed, falls, protocol
//   checkpoint.bin         written atomically (temp file + rename) at every episode boundary
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "stride/learner/session.hpp"

namespace stride::learner {

/// The names of a run folder's files.
namespace run_files {
inline constexpr const char* value_table = "v_table.csv";
inline constexpr const char* episodes = "episodes.csv";
inline constexpr const char* steps = "steps.csv";
inline constexpr const char* paths = "paths.csv";
inline constexpr const char* best = "best.txt";
inline constexpr const char* evaluation = "evaluation.csv";
inline constexpr const char* checkpoint = "checkpoint.bin";
/// "v_snapshot_<rl_step>.csv"
std::string snapshot(std::int64_t rl_step);
/// The step of a snapshot file name, or -1 for another name.
std::int64_t snapshot_step(const std::string& file_name);
}  // namespace run_files

/// What an agent sharing V (docs/swarm.md) adds to its checkpoint.
struct shared_checkpoint {
  std::int64_t round = 0;               ///< the last round it sent (its RL steps)
  std::vector<std::uint32_t> entries;   ///< that round's update, to send again if it was
  std::vector<double> increments;       ///< lost with the service
  std::int64_t merged_updates = 0;      ///< updates in the newest merged table it took
  std::uint64_t snapshots_written = 0;  ///< how many of snapshot_steps it wrote
};

/// A learner checkpoint: enough to continue a run exactly from an episode boundary.
struct checkpoint {
  std::string config;            ///< learner_config::canonical() of the run
  std::vector<std::byte> state;  ///< session_state, field by field (stride/sdk/state_fields.hpp)
  std::vector<double> values;    ///< V
  std::vector<eligibility_traces::entry> traces;
  std::map<std::string, std::uint64_t> file_sizes;  ///< artefact CSV sizes to truncate to
  std::optional<shared_checkpoint> shared;          ///< V shared with other agents
};

/// A checkpoint as bytes (numbers little-endian on every host): what the file holds, and the
/// end of the learner FMU's state image.
std::vector<std::byte> checkpoint_bytes(const checkpoint& c);
/// Reads checkpoint_bytes(); throws learner_error starting with `what` for damaged or foreign
/// bytes.
checkpoint checkpoint_from_bytes(std::span<const std::byte> bytes, const std::string& what);

/// Writes `file` atomically: `file`.tmp, flushed and synced, then renamed over `file`.
void write_checkpoint(const std::filesystem::path& file, const checkpoint& c);
/// Reads a checkpoint; throws learner_error naming the file for a missing, truncated or foreign
/// file.
checkpoint read_checkpoint(const std::filesystem::path& file);
/// Throws learner_error naming the first setting that differs between a checkpoint's
/// configuration and the run's.
void check_checkpoint_config(const std::string& saved, const std::string& current,
                             const std::filesystem::path& file);

/// Writes the V table as CSV: one column per grid dimension, then V.
void write_value_table(const std::filesystem::path& file, const state_grid& grid,
                       const value_table& v);

/// Appends rows to the run's CSV logs; each file gets its header when created. On resume the
/// files are cut back to the sizes recorded in the checkpoint, so rows written after it vanish.
/// The cut is made before the first row is written (or flush/close), so that a saved state
/// restored in between (cut_back) can still keep the rows up to its own moment. That holds for
/// new files too: they are replaced only then, so an instance re-created after a lost worker
/// (docs/failover.md) continues the rows its restored state had.
class artefact_writer {
 public:
  artefact_writer() = default;
  /// Opens (creating `dir`) the logs. `resume_sizes` null: new files (existing ones replaced at
  /// the first row, flush or close unless cut_back comes first);
  /// else existing logs are continued, cut back to their size in the map (absent: to the header
  /// alone, as if new).
  artefact_writer(std::filesystem::path dir, const state_grid& grid, bool log_steps,
                  const std::map<std::string, std::uint64_t>* resume_sizes);
  ~artefact_writer();
  artefact_writer(const artefact_writer&) = delete;
  artefact_writer& operator=(const artefact_writer&) = delete;
  artefact_writer(artefact_writer&& other) noexcept;
  artefact_writer& operator=(artefact_writer&& other) noexcept;

  bool active() const { return !dir_.empty(); }
  const std::filesystem::path& dir() const { return dir_; }

  void step(const step_record& s);
  void episode(const episode_record& e);
  void path_point(std::int64_t episode, std::int64_t rl_step, double time, double x, double y,
                  bool fallen);
  /// Flushes every log and returns their sizes (for the checkpoint).
  std::map<std::string, std::uint64_t> flush();
  /// Cuts the logs back to `sizes` (as flush returned them at a saved moment) before the next
  /// row; logs not in the map stay as they are. \throws learner_error when a log is shorter.
  void cut_back(const std::map<std::string, std::uint64_t>& sizes);
  void close();

 private:
  struct log_file {
    std::string name;
    std::FILE* f = nullptr;
    std::optional<std::uint64_t> cut;  ///< pending: the size to cut the file back to
    std::string header;                ///< pending: written after the cut (a new file)
  };
  void apply_cuts();
  std::FILE* open(const std::string& name, const std::string& header,
                  const std::map<std::string, std::uint64_t>* resume_sizes);
  void write(std::FILE* f, const std::string& line);

  std::filesystem::path dir_;
  const state_grid* grid_ = nullptr;
  std::vector<log_file> files_;
  std::FILE* steps_ = nullptr;
  std::FILE* episodes_ = nullptr;
  std::FILE* paths_ = nullptr;
};

/// "period_time=600, swing_right_left=20" for a state or a point.
std::string describe_point(const state_grid& grid, const std::vector<double>& values);

/// The best states of a value table: the arg max, and the region spanned by the `top` states
/// with the largest V, as per-dimension [min, max] bounds.
struct best_summary {
  std::size_t best = 0;
  double best_value = 0;
  std::vector<double> best_values;
  std::vector<std::pair<double, double>> region;  ///< per dimension, values
  std::size_t region_states = 0;
  std::string text;  ///< human-readable, several lines
};
best_summary summarize_best(const state_grid& grid, const value_table& v, std::size_t top = 10);

/// How a learn run ended (best.txt).
struct best_record {
  std::string text;  ///< as written, several lines
  protocol rules = protocol::paper;
  std::int64_t rl_steps = 0;
  std::int64_t episodes = 0;
  std::int64_t falls = 0;
};
void write_best(const std::filesystem::path& dir, const best_summary& best, protocol rules,
                std::int64_t rl_steps, std::int64_t episodes, std::int64_t falls);
/// \throws learner_error naming the file when it is missing or malformed.
best_record read_best(const std::filesystem::path& file);

/// The result of an evaluate run (evaluation.csv).
struct evaluation_result {
  std::vector<std::pair<std::string, double>> point;  ///< grid dimension name, value
  std::int64_t windows = 0;                           ///< measurement windows without a fall
  std::int64_t falls = 0;
  double distance = 0;        ///< Σ window distances, m
  double measured_time = 0;   ///< Σ window durations, s
  double mean_speed = 0;      ///< as the protocol defines it, cm/s
  double sim_time = 0;        ///< s
  double physical_speed = 0;  ///< distance / measured time, cm/s
  protocol rules = protocol::paper;
};
void write_evaluation(const std::filesystem::path& dir, const evaluation_result& r);
/// \throws learner_error naming the file when it is missing or malformed.
evaluation_result read_evaluation(const std::filesystem::path& file);

/// A numeric CSV log of a run (v_table, snapshots, episodes, steps, paths): the header and the
/// complete rows (a row cut short by a killed run is left out).
struct csv_columns {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  /// Index of a column, or -1.
  int column(const std::string& name) const;
};
/// \throws learner_error naming the file when it cannot be read.
csv_columns read_csv_log(const std::filesystem::path& file);

}  // namespace stride::learner
