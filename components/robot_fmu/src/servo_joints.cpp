// Servo IDs by joint name and servo models by joint name.
#include "servo_joints.hpp"

#include <string>

#include "config_check.hpp"

namespace stride::robot {

namespace {

int find_joint(const robot_model& model, const std::string& name) {
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (model.joints[j].name == name) return static_cast<int>(j);
  }
  return -1;
}

}  // namespace

void assign_servo_joints(robot_model& model, const robot_config& config) {
  if (config.servo_joints.empty()) return;
  std::vector<int> id_of_joint(model.joints.size(), 0);
  for (std::size_t i = 0; i < config.servo_joints.size(); ++i) {
    const std::string& name = config.servo_joints[i];
    // fixed joints are merged away by the loader, so they are not found either
    const int j = find_joint(model, name);
    require(j >= 0, "servo_joints",
            "joint '" + name + "' is not a movable joint of " + config.urdf_path);
    int& id = id_of_joint[static_cast<std::size_t>(j)];
    require(id == 0, "servo_joints", "joint '" + name + "' is listed twice");
    id = static_cast<int>(i) + 1;
  }
  for (std::size_t j = 0; j < model.joints.size(); ++j) model.joints[j].servo_id = id_of_joint[j];
}

void check_joint_servos(const robot_model& model, const robot_config& config) {
  for (const auto& [name, servo] : config.joint_servos) {
    const int j = find_joint(model, name);
    require(j >= 0 && model.joints[static_cast<std::size_t>(j)].servo_id > 0, "joint_servos",
            "joint '" + name + "' is not a servo joint of " + config.urdf_path);
  }
}

std::vector<servo_config> servo_models(const robot_model& model, const robot_config& config) {
  std::vector<servo_config> models(model.joints.size(), config.servo);
  for (const auto& [name, servo] : config.joint_servos) {
    const int j = find_joint(model, name);
    // joints welded by rigid_servos are no longer in the model
    if (j >= 0) models[static_cast<std::size_t>(j)] = servo;
  }
  return models;
}

}  // namespace stride::robot
