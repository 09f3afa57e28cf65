#include "stride/learner/session.hpp"

#include <cmath>

namespace stride::learner {
namespace {

void require(bool ok, const char* name, const std::string& what) {
  if (!ok) throw learner_error(std::string(name) + ": " + what);
}

bool finite(double v) {
  return std::isfinite(v);
}

// the authors' controller counts its window in 16 ms control iterations (Webots basicTimeStep)
constexpr std::int64_t k_control_iteration_ns = 16'000'000;

}  // namespace

std::optional<protocol> parse_protocol(std::string_view name) {
  if (name == "paper") return protocol::paper;
  if (name == "authors-code") return protocol::authors_code;
  return std::nullopt;
}

std::string_view to_string(protocol p) {
  return p == protocol::authors_code ? "authors-code" : "paper";
}

learner_config protocol_defaults(protocol p) {
  learner_config c;
  c.rules = p;
  if (p == protocol::authors_code) {
    c.td.lambda = 0.3;
    c.steps_per_episode = 30;
    c.max_falls = 10;
    c.settle_footsteps = 0;
    // 10^((v + 1e-5)/10)/3 = K1·10^(v/10) with K1 = 10^(1e-6)/3
    c.reward.k1 = std::pow(10.0, 1e-6) / 3.0;
    c.reward.k2 = 10.0;
    c.reward.negative_reward = -200;
    c.reward.speed_cap = 30;
    c.reward.capped_reward = 50;
    c.balance = false;
  }
  return c;
}

void learner_config::validate() const {
  require(grid.size() > 0, "grid", "no states");
  require(finite(td.alpha) && td.alpha > 0 && td.alpha <= 1, "alpha", "must be in (0, 1]");
  require(finite(td.gamma) && td.gamma >= 0 && td.gamma <= 1, "gamma", "must be in [0, 1]");
  require(finite(td.lambda) && td.lambda >= 0 && td.lambda <= 1, "lambda", "must be in [0, 1]");
  require(finite(epsilon) && epsilon >= 0 && epsilon <= 1, "epsilon", "must be in [0, 1]");
  require(steps_per_episode >= 1, "steps_per_episode", "must be >= 1");
  require(max_falls >= 1, "max_falls", "must be >= 1");
  require(footsteps_per_step >= 1, "footsteps_per_step", "must be >= 1");
  require(settle_footsteps >= 0, "settle_footsteps", "must be >= 0");
  require(finite(reward.k1), "k1", "must be finite");
  require(finite(reward.k2) && reward.k2 > 0, "k2", "must be > 0");
  require(finite(reward.negative_reward), "negative_reward", "must be finite");
  require(finite(initial_value), "initial_value", "must be finite");
  require(total_steps >= 0, "total_steps", "must be >= 0");
  require(finite(step_timeout) && step_timeout > 0, "step_timeout", "must be > 0");
  require(finite(stand_time) && stand_time >= 0, "stand_time", "must be >= 0");
  require(finite(reward.speed_cap) && reward.speed_cap >= 0, "speed_cap", "must be >= 0");
  require(finite(reward.capped_reward), "capped_reward", "must be finite");
  if (rules == protocol::authors_code) {
    require(grid.dimension("period_time").has_value(), "grid",
            "the authors-code protocol times its window in periods: the grid needs a "
            "period_time dimension, got " +
                grid.str());
  }
  if (mode == learner_mode::evaluate) {
    require(eval_point.size() == grid.dimension_count(), "eval_point",
            "needs one value per grid dimension (" + std::to_string(grid.dimension_count()) + ": " +
                grid.str() + "), got " + std::to_string(eval_point.size()));
  }
}

std::string learner_config::canonical() const {
  std::string s;
  auto add = [&s](const char* key, const std::string& value) {
    s += key;
    s += '=';
    s += value;
    s += '\n';
  };
  add("grid", grid.str());
  add("mode", std::to_string(static_cast<int>(mode)));
  add("protocol", std::string(to_string(rules)));
  std::string point;
  for (double v : eval_point) point += (point.empty() ? "" : ",") + format_number(v);
  add("eval_point", point);
  add("alpha", format_number(td.alpha));
  add("gamma", format_number(td.gamma));
  add("lambda", format_number(td.lambda));
  add("epsilon", format_number(epsilon));
  add("steps_per_episode", std::to_string(steps_per_episode));
  add("max_falls", std::to_string(max_falls));
  add("footsteps_per_step", std::to_string(footsteps_per_step));
  add("settle_footsteps", std::to_string(settle_footsteps));
  add("k1", format_number(reward.k1));
  add("k2", format_number(reward.k2));
  add("negative_reward", format_number(reward.negative_reward));
  add("speed_cap", format_number(reward.speed_cap));
  add("capped_reward", format_number(reward.capped_reward));
  add("initial_value", format_number(initial_value));
  add("seed", std::to_string(seed));
  add("stand_time", format_number(stand_time));
  // total_steps is left out on purpose: a resumed run may be given more steps
  return s;
}

session::session(const learner_config& config, session_state& state, value_table& values,
                 eligibility_traces& traces)
    : cfg_(config), st_(state), v_(values), z_(traces) {}

void session::start() {
  st_ = session_state{};
  st_.rng = seed_rng(cfg_.seed);
  z_.clear();
  if (cfg_.mode == learner_mode::learn) {
    begin_episode();
  } else {
    st_.episode = 1;
    restart();
  }
}

void session::begin_episode() {
  st_.episode += 1;
  st_.step_in_episode = 0;
  st_.falls_in_episode = 0;
  st_.steps_without_fall = 0;
  st_.episode_reward = 0;
  z_.clear();
  st_.state = static_cast<std::int64_t>(uniform_below(st_.rng, cfg_.grid.size()));
  st_.episode_first_state = st_.state;
  restart();
}

void session::restart() {
  st_.restarts += 1;
  st_.restart_pending = true;
  st_.balance_gate = false;
  st_.footsteps_seen = 0;
  st_.last_footsteps = 0;  // the gait's counter starts again at 0
  st_.phase = static_cast<int>(walk_phase::settling);
  st_.target_footsteps = cfg_.settle_footsteps;
  st_.phase_start_ns = st_.clock_ns;
}

void session::start_measuring(const plant_inputs& in) {
  st_.phase = static_cast<int>(walk_phase::measuring);
  st_.x0 = in.base_x;
  st_.y0 = in.base_y;
  st_.t0_ns = st_.clock_ns;
  st_.phase_start_ns = st_.clock_ns;
  st_.target_footsteps = st_.footsteps_seen + cfg_.footsteps_per_step;
  if (cfg_.rules == protocol::authors_code) {
    // the controller's test cont >= (period_time/8)·W, with cont counting 16 ms iterations
    const auto iterations = static_cast<std::int64_t>(
        std::ceil(period_time_ms() / 8.0 * static_cast<double>(cfg_.footsteps_per_step)));
    st_.window_end_ns = st_.clock_ns + iterations * k_control_iteration_ns;
  }
}

double session::period_time_ms() const {
  return current_values()[*cfg_.grid.dimension("period_time")];
}

double session::window_speed(double distance, double duration) const {
  if (cfg_.rules == protocol::paper) return duration > 0 ? 100.0 * distance / duration : 0.0;
  // the controller divides by W periods although its window lasts 2·W, and reads less than
  // 1 cm as standing still
  if (distance <= 0.01) return 0.0;
  return 100.0 * distance /
         (static_cast<double>(cfg_.footsteps_per_step) * period_time_ms() / 1000.0);
}

bool session::episode_over() const {
  if (cfg_.rules == protocol::authors_code) {
    return st_.steps_without_fall > cfg_.steps_per_episode || st_.falls_in_episode > cfg_.max_falls;
  }
  return st_.step_in_episode >= cfg_.steps_per_episode || st_.falls_in_episode >= cfg_.max_falls;
}

double session::mean_speed() const {
  if (cfg_.rules == protocol::authors_code) {
    return st_.eval_windows > 0 ? st_.eval_speed_sum / static_cast<double>(st_.eval_windows) : 0.0;
  }
  return st_.eval_time > 0 ? 100.0 * st_.eval_distance / st_.eval_time : 0.0;
}

std::vector<double> session::current_values() const {
  if (cfg_.mode == learner_mode::evaluate) return cfg_.eval_point;
  return cfg_.grid.values(static_cast<std::size_t>(st_.state));
}

bool session::walking() const {
  return cfg_.mode != learner_mode::evaluate ||
         static_cast<double>(st_.clock_ns) >= cfg_.stand_time * 1e9;
}

advance_report session::advance(const plant_inputs& in, std::int64_t h_ns) {
  advance_report r;
  st_.clock_ns += h_ns;
  const walk_phase ph = phase();
  if (ph == walk_phase::finished || ph == walk_phase::episode_ended) return r;
  if (!walking()) {
    // standing before an evaluation: nothing to measure, no footsteps to wait for
    st_.phase_start_ns = st_.clock_ns;
    return r;
  }

  const bool after_restart = st_.restart_pending;
  st_.restart_pending = false;
  st_.balance_gate = true;
  if (after_restart && in.fallen) {
    throw learner_error(
        "the robot is still fallen one step after a reset: connect learner.reset_robot to "
        "robot.reset (and to gait.restart)");
  }
  if (!std::isfinite(in.base_x) || !std::isfinite(in.base_y)) {
    throw learner_error("base_x/base_y is not finite");
  }
  if (in.footsteps != st_.last_footsteps) {
    // a smaller count means the gait was restarted: it counts again from 0
    st_.footsteps_seen +=
        in.footsteps > st_.last_footsteps ? in.footsteps - st_.last_footsteps : in.footsteps;
    st_.last_footsteps = in.footsteps;
    r.footstep = true;
  }

  if (in.fallen) {
    finish_step(r, in, true, 0.0, 0.0);
    return r;
  }
  if (ph == walk_phase::settling && st_.footsteps_seen >= st_.target_footsteps) {
    start_measuring(in);
  } else if (ph == walk_phase::measuring &&
             (cfg_.rules == protocol::authors_code ? st_.clock_ns >= st_.window_end_ns
                                                   : st_.footsteps_seen >= st_.target_footsteps)) {
    const double distance = std::hypot(in.base_x - st_.x0, in.base_y - st_.y0);
    const double duration = static_cast<double>(st_.clock_ns - st_.t0_ns) / 1e9;
    finish_step(r, in, false, distance, duration);
    return r;
  }
  const bool waits_for_footsteps = ph == walk_phase::settling || cfg_.rules == protocol::paper;
  if (waits_for_footsteps &&
      static_cast<double>(st_.clock_ns - st_.phase_start_ns) / 1e9 > cfg_.step_timeout) {
    throw learner_error("no progress: " + std::to_string(st_.footsteps_seen) + " of " +
                        std::to_string(st_.target_footsteps) + " footsteps after " +
                        format_number(cfg_.step_timeout) +
                        " s (step_timeout); is gait.walking true and gait.footsteps connected "
                        "to learner.footsteps?");
  }
  return r;
}

void session::finish_step(advance_report& r, const plant_inputs& in, bool fell, double distance,
                          double duration) {
  const double speed = fell ? 0.0 : window_speed(distance, duration);
  const double reward = step_reward(speed, fell, cfg_.reward);
  st_.rl_step += 1;
  st_.step_in_episode += 1;
  st_.last_reward = reward;
  st_.last_speed = speed;
  st_.episode_reward += reward;
  if (fell) {
    st_.falls_in_episode += 1;
    st_.total_falls += 1;
    st_.steps_without_fall = 0;
  }
  st_.steps_without_fall += 1;  // the controller counts the falling step as the first
  step_record rec;
  rec.rl_step = st_.rl_step;
  rec.episode = st_.episode;
  rec.step_in_episode = st_.step_in_episode;
  rec.state = static_cast<std::size_t>(st_.state);
  rec.values = current_values();
  rec.fell = fell;
  rec.distance = distance;
  rec.duration = duration;
  rec.speed = speed;
  rec.reward = reward;

  const bool finished = cfg_.total_steps > 0 && st_.rl_step >= cfg_.total_steps;
  if (cfg_.mode == learner_mode::evaluate) {
    if (!fell) {
      st_.eval_distance += distance;
      st_.eval_time += duration;
      st_.eval_speed_sum += speed;
      st_.eval_windows += 1;
    }
    rec.next_state = rec.state;
    r.step = rec;
    if (finished) {
      st_.phase = static_cast<int>(walk_phase::finished);
      r.finished = true;
      return;
    }
  } else {
    const std::size_t s = rec.state;
    v_.before_update(st_.rl_step);
    const std::size_t a = choose_epsilon_greedy(v_, cfg_.grid, s, cfg_.epsilon, st_.rng);
    const std::size_t s_next = successor(cfg_.grid, s, a);
    const double delta = td_lambda_update(v_, z_, s, reward, s_next, cfg_.td);
    v_.after_update(st_.rl_step);
    st_.last_delta = delta;
    rec.action = a;
    rec.next_state = s_next;
    rec.delta = delta;
    rec.value = v_.get(s);
    r.step = rec;
    st_.state = static_cast<std::int64_t>(s_next);

    const bool episode_done = episode_over();
    if (episode_done || finished) {
      episode_record e;
      e.episode = st_.episode;
      e.steps = st_.step_in_episode;
      e.falls = st_.falls_in_episode;
      e.reward = st_.episode_reward;
      e.sum_abs_dv = sum_abs_value_change(v_, z_);
      e.first_state = static_cast<std::size_t>(st_.episode_first_state);
      e.last_state = s_next;
      e.rl_step = st_.rl_step;
      e.time = static_cast<double>(st_.clock_ns) / 1e9;
      e.complete = episode_done;
      st_.last_episode_reward = e.reward;
      st_.last_sum_abs_dv = e.sum_abs_dv;
      r.episode = e;
      st_.phase = static_cast<int>(finished ? walk_phase::finished : walk_phase::episode_ended);
      r.finished = finished;
      return;
    }
  }
  // go on walking in the (new) state
  if (fell) {
    restart();
    r.restarted = true;
    return;
  }
  st_.phase = static_cast<int>(walk_phase::settling);
  st_.target_footsteps = st_.footsteps_seen + cfg_.settle_footsteps;
  st_.phase_start_ns = st_.clock_ns;
  if (cfg_.settle_footsteps == 0) start_measuring(in);
}

}  // namespace stride::learner
