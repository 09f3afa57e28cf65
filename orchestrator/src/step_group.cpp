// The stepping engine of a group of components in one process.
#include "stride/cosim/step_group.hpp"

#include "stride/cosim/error.hpp"
#include "value_lanes.hpp"

namespace stride::cosim {

using detail::lane;

local_step_group::local_step_group(std::vector<component*> members) : members_(std::move(members)) {
  for (const component* c : members_) {
    if (c == nullptr) throw validation_error("local_step_group: null member");
  }
}

void local_step_group::arrange(group_layout layout) {
  const std::size_t n = members_.size();
  if (layout.order.size() != n || layout.multiples.size() != n) {
    throw validation_error("step group: the layout has " + std::to_string(layout.order.size()) +
                           " members, the group " + std::to_string(n));
  }
  std::vector<bool> seen(n, false);
  for (std::size_t m : layout.order) {
    if (m >= n || seen[m]) throw validation_error("step group: the order is not a permutation");
    seen[m] = true;
  }
  for (const int multiple : layout.multiples) {
    if (multiple < 1) throw validation_error("step group: a step multiple is below 1");
  }
  if (layout.base_step <= duration::zero()) {
    throw validation_error("step group: the base step must be positive");
  }
  for (const auto& l : layout.links) {
    if (l.from >= n || l.to >= n) throw validation_error("step group: a link names no member");
  }
  layout_ = std::move(layout);
  steps_now_.assign(n, false);
  scratch_.assign(n, {});
}

void local_step_group::prepare(std::span<const member_cache> members) {
  if (members.size() != members_.size()) {
    throw validation_error("step group: " + std::to_string(members.size()) + " caches for " +
                           std::to_string(members_.size()) + " members");
  }
  caches_.assign(members.begin(), members.end());
  // a link must fit the exposed variables the caches and inputs are laid out by
  for (const auto& l : layout_.links) {
    std::size_t outputs = 0;
    detail::with_type(l.type, [&]<class T>() { outputs = lane<T>(caches_[l.from].latest).size(); });
    if (l.from_slot >= outputs) {
      throw validation_error("step group: a link reads output slot " + std::to_string(l.from_slot) +
                             " of '" + members_[l.from]->name() + "', which exposes " +
                             std::to_string(outputs));
    }
  }
}

std::optional<std::size_t> local_step_group::step(time_point t, std::int64_t index,
                                                  std::span<const value_block* const> inputs,
                                                  std::span<value_block* const> outputs) {
  const std::size_t n = members_.size();
  if (caches_.size() != n) throw validation_error("step group: step() before prepare()");
  if (inputs.size() != n || outputs.size() != n) {
    throw validation_error("step group: inputs or outputs for " + std::to_string(inputs.size()) +
                           " members, the group has " + std::to_string(n));
  }
  const time_point next = t + layout_.base_step;
  for (std::size_t m = 0; m < n; ++m) {
    steps_now_[m] = index % layout_.multiples[m] == 0;
    if (steps_now_[m]) caches_[m].published = caches_[m].latest;
  }
  for (std::size_t m : layout_.order) {
    if (!steps_now_[m]) continue;
    value_block& in = scratch_[m];
    in = *inputs[m];
    for (const auto& l : layout_.links) {
      if (l.to != m) continue;
      const member_cache& source = caches_[l.from];
      const bool published = detail::reads_published(l.previous, steps_now_[l.from], source.time,
                                                     l.previous ? t : next);
      detail::with_type(l.type, [&]<class T>() {
        auto& slots = lane<T>(in);
        if (l.to_slot >= slots.size()) {
          throw validation_error("step group: a link writes input slot " +
                                 std::to_string(l.to_slot) + " of '" + members_[m]->name() +
                                 "', which has " + std::to_string(slots.size()));
        }
        slots[l.to_slot] = lane<T>(published ? source.published : source.latest)[l.from_slot];
      });
    }
    const duration dt = layout_.base_step * layout_.multiples[m];
    step_result result = step_result::complete;
    try {
      result = members_[m]->step(caches_[m].time, dt, in, caches_[m].latest);
    } catch (const component_error&) {
      throw;
    } catch (const std::exception& e) {
      throw component_error("component '" + members_[m]->name() + "': " + e.what());
    }
    if (result == step_result::terminate) return m;
    caches_[m].time += dt;
    *outputs[m] = caches_[m].latest;
  }
  return std::nullopt;
}

}  // namespace stride::cosim
