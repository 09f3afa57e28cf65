#include "failover_component.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "stride/cosim/time.hpp"

namespace stride::remote {

std::optional<std::string> standby_pool::replacement_for(const std::string& lost) {
  std::lock_guard lock(mutex_);
  if (const auto it = replaced_.find(lost); it != replaced_.end()) return it->second;
  if (next_ >= workers_.size()) return std::nullopt;
  return replaced_[lost] = workers_[next_++];
}

std::optional<std::string> standby_pool::replaced_by(const std::string& worker) const {
  std::lock_guard lock(mutex_);
  const auto it = replaced_.find(worker);
  if (it == replaced_.end()) return std::nullopt;
  return it->second;
}

void standby_pool::discard(const std::string& worker) {
  std::lock_guard lock(mutex_);
  std::erase_if(replaced_, [&](const auto& entry) { return entry.second == worker; });
}

long standby_pool::failovers() const {
  std::lock_guard lock(mutex_);
  return static_cast<long>(replaced_.size());
}

failover_component::failover_component(std::unique_ptr<cosim::component> first, std::string worker,
                                       factory make, std::shared_ptr<standby_pool> standby,
                                       int snapshot_every, cosim::log_sink log)
    : inner_(std::move(first)),
      worker_(std::move(worker)),
      make_(std::move(make)),
      standby_(std::move(standby)),
      snapshot_every_(std::max(snapshot_every, 1)),
      log_(log ? std::move(log) : cosim::stderr_log_sink()) {}

std::unique_ptr<failover_component> failover_component::start(const std::string& worker,
                                                              factory make,
                                                              std::shared_ptr<standby_pool> standby,
                                                              int snapshot_every,
                                                              cosim::log_sink log) {
  std::string on = worker;
  for (;;) {
    try {
      std::unique_ptr<cosim::component> first = make(on);
      if (on != worker && log) {
        log(cosim::log_level::warning, first->name(), "failover",
            "worker '" + worker + "' was lost before the run: starts on standby worker '" + on +
                "'");
      }
      return std::make_unique<failover_component>(std::move(first), on, std::move(make),
                                                  std::move(standby), snapshot_every,
                                                  std::move(log));
    } catch (const worker_lost& lost) {
      const std::optional<std::string> next = standby->replacement_for(on);
      if (!next)
        throw cosim::component_error(std::string(lost.what()) + "; no standby worker is left");
      on = *next;
    }
  }
}

template <class F>
auto failover_component::guarded(F&& f) -> decltype(f(std::declval<cosim::component&>())) {
  for (;;) {
    try {
      return f(*inner_);
    } catch (const worker_lost& lost) {
      fail_over(lost);
    }
  }
}

void failover_component::remember(call what) {
  if (!initialized_) {
    prefix_.push_back(std::move(what));
  } else if (std::holds_alternative<restore_call>(what)) {
    // an image replaces everything before it
    since_.clear();
    since_.push_back(std::move(what));
    steps_since_image_ = 0;
  } else {
    since_.push_back(std::move(what));
  }
}

void failover_component::replay(cosim::component& c, const call& what) const {
  struct visitor {
    cosim::component& c;
    void operator()(const setup_call& s) const { c.setup(s.start, s.stop); }
    void operator()(const enter_call&) const { c.enter_initialization(); }
    void operator()(const exit_call&) const { c.exit_initialization(); }
    void operator()(const set_call& s) const { c.set_values(s.refs, s.values); }
    void operator()(const expose_call& e) const { c.expose(e.inputs, e.outputs); }
    void operator()(const step_call& s) const {
      cosim::value_block ignored;
      c.step(s.t, s.dt, s.inputs, ignored);
    }
    void operator()(const restore_call& r) const { c.restore_state(r.image); }
  };
  std::visit(visitor{c}, what);
}

void failover_component::fail_over(const cosim::component_error& lost) {
  const std::string worker_before = worker_;
  std::string from = worker_;
  for (;;) {
    const std::optional<std::string> to = standby_->replacement_for(from);
    if (!to) throw cosim::component_error(std::string(lost.what()) + "; no standby worker is left");
    const auto began = std::chrono::steady_clock::now();
    try {
      std::unique_ptr<cosim::component> fresh = make_(*to);
      for (const call& c : prefix_) replay(*fresh, c);
      for (const call& c : since_) replay(*fresh, c);
      inner_ = std::move(fresh);
      worker_ = *to;
      ++generation_;
    } catch (const worker_lost&) {
      from = *to;  // the standby went too: the next one replaces it
      continue;
    } catch (const std::exception& e) {
      log_(cosim::log_level::warning, name(), "failover",
           "standby worker '" + *to + "' cannot take over: " + e.what());
      standby_->discard(*to);
      continue;
    }
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::steady_clock::now() - began);
    std::ostringstream line;
    line << "worker '" << worker_before << "' is lost";
    if (now_) line << " after t = " << cosim::format_seconds(*now_) << " s";
    const bool from_image = !since_.empty() && std::holds_alternative<restore_call>(since_.front());
    if (from != worker_before) line << " (and so is standby worker '" << from << "')";
    line << ": continues on standby worker '" << *to << "' ("
         << (from_image ? "from its last state image, " : "from the start, ") << steps_since_image_
         << " steps replayed in " << ms.count() << " ms)";
    log_(cosim::log_level::warning, name(), "failover", line.str());
    return;
  }
}

void failover_component::setup(cosim::time_point start, std::optional<cosim::time_point> stop) {
  guarded([&](cosim::component& c) { c.setup(start, stop); });
  remember(setup_call{start, stop});
}

void failover_component::enter_initialization() {
  guarded([](cosim::component& c) { c.enter_initialization(); });
  remember(enter_call{});
}

void failover_component::exit_initialization() {
  guarded([](cosim::component& c) { c.exit_initialization(); });
  remember(exit_call{});
  initialized_ = true;
}

void failover_component::terminate() {
  guarded([](cosim::component& c) { c.terminate(); });
}

void failover_component::set_values(const cosim::variable_refs& refs,
                                    const cosim::value_block& values) {
  guarded([&](cosim::component& c) { c.set_values(refs, values); });
  remember(set_call{refs, values});
}

void failover_component::get_values(const cosim::variable_refs& refs, cosim::value_block& values) {
  guarded([&](cosim::component& c) { c.get_values(refs, values); });
}

void failover_component::expose(const cosim::variable_refs& inputs,
                                const cosim::variable_refs& outputs) {
  guarded([&](cosim::component& c) { c.expose(inputs, outputs); });
  remember(expose_call{inputs, outputs});
}

cosim::step_result failover_component::step(cosim::time_point t, cosim::duration dt,
                                            const cosim::value_block& inputs,
                                            cosim::value_block& outputs) {
  const cosim::step_result result =
      guarded([&](cosim::component& c) { return c.step(t, dt, inputs, outputs); });
  record_step(t, dt, inputs);
  if (image_due()) save_state();
  return result;
}

void failover_component::record_step(cosim::time_point t, cosim::duration dt,
                                     const cosim::value_block& inputs) {
  remember(step_call{t, dt, inputs});
  now_ = t + dt;
  ++steps_since_image_;
}

void failover_component::take_image() {
  remember(restore_call{inner_->save_state()});
}

std::vector<std::byte> failover_component::save_state() {
  std::vector<std::byte> image = guarded([](cosim::component& c) { return c.save_state(); });
  if (initialized_) remember(restore_call{image});
  return image;
}

void failover_component::restore_state(std::span<const std::byte> state) {
  guarded([&](cosim::component& c) { c.restore_state(state); });
  remember(restore_call{{state.begin(), state.end()}});
}

}  // namespace stride::remote
