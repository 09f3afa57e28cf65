#include "shared_values.hpp"

#include <stdexcept>
#include <utility>

#include "stride/learner/session.hpp"

namespace stride::learner {

namespace {
// An agent waits this long for the others at a synchronous round: far more than any RL step
// takes, so reaching it means an agent is gone.
constexpr std::chrono::minutes k_round_timeout{5};
}  // namespace

shared_values::shared_values(dense_value_table& replica, std::vector<double> initial,
                             const remote::table_endpoint& where, int agent, std::int64_t last_step,
                             merged_callback on_merged, const shared_checkpoint* resumed)
    : replica_(replica),
      client_(where, agent),
      last_step_(last_step),
      on_merged_(std::move(on_merged)),
      initial_(std::move(initial)) {
  if (resumed != nullptr) rejoin(*resumed);
}

void shared_values::rejoin(const shared_checkpoint& at) {
  entries_ = at.entries;
  increments_ = at.increments;
  last_round_ = at.round;
  merged_updates_ = at.merged_updates;
  client_.resume(last_round_, entries_, increments_, initial_, last_round_ >= last_step_);
}

void shared_values::add(std::size_t s, double delta) {
  // the replica changes at once (V after the update is logged); the service adds the same
  // increment to the shared table
  replica_.add(s, delta);
  entries_.push_back(static_cast<std::uint32_t>(s));
  increments_.push_back(delta);
}

void shared_values::before_update(std::int64_t step) {
  // the last update was sent: this step's begins
  entries_.clear();
  increments_.clear();
  try {
    take(client_.wait_round(step - 1, k_round_timeout));
  } catch (const std::exception& e) {
    throw learner_error(e.what());
  }
}

void shared_values::after_update(std::int64_t step) {
  try {
    client_.send(step, entries_, increments_,
                 step == 1 ? std::span<const double>(initial_) : std::span<const double>(),
                 step >= last_step_);
  } catch (const std::exception& e) {
    throw learner_error(e.what());
  }
  last_round_ = step;
}

void shared_values::finish() {
  try {
    take(client_.wait_final(k_round_timeout));
  } catch (const std::exception& e) {
    throw learner_error(e.what());
  }
}

void shared_values::take(const remote::table_snapshot& t) {
  // nothing merged yet (round 0, or an asynchronous table before its first update)
  if (t.values.empty() || t.updates <= merged_updates_) return;
  if (t.values.size() != replica_.size()) {
    throw learner_error("shared table has " + std::to_string(t.values.size()) +
                        " entries, this learner's grid " + std::to_string(replica_.size()));
  }
  replica_.values() = t.values;
  merged_updates_ = t.updates;
  if (on_merged_) on_merged_(t);
}

}  // namespace stride::learner
