#include "remote_group.hpp"

#include "stride/cosim/error.hpp"

namespace stride::remote {

remote_group::remote_group(std::shared_ptr<client> link, std::string worker,
                           std::vector<remote_component*> members)
    : link_(std::move(link)), worker_(std::move(worker)), members_(std::move(members)) {
  for (const auto* m : members_) name_ += (name_.empty() ? "" : "+") + m->name();
  writer_ = link_->connect(worker_);
  wire_members_.resize(members_.size());
  storage_.resize(2 * members_.size());
  for (std::size_t k = 0; k < members_.size(); ++k) {
    wire_members_[k].component = const_cast<char*>(members_[k]->name().c_str());
  }
}

stride_remote_request remote_group::request(op o) {
  stride_remote_request r{};
  r.op = static_cast<std::int32_t>(o);
  r.component = name_.data();
  r.text = const_cast<char*>("");
  r.members._length = r.members._maximum = static_cast<std::uint32_t>(wire_members_.size());
  r.members._buffer = wire_members_.data();
  r.members._release = false;
  return r;
}

reply_data remote_group::call(stride_remote_request& r) {
  return link_->call_for("step group " + name_ + " on worker '" + worker_ + "'", writer_, worker_,
                         r, [this](const reply_data::log_line& l) {
                           // a line of the group itself (a stall) goes out once
                           for (auto* m : members_) {
                             if (m->name() == l.source || (l.source.empty() && m == members_[0])) {
                               m->forward_log(l);
                             }
                           }
                         });
}

void remote_group::arrange(cosim::group_layout layout) {
  layout_ = std::move(layout);
}

void remote_group::prepare(std::span<const cosim::member_cache> members) {
  if (members.size() != members_.size()) {
    throw cosim::validation_error("step group " + name_ + ": caches for " +
                                  std::to_string(members.size()) + " members");
  }
  stride_remote_request r = request(op::group_setup);
  r.dt_ns = layout_.base_step.count();
  for (std::size_t k = 0; k < members_.size(); ++k) {
    auto& w = wire_members_[k];
    w.multiple = layout_.multiples.at(k);
    w.time_ns = members[k].time.time_since_epoch().count();
    put_values(members[k].latest, w.latest, storage_[2 * k]);
    put_values(members[k].published, w.published, storage_[2 * k + 1]);
  }
  std::vector<std::uint32_t> order(layout_.order.begin(), layout_.order.end());
  r.order._length = r.order._maximum = static_cast<std::uint32_t>(order.size());
  r.order._buffer = order.data();
  r.order._release = false;
  std::vector<stride_remote_group_link> links;
  for (const auto& l : layout_.links) {
    links.push_back({static_cast<std::uint32_t>(l.from), static_cast<std::uint32_t>(l.from_slot),
                     static_cast<std::uint32_t>(l.to), static_cast<std::uint32_t>(l.to_slot),
                     static_cast<std::int32_t>(l.type), l.previous});
  }
  r.links._length = r.links._maximum = static_cast<std::uint32_t>(links.size());
  r.links._buffer = links.data();
  r.links._release = false;
  call(r);
  for (auto& w : wire_members_) w.published = {};  // steps carry inputs only
}

std::optional<std::size_t> remote_group::step(cosim::time_point t, std::int64_t index,
                                              std::span<const cosim::value_block* const> inputs,
                                              std::span<cosim::value_block* const> outputs) {
  const std::size_t n = members_.size();
  if (inputs.size() != n || outputs.size() != n) {
    throw cosim::validation_error("step group " + name_ + ": inputs or outputs for " +
                                  std::to_string(inputs.size()) + " members");
  }
  stride_remote_request r = request(op::group_step);
  r.t_ns = t.time_since_epoch().count();
  r.dt_ns = layout_.base_step.count();
  r.index = index;
  for (std::size_t k = 0; k < n; ++k)
    put_values(*inputs[k], wire_members_[k].latest, storage_[2 * k]);
  reply_data reply = call(r);
  if (reply.outputs.size() != n || reply.ended >= static_cast<int>(n)) {
    throw cosim::component_error("step group " + name_ + " on worker '" + worker_ +
                                 "': group_step: the reply does not fit the group");
  }
  // the members that stepped, in order, up to the one that ended the run
  for (std::size_t k : layout_.order) {
    if (static_cast<int>(k) == reply.ended) return k;
    if (index % layout_.multiples[k] != 0) continue;
    if (!same_shape(reply.outputs[k], *outputs[k])) {
      throw cosim::component_error("step group " + name_ + " on worker '" + worker_ +
                                   "': group_step: the reply does not hold the outputs of '" +
                                   members_[k]->name() + "'");
    }
    *outputs[k] = std::move(reply.outputs[k]);
  }
  return std::nullopt;
}

}  // namespace stride::remote
