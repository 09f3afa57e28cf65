#include "failover_group.hpp"

#include <stdexcept>

#include "stride/cosim/error.hpp"

namespace stride::remote {

// A member of the record keeper's engine: its step records what the member stepped with on the
// worker and gives back the outputs that the worker sent. Nothing else is ever called on it.
class failover_group::recorder final : public cosim::component {
 public:
  recorder(failover_group& group, std::size_t member) : group_(group), member_(member) {}

  const std::string& name() const noexcept override { return group_.members_[member_]->name(); }
  const cosim::model_description& model_description() const noexcept override {
    return group_.members_[member_]->model_description();
  }
  cosim::step_result step(cosim::time_point t, cosim::duration dt, const cosim::value_block& in,
                          cosim::value_block& out) override {
    group_.records_step(member_, in, t, dt, out);
    return group_.ended_ == member_ ? cosim::step_result::terminate : cosim::step_result::complete;
  }

  void setup(cosim::time_point, std::optional<cosim::time_point>) override { unused(); }
  void enter_initialization() override { unused(); }
  void exit_initialization() override { unused(); }
  void terminate() override { unused(); }
  void set_values(const cosim::variable_refs&, const cosim::value_block&) override { unused(); }
  void get_values(const cosim::variable_refs&, cosim::value_block&) override { unused(); }
  void expose(const cosim::variable_refs&, const cosim::variable_refs&) override { unused(); }
  std::vector<std::byte> save_state() override {
    unused();
    return {};
  }
  void restore_state(std::span<const std::byte>) override { unused(); }

 private:
  [[noreturn]] static void unused() {
    throw std::logic_error("failover_group: a recorder only steps");
  }
  failover_group& group_;
  std::size_t member_;
};

failover_group::failover_group(std::vector<failover_component*> members, group_factory make,
                               std::shared_ptr<standby_pool> standby)
    : members_(std::move(members)), make_(std::move(make)), standby_(std::move(standby)) {
  std::vector<cosim::component*> recorders;
  for (std::size_t k = 0; k < members_.size(); ++k) {
    recorders_.push_back(std::make_unique<recorder>(*this, k));
    recorders.push_back(recorders_.back().get());
  }
  shadow_ = std::make_unique<cosim::local_step_group>(std::move(recorders));
  shadow_outputs_.resize(members_.size());
  for (auto& o : shadow_outputs_) shadow_output_ptrs_.push_back(&o);
}

failover_group::~failover_group() = default;

void failover_group::arrange(cosim::group_layout layout) {
  shadow_->arrange(layout);  // checks the layout
  layout_ = std::move(layout);
  remote_.reset();
}

void failover_group::prepare(std::span<const cosim::member_cache> members) {
  shadow_->prepare(members);
  guarded([&](cosim::step_group& g) { g.prepare(members); });
  prepared_ = true;  // a group built again from now on is prepared with the record's caches
}

std::optional<std::size_t> failover_group::step(cosim::time_point t, std::int64_t index,
                                                std::span<const cosim::value_block* const> inputs,
                                                std::span<cosim::value_block* const> outputs) {
  guarded([&](cosim::step_group& g) { ended_ = g.step(t, index, inputs, outputs); });
  // the same step again, recorded: each member's inputs as the worker's engine gave them
  stepped_ = outputs;
  const std::optional<std::size_t> shadow_ended =
      shadow_->step(t, index, inputs, shadow_output_ptrs_);
  if (shadow_ended != ended_) {
    throw cosim::component_error("step group: the record of the step does not match the worker's");
  }
  for (auto* m : members_) {
    if (m->image_due()) {
      guarded([&](cosim::step_group&) { m->take_image(); });
    }
  }
  return ended_;
}

void failover_group::records_step(std::size_t member, const cosim::value_block& inputs,
                                  cosim::time_point t, cosim::duration dt,
                                  cosim::value_block& outputs) {
  members_[member]->record_step(t, dt, inputs);
  outputs = *stepped_[member];
}

template <class F>
void failover_group::guarded(F&& f) {
  for (;;) {
    try {
      f(running());
      return;
    } catch (const worker_lost& lost) {
      fail_over(lost);
    }
  }
}

cosim::step_group& failover_group::running() {
  bool moved = !remote_;
  for (std::size_t k = 0; k < members_.size() && !moved; ++k) {
    moved = members_[k]->generation() != generations_[k];
  }
  if (!moved) return *remote_;
  // a member may have failed over alone (a call of the algorithm's own): the others follow it
  for (auto* m : members_) {
    while (standby_->replaced_by(m->worker())) {
      m->move_to_standby(
          worker_lost("worker '" + m->worker() + "' is lost (another member of its group saw it)"));
    }
  }
  const std::string& worker = members_.front()->worker();
  std::vector<cosim::component*> instances;
  generations_.clear();
  for (auto* m : members_) {
    if (m->worker() != worker) {
      throw cosim::component_error("step group: its members are on workers '" + worker + "' and '" +
                                   m->worker() + "' after a failover");
    }
    instances.push_back(&m->instance());
    generations_.push_back(m->generation());
  }
  remote_ = make_(instances, worker);
  remote_->arrange(layout_);
  if (prepared_) remote_->prepare(shadow_->caches());
  return *remote_;
}

void failover_group::fail_over(const cosim::component_error& lost) {
  remote_.reset();  // refers to the instances that go
  for (auto* m : members_) m->move_to_standby(lost);
}

}  // namespace stride::remote
