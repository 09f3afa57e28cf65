#include "hosted.hpp"

#include <algorithm>
#include <stdexcept>

namespace stride::remote {

hosted_group::hosted_group(const stride_remote_request& setup, const finder& find) {
  const std::size_t n = setup.members._length;
  if (n < 2) throw std::runtime_error("a step group needs at least two members");
  std::vector<cosim::component*> parts;
  std::vector<cosim::member_cache> caches(n);
  cosim::group_layout layout;
  for (std::size_t k = 0; k < n; ++k) {
    const stride_remote_group_member& m = setup.members._buffer[k];
    names_.emplace_back(m.component != nullptr ? m.component : "");
    hosted_instance& i = find(names_.back());
    members_.push_back(&i);
    parts.push_back(i.component.get());
    layout.multiples.push_back(m.multiple);
    caches[k].time = cosim::time_point(cosim::duration(m.time_ns));
    get_values(m.latest, i.outputs, caches[k].latest);
    get_values(m.published, i.outputs, caches[k].published);
  }
  layout.order.assign(setup.order._buffer, setup.order._buffer + setup.order._length);
  layout.base_step = cosim::duration(setup.dt_ns);
  for (std::uint32_t k = 0; k < setup.links._length; ++k) {
    const stride_remote_group_link& l = setup.links._buffer[k];
    const auto type = static_cast<cosim::variable_type>(l.type);
    if (type != cosim::exchange_type(type)) throw std::runtime_error("a link has no exchange type");
    layout.links.push_back({l.from, l.from_slot, l.to, l.to_slot, type, l.previous});
  }
  group_ = std::make_unique<cosim::local_step_group>(std::move(parts));
  group_->arrange(std::move(layout));
  group_->prepare(caches);
  inputs_.resize(n);
  outputs_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    input_ptrs_.push_back(&inputs_[k]);
    output_ptrs_.push_back(&outputs_[k]);
  }
  wire_outputs_.resize(n);
  storage_.resize(n);
}

void hosted_group::step(const stride_remote_request& r, stride_remote_reply& reply) {
  const std::size_t n = members_.size();
  if (r.members._length != n) {
    throw std::runtime_error("group step with " + std::to_string(r.members._length) +
                             " members for a group of " + std::to_string(n));
  }
  for (std::size_t k = 0; k < n; ++k) {
    get_values(r.members._buffer[k].latest, members_[k]->inputs, inputs_[k]);
    outputs_[k] = {};  // only the members that step send values back
  }
  const auto ended =
      group_->step(cosim::time_point(cosim::duration(r.t_ns)), r.index, input_ptrs_, output_ptrs_);
  for (std::size_t k = 0; k < n; ++k) {
    wire_outputs_[k] = {};
    put_values(outputs_[k], wire_outputs_[k], storage_[k]);
  }
  reply.outputs._length = reply.outputs._maximum = static_cast<std::uint32_t>(n);
  reply.outputs._buffer = wire_outputs_.data();
  reply.outputs._release = false;
  reply.ended = ended ? static_cast<std::int32_t>(*ended) : -1;
}

bool hosted_group::has_member(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

}  // namespace stride::remote
