// A component on a worker that outlives the worker: it keeps a state image of the instance every
// N steps and a record of the calls since, and when the worker is lost it re-creates the instance
// on a standby worker, restores the image, replays the record and redoes the call that failed.
// Every component is deterministic, so the run goes on exactly as it would have (docs/failover.md).
#ifndef STRIDE_REMOTE_FAILOVER_COMPONENT_HPP
#define STRIDE_REMOTE_FAILOVER_COMPONENT_HPP

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "client.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/log.hpp"

namespace stride::remote {

/// The standby workers of a run, shared by its failover components. The components of one lost
/// worker all move to the same standby.
class standby_pool {
 public:
  explicit standby_pool(std::vector<std::string> workers) : workers_(std::move(workers)) {}
  /// The worker that replaces `lost`: the one already chosen for it, else the next unused
  /// standby; nullopt when none is left.
  std::optional<std::string> replacement_for(const std::string& lost);
  /// The worker chosen to replace `worker` if it was lost, else nullopt.
  std::optional<std::string> replaced_by(const std::string& worker) const;
  /// `worker` cannot be used (it did not answer): later calls skip it.
  void discard(const std::string& worker);
  /// Failovers so far (each lost worker counts once).
  long failovers() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> workers_;
  std::size_t next_ = 0;
  std::map<std::string, std::string> replaced_;  // lost worker → its replacement
};

class failover_component final : public cosim::component {
 public:
  /// Makes a fresh instance of this component on the named worker (archive shipped as needed).
  /// Its calls throw worker_lost when the worker is gone.
  using factory = std::function<std::unique_ptr<cosim::component>(const std::string& worker)>;

  /// Instantiates the component on `worker` or, should that worker be lost meanwhile, on the next
  /// standby. \throws cosim::component_error when no standby is left.
  static std::unique_ptr<failover_component> start(const std::string& worker, factory make,
                                                   std::shared_ptr<standby_pool> standby,
                                                   int snapshot_every, cosim::log_sink log);

  /// `first` runs on `worker`; `snapshot_every` > 0: a state image after every that many steps.
  failover_component(std::unique_ptr<cosim::component> first, std::string worker, factory make,
                     std::shared_ptr<standby_pool> standby, int snapshot_every,
                     cosim::log_sink log);

  const std::string& name() const noexcept override { return inner_->name(); }
  const cosim::model_description& model_description() const noexcept override {
    return inner_->model_description();
  }
  /// The worker the instance is on now.
  const std::string& worker() const noexcept { return worker_; }

  void setup(cosim::time_point start, std::optional<cosim::time_point> stop) override;
  void enter_initialization() override;
  void exit_initialization() override;
  void terminate() override;
  void set_values(const cosim::variable_refs& refs, const cosim::value_block& values) override;
  void get_values(const cosim::variable_refs& refs, cosim::value_block& values) override;
  void expose(const cosim::variable_refs& inputs, const cosim::variable_refs& outputs) override;
  cosim::step_result step(cosim::time_point t, cosim::duration dt, const cosim::value_block& inputs,
                          cosim::value_block& outputs) override;
  std::vector<std::byte> save_state() override;
  void restore_state(std::span<const std::byte> state) override;

  // For a failover_group, which steps its members' instances on their worker as one unit.
  /// The instance on the current worker.
  cosim::component& instance() noexcept { return *inner_; }
  /// Counts the instances made so far: it changes whenever this component fails over.
  int generation() const noexcept { return generation_; }
  /// Records a step the group made the instance take, with the inputs it stepped with.
  void record_step(cosim::time_point t, cosim::duration dt, const cosim::value_block& inputs);
  /// Whether a state image is due after the steps recorded.
  bool image_due() const noexcept { return steps_since_image_ >= snapshot_every_; }
  /// Takes the state image that is due. \throws worker_lost: the group fails over, not this.
  void take_image();
  /// Fails over as after a lost call: the instance moves to the standby that replaces its worker.
  void move_to_standby(const cosim::component_error& lost) { fail_over(lost); }

 private:
  struct setup_call {
    cosim::time_point start;
    std::optional<cosim::time_point> stop;
  };
  struct enter_call {};
  struct exit_call {};
  struct set_call {
    cosim::variable_refs refs;
    cosim::value_block values;
  };
  struct expose_call {
    cosim::variable_refs inputs, outputs;
  };
  struct step_call {
    cosim::time_point t;
    cosim::duration dt;
    cosim::value_block inputs;
  };
  struct restore_call {
    std::vector<std::byte> image;
  };
  using call = std::variant<setup_call, enter_call, exit_call, set_call, expose_call, step_call,
                            restore_call>;

  // runs `f` on the instance; when its worker is lost, fails over and runs it again
  template <class F>
  auto guarded(F&& f) -> decltype(f(std::declval<cosim::component&>()));
  // brings an instance on a standby to where the lost one was; throws `lost` when no standby
  // is left or none can take it
  void fail_over(const cosim::component_error& lost);
  void replay(cosim::component& c, const call& what) const;
  void remember(call what);

  std::unique_ptr<cosim::component> inner_;
  std::string worker_;
  factory make_;
  std::shared_ptr<standby_pool> standby_;
  int snapshot_every_;
  cosim::log_sink log_;
  std::vector<call> prefix_;  // up to the end of initialization: reaches the first step
  std::vector<call> since_;   // after prefix_: the last image (a restore_call first) and on
  int steps_since_image_ = 0;
  int generation_ = 0;
  bool initialized_ = false;
  std::optional<cosim::time_point> now_;  // after the last step, for the log line
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_FAILOVER_COMPONENT_HPP
