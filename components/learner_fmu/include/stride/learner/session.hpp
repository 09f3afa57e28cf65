// The learning (or evaluating) agent in its closed loop, without FMI: it watches the gait's
// footstep counter, the torso position and the fall flag each communication step, turns W
// footsteps into one RL step (speed → reward → TD(λ) update → next gait parameters), restarts the
// robot after falls and at episode starts, and ends episodes after `steps_per_episode` steps or
// `max_falls` falls.
//
// One RL step, in footsteps of gait.footsteps:
//   settle:  `settle_footsteps` footsteps after new parameters were output (or after a restart),
//            not measured: the generator latches period_time at the next double-support centre,
//            so the first footstep after a change still runs on the old parameters;
//   measure: W footsteps; speed = |Δ(x, y)| of the torso / elapsed simulated time.
// A fall at any moment ends the step with the negative reward and restarts robot and gait.
// Every episode starts with a restart too, so the continuation from an episode boundary depends
// only on the learner's own state: that is what makes checkpoints exact (see learner_fmu.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "stride/learner/grid.hpp"
#include "stride/learner/rng.hpp"
#include "stride/learner/td_lambda.hpp"

namespace stride::learner {

enum class learner_mode : int {
  learn = 0,     ///< TD(λ) over the grid
  evaluate = 1,  ///< walk with fixed parameters and measure (no learning, no episodes)
};

/// How RL steps are walked and measured and when an episode ends (docs/learner.md, "Protocols").
/// The numbers (λ, rewards, W, episode length) are settings of their own whose defaults the
/// protocol chooses (see protocol_defaults).
enum class protocol : int {
  /// the study's text: settle_footsteps, then W footsteps measured; speed = distance / measured
  /// time; an episode ends after steps_per_episode steps or max_falls falls
  paper = 0,
  /// the authors' Webots controller: a window of 2·W·period_time (in whole 16 ms control
  /// iterations) from the step's start; speed = distance / (W·period_time), 0 below 1 cm; an
  /// episode ends when more than steps_per_episode steps in a row passed without a fall (the
  /// falling step counts as the first) or after more than max_falls falls
  authors_code = 1,
};

/// "paper" or "authors-code"; nullopt for any other name.
std::optional<protocol> parse_protocol(std::string_view name);
std::string_view to_string(protocol p);

/// Everything fixed for a run; defaults are the paper's Table 2 and Experiment 1.
struct learner_config {
  state_grid grid = state_grid::parse("period_time:450:960:15,swing_right_left:15:39:2");
  learner_mode mode = learner_mode::learn;
  protocol rules = protocol::paper;
  std::vector<double> eval_point;  ///< evaluate: one value per grid dimension
  td_params td{};
  double epsilon = 0.15;
  int steps_per_episode = 40;
  int max_falls = 10;
  int footsteps_per_step = 4;  ///< W
  int settle_footsteps = 1;
  reward_params reward{};
  double initial_value = 0.0;
  std::uint64_t seed = 1;
  std::int64_t total_steps = 0;  ///< the run ends after this many RL steps; 0 = never
  double step_timeout = 60.0;    ///< s of simulated time in one phase without enough footsteps
  bool balance = true;           ///< gyro balance on (balance_on is false after a restart anyway)
  double stand_time = 0.0;       ///< evaluate: s the robot stands before it walks

  /// Throws learner_error naming the first setting out of its range (or, for authors_code, a
  /// grid without a period_time dimension).
  void validate() const;
  /// Every setting that shapes the learning as "key=value" lines, to check that a checkpoint
  /// belongs to this configuration.
  std::string canonical() const;
};

enum class walk_phase : int { settling = 0, measuring = 1, episode_ended = 2, finished = 3 };

/// Everything that evolves besides V and the traces (FMU state, checkpoint).
struct session_state {
  rng_state rng{};
  std::int64_t clock_ns = 0;  ///< simulated time seen by the learner (restored by a resume)
  std::int64_t state = 0;     ///< current grid state (learn mode)
  std::int64_t rl_step = 0;   ///< completed RL steps (measurement windows when evaluating)
  std::int64_t episode = 0;   ///< current episode, 1-based (0 before the first)
  int step_in_episode = 0;
  int falls_in_episode = 0;
  std::int64_t total_falls = 0;
  double episode_reward = 0;  ///< accumulated reward of the current episode
  double last_reward = 0;
  double last_speed = 0;  ///< cm/s of the last measured window
  double last_delta = 0;
  double last_episode_reward = 0;
  double last_sum_abs_dv = 0;  ///< Σ|ΔV| of the last completed episode
  std::int64_t episode_first_state = 0;
  int phase = static_cast<int>(walk_phase::settling);
  int footsteps_seen = 0;  ///< footsteps since the last restart
  int last_footsteps = 0;  ///< the gait's counter at the previous step
  int target_footsteps = 0;
  std::int64_t phase_start_ns = 0;
  double x0 = 0, y0 = 0;  ///< torso at the start of the measurement
  std::int64_t t0_ns = 0;
  std::int64_t window_end_ns = 0;  ///< authors_code: end of the measurement window
  int steps_without_fall = 0;      ///< authors_code: the episode length rule
  double eval_speed_sum = 0;       ///< evaluate: Σ speed of the windows without a fall, cm/s
  int restarts = 0;                ///< counter output: robot reset and gait restart
  bool restart_pending = false;    ///< a restart was output at the previous step
  bool balance_gate = false;       ///< false on the one step right after a restart
  double eval_distance = 0;        ///< evaluate: Σ distance of the measured windows, m
  double eval_time = 0;            ///< evaluate: Σ duration of the measured windows, s
  std::int64_t eval_windows = 0;   ///< evaluate: windows without a fall
};
static_assert(std::is_trivially_copyable_v<session_state>);

/// Its fields, for state images and checkpoints (stride/sdk/state_fields.hpp; the learner FMU
/// checks that the list covers the struct).
template <class F>
void state_fields(session_state& s, F&& f) {
  f(s.rng, s.clock_ns, s.state, s.rl_step, s.episode, s.step_in_episode, s.falls_in_episode,
    s.total_falls, s.episode_reward, s.last_reward, s.last_speed, s.last_delta,
    s.last_episode_reward, s.last_sum_abs_dv, s.episode_first_state, s.phase, s.footsteps_seen,
    s.last_footsteps, s.target_footsteps, s.phase_start_ns, s.x0, s.y0, s.t0_ns, s.window_end_ns,
    s.steps_without_fall, s.eval_speed_sum, s.restarts, s.restart_pending, s.balance_gate,
    s.eval_distance, s.eval_time, s.eval_windows);
}

/// The settings a protocol implies: Table 2 for paper; config.h and Walk.cpp of the authors'
/// controller for authors_code (λ 0.3, −200 per fall, 30 steps, the capped reward
/// 10^((v + 1e-5)/10)/3 below 30 cm/s and 50 from there, no settle footstep, balance off).
learner_config protocol_defaults(protocol p);

/// The plant as the learner sees it at a communication point.
struct plant_inputs {
  double base_x = 0;  ///< torso x, m
  double base_y = 0;  ///< torso y, m
  bool fallen = false;
  int footsteps = 0;  ///< the gait's completed steps since its last (re)start
};

struct step_record {
  std::int64_t rl_step = 0;  ///< 1-based number of this step
  std::int64_t episode = 0;
  int step_in_episode = 0;     ///< 1-based
  std::size_t state = 0;       ///< grid state (learning mode)
  std::vector<double> values;  ///< the parameter values walked: the state's, or eval_point
  std::size_t action = 0;
  std::size_t next_state = 0;
  bool fell = false;
  double distance = 0;  ///< m (0 after a fall)
  double duration = 0;  ///< s (0 after a fall)
  double speed = 0;     ///< cm/s
  double reward = 0;
  double delta = 0;
  double value = 0;  ///< V(state) after the update
};

struct episode_record {
  std::int64_t episode = 0;
  int steps = 0;
  int falls = 0;
  double reward = 0;      ///< accumulated
  double sum_abs_dv = 0;  ///< Σ_s |V_end(s) − V_start(s)|
  std::size_t first_state = 0;
  std::size_t last_state = 0;
  std::int64_t rl_step = 0;  ///< RL steps done at its end
  double time = 0;           ///< learner clock at its end, s
  bool complete = true;      ///< false when the run ended inside the episode
};

/// What one advance() produced.
struct advance_report {
  bool footstep = false;   ///< the footstep counter moved
  bool restarted = false;  ///< a restart was output (fall)
  std::optional<step_record> step;
  std::optional<episode_record> episode;  ///< the episode ended: call begin_episode() next
  bool finished = false;                  ///< total_steps reached: end the run
};

/// The agent. Holds references: the state, the table and the traces live in the caller (the
/// FMU keeps the state in its data struct and the table in the model).
class session {
 public:
  session(const learner_config& config, session_state& state, value_table& values,
          eligibility_traces& traces);

  /// Fresh start: seeds the random numbers, then begins the first episode (learn) or the
  /// evaluation. The plant is assumed fresh.
  void start();
  /// Begins the next episode after a report with `episode` set: a uniformly random start state,
  /// traces cleared, and a restart of robot and gait.
  void begin_episode();
  /// One communication step of length h_ns with the plant's outputs at its end.
  /// Throws learner_error when the plant does not progress (no footsteps within step_timeout,
  /// or still fallen right after a reset).
  advance_report advance(const plant_inputs& in, std::int64_t h_ns);

  /// Gait parameter values to output now (grid values of the state, or the evaluation point).
  std::vector<double> current_values() const;
  /// Evaluate mode: the mean speed of the protocol (paper: Σ distance / Σ time; authors_code:
  /// the mean of the window speeds), cm/s; 0 before the first window.
  double mean_speed() const;
  walk_phase phase() const { return static_cast<walk_phase>(st_.phase); }
  /// Whether the gait should walk: false during the stand_time of an evaluation.
  bool walking() const;
  const learner_config& config() const { return cfg_; }

 private:
  void restart();
  void start_measuring(const plant_inputs& in);
  double period_time_ms() const;
  double window_speed(double distance, double duration) const;
  bool episode_over() const;
  void finish_step(advance_report& r, const plant_inputs& in, bool fell, double distance,
                   double duration);

  const learner_config& cfg_;
  session_state& st_;
  value_table& v_;
  eligibility_traces& z_;
};

}  // namespace stride::learner
