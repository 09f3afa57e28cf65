// Components with standby workers that share a worker still step there as one group (one request
// per macro step). The group keeps, in this process, a copy of the group's stepping engine whose
// members only record: it gives each member the inputs it stepped with on the worker (the links
// among members resolved) and the caches the group stands at. When the worker is lost, every
// member fails over as a failover_component does, replaying its own record on the standby, and
// the group is built again there and prepared with those caches (docs/failover.md).
#ifndef STRIDE_REMOTE_FAILOVER_GROUP_HPP
#define STRIDE_REMOTE_FAILOVER_GROUP_HPP

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "failover_component.hpp"
#include "stride/cosim/step_group.hpp"

namespace stride::remote {

class failover_group final : public cosim::step_group {
 public:
  /// The group of the given instances (all on `worker`) as it runs there.
  using group_factory = std::function<std::unique_ptr<cosim::step_group>(
      const std::vector<cosim::component*>& instances, const std::string& worker)>;

  /// \pre the members are on one worker and outlive the group.
  failover_group(std::vector<failover_component*> members, group_factory make,
                 std::shared_ptr<standby_pool> standby);
  ~failover_group() override;

  void arrange(cosim::group_layout layout) override;
  void prepare(std::span<const cosim::member_cache> members) override;
  std::optional<std::size_t> step(cosim::time_point t, std::int64_t index,
                                  std::span<const cosim::value_block* const> inputs,
                                  std::span<cosim::value_block* const> outputs) override;

 private:
  class recorder;

  // runs `f` on the group as it runs on the worker; when the worker is lost, the members fail
  // over and the group is built again on their standby, and `f` runs again
  template <class F>
  void guarded(F&& f);
  // the group on the worker, built again when a member has moved since
  cosim::step_group& running();
  void fail_over(const cosim::component_error& lost);
  void records_step(std::size_t member, const cosim::value_block& inputs, cosim::time_point t,
                    cosim::duration dt, cosim::value_block& outputs);

  std::vector<failover_component*> members_;
  group_factory make_;
  std::shared_ptr<standby_pool> standby_;
  cosim::group_layout layout_;
  std::unique_ptr<cosim::step_group> remote_;
  std::vector<int> generations_;  // of the members when remote_ was built
  bool prepared_ = false;
  // the record keeper: the same engine over members that only record
  std::vector<std::unique_ptr<recorder>> recorders_;
  std::unique_ptr<cosim::local_step_group> shadow_;
  std::vector<cosim::value_block> shadow_outputs_;
  std::vector<cosim::value_block*> shadow_output_ptrs_;
  // the outputs of the step on the worker, which the recorders hand to the engine
  std::span<cosim::value_block* const> stepped_;
  std::optional<std::size_t> ended_;
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_FAILOVER_GROUP_HPP
