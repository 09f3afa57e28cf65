// Reading plant profile files (docs/plant-profile.md). Every element and attribute is known;
// anything else is an error naming the file and line, so a typo never passes silently.
#include "stride/robot/plant_profile.hpp"

#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace stride::robot {

namespace {

constexpr double k_unset = std::numeric_limits<double>::quiet_NaN();

// clang-format off
constexpr plant_setting k_settings[] = {
    {"physics.step", "physics_step", [](robot_config& c) -> double& { return c.physics_step; },
     "s", 1e-4, 0.05, "Internal physics step; each doStep runs the whole steps that fit"},
    {"physics.erp", "erp", [](robot_config& c) -> double& { return c.erp; }, "", 0, 1,
     "World error reduction"},
    {"physics.cfm", "cfm", [](robot_config& c) -> double& { return c.cfm; }, "", 0, 1,
     "World constraint force mixing"},
    {"contact.friction", "friction", [](robot_config& c) -> double& { return c.contact.mu; }, "",
     0, 1e3, "Coulomb friction coefficient of contacts"},
    {"contact.bounce", "bounce", [](robot_config& c) -> double& { return c.contact.bounce; }, "",
     0, 1, "Contact restitution"},
    {"contact.soft_erp", "contact_soft_erp",
     [](robot_config& c) -> double& { return c.contact.soft_erp; }, "", 0, 1,
     "Contact softness: error reduction"},
    {"contact.soft_cfm", "contact_soft_cfm",
     [](robot_config& c) -> double& { return c.contact.soft_cfm; }, "", 0, 1,
     "Contact softness: constraint force mixing"},
    {"servo.p_gain", "servo_p_gain", [](robot_config& c) -> double& { return c.servo.p_gain; },
     "1/s", 0, 1e4, "Velocity target = gain * position error (every servo)"},
    {"servo.max_velocity", "servo_max_velocity",
     [](robot_config& c) -> double& { return c.servo.max_velocity; }, "rad/s", 0, 1e3,
     "Servo speed limit (every servo)"},
    {"servo.max_acceleration", "servo_max_acceleration",
     [](robot_config& c) -> double& { return c.servo.max_acceleration; }, "rad/s2", 0, 1e6,
     "Servo acceleration limit, 0: none (every servo)"},
    {"servo.torque_limit", "servo_torque_limit",
     [](robot_config& c) -> double& { return c.servo.torque_limit; }, "N.m", 0, 1e3,
     "Servo torque limit (every servo)"},
    {"servo.damping", "servo_damping", [](robot_config& c) -> double& { return c.servo.damping; },
     "N.m.s/rad", 0, 1e3, "Joint viscous damping (every servo)"},
    {"servo.static_friction", "servo_static_friction",
     [](robot_config& c) -> double& { return c.servo.static_friction; }, "N.m", 0, 1e3,
     "Joint static friction (every servo)"},
    {"servo.compliance", "servo_compliance",
     [](robot_config& c) -> double& { return c.servo.compliance; }, "N.m.s/rad", 0, 1e6,
     "Motor compliance, 0: rigid velocity servo (every servo)"},
    {"fall.tilt", "fall_tilt", [](robot_config& c) -> double& { return c.fall_tilt; }, "rad", 0,
     3.2, "fallen when the root link tilts more than this"},
    {"fall.height", "fall_height", [](robot_config& c) -> double& { return c.fall_height; }, "m",
     -10, 10, "fallen when the root link origin is lower than this"},
    {"reset.clearance", "reset_clearance",
     [](robot_config& c) -> double& { return c.reset_clearance; }, "m", -1, 1,
     "Lowest collision point above the floor after a reset"},
};
// clang-format on

class reader {
 public:
  explicit reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const tinyxml2::XMLElement* e, const std::string& what) const {
    throw model_error(source_ + (e ? ":" + std::to_string(e->GetLineNum()) : std::string()) + ": " +
                      what);
  }

  // every attribute of `e` must be in `known`
  void only(const tinyxml2::XMLElement& e, std::initializer_list<const char*> known) const {
    for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
      bool ok = false;
      for (const char* k : known) ok = ok || std::strcmp(k, a->Name()) == 0;
      if (!ok) {
        std::string list;
        for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
        fail(&e, "<" + std::string(e.Name()) + ">: unknown attribute '" + a->Name() +
                     "' (known: " + list + ")");
      }
    }
  }

  std::string text(const tinyxml2::XMLElement& e, const char* name, bool required) const {
    const char* v = e.Attribute(name);
    if (v == nullptr) {
      if (required) fail(&e, "<" + std::string(e.Name()) + ">: missing attribute '" + name + "'");
      return {};
    }
    return v;
  }

  double number(const tinyxml2::XMLElement& e, const char* name) const {
    const std::string v = text(e, name, true);
    std::istringstream in(v);
    double x = 0.0;
    in >> x;
    if (!in || !(in >> std::ws).eof() || !std::isfinite(x)) {
      fail(&e, "<" + std::string(e.Name()) + " " + name + "=\"" + v + "\">: not a finite number");
    }
    return x;
  }

  bool boolean(const tinyxml2::XMLElement& e, const char* name) const {
    const std::string v = text(e, name, true);
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail(&e, "<" + std::string(e.Name()) + " " + name + "=\"" + v + "\">: not true or false");
  }

  std::vector<std::string> patterns(const tinyxml2::XMLElement& e, const char* name) const {
    std::istringstream in(text(e, name, true));
    std::vector<std::string> out;
    for (std::string p; in >> p;) out.push_back(p);
    if (out.empty()) fail(&e, "<" + std::string(e.Name()) + ">: empty '" + name + "'");
    return out;
  }

  // <physics>, <contact>, <fall>, <reset>: attributes named after plant_settings()
  bool setting_element(const tinyxml2::XMLElement& e, profile_layer& layer) const {
    const std::string element = e.Name();
    if (element == "servo") return false;
    bool known_element = false;
    for (const plant_setting& s : k_settings) {
      known_element = known_element || std::string(s.profile_name).starts_with(element + ".");
    }
    if (!known_element) return false;
    for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
      const std::string key = element + "." + a->Name();
      std::size_t i = 0;
      while (i < std::size(k_settings) && key != k_settings[i].profile_name) ++i;
      if (i == std::size(k_settings)) {
        fail(&e, "<" + element + ">: unknown attribute '" + a->Name() + "'");
      }
      const double v = number(e, a->Name());
      if (v < k_settings[i].min || v > k_settings[i].max) {
        fail(&e, key + " = " + a->Value() + " is outside [" + std::to_string(k_settings[i].min) +
                     ", " + std::to_string(k_settings[i].max) + "]");
      }
      layer.settings[i] = v;
    }
    return true;
  }

  servo_rule servo(const tinyxml2::XMLElement& e) const {
    only(e, {"joints", "p_gain", "max_velocity", "max_acceleration", "torque_limit", "damping",
             "static_friction", "compliance", "clamp_to_limits"});
    servo_rule r;
    r.line = e.GetLineNum();
    r.patterns = patterns(e, "joints");
    servo_config& v = r.values;
    const std::pair<const char*, double*> fields[] = {{"p_gain", &v.p_gain},
                                                      {"max_velocity", &v.max_velocity},
                                                      {"max_acceleration", &v.max_acceleration},
                                                      {"torque_limit", &v.torque_limit},
                                                      {"damping", &v.damping},
                                                      {"static_friction", &v.static_friction},
                                                      {"compliance", &v.compliance}};
    for (auto [name, field] : fields) {
      *field = e.Attribute(name) ? number(e, name) : k_unset;
      if (*field < 0) fail(&e, "<servo " + std::string(name) + ">: must not be negative");
    }
    if (e.Attribute("clamp_to_limits")) {
      r.clamp_set = true;
      v.clamp_to_limits = boolean(e, "clamp_to_limits");
    }
    return r;
  }

  profile_layer empty_layer() const {
    profile_layer l;
    l.settings.assign(std::size(k_settings), k_unset);
    return l;
  }

  // the content a preset may override: settings and servo rules
  bool layer_element(const tinyxml2::XMLElement& e, profile_layer& layer) const {
    if (setting_element(e, layer)) return true;
    if (std::string(e.Name()) == "servo") {
      layer.servos.push_back(servo(e));
      return true;
    }
    return false;
  }

  board_channel channel(const tinyxml2::XMLElement& e) const {
    only(e, {"name", "signal", "gain", "offset", "round", "description"});
    board_channel c;
    c.name = text(e, "name", true);
    const std::string signal = text(e, "signal", true);
    const char* signals[] = {"gyro_x", "gyro_y", "gyro_z", "acc_x", "acc_y", "acc_z"};
    std::size_t i = 0;
    while (i < std::size(signals) && signal != signals[i]) ++i;
    if (i == std::size(signals)) {
      fail(&e, "<board signal=\"" + signal +
                   "\">: not one of gyro_x, gyro_y, gyro_z, acc_x, "
                   "acc_y, acc_z");
    }
    c.from = static_cast<board_channel::source>(i);
    if (e.Attribute("gain")) c.gain = number(e, "gain");
    if (e.Attribute("offset")) c.offset = number(e, "offset");
    const std::string round = e.Attribute("round") ? text(e, "round", true) : "none";
    if (round == "none") {
      c.round = board_channel::rounding::none;
    } else if (round == "floor") {
      c.round = board_channel::rounding::floor;
    } else if (round == "nearest") {
      c.round = board_channel::rounding::nearest;
    } else {
      fail(&e, "<board round=\"" + round + "\">: not none, floor or nearest");
    }
    c.description = text(e, "description", false);
    return c;
  }

  plant_profile read(const tinyxml2::XMLDocument& doc) const {
    const tinyxml2::XMLElement* root = doc.RootElement();
    if (root == nullptr || std::string(root->Name()) != "plant_profile") {
      fail(root, "the root element must be <plant_profile>");
    }
    only(*root, {"name", "version"});
    if (root->Attribute("version") && text(*root, "version", true) != "1") {
      fail(root, "<plant_profile version=\"" + text(*root, "version", true) +
                     "\">: this Stride reads version 1");
    }
    plant_profile p;
    p.source = source_;
    p.name = text(*root, "name", false);
    p.base = empty_layer();
    std::set<std::string> names;  // FMU variable names the profile introduces
    const auto new_name = [&](const tinyxml2::XMLElement& e, const std::string& n) {
      if (n.empty()) fail(&e, "<" + std::string(e.Name()) + ">: empty name");
      if (!names.insert(n).second) fail(&e, "name '" + n + "' is used twice");
    };
    bool have_presets = false;
    for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e;
         e = e->NextSiblingElement()) {
      const std::string element = e->Name();
      if (layer_element(*e, p.base)) continue;
      if (element == "joints") {
        only(*e, {"order", "passive"});
        if (e->Attribute("order")) {
          p.joint_order = text(*e, "order", true);
          if (p.joint_order != "urdf" && p.joint_order != "servo_id") {
            fail(e, "<joints order=\"" + p.joint_order + "\">: not urdf or servo_id");
          }
        }
        if (e->Attribute("passive")) p.passive = patterns(*e, "passive");
      } else if (element == "pose") {
        only(*e, {"joints", "value"});
        for (const std::string& j : patterns(*e, "joints"))
          p.pose.emplace_back(j, number(*e, "value"));
      } else if (element == "weld") {
        only(*e, {"joints", "parameter", "description"});
        weld_group w{patterns(*e, "joints"), text(*e, "parameter", false),
                     text(*e, "description", false)};
        if (!w.parameter.empty()) new_name(*e, w.parameter);
        p.welds.push_back(std::move(w));
      } else if (element == "imu") {
        only(*e, {"link"});
        p.imu_link = text(*e, "link", true);
      } else if (element == "feet") {
        only(*e, {"left", "right"});
        p.left_foot = text(*e, "left", true);
        p.right_foot = text(*e, "right", true);
      } else if (element == "board") {
        p.board.push_back(channel(*e));
        new_name(*e, p.board.back().name);
      } else if (element == "contact_force") {
        only(*e, {"name", "link"});
        p.contact_forces.push_back({text(*e, "name", true), text(*e, "link", true)});
        new_name(*e, p.contact_forces.back().name);
      } else if (element == "presets") {
        if (have_presets) fail(e, "<presets> given twice");
        have_presets = true;
        only(*e, {"parameter", "default"});
        if (e->Attribute("parameter")) p.preset_parameter = text(*e, "parameter", true);
        new_name(*e, p.preset_parameter);
        p.default_preset = text(*e, "default", true);
        for (const tinyxml2::XMLElement* pe = e->FirstChildElement(); pe;
             pe = pe->NextSiblingElement()) {
          if (std::string(pe->Name()) != "preset") {
            fail(pe,
                 "<presets> holds only <preset> elements, not <" + std::string(pe->Name()) + ">");
          }
          only(*pe, {"name"});
          profile_preset preset{text(*pe, "name", true), empty_layer()};
          for (const auto& other : p.presets) {
            if (other.name == preset.name) fail(pe, "preset '" + preset.name + "' given twice");
          }
          for (const tinyxml2::XMLElement* c = pe->FirstChildElement(); c;
               c = c->NextSiblingElement()) {
            if (!layer_element(*c, preset.layer)) {
              fail(c,
                   "<preset> may hold <physics>, <contact>, <fall>, <reset> and <servo>, "
                   "not <" +
                       std::string(c->Name()) + ">");
            }
          }
          p.presets.push_back(std::move(preset));
        }
        bool found = false;
        for (const auto& preset : p.presets) found = found || preset.name == p.default_preset;
        if (!found) fail(e, "<presets default=\"" + p.default_preset + "\">: no such preset");
      } else {
        fail(e, "unknown element <" + element +
                    "> (known: physics, contact, fall, reset, servo, joints, pose, weld, imu, "
                    "feet, board, contact_force, presets)");
      }
    }
    return p;
  }

 private:
  std::string source_;
};

}  // namespace

std::span<const plant_setting> plant_settings() {
  return k_settings;
}

plant_profile parse_plant_profile(const std::string& xml, const std::string& source) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw model_error(source + ":" + std::to_string(doc.ErrorLineNum()) +
                      ": not well-formed XML (" + doc.ErrorStr() + ")");
  }
  return reader(source).read(doc);
}

plant_profile load_plant_profile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw model_error(path + ": cannot read the plant profile");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_plant_profile(text.str(), path);
}

plant_profile default_plant_profile() {
  plant_profile p;
  p.source = "(no profile)";
  p.base.settings.assign(std::size(k_settings), k_unset);
  return p;
}

}  // namespace stride::robot
