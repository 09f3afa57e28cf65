// learner.fmu: TD(λ) over a grid of gait parameters (Silva et al., "Using reinforcement learning
// to optimize gait generation parameters of a humanoid robot") as an FMI 2.0 co-simulation
// component, or, in evaluation mode, a fixed-parameter walking benchmark.
//
// Inputs   base_x, base_y (m), fallen (robot); footsteps (gait)
// Params   grid, mode, eval_point, alpha, gamma, lambda, epsilon, steps_per_episode, max_falls,
//          footsteps_per_step (W), settle_footsteps, k1, k2, negative_reward, initial_value,
//          seed, total_steps, output_dir, resume, snapshot_steps, shared_table, agent, ...
//          (all fixed; shared_table and agent: V shared with other agents, docs/swarm.md)
// Outputs  value[1..4] (the current state's parameter values → gait parameters), reset_robot
//          (counter → robot.reset and gait.restart), balance_on (→ gait.balance_on), progress
//          variables (episode, rl_step, last_reward, state_value, sum_abs_dv, progress, ...)
// Step     any h; the learner must step after gait and robot (declare it last in the system).
//
// Exact checkpoints. Every episode starts with a reset of the robot and a restart of the gait.
// The gait's first tick after a restart would still see the gyro of the robot before its reset
// (the gyro feedback is delayed by one step), so balance_on is false for exactly that one tick,
// as it is for the first tick of a fresh run. The continuation from an episode boundary then
// depends only on the learner's state, which the checkpoint holds (session state with RNG and
// clock, V, traces, log sizes): a run resumed from it is bit-identical to the uninterrupted one.
//
// Data layout: parameters, inputs, outputs and the session state (trivially copyable) live in
// the data struct; the value table (any size) and the traces live in the model, and
// save_state/restore_state append them to the data bytes, with an agent's place in the shared
// rounds (a restored agent rejoins them, docs/failover.md).
#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shared_values.hpp"
#include "stride/common/bytes.hpp"
#include "stride/learner/artefacts.hpp"
#include "stride/learner/session.hpp"
#include "stride/sdk/fmu.hpp"

namespace stride::learner {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t k_outputs = k_max_dimensions;

struct learner_data {
  // inputs
  double base_x = 0.0;
  double base_y = 0.0;
  bool fallen = false;
  int footsteps = 0;
  // parameters
  sdk::text grid{"period_time:450:960:15,swing_right_left:15:39:2"};
  int mode = 0;
  sdk::text protocol{"paper"};
  sdk::text eval_point{};
  double alpha = 0.10;
  double gamma = 0.90;
  double lambda = 0.05;
  double epsilon = 0.15;
  int steps_per_episode = 40;
  int max_falls = 10;
  int footsteps_per_step = 4;
  int settle_footsteps = 1;
  double k1 = 0.33;
  double k2 = 10.0;
  double negative_reward = -400.0;
  double speed_cap = 0.0;
  double capped_reward = 0.0;
  double initial_value = 0.0;
  int seed = 1;
  int total_steps = 300000;
  double step_timeout = 60.0;
  double stand_time = 0.0;
  bool balance = true;
  sdk::text output_dir{};
  sdk::text resume{};
  sdk::text snapshot_steps{};
  sdk::text shared_table{};
  int agent = 1;
  int path_every = 1;
  bool log_steps = true;
  bool log_progress = true;
  double progress_interval = 5.0;
  // outputs
  double value[k_outputs] = {};
  int reset_robot = 0;
  bool walking = true;
  bool balance_on = false;
  int episode = 0;
  int rl_step = 0;
  int step_in_episode = 0;
  int falls_in_episode = 0;
  int total_falls = 0;
  int state_index = 0;
  double last_reward = 0.0;
  double last_speed = 0.0;
  double episode_reward = 0.0;
  double state_value = 0.0;
  double sum_abs_dv = 0.0;
  double progress = 0.0;
  // internal
  session_state session{};
  bool started = false;
  bool finalized = false;
  std::uint32_t set_explicitly = 0;  // bit i: k_protocol_settings[i] came from fmi2Set
};

template <class F>
void state_fields(learner_data& d, F&& f) {
  f(d.base_x, d.base_y, d.fallen, d.footsteps, d.grid, d.mode, d.protocol, d.eval_point, d.alpha,
    d.gamma, d.lambda, d.epsilon, d.steps_per_episode, d.max_falls, d.footsteps_per_step,
    d.settle_footsteps, d.k1, d.k2, d.negative_reward, d.speed_cap, d.capped_reward,
    d.initial_value, d.seed, d.total_steps, d.step_timeout, d.stand_time, d.balance, d.output_dir,
    d.resume, d.snapshot_steps, d.shared_table, d.agent, d.path_every, d.log_steps, d.log_progress,
    d.progress_interval);
  f(d.value, d.reset_robot, d.walking, d.balance_on, d.episode, d.rl_step, d.step_in_episode,
    d.falls_in_episode, d.total_falls, d.state_index, d.last_reward, d.last_speed, d.episode_reward,
    d.state_value, d.sum_abs_dv, d.progress, d.session, d.started, d.finalized, d.set_explicitly);
}

// The settings whose defaults the protocol chooses: explicit sets win over the protocol.
struct protocol_setting {
  const char* name;
  void (*take_default)(learner_data&, const learner_config&);
};
// clang-format off
constexpr protocol_setting k_protocol_settings[] = {
    {"alpha", [](learner_data& d, const learner_config& c) { d.alpha = c.td.alpha; }},
    {"gamma", [](learner_data& d, const learner_config& c) { d.gamma = c.td.gamma; }},
    {"lambda", [](learner_data& d, const learner_config& c) { d.lambda = c.td.lambda; }},
    {"epsilon", [](learner_data& d, const learner_config& c) { d.epsilon = c.epsilon; }},
    {"steps_per_episode",
     [](learner_data& d, const learner_config& c) { d.steps_per_episode = c.steps_per_episode; }},
    {"max_falls", [](learner_data& d, const learner_config& c) { d.max_falls = c.max_falls; }},
    {"footsteps_per_step",
     [](learner_data& d, const learner_config& c) { d.footsteps_per_step = c.footsteps_per_step; }},
    {"settle_footsteps",
     [](learner_data& d, const learner_config& c) { d.settle_footsteps = c.settle_footsteps; }},
    {"k1", [](learner_data& d, const learner_config& c) { d.k1 = c.reward.k1; }},
    {"k2", [](learner_data& d, const learner_config& c) { d.k2 = c.reward.k2; }},
    {"negative_reward",
     [](learner_data& d, const learner_config& c) { d.negative_reward = c.reward.negative_reward; }},
    {"speed_cap", [](learner_data& d, const learner_config& c) { d.speed_cap = c.reward.speed_cap; }},
    {"capped_reward",
     [](learner_data& d, const learner_config& c) { d.capped_reward = c.reward.capped_reward; }},
    {"balance", [](learner_data& d, const learner_config& c) { d.balance = c.balance; }},
};
// clang-format on
static_assert(std::size(k_protocol_settings) <= 32);

protocol parse_protocol_parameter(std::string_view name) {
  const auto p = parse_protocol(name);
  if (!p) {
    throw sdk::model_error("protocol '" + std::string(name) +
                           "' is not a learner protocol (paper, authors-code)");
  }
  return *p;
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0) || seconds > 1e8) return "?";
  const auto s = static_cast<long long>(seconds + 0.5);
  char buf[64];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%lldm%02llds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%llds", s);
  }
  return buf;
}

class learner_model : public sdk::model_base<learner_data> {
 public:
  explicit learner_model(const sdk::instance_context& context) : context_(context) {}

  static sdk::model_info info() {
    sdk::model_info i;
    i.model_name = "learner";
    i.model_identifier = "learner";
    i.description =
        "TD(lambda) learning of gait parameters over a grid (Silva et al.), or fixed-parameter "
        "evaluation; drives gait.fmu parameters and restarts robot.fmu";
    i.default_step_size = 0.008;
    i.log_categories = {{"logProgress", "One line per episode: steps, reward, best state, ETA"}};
    return i;
  }

  static sdk::variable_table variables() {
    sdk::table_builder<learner_data> t;
    using d = learner_data;
    t.add("base_x", &d::base_x).input().unit("m").describe("Torso x (robot.base_x)");
    t.add("base_y", &d::base_y).input().unit("m").describe("Torso y (robot.base_y)");
    t.add("fallen", &d::fallen).input().describe("The robot fell (robot.fallen)");
    t.add("footsteps", &d::footsteps)
        .input()
        .describe("Completed steps since the gait's last (re)start (gait.footsteps)");

    t.add("grid", &d::grid)
        .parameter()
        .describe(
            "States: name:min:max:step per gait parameter, ',' between (1..4 dimensions); "
            "value[i] outputs dimension i");
    t.add("mode", &d::mode)
        .parameter()
        .range(0, 1)
        .describe("0 = learn (TD(lambda)), 1 = evaluate (walk with eval_point and measure)");
    t.add("eval_point", &d::eval_point)
        .parameter()
        .describe("Evaluation mode: one value per grid dimension, ',' between");
    t.add("protocol", &d::protocol)
        .parameter()
        .describe(
            "paper (Table 2 as printed) or authors-code (the authors' Webots controller): how a "
            "step is measured, when an episode ends, and the defaults of the settings below; "
            "parameters set explicitly win");
    t.add("alpha", &d::alpha).parameter().range(0, 1).describe("Learning rate");
    t.add("gamma", &d::gamma).parameter().range(0, 1).describe("Discount factor");
    t.add("lambda", &d::lambda).parameter().range(0, 1).describe("Eligibility trace decay");
    t.add("epsilon", &d::epsilon).parameter().range(0, 1).describe("Exploration probability");
    t.add("steps_per_episode", &d::steps_per_episode)
        .parameter()
        .min(1)
        .describe("An episode ends after this many RL steps");
    t.add("max_falls", &d::max_falls).parameter().min(1).describe("... or after this many falls");
    t.add("footsteps_per_step", &d::footsteps_per_step)
        .parameter()
        .min(1)
        .describe("W: footsteps measured per RL step");
    t.add("settle_footsteps", &d::settle_footsteps)
        .parameter()
        .min(0)
        .describe(
            "Footsteps walked, unmeasured, after new parameters (the gait latches period_time "
            "at the next double-support centre) or a restart");
    t.add("k1", &d::k1).parameter().describe("Reward K1 * 10^(speed / K2)");
    t.add("k2", &d::k2).parameter().unit("cm/s").min(1e-9).describe("Reward K2");
    t.add("negative_reward", &d::negative_reward)
        .parameter()
        .describe("Reward of an RL step in which the robot fell");
    t.add("speed_cap", &d::speed_cap)
        .parameter()
        .unit("cm/s")
        .min(0)
        .describe("From this speed on the reward is capped_reward (0: no cap)");
    t.add("capped_reward", &d::capped_reward)
        .parameter()
        .describe("Reward of a step at or above speed_cap");
    t.add("initial_value", &d::initial_value).parameter().describe("Initial V of every state");
    t.add("seed", &d::seed).parameter().describe("Random seed (start states, exploration, ties)");
    t.add("total_steps", &d::total_steps)
        .parameter()
        .min(0)
        .describe("The run ends (FMI terminate) after this many RL steps; 0 = never");
    t.add("step_timeout", &d::step_timeout)
        .parameter()
        .unit("s")
        .min(1e-3)
        .describe("Error when a settle or measurement phase lasts longer (no footsteps)");
    t.add("stand_time", &d::stand_time)
        .parameter()
        .unit("s")
        .min(0)
        .describe("Evaluate mode: the robot stands this long before it walks (walking output)");
    t.add("balance", &d::balance)
        .parameter()
        .describe("Gyro balance on (balance_on is false anyway for the tick after a restart)");
    t.add("output_dir", &d::output_dir)
        .parameter()
        .describe("Folder for V tables, logs, best config, checkpoint ('' = none; ${output_dir})");
    t.add("resume", &d::resume)
        .parameter()
        .describe("Checkpoint file or folder to continue from ('' = fresh; ${resume})");
    t.add("snapshot_steps", &d::snapshot_steps)
        .parameter()
        .describe("RL steps after which v_snapshot_<N>.csv is written, ',' between");
    t.add("shared_table", &d::shared_table)
        .parameter()
        .describe(
            "V shared with other agents: the table's endpoint ('' = V of its own; "
            "${shared_table}, docs/swarm.md)");
    t.add("agent", &d::agent)
        .parameter()
        .min(1)
        .describe("This agent's number when V is shared (${agent}): its seed and its share");
    t.add("path_every", &d::path_every)
        .parameter()
        .min(0)
        .describe("Record the torso path of every n-th episode in paths.csv (0 = none)");
    t.add("log_steps", &d::log_steps).parameter().describe("Write steps.csv (one row per RL step)");
    t.add("log_progress", &d::log_progress)
        .parameter()
        .describe("Log one progress line per episode (info, category logProgress)");
    t.add("progress_interval", &d::progress_interval)
        .parameter()
        .unit("s")
        .min(0)
        .describe("At most one progress line per this many wall seconds");

    t.add("value", &d::value)
        .output()
        .describe("Parameter values of the current state, by grid dimension (0 if unused)");
    t.add("reset_robot", &d::reset_robot)
        .output()
        .discrete()
        .describe("Restart counter: wire to robot.reset and gait.restart");
    t.add("walking", &d::walking)
        .output()
        .describe("Wire to gait.walking: false while the robot stands (stand_time)");
    t.add("balance_on", &d::balance_on)
        .output()
        .describe("Wire to gait.balance_on: false on the tick after a restart");
    t.add("episode", &d::episode).output().describe("Current episode (1-based)");
    t.add("rl_step", &d::rl_step).output().describe("Completed RL steps");
    t.add("step_in_episode", &d::step_in_episode).output().describe("RL steps in this episode");
    t.add("falls_in_episode", &d::falls_in_episode).output().describe("Falls in this episode");
    t.add("total_falls", &d::total_falls).output().describe("Falls since the start");
    t.add("state_index", &d::state_index).output().describe("Current grid state");
    t.add("last_reward", &d::last_reward).output().describe("Reward of the last RL step");
    t.add("last_speed", &d::last_speed)
        .output()
        .unit("cm/s")
        .describe("Speed measured in the last RL step");
    t.add("episode_reward", &d::episode_reward)
        .output()
        .describe("Accumulated reward of the current episode");
    t.add("state_value", &d::state_value).output().describe("V of the current state");
    t.add("sum_abs_dv", &d::sum_abs_dv)
        .output()
        .describe("Sum of |V change| over the states in the last completed episode");
    t.add("progress", &d::progress).output().describe("Fraction of total_steps done (0..1)");
    return t.finish();
  }

  void on_set(const sdk::variable& v) override {
    if (v.causality_kind != sdk::causality::parameter) return;
    if (v.name == "protocol") {
      const learner_config defaults =
          protocol_defaults(parse_protocol_parameter(data_.protocol.view()));
      for (std::size_t i = 0; i < std::size(k_protocol_settings); ++i) {
        if ((data_.set_explicitly & (1u << i)) == 0)
          k_protocol_settings[i].take_default(data_, defaults);
      }
      return;
    }
    for (std::size_t i = 0; i < std::size(k_protocol_settings); ++i) {
      if (v.name == k_protocol_settings[i].name) data_.set_explicitly |= 1u << i;
    }
  }

  void enter_initialization() override {
    config_ = make_config();
    snapshots_ = parse_step_list(data_.snapshot_steps.view(), "snapshot_steps");
    const std::string out = std::string(data_.output_dir.view());
    const std::string resume = std::string(data_.resume.view());
    for (const auto& [name, text] : {std::pair{"output_dir", out}, std::pair{"resume", resume}}) {
      if (text.find("${") != std::string::npos) {
        throw sdk::model_error(std::string(name) + " '" + text +
                               "' has an unsubstituted ${...}: run the system with stride run");
      }
    }
    values_ = dense_value_table(config_.grid.size(), config_.initial_value);
    traces_.clear();
    shared_.reset();
    next_snapshot_ = 0;
    std::optional<remote::table_endpoint> shared_table;
    if (!data_.shared_table.view().empty()) shared_table = agent_config();

    std::optional<checkpoint> ck;
    if (!resume.empty()) {
      fs::path file(resume);
      if (fs::is_directory(file)) file /= run_files::checkpoint;
      if (fs::exists(file)) {
        ck = read_checkpoint(file);
        restore_checkpoint(*ck, file);
        context_.log->log(sdk::log_level::info, "logProgress",
                          "resuming from " + file.string() + " after RL step " +
                              std::to_string(data_.session.rl_step) + " (episode " +
                              std::to_string(data_.session.episode) + ")");
      } else {
        context_.log->warning("resume: no checkpoint at " + file.string() +
                              " (killed before the first episode ended?): starting afresh");
      }
    }
    if (shared_table) join_shared_table(*shared_table, !resume.empty(), ck);
    session_ = std::make_unique<session>(
        config_, data_.session, shared_ ? static_cast<value_table&>(*shared_) : values_, traces_);
    if (!out.empty()) {
      // resumed without a checkpoint of its own: the logs are cut back to their headers, unless
      // a state restored before the first row says otherwise (a run resumed by stride)
      const std::map<std::string, std::uint64_t> none;
      writer_ = artefact_writer(fs::path(out), config_.grid, data_.log_steps,
                                ck               ? &ck->file_sizes
                                : resume.empty() ? nullptr
                                                 : &none);
    }
    if (!ck) {
      session_->start();
    } else if (session_->phase() == walk_phase::episode_ended) {
      session_->begin_episode();
    }
    data_.started = true;
    data_.finalized = false;
    wall_start_ = last_log_ = std::chrono::steady_clock::now();
    steps_at_start_ = data_.session.rl_step;
    publish();
  }

  void exit_initialization() override { publish(); }

  void calculate_values() override { publish(); }

  sdk::step_result do_step(sdk::time_ns, sdk::time_ns h) override {
    if (!data_.started) throw sdk::model_error("do_step before initialization");
    if (session_->phase() == walk_phase::finished) {
      finalize();
      return sdk::step_result::terminate;
    }
    const plant_inputs in{data_.base_x, data_.base_y, data_.fallen, data_.footsteps};
    advance_report r;
    try {
      r = session_->advance(in, h);
    } catch (const learner_error& e) {
      throw sdk::model_error(e.what());
    }
    const session_state& st = data_.session;
    if (writer_.active()) {
      const bool record_path = data_.path_every > 0 && (st.episode - 1) % data_.path_every == 0;
      if (record_path && (r.footstep || in.fallen)) {
        writer_.path_point(st.episode, st.rl_step, static_cast<double>(st.clock_ns) / 1e9,
                           in.base_x, in.base_y, in.fallen);
      }
      if (r.step) writer_.step(*r.step);
    }
    if (r.step) on_step(*r.step);
    if (r.episode) on_episode_end(*r.episode, r.finished);
    publish();
    if (r.finished) {
      finalize();
      return sdk::step_result::terminate;
    }
    return sdk::step_result::ok;
  }

  void terminate() override {
    if (data_.started) finalize();
    writer_.close();
  }

  // state = the data's fields, then V, the traces and the sizes of the logs (so that a restored
  // state continues them from its own moment, e.g. a run resumed by stride) as in a checkpoint,
  // with an agent's place in the shared rounds
  std::vector<std::byte> save_state() const override {
    common::byte_writer w;
    sdk::put_state(w, data_);
    checkpoint rest;
    rest.values = values_.values();
    rest.traces = traces_.entries;
    if (writer_.active()) rest.file_sizes = writer_.flush();
    if (shared_) rest.shared = shared_place();
    w.put_bytes(checkpoint_bytes(rest));
    return w.take();
  }

  void restore_state(std::span<const std::byte> bytes) override {
    sdk::state_reader r(bytes);
    learner_data restored = data_;
    sdk::get_state(r, restored);
    const auto tail = r.get_bytes();
    r.require_end();
    checkpoint rest;
    try {
      rest = checkpoint_from_bytes(tail, "learner state");
    } catch (const learner_error& e) {
      throw sdk::model_error(e.what());
    }
    if (data_.started) {
      if (rest.values.size() != values_.size()) {
        throw sdk::model_error("learner state has " + std::to_string(rest.values.size()) +
                               " values, the grid " + std::to_string(values_.size()));
      }
      if (rest.shared.has_value() != (shared_ != nullptr)) {
        throw sdk::model_error(rest.shared
                                   ? "learner state is of an agent sharing V, this learner does not"
                                   : "learner state is of a learner with V of its own, this one "
                                     "shares V");
      }
    } else if (restored.started) {
      throw sdk::model_error("learner state from an initialized instance needs initialization");
    }
    data_ = restored;
    values_.values() = std::move(rest.values);
    traces_.entries = std::move(rest.traces);
    if (writer_.active() && !rest.file_sizes.empty()) writer_.cut_back(rest.file_sizes);
    if (shared_ && rest.shared) rejoin_shared_table(*rest.shared);
  }

 private:
  // an agent sharing V: its own seed stream and its share of total_steps
  remote::table_endpoint agent_config() {
    remote::table_endpoint where;
    try {
      where = remote::table_endpoint::parse(data_.shared_table.view());
    } catch (const std::invalid_argument& e) {
      throw sdk::model_error(std::string("parameter shared_table: ") + e.what());
    }
    if (data_.agent > where.agents) {
      throw sdk::model_error("parameter agent: " + std::to_string(data_.agent) +
                             " is more than the shared table's " + std::to_string(where.agents) +
                             " agents");
    }
    if (config_.mode != learner_mode::learn) {
      throw sdk::model_error("parameter shared_table: only a learning learner (mode 0) shares V");
    }
    if (config_.total_steps <= 0) {
      throw sdk::model_error("parameter total_steps: agents sharing V need a total (> 0)");
    }
    config_.seed = agent_seed(config_.seed, data_.agent);
    // the run's total, shared: every agent walks the same number of rounds
    config_.total_steps = (config_.total_steps + where.agents - 1) / where.agents;
    return where;
  }

  // joins the table; a resumed agent says after which round it continues
  void join_shared_table(const remote::table_endpoint& where, bool resuming,
                         const std::optional<checkpoint>& ck) {
    if (ck && !ck->shared) {
      throw sdk::model_error("resume: the checkpoint is of a learner that did not share V");
    }
    const shared_checkpoint none;  // resumed without a checkpoint: from round 0
    const shared_checkpoint* from = nullptr;
    if (resuming) {
      from = ck ? &*ck->shared : &none;
      next_snapshot_ = static_cast<std::size_t>(from->snapshots_written);
    }
    try {
      shared_ = std::make_unique<shared_values>(
          values_, std::vector<double>(config_.grid.size(), config_.initial_value), where,
          data_.agent, config_.total_steps,
          [this](const remote::table_snapshot& t) { on_merged(t); }, from);
    } catch (const std::exception& e) {
      throw sdk::model_error(e.what());
    }
  }

  // this agent's place in the shared rounds (its checkpoint and state images carry it)
  shared_checkpoint shared_place() const {
    shared_checkpoint sh;
    sh.round = shared_->last_round();
    sh.entries = shared_->last_entries();
    sh.increments = shared_->last_increments();
    sh.merged_updates = shared_->merged_updates();
    sh.snapshots_written = next_snapshot_;
    return sh;
  }

  // a restored state (e.g. on a standby worker, docs/failover.md): the table service answers
  // the rounds this agent walks again with the tables it merged then, counting nothing twice
  void rejoin_shared_table(const shared_checkpoint& at) {
    try {
      shared_->rejoin(at);
    } catch (const std::exception& e) {
      throw sdk::model_error(e.what());
    }
    // the snapshots up to the merged table it had were written then
    next_snapshot_ = static_cast<std::size_t>(
        std::upper_bound(snapshots_.begin(), snapshots_.end(), at.merged_updates) -
        snapshots_.begin());
  }

  // agent 1 writes the V snapshots the merged tables pass (RL steps of all agents counted)
  void on_merged(const remote::table_snapshot& t) {
    if (data_.agent != 1 || !writer_.active()) return;
    while (next_snapshot_ < snapshots_.size() && snapshots_[next_snapshot_] <= t.updates) {
      write_value_table(writer_.dir() / run_files::snapshot(snapshots_[next_snapshot_]),
                        config_.grid, values_);
      ++next_snapshot_;
    }
  }

  learner_config make_config() const {
    try {
      learner_config c;
      c.grid = state_grid::parse(data_.grid.view(), "grid");
      c.mode = static_cast<learner_mode>(data_.mode);
      c.rules = parse_protocol_parameter(data_.protocol.view());
      c.eval_point = parse_number_list(data_.eval_point.view(), "eval_point");
      c.td = {data_.alpha, data_.gamma, data_.lambda};
      c.epsilon = data_.epsilon;
      c.steps_per_episode = data_.steps_per_episode;
      c.max_falls = data_.max_falls;
      c.footsteps_per_step = data_.footsteps_per_step;
      c.settle_footsteps = data_.settle_footsteps;
      c.reward = {data_.k1, data_.k2, data_.negative_reward, data_.speed_cap, data_.capped_reward};
      c.initial_value = data_.initial_value;
      c.seed = static_cast<std::uint64_t>(static_cast<std::int64_t>(data_.seed));
      c.total_steps = data_.total_steps;
      c.step_timeout = data_.step_timeout;
      c.stand_time = data_.stand_time;
      c.balance = data_.balance;
      c.validate();
      return c;
    } catch (const learner_error& e) {
      throw sdk::model_error(e.what());
    }
  }

  void restore_checkpoint(const checkpoint& ck, const fs::path& file) {
    check_checkpoint_config(ck.config, config_.canonical(), file);
    if (ck.values.size() != values_.size()) {
      throw sdk::model_error(file.string() + ": checkpoint does not fit this learner's grid");
    }
    sdk::read_state_image(ck.state, data_.session);
    values_.values() = ck.values;
    traces_.entries = ck.traces;
  }

  void on_step(const step_record& s) {
    if (config_.mode == learner_mode::learn && !shared_ &&
        std::binary_search(snapshots_.begin(), snapshots_.end(), s.rl_step) && writer_.active()) {
      write_value_table(writer_.dir() / run_files::snapshot(s.rl_step), config_.grid, values_);
    }
  }

  void on_episode_end(const episode_record& e, bool finished) {
    if (writer_.active()) {
      writer_.episode(e);
      checkpoint ck;
      ck.config = config_.canonical();
      ck.state = sdk::state_image(data_.session);
      ck.values = values_.values();
      ck.traces = traces_.entries;
      ck.file_sizes = writer_.flush();
      if (shared_) ck.shared = shared_place();
      write_checkpoint(writer_.dir() / run_files::checkpoint, ck);
    }
    log_progress(e, finished);
    if (!finished) session_->begin_episode();
  }

  void log_progress(const episode_record& e, bool force) {
    if (!data_.log_progress) return;
    const auto now = std::chrono::steady_clock::now();
    const double since_log = std::chrono::duration<double>(now - last_log_).count();
    if (!force && since_log < data_.progress_interval) return;
    last_log_ = now;
    const double wall = std::chrono::duration<double>(now - wall_start_).count();
    const std::int64_t done = data_.session.rl_step - steps_at_start_;
    const double rate = wall > 0 ? static_cast<double>(done) / wall : 0.0;
    std::string msg = "episode " + std::to_string(e.episode) + " | RL step " +
                      std::to_string(data_.session.rl_step);
    if (config_.total_steps > 0) {
      char pct[32];
      std::snprintf(pct, sizeof pct, " (%.1f%%)",
                    100.0 * static_cast<double>(data_.session.rl_step) /
                        static_cast<double>(config_.total_steps));
      msg += "/" + std::to_string(config_.total_steps) + pct;
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, " | reward %.1f, falls %d, sum|dV| %.2f | %.1f steps/s",
                  e.reward, e.falls, e.sum_abs_dv, rate);
    msg += buf;
    if (config_.total_steps > 0 && rate > 0) {
      msg +=
          " | ETA " +
          format_duration(static_cast<double>(config_.total_steps - data_.session.rl_step) / rate);
    }
    const std::size_t best = best_state(values_);
    msg += " | best " + describe_point(config_.grid, config_.grid.values(best)) + " (V " +
           format_number(std::round(values_.get(best) * 100) / 100) + ")";
    context_.log->log(sdk::log_level::info, "logProgress", msg);
  }

  void finalize() {
    if (data_.finalized) return;
    data_.finalized = true;
    if (config_.mode == learner_mode::learn) {
      // a shared table: every agent takes the final table (after every agent's last step);
      // agent 1 writes it. A run stopped early writes agent 1's replica as it is.
      if (shared_ && session_->phase() == walk_phase::finished) {
        try {
          shared_->finish();
        } catch (const learner_error& e) {
          throw sdk::model_error(e.what());
        }
      }
      const best_summary b = summarize_best(config_.grid, values_);
      if (writer_.active() && (!shared_ || data_.agent == 1)) {
        write_value_table(writer_.dir() / run_files::value_table, config_.grid, values_);
        write_best(writer_.dir(), b, config_.rules,
                   shared_ ? shared_->merged_updates() : data_.session.rl_step,
                   data_.session.episode, data_.session.total_falls);
      }
      if (data_.log_progress) {
        std::string text = b.text;
        while (!text.empty() && text.back() == '\n') text.pop_back();
        context_.log->log(sdk::log_level::info, "logProgress", text);
      }
    } else {
      const session_state& st = data_.session;
      const double speed = session_->mean_speed();
      const double physical = st.eval_time > 0 ? 100.0 * st.eval_distance / st.eval_time : 0.0;
      if (writer_.active()) {
        evaluation_result r;
        for (std::size_t d = 0; d < config_.grid.dimension_count(); ++d) {
          r.point.emplace_back(config_.grid.dimensions()[d].name, config_.eval_point[d]);
        }
        r.windows = st.rl_step;
        r.falls = st.total_falls;
        r.distance = st.eval_distance;
        r.measured_time = st.eval_time;
        r.mean_speed = speed;
        r.sim_time = static_cast<double>(st.clock_ns) / 1e9;
        r.physical_speed = physical;
        r.rules = config_.rules;
        write_evaluation(writer_.dir(), r);
      }
      if (data_.log_progress) {
        char buf[240];
        std::snprintf(buf, sizeof buf,
                      "evaluated %s: %lld windows, %lld falls, %.3f m in %.1f s measured, mean "
                      "speed %.2f cm/s (%s protocol; physical %.2f cm/s)",
                      describe_point(config_.grid, config_.eval_point).c_str(),
                      static_cast<long long>(st.rl_step), static_cast<long long>(st.total_falls),
                      st.eval_distance, st.eval_time, speed,
                      std::string(to_string(config_.rules)).c_str(), physical);
        context_.log->log(sdk::log_level::info, "logProgress", buf);
      }
    }
    if (writer_.active()) writer_.flush();
  }

  void publish() {
    if (!data_.started || !session_) return;
    const session_state& st = data_.session;
    const std::vector<double> v = session_->current_values();
    for (std::size_t i = 0; i < k_outputs; ++i) data_.value[i] = i < v.size() ? v[i] : 0.0;
    data_.reset_robot = st.restarts;
    data_.walking = session_->walking();
    data_.balance_on = config_.balance && st.balance_gate;
    data_.episode = static_cast<int>(st.episode);
    data_.rl_step = static_cast<int>(st.rl_step);
    data_.step_in_episode = st.step_in_episode;
    data_.falls_in_episode = st.falls_in_episode;
    data_.total_falls = static_cast<int>(st.total_falls);
    data_.state_index = static_cast<int>(st.state);
    data_.last_reward = st.last_reward;
    data_.last_speed = st.last_speed;
    data_.episode_reward = st.episode_reward;
    data_.state_value =
        config_.mode == learner_mode::learn ? values_.get(static_cast<std::size_t>(st.state)) : 0;
    data_.sum_abs_dv = st.last_sum_abs_dv;
    data_.progress = config_.total_steps > 0 ? static_cast<double>(st.rl_step) /
                                                   static_cast<double>(config_.total_steps)
                                             : 0.0;
  }

  sdk::instance_context context_;
  learner_config config_;
  dense_value_table values_;
  std::unique_ptr<shared_values> shared_;  // V shared with other agents (else values_ alone)
  std::size_t next_snapshot_ = 0;
  eligibility_traces traces_;
  std::unique_ptr<session> session_;
  // mutable: save_state flushes the logs to put their sizes into the state
  mutable artefact_writer writer_;
  std::vector<std::int64_t> snapshots_;
  std::chrono::steady_clock::time_point wall_start_{}, last_log_{};
  std::int64_t steps_at_start_ = 0;
};

}  // namespace
}  // namespace stride::learner

STRIDE_FMU(stride::learner::learner_model)
