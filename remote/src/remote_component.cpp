#include "remote_component.hpp"

#include "me_wire.hpp"
#include "protocol.hpp"

#include "stride/cosim/error.hpp"

namespace stride::remote {

remote_component::remote_component(
    std::shared_ptr<client> link, std::string worker, std::string name, std::string hash,
    cosim::model_description description, cosim::log_sink log, bool debug_logging,
    const std::optional<cosim::model_exchange_options>& model_exchange)
    : link_(std::move(link)),
      worker_(std::move(worker)),
      name_(std::move(name)),
      description_(std::move(description)),
      log_(log ? std::move(log) : cosim::stderr_log_sink()) {
  writer_ = link_->connect(worker_);
  stride_remote_request r = request(op::instantiate);
  r.text = hash.data();
  r.logging = debug_logging;
  const cosim::value_block settings = model_exchange_to_wire(model_exchange);
  wire_storage storage;
  put_values(settings, r.data, storage);
  call(r);
}

stride_remote_request remote_component::request(op o) const {
  stride_remote_request r{};
  r.op = static_cast<std::int32_t>(o);
  r.component = const_cast<char*>(name_.c_str());
  r.text = const_cast<char*>("");
  return r;
}

reply_data remote_component::call(stride_remote_request& r) {
  return link_->call_for("component '" + name_ + "' on worker '" + worker_ + "'", writer_, worker_,
                         r, [this](const reply_data::log_line& l) { forward_log(l); });
}

void remote_component::forward_log(const reply_data::log_line& line) const {
  log_(line.level, name_, line.category, line.message);
}

void remote_component::setup(cosim::time_point start, std::optional<cosim::time_point> stop) {
  stride_remote_request r = request(op::setup);
  r.t_ns = start.time_since_epoch().count();
  r.dt_ns = stop ? stop->time_since_epoch().count() : -1;
  call(r);
}

void remote_component::enter_initialization() {
  stride_remote_request r = request(op::enter_initialization);
  call(r);
}

void remote_component::exit_initialization() {
  stride_remote_request r = request(op::exit_initialization);
  call(r);
}

void remote_component::terminate() {
  stride_remote_request r = request(op::terminate);
  call(r);
}

void remote_component::set_values(const cosim::variable_refs& refs,
                                  const cosim::value_block& values) {
  stride_remote_request r = request(op::set_values);
  wire_storage storage;
  put_values(values, r.data, storage);
  put_refs(refs, r.more);
  call(r);
}

void remote_component::get_values(const cosim::variable_refs& refs, cosim::value_block& values) {
  stride_remote_request r = request(op::get_values);
  put_refs(refs, r.data);
  reply_data reply = call(r);
  if (!fits(reply.values, refs)) {
    throw cosim::component_error("component '" + name_ + "' on worker '" + worker_ +
                                 "': get_values: the reply does not hold the values asked for");
  }
  values = std::move(reply.values);
}

void remote_component::expose(const cosim::variable_refs& inputs,
                              const cosim::variable_refs& outputs) {
  stride_remote_request r = request(op::expose);
  put_refs(inputs, r.data);
  put_refs(outputs, r.more);
  call(r);
  outputs_ = outputs;
}

cosim::step_result remote_component::step(cosim::time_point t, cosim::duration dt,
                                          const cosim::value_block& inputs,
                                          cosim::value_block& outputs) {
  stride_remote_request r = request(op::step);
  r.t_ns = t.time_since_epoch().count();
  r.dt_ns = dt.count();
  wire_storage storage;
  put_values(inputs, r.data, storage);
  reply_data reply = call(r);
  if (reply.result == status::terminate) return cosim::step_result::terminate;
  if (!fits(reply.values, outputs_)) {
    throw cosim::component_error("component '" + name_ + "' on worker '" + worker_ +
                                 "': step: the reply does not hold the exposed outputs");
  }
  outputs = std::move(reply.values);
  return cosim::step_result::complete;
}

std::vector<std::byte> remote_component::save_state() {
  stride_remote_request r = request(op::save_state);
  return call(r).blob;
}

void remote_component::restore_state(std::span<const std::byte> state) {
  stride_remote_request r = request(op::restore_state);
  put_blob(state, r.blob);
  call(r);
}

}  // namespace stride::remote
