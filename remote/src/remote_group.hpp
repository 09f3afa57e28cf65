// Components on one worker that step together: one request per macro step carries the inputs of
// every member, one reply brings back the outputs of every member that stepped; the connections
// among them are resolved on the worker (hosted.hpp) and never travel.
#ifndef STRIDE_REMOTE_REMOTE_GROUP_HPP
#define STRIDE_REMOTE_REMOTE_GROUP_HPP

#include <memory>
#include <string>
#include <vector>

#include "client.hpp"
#include "remote_component.hpp"
#include "stride/cosim/step_group.hpp"

namespace stride::remote {

class remote_group final : public cosim::step_group {
 public:
  /// \pre the members are instances on `worker`, and outlive the group.
  remote_group(std::shared_ptr<client> link, std::string worker,
               std::vector<remote_component*> members);

  void arrange(cosim::group_layout layout) override;
  void prepare(std::span<const cosim::member_cache> members) override;
  std::optional<std::size_t> step(cosim::time_point t, std::int64_t index,
                                  std::span<const cosim::value_block* const> inputs,
                                  std::span<cosim::value_block* const> outputs) override;

 private:
  stride_remote_request request(op o);
  // sends it; a reply with an error becomes a component_error naming the group and worker
  reply_data call(stride_remote_request& r);

  std::shared_ptr<client> link_;
  dds_entity_t writer_ = 0;
  std::string worker_;
  std::string name_;  // "gait+robot": the members' names
  std::vector<remote_component*> members_;
  cosim::group_layout layout_;
  std::vector<stride_remote_group_member> wire_members_;
  std::vector<wire_storage> storage_;  // two per member: latest/inputs and published
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_REMOTE_GROUP_HPP
