// A plant profile applied to a robot model: which joints are servos, in which order, with which
// servo model, and every setting the plant needs (docs/plant-profile.md).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "stride/common/text.hpp"
#include "stride/robot/plant_profile.hpp"

namespace stride::robot {

namespace {

[[noreturn]] void fail(const plant_profile& p, const std::string& what) {
  throw model_error(p.source + ": " + what);
}

bool matches_any(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(),
                     [&](const std::string& p) { return text::glob_match(p, name); });
}

// fills the attributes `rule` sets
void apply_rule(const servo_rule& rule, servo_config& s) {
  const std::pair<double, double*> fields[] = {{rule.values.p_gain, &s.p_gain},
                                               {rule.values.max_velocity, &s.max_velocity},
                                               {rule.values.max_acceleration, &s.max_acceleration},
                                               {rule.values.torque_limit, &s.torque_limit},
                                               {rule.values.damping, &s.damping},
                                               {rule.values.static_friction, &s.static_friction},
                                               {rule.values.compliance, &s.compliance}};
  for (auto [value, field] : fields) {
    if (!std::isnan(value)) *field = value;
  }
  if (rule.clamp_set) s.clamp_to_limits = rule.values.clamp_to_limits;
}

bool same_servo(const servo_config& a, const servo_config& b) {
  return a.p_gain == b.p_gain && a.max_velocity == b.max_velocity &&
         a.max_acceleration == b.max_acceleration && a.torque_limit == b.torque_limit &&
         a.compliance == b.compliance && a.damping == b.damping &&
         a.static_friction == b.static_friction && a.clamp_to_limits == b.clamp_to_limits;
}

void require_link(const plant_profile& p, const robot_model& m, const std::string& link,
                  const std::string& what) {
  if (m.find_link(link) < 0) fail(p, what + ": the model has no link '" + link + "'");
}

std::vector<int> actuated_joints(const plant_profile& p, const robot_model& m) {
  for (const std::string& pattern : p.passive) {
    const bool used = std::any_of(m.joints.begin(), m.joints.end(), [&](const model_joint& j) {
      return text::glob_match(pattern, j.name);
    });
    if (!used) fail(p, "<joints passive>: '" + pattern + "' matches no joint of " + m.source);
  }
  std::vector<int> out;
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    // a mimic joint follows its master and is never a servo
    if (m.joints[j].mimic_joint >= 0 || matches_any(p.passive, m.joints[j].name)) continue;
    out.push_back(static_cast<int>(j));
  }
  if (p.joint_order == "servo_id") {
    for (int j : out) {
      if (m.joints[static_cast<std::size_t>(j)].servo_id == 0) {
        fail(p, "<joints order=\"servo_id\">: joint '" +
                    m.joints[static_cast<std::size_t>(j)].name + "' has no <servo id> in " +
                    m.source + " (mark it passive or order by urdf)");
      }
    }
    std::sort(out.begin(), out.end(), [&](int a, int b) {
      return m.joints[static_cast<std::size_t>(a)].servo_id <
             m.joints[static_cast<std::size_t>(b)].servo_id;
    });
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (m.joints[static_cast<std::size_t>(out[i])].servo_id != static_cast<int>(i) + 1) {
        fail(p, "<joints order=\"servo_id\">: the servo IDs of " + m.source + " must number 1.." +
                    std::to_string(out.size()));
      }
    }
  }
  return out;
}

}  // namespace

resolved_plant resolve_plant(const plant_profile& p, const robot_model& m, std::string_view preset,
                             std::span<const double> overrides, std::span<const bool> welds_on) {
  resolved_plant r;
  robot_config& c = r.config;
  const std::span<const plant_setting> settings = plant_settings();

  // layers: the file, then its preset
  std::vector<const profile_layer*> layers = {&p.base};
  const std::string chosen = preset.empty() ? p.default_preset : std::string(preset);
  if (!chosen.empty()) {
    const auto it = std::find_if(p.presets.begin(), p.presets.end(),
                                 [&](const profile_preset& x) { return x.name == chosen; });
    if (it == p.presets.end()) {
      std::string names;
      for (const auto& x : p.presets) names += (names.empty() ? "" : ", ") + x.name;
      fail(p, "no preset '" + chosen + "'" + (names.empty() ? "" : " (presets: " + names + ")"));
    }
    layers.push_back(&it->layer);
  }
  std::vector<bool> given(settings.size(), false);
  for (const profile_layer* layer : layers) {
    for (std::size_t i = 0; i < settings.size(); ++i) {
      if (std::isnan(layer->settings[i])) continue;
      settings[i].field(c) = layer->settings[i];
      given[i] = true;
    }
  }

  // servos: joint order, then the rules in file order (the preset's last)
  r.actuated = actuated_joints(p, m);
  const servo_config defaults = c.servo;
  std::vector<servo_config> per_joint(r.actuated.size(), defaults);
  bool any_rule = false;
  for (const profile_layer* layer : layers) {
    for (const servo_rule& rule : layer->servos) {
      any_rule = true;
      for (const std::string& pattern : rule.patterns) {
        bool used = false;
        for (std::size_t k = 0; k < r.actuated.size(); ++k) {
          const std::string& name = m.joints[static_cast<std::size_t>(r.actuated[k])].name;
          if (!text::glob_match(pattern, name)) continue;
          used = true;
          apply_rule(servo_rule{{}, rule.values, rule.clamp_set, rule.line}, per_joint[k]);
        }
        if (!used) {
          fail(p, "line " + std::to_string(rule.line) + ": <servo joints> '" + pattern +
                      "' matches no servo joint of " + m.source);
        }
      }
    }
  }
  if (!any_rule && !r.actuated.empty()) {
    std::ostringstream w;
    w << "no <servo> rule: every servo joint guessed as Webots' position servo (P "
      << defaults.p_gain << " 1/s, " << defaults.max_velocity << " rad/s, " << defaults.torque_limit
      << " N.m)";
    r.warnings.push_back(w.str());
  }
  // explicitly set FMU parameters win, for every servo
  for (std::size_t i = 0; i < settings.size() && i < overrides.size(); ++i) {
    if (std::isnan(overrides[i])) continue;
    settings[i].field(c) = overrides[i];
    given[i] = true;
    if (std::string_view(settings[i].profile_name).starts_with("servo.")) {
      for (servo_config& s : per_joint) {
        robot_config one;  // the setting's field, reached through a config holding this servo
        one.servo = s;
        settings[i].field(one) = overrides[i];
        s = one.servo;
      }
    }
  }
  for (std::size_t k = 0; k < r.actuated.size(); ++k) {
    c.servo_joints.push_back(m.joints[static_cast<std::size_t>(r.actuated[k])].name);
  }
  if (!per_joint.empty()) {
    c.servo = per_joint.front();
    const bool uniform =
        std::all_of(per_joint.begin(), per_joint.end(),
                    [&](const servo_config& s) { return same_servo(s, per_joint.front()); });
    if (!uniform) {
      for (std::size_t k = 0; k < per_joint.size(); ++k) {
        c.joint_servos.emplace_back(c.servo_joints[k], per_joint[k]);
      }
    }
  }

  // initial pose by joint pattern; later entries win
  c.initial_pose.assign(r.actuated.size(), 0.0);
  for (const auto& [pattern, value] : p.pose) {
    bool used = false;
    for (std::size_t k = 0; k < r.actuated.size(); ++k) {
      if (!text::glob_match(pattern, c.servo_joints[k])) continue;
      c.initial_pose[k] = value;
      used = true;
    }
    if (!used) fail(p, "<pose joints> '" + pattern + "' matches no servo joint of " + m.source);
  }
  for (std::size_t k = 0; k < r.actuated.size(); ++k) {
    const model_joint& j = m.joints[static_cast<std::size_t>(r.actuated[k])];
    if (j.limited && (c.initial_pose[k] < j.lower || c.initial_pose[k] > j.upper)) {
      fail(p, "initial pose of joint '" + j.name + "' (" + std::to_string(c.initial_pose[k]) +
                  ") is outside its URDF limits [" + std::to_string(j.lower) + ", " +
                  std::to_string(j.upper) + "]: give it a <pose>");
    }
  }

  // welds: by servo ID (position in the arrays + 1)
  for (std::size_t g = 0; g < p.welds.size(); ++g) {
    std::vector<int> ids;
    for (const std::string& pattern : p.welds[g].patterns) {
      bool used = false;
      for (std::size_t k = 0; k < r.actuated.size(); ++k) {
        if (!text::glob_match(pattern, c.servo_joints[k])) continue;
        ids.push_back(static_cast<int>(k) + 1);
        used = true;
      }
      if (!used) fail(p, "<weld joints> '" + pattern + "' matches no servo joint of " + m.source);
    }
    const bool on = g < welds_on.size() ? welds_on[g] : true;
    if (on) c.rigid_servos.insert(c.rigid_servos.end(), ids.begin(), ids.end());
    r.weld_joints.push_back(std::move(ids));
  }

  // links
  if (p.imu_link.empty()) {
    r.warnings.push_back("no <imu link>: the IMU sits on the root link");
  } else {
    require_link(p, m, p.imu_link, "<imu>");
    c.imu_link = p.imu_link;
  }
  if (!p.left_foot.empty()) {
    require_link(p, m, p.left_foot, "<feet left>");
    require_link(p, m, p.right_foot, "<feet right>");
    c.left_foot_link = p.left_foot;
    c.right_foot_link = p.right_foot;
  }
  for (const contact_output& f : p.contact_forces) {
    require_link(p, m, f.link, "<contact_force name=\"" + f.name + "\">");
    c.contact_links.push_back(f.link);
  }
  const auto guessed = [&](const char* name) {
    for (std::size_t i = 0; i < settings.size(); ++i) {
      if (std::string_view(settings[i].profile_name) != name || given[i]) continue;
      std::ostringstream w;
      w << "no " << name << ": " << settings[i].field(c) << " " << settings[i].unit << " guessed";
      r.warnings.push_back(w.str());
    }
  };
  guessed("physics.step");
  if (!m.fixed_base) {
    guessed("fall.tilt");
    guessed("fall.height");
  }
  return r;
}

}  // namespace stride::robot
