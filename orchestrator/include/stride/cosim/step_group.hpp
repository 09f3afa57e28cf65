// Components that step together as one unit where they run (e.g. several components on one
// worker process): the master algorithm hands over the inputs of all members at once and gets
// all their outputs back, and the connections among the members are resolved by the group, so
// they never travel to the algorithm and back within a step.
#ifndef STRIDE_COSIM_STEP_GROUP_HPP
#define STRIDE_COSIM_STEP_GROUP_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "stride/cosim/component.hpp"
#include "stride/cosim/time.hpp"

namespace stride::cosim {

/// A connection between two members, resolved inside the group. Slots are positions in the
/// lane of `type` of the members' exposed outputs (source) and exposed inputs (target).
struct group_link {
  std::size_t from = 0;  ///< source member (position in the group's member list)
  std::size_t from_slot = 0;
  std::size_t to = 0;  ///< target member
  std::size_t to_slot = 0;
  variable_type type = variable_type::real;  ///< exchange type
  bool previous = false;  ///< reads the previous communication point (delay, Jacobi)
};

/// How the members step: fixed by the algorithm before initialization.
struct group_layout {
  std::vector<std::size_t> order;  ///< member positions in stepping order
  std::vector<int> multiples;      ///< per member: steps every `multiple` base steps
  duration base_step{};
  std::vector<group_link> links;
};

/// Where a member stands between two macro steps.
struct member_cache {
  time_point time{};
  value_block latest;     ///< exposed outputs at `time`
  value_block published;  ///< exposed outputs at the previous communication point
};

/// The unit a master algorithm steps in place of several components.
///
/// The members are initialized one by one like any component (their own setup, expose,
/// initialization); then the algorithm calls arrange() (once), prepare() (after initialization
/// and after every restore) and step() once per macro step. A member reads exactly the values it
/// would read stepping alone, so grouping never changes a result.
class step_group {
 public:
  virtual ~step_group() = default;
  /// Fixes the stepping order, step multiples and internal links.
  virtual void arrange(group_layout layout) = 0;
  /// Sets every member's time and cached outputs.
  virtual void prepare(std::span<const member_cache> members) = 0;
  /// The macro step from `t`, the `index`-th of the run: each member with index % multiple == 0
  /// steps, in order, with its exposed inputs taken from `inputs[m]` except the slots fed by
  /// links; its exposed outputs afterwards go to `outputs[m]`. Returns the member that asked to
  /// end the simulation (the members after it in order did not step), if any.
  /// \throws component_error naming the member.
  virtual std::optional<std::size_t> step(time_point t, std::int64_t index,
                                          std::span<const value_block* const> inputs,
                                          std::span<value_block* const> outputs) = 0;
};

/// A group of components in this process: the stepping engine behind any group (a worker runs
/// one for the members it hosts).
class local_step_group final : public step_group {
 public:
  /// \pre every member outlives the group.
  explicit local_step_group(std::vector<component*> members);
  void arrange(group_layout layout) override;
  void prepare(std::span<const member_cache> members) override;
  std::optional<std::size_t> step(time_point t, std::int64_t index,
                                  std::span<const value_block* const> inputs,
                                  std::span<value_block* const> outputs) override;
  /// Where each member stands now (after prepare() and every step).
  std::span<const member_cache> caches() const noexcept { return caches_; }

 private:
  std::vector<component*> members_;
  group_layout layout_;
  std::vector<member_cache> caches_;
  std::vector<bool> steps_now_;
  std::vector<value_block> scratch_;  // per member: its inputs with the links applied
};

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_STEP_GROUP_HPP
