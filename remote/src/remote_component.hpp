// A component that runs on a worker: every call of the component interface becomes one request
// and one reply, a communication step included (all inputs out, all outputs back).
#ifndef STRIDE_REMOTE_REMOTE_COMPONENT_HPP
#define STRIDE_REMOTE_REMOTE_COMPONENT_HPP

#include <memory>
#include <optional>
#include <string>

#include "client.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/log.hpp"
#include "stride/cosim/model_exchange.hpp"

namespace stride::remote {

class remote_component final : public cosim::component {
 public:
  /// Instantiates `name` on `worker` from the FMU with `hash`, which the worker has loaded, as
  /// Model Exchange with `model_exchange` when set, else as Co-Simulation. Messages the
  /// instance logs go to `log` (default: stderr) with its name as the source.
  remote_component(std::shared_ptr<client> link, std::string worker, std::string name,
                   std::string hash, cosim::model_description description, cosim::log_sink log,
                   bool debug_logging,
                   const std::optional<cosim::model_exchange_options>& model_exchange);

  const std::string& name() const noexcept override { return name_; }
  const std::string& worker() const noexcept { return worker_; }
  const cosim::model_description& model_description() const noexcept override {
    return description_;
  }

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

  /// Passes a line the instance logged on the worker to this side's log.
  void forward_log(const reply_data::log_line& line) const;

 private:
  // a request for this instance, strings set
  stride_remote_request request(op o) const;
  // sends it; a reply with an error becomes a component_error naming worker and component
  reply_data call(stride_remote_request& r);

  std::shared_ptr<client> link_;
  dds_entity_t writer_ = 0;
  std::string worker_;
  std::string name_;
  cosim::model_description description_;
  cosim::variable_refs outputs_;
  cosim::log_sink log_;
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REMOTE_COMPONENT_HPP
