// What a worker hosts for a run: component instances, and step groups of them that step
// together with one request per macro step.
#ifndef STRIDE_REMOTE_HOSTED_HPP
#define STRIDE_REMOTE_HOSTED_HPP

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "protocol.hpp"
#include "stride/cosim/component.hpp"
#include "stride/cosim/step_group.hpp"

namespace stride::remote {

/// One component instance and what its steps exchange.
struct hosted_instance {
  std::unique_ptr<cosim::component> component;
  cosim::variable_refs inputs;   ///< exposed
  cosim::variable_refs outputs;  ///< exposed
  cosim::value_block in;
  cosim::value_block out;
};

/// A step group of instances of one run, stepped by a local step group.
class hosted_group {
 public:
  using finder = std::function<hosted_instance&(const std::string& name)>;
  /// From a group_setup request. \throws std::runtime_error (or cosim errors) for members that
  /// do not exist or values that do not fit their exposed variables.
  hosted_group(const stride_remote_request& setup, const finder& find);

  /// Serves a group_step request: fills `reply`'s outputs and ended, which point into this
  /// group until the next step.
  void step(const stride_remote_request& r, stride_remote_reply& reply);

  /// Whether `name` is a member.
  bool has_member(const std::string& name) const;

 private:
  std::vector<std::string> names_;
  std::vector<hosted_instance*> members_;
  std::unique_ptr<cosim::local_step_group> group_;
  std::vector<cosim::value_block> inputs_;
  std::vector<cosim::value_block> outputs_;
  std::vector<const cosim::value_block*> input_ptrs_;
  std::vector<cosim::value_block*> output_ptrs_;
  std::vector<stride_remote_values> wire_outputs_;
  std::vector<wire_storage> storage_;
};

}  // namespace stride::remote

#endif  // STRIDE_REMOTE_HOSTED_HPP
