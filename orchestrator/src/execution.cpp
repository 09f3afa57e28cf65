#include "stride/cosim/execution.hpp"

#include "stride/cosim/error.hpp"

namespace stride::cosim {

execution::execution(std::unique_ptr<fixed_step_algorithm> algo, time_point start)
    : algo_(std::move(algo)), start_(start) {
  if (!algo_) throw validation_error("execution: null algorithm");
}

execution::~execution() {
  if (initialized_ && !finished_) finish(current_time(), {});
}

void execution::add_observer(std::shared_ptr<observer> obs) {
  if (initialized_) throw validation_error("cannot add an observer after initialization");
  obs->attach(*this);
  observers_.push_back(std::move(obs));
}

time_point execution::current_time() const noexcept {
  return initialized_ ? algo_->current_time() : start_;
}

void execution::initialize(std::optional<time_point> stop) {
  if (initialized_) return;
  algo_->freeze();
  try {
    algo_->initialize(start_, stop);
  } catch (const std::exception& e) {
    initialized_ = true;
    finish(start_, e.what());
    throw;
  }
  initialized_ = true;
  for (auto& o : observers_) o->simulation_initialized(*this, start_);
}

void execution::finish(time_point t, const std::string& error) noexcept {
  if (finished_) return;
  finished_ = true;
  for (auto& o : observers_) {
    try {
      o->simulation_ended(*this, t, error);
    } catch (...) {
      // observers must not stop the shutdown of the others
    }
  }
  algo_->terminate_all();
}

void execution::end() noexcept {
  if (initialized_) finish(current_time(), {});
}

run_result execution::simulate_until(time_point stop) {
  if (finished_) throw validation_error("the simulation has already ended");
  if (!initialized_) initialize(stop);
  run_result result;
  const duration h = algo_->base_step();
  try {
    while (algo_->current_time() + h <= stop) {
      const step_outcome outcome = algo_->step();
      if (outcome.terminated) {
        result.terminated_by_component = true;
        result.terminated_by = algo_->component_at(outcome.terminated_by).name();
        break;
      }
      const time_point t = algo_->current_time();
      for (auto& o : observers_) o->step_complete(*this, algo_->step_count(), t);
    }
  } catch (const std::exception& e) {
    finish(algo_->current_time(), e.what());
    throw;
  }
  result.end_time = algo_->current_time();
  result.steps = algo_->step_count();
  if (result.terminated_by_component) finish(result.end_time, {});
  return result;
}

}  // namespace stride::cosim
