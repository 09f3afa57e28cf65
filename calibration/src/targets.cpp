#include "stride/calibration/targets.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <utility>

#include "stride/gait/config_ini.hpp"
#include "stride/gait/kinematics.hpp"
#include "text.hpp"

namespace stride::calibration {

namespace {

constexpr int k_max_servo_id = gait::servo_total;
constexpr std::string_view k_delta_prefix = "delta_";

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw target_error(file.string() + ": cannot read the target file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw target_error(file.string() + ": cannot read the target file");
  return text;
}

[[noreturn]] void fail(const std::string& source, int line, const std::string& message) {
  throw target_error(source + ":" + std::to_string(line) + ": " + message);
}

// a CSV field: trimmed, surrounding double quotes removed
std::string_view field(std::string_view s) {
  s = detail::trim(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
    s = detail::trim(s.substr(1, s.size() - 2));
  return s;
}

}  // namespace

std::string_view to_string(angle_unit unit) noexcept {
  switch (unit) {
    case angle_unit::count:
      return "count";
    case angle_unit::deg:
      return "deg";
    case angle_unit::rad:
      return "rad";
  }
  return "?";
}

double to_counts(double value, angle_unit unit) {
  switch (unit) {
    case angle_unit::count:
      return value;
    case angle_unit::deg:
      return gait::servo_center + value / gait::degrees_per_count;
    case angle_unit::rad:
      return gait::servo_center + value * (180.0 / std::numbers::pi) / gait::degrees_per_count;
  }
  return value;
}

double from_counts(double counts, angle_unit unit) {
  switch (unit) {
    case angle_unit::count:
      return counts;
    case angle_unit::deg:
      return (counts - gait::servo_center) * gait::degrees_per_count;
    case angle_unit::rad:
      return (counts - gait::servo_center) * gait::degrees_per_count * std::numbers::pi / 180.0;
  }
  return counts;
}

// ---------------------------------------------------------------------------------------------
// joint posture CSV

joint_target parse_joint_target(std::string_view text, const std::string& source) {
  joint_target target;
  target.source = source;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark

  std::vector<std::string_view> lines = detail::split(text, '\n');
  std::size_t columns = 0;
  std::size_t id_column = 0, value_column = 0;
  std::vector<std::pair<std::size_t, std::size_t>> delta_columns;  // (column, offset index)
  bool have_header = false;
  std::map<std::pair<int, int>, int> first_line;  // (posture, servo ID) -> line
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const std::string_view body = detail::trim(lines[i]);
    if (body.empty() || body.front() == '#') continue;
    const std::vector<std::string_view> fields = detail::split(body, ',');

    if (!have_header) {
      std::optional<std::size_t> id, unit_column;
      std::string unit_name;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        const std::string name = detail::lower(field(fields[c]));
        if (name == "id") {
          if (id) fail(source, line, "the header has column 'id' twice");
          id = c;
        } else if (name == "count" || name == "deg" || name == "rad") {
          if (unit_column)
            fail(source, line,
                 "the header has both '" + unit_name + "' and '" + name +
                     "': give exactly one of count, deg, rad");
          unit_column = c;
          unit_name = name;
          target.unit = name == "count" ? angle_unit::count
                        : name == "deg" ? angle_unit::deg
                                        : angle_unit::rad;
        } else if (name.starts_with(k_delta_prefix)) {
          const std::string key = name.substr(k_delta_prefix.size());
          const auto offset = find_offset(key);
          if (!offset) {
            std::string known;
            for (const offset_info& o : offset_table())
              known +=
                  (known.empty() ? "" : ", ") + std::string(k_delta_prefix) + std::string(o.key);
            fail(source, line, "unknown column '" + name + "' (known: " + known + ")");
          }
          for (const auto& [column, index] : delta_columns)
            if (index == *offset) fail(source, line, "the header has column '" + name + "' twice");
          delta_columns.emplace_back(c, *offset);
        }
      }
      if (!id || !unit_column) {
        std::string hint;
        if (body.front() == '[' || body.front() == ';')
          hint = " (a plant target? use --mode plant)";
        fail(source, line,
             "expected a CSV header with column 'id' and one of 'count', 'deg', 'rad', got '" +
                 std::string(body) + "'" + hint);
      }
      have_header = true;
      columns = fields.size();
      id_column = *id;
      value_column = *unit_column;
      continue;
    }

    if (fields.size() != columns)
      fail(source, line,
           "expected " + std::to_string(columns) + " fields as in the header, got " +
               std::to_string(fields.size()));
    const std::string_view id_text = field(fields[id_column]);
    const auto id = detail::parse_integer(id_text);
    if (!id) fail(source, line, "servo ID '" + std::string(id_text) + "' is not an integer");
    if (*id < 1 || *id > k_max_servo_id)
      fail(source, line,
           "unknown servo ID " + std::to_string(*id) + " (DARwIn-OP servo IDs are 1.." +
               std::to_string(k_max_servo_id) + ")");
    const int servo = static_cast<int>(*id);
    offset_values delta{};
    for (const auto& [column, index] : delta_columns) {
      const std::string_view text = field(fields[column]);
      const auto v = detail::parse_double(text);
      const std::string name = std::string(k_delta_prefix) + std::string(offset_table()[index].key);
      if (!v || !std::isfinite(*v))
        fail(source, line, name + " '" + std::string(text) + "' is not a finite number");
      delta[index] = *v;
    }
    std::size_t p = 0;
    while (p < target.postures.size() && target.postures[p].delta != delta) ++p;
    if (p == target.postures.size()) target.postures.push_back({delta, line});
    const int posture = static_cast<int>(p);
    if (const auto it = first_line.find({posture, servo}); it != first_line.end())
      fail(source, line,
           "duplicate servo ID " + std::to_string(servo) +
               (delta_columns.empty() ? "" : " in one posture (same deltas)") + " (first on line " +
               std::to_string(it->second) + ")");
    const std::string_view value_text = field(fields[value_column]);
    const auto value = detail::parse_double(value_text);
    if (!value)
      fail(source, line,
           "value '" + std::string(value_text) + "' of servo " + std::to_string(servo) +
               " is not a number");
    if (!std::isfinite(*value))
      fail(source, line, "value of servo " + std::to_string(servo) + " is not finite");
    const double counts = to_counts(*value, target.unit);
    if (counts < 0.0 || counts > gait::servo_max)
      fail(source, line,
           "value " + std::string(value_text) + " " + std::string(to_string(target.unit)) +
               " of servo " + std::to_string(servo) + " is outside the servo range 0..4095 counts");
    first_line.emplace(std::pair{posture, servo}, line);
    target.joints.push_back({servo, counts, line, posture});
  }
  if (!have_header)
    throw target_error(source + ": empty target: no CSV header (id and one of count, deg, rad)");
  if (target.joints.empty()) throw target_error(source + ": empty target: no joint rows");
  std::sort(target.joints.begin(), target.joints.end(),
            [](const joint_reading& a, const joint_reading& b) {
              return std::pair{a.posture, a.id} < std::pair{b.posture, b.id};
            });
  return target;
}

joint_target read_joint_target(const std::filesystem::path& file) {
  return parse_joint_target(read_file(file), file.string());
}

std::vector<offset_values> recommended_posture_plan() {
  const std::size_t x = *find_offset("x_offset"), y = *find_offset("y_offset"),
                    z = *find_offset("z_offset");
  std::vector<offset_values> plan;
  for (const double dx : {-30.0, 0.0, 30.0})
    for (const double dz : {-10.0, 5.0, 20.0})
      for (const double dy : {-15.0, 0.0, 15.0}) {
        offset_values d{};
        d[x] = dx;
        d[y] = dy;
        d[z] = dz;
        plan.push_back(d);
      }
  return plan;
}

// ---------------------------------------------------------------------------------------------
// plant posture INI

int plant_target::residual_count() const {
  return (pitch_deg ? 1 : 0) + (roll_deg ? 1 : 0) + (height_m ? 1 : 0) + (com_over_support ? 2 : 0);
}

plant_target parse_plant_target(std::string_view text, const std::string& source) {
  plant_target t;
  t.source = source;
  const gait::ini_document doc = gait::ini_document::parse(text, source);

  enum class section { none, target, settle, other };
  section current = section::none;
  std::map<std::string, int> seen;  // "section/key" -> line
  int average_line = 0;
  bool average_given = false;

  const auto& lines = doc.lines();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const gait::ini_line& l = lines[i];
    using kind = gait::ini_line::kind;
    if (l.type == kind::blank || l.type == kind::comment) continue;
    if (l.type == kind::invalid) {
      const std::string text(detail::trim(l.text));
      fail(
          source, line,
          "expected 'key = value' or '[section]', got '" + text + "'" +
              (text.find(',') != std::string::npos ? " (a joint posture? use --mode joints)" : ""));
    }
    if (l.type == kind::section) {
      if (detail::iequals(l.name, "Plant Target"))
        current = section::target;
      else if (detail::iequals(l.name, "Settle"))
        current = section::settle;
      else
        fail(source, line, "unknown section [" + l.name + "] (known: [Plant Target], [Settle])");
      continue;
    }
    // an entry
    if (current == section::none)
      fail(source, line, "'" + l.name + "' is outside a section ([Plant Target] or [Settle])");
    const std::string key = detail::lower(l.name);
    const std::string slot = (current == section::target ? "target/" : "settle/") + key;
    if (const auto it = seen.find(slot); it != seen.end())
      fail(source, line,
           "'" + l.name + "' is given twice (first on line " + std::to_string(it->second) + ")");
    seen.emplace(slot, line);

    const auto number = [&](double lo, double hi, const char* range) {
      const auto v = detail::parse_double(l.value);
      if (!v) fail(source, line, "'" + l.name + "' = '" + l.value + "' is not a number");
      if (!std::isfinite(*v) || *v < lo || *v > hi)
        fail(source, line, "'" + l.name + "' = " + l.value + " is outside " + range);
      return *v;
    };
    const auto positive = [&]() {
      const auto v = detail::parse_double(l.value);
      if (!v) fail(source, line, "'" + l.name + "' = '" + l.value + "' is not a number");
      if (!std::isfinite(*v) || *v <= 0)
        fail(source, line, "'" + l.name + "' = " + l.value + " must be positive");
      return *v;
    };

    if (current == section::target) {
      if (key == "pitch_deg") {
        t.pitch_deg = number(-90, 90, "-90..90 deg");
      } else if (key == "roll_deg") {
        t.roll_deg = number(-90, 90, "-90..90 deg");
      } else if (key == "height_m") {
        t.height_m = number(0.01, 1.0, "0.01..1 m");
      } else if (key == "com_over_support") {
        const std::string v = detail::lower(detail::trim(l.value));
        if (v == "true" || v == "yes" || v == "on" || v == "1")
          t.com_over_support = true;
        else if (v == "false" || v == "no" || v == "off" || v == "0")
          t.com_over_support = false;
        else
          fail(source, line, "'" + l.name + "' = '" + l.value + "' is not true or false");
      } else if (key == "pitch_sigma_deg") {
        t.pitch_sigma_deg = positive();
      } else if (key == "roll_sigma_deg") {
        t.roll_sigma_deg = positive();
      } else if (key == "height_sigma_m") {
        t.height_sigma_m = positive();
      } else if (key == "com_sigma_m") {
        t.com_sigma_m = positive();
      } else {
        fail(source, line,
             "unknown key '" + l.name +
                 "' in [Plant Target] (known: pitch_deg, roll_deg, height_m, com_over_support, "
                 "pitch_sigma_deg, roll_sigma_deg, height_sigma_m, com_sigma_m)");
      }
    } else {
      if (key == "time_s") {
        t.settle_s = number(0.008, 60, "0.008..60 s");
      } else if (key == "average_s") {
        t.average_s = number(0.008, 60, "0.008..60 s");
        average_line = line;
        average_given = true;
      } else if (key == "max_iterations") {
        const auto v = detail::parse_integer(l.value);
        if (!v || *v < 1 || *v > 1000)
          fail(source, line, "'" + l.name + "' = '" + l.value + "' is not an integer in 1..1000");
        t.max_iterations = static_cast<int>(*v);
      } else {
        fail(source, line,
             "unknown key '" + l.name + "' in [Settle] (known: time_s, average_s, max_iterations)");
      }
    }
  }
  if (t.average_s > t.settle_s) {
    if (average_given)
      fail(source, average_line, "average_s is longer than the settle time time_s");
    t.average_s = t.settle_s;
  }
  if (t.residual_count() == 0)
    throw target_error(source +
                       ": empty target: set at least one of pitch_deg, roll_deg, height_m or "
                       "com_over_support = true in [Plant Target]");
  return t;
}

plant_target read_plant_target(const std::filesystem::path& file) {
  return parse_plant_target(read_file(file), file.string());
}

}  // namespace stride::calibration
