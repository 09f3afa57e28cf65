#include "recorded_frames.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/run_plots.hpp"

namespace stride::viewer {

namespace fs = std::filesystem;

std::vector<std::string> csv_header(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw cosim::validation_error(file.string() + ": cannot open the results file");
  std::string line;
  std::getline(in, line);
  return text::csv_fields(line);
}

std::vector<std::string> full_pose_prefixes(const std::vector<std::string>& columns) {
  std::vector<std::string> prefixes;
  for (const auto& p : cosim::pose_prefixes(columns)) {
    const bool all =
        std::all_of(std::begin(k_pose_columns), std::end(k_pose_columns), [&](const char* c) {
          return std::find(columns.begin(), columns.end(), p + "." + c) != columns.end();
        });
    if (all) prefixes.push_back(p);
  }
  return prefixes;
}

recorded_frames read_frames(const fs::path& file, const std::string& prefix,
                            const std::vector<int>& servo_ids,
                            const std::vector<std::string>& state_columns,
                            const frame_selection& selection) {
  std::ifstream in(file);
  if (!in) throw cosim::validation_error(file.string() + ": cannot open the results file");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = text::csv_fields(line);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < header.size(); ++i) index.emplace(header[i], i);

  std::vector<std::string> missing;
  const auto column = [&](const std::string& name) -> std::size_t {
    const auto it = index.find(name);
    if (it == index.end()) {
      missing.push_back(name);
      return 0;
    }
    return it->second;
  };
  const std::size_t time = column("time");
  std::vector<std::size_t> pose;
  for (const char* c : k_pose_columns) pose.push_back(column(prefix + "." + c));
  std::vector<std::size_t> joints;
  for (const int id : servo_ids) {
    joints.push_back(column(prefix + ".joint_angle[" + std::to_string(id) + "]"));
  }
  std::vector<std::size_t> state;
  for (const auto& s : state_columns) state.push_back(column(s));
  const std::size_t span = selection.span_column.empty() ? 0 : column(selection.span_column);
  if (!missing.empty()) {
    std::string names;
    for (const auto& m : missing) names += (names.empty() ? "" : ", ") + m;
    throw cosim::validation_error(file.string() + " has no column " + names);
  }
  const auto fallen_it = index.find(prefix + ".fallen");

  recorded_frames f;
  f.prefix = prefix;
  int max_id = 0;
  for (const int id : servo_ids) max_id = std::max(max_id, id);
  f.q.resize(static_cast<std::size_t>(max_id));
  f.state.resize(state_columns.size());
  for (std::size_t s = 0; s < state_columns.size(); ++s) f.state[s].first = state_columns[s];

  // decimation: the first row of each 1/fps bin of simulated time (bins kept as doubles: a file
  // may hold any finite time, far beyond an integer's range)
  const auto bin = [&](double t) {
    return selection.fps > 0 ? std::floor(t * selection.fps + 1e-6) : 0.0;
  };
  std::optional<double> last_bin;
  bool was_fallen = false;
  std::size_t line_number = 1;
  std::vector<double> row(header.size());
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    const std::vector<std::string> fields = text::csv_fields(line);
    if (fields.size() != header.size()) {
      throw std::runtime_error(file.string() + ":" + std::to_string(line_number) + ": " +
                               std::to_string(fields.size()) + " values for " +
                               std::to_string(header.size()) + " columns");
    }
    const auto number = [&](std::size_t c) {
      const auto v = text::parse_double(fields[c]);
      if (!v || !std::isfinite(*v)) {
        throw std::runtime_error(file.string() + ":" + std::to_string(line_number) + ": " +
                                 header[c] + " = '" + fields[c] + "' is not a finite number");
      }
      return *v;
    };
    const double t = number(time);
    if (selection.from && t < *selection.from - 1e-9) continue;
    if (selection.to && t > *selection.to + 1e-9) break;
    if (!selection.span_column.empty()) {
      const double v = number(span);
      if (f.spans.empty() || f.spans.back().value != v) f.spans.push_back({v, t, t});
      f.spans.back().to = t;
    }
    bool fallen = false;
    if (fallen_it != index.end()) fallen = number(fallen_it->second) != 0.0;
    const bool falls_now = fallen && !was_fallen;
    if (falls_now) f.falls.push_back(t);
    was_fallen = fallen;
    // the first row of each interval, and the row of a fall so that its frame is shown
    const bool due = selection.fps <= 0 || !last_bin || bin(t) > *last_bin;
    if (!due && !falls_now) continue;
    last_bin = bin(t);
    f.t.push_back(t);
    std::vector<double>* targets[] = {&f.x, &f.y, &f.z, &f.roll, &f.pitch, &f.yaw};
    for (std::size_t i = 0; i < pose.size(); ++i) targets[i]->push_back(number(pose[i]));
    for (std::size_t j = 0; j < servo_ids.size(); ++j) {
      f.q[static_cast<std::size_t>(servo_ids[j] - 1)].push_back(number(joints[j]));
    }
    if (fallen_it != index.end()) f.fallen.push_back(fallen ? 1 : 0);
    for (std::size_t s = 0; s < state.size(); ++s) f.state[s].second.push_back(number(state[s]));
  }
  return f;
}

void thin_frames(recorded_frames& f, std::size_t max_frames) {
  if (max_frames == 0 || f.t.size() <= max_frames) return;
  const std::size_t every = (f.t.size() + max_frames - 1) / max_frames;
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    const bool falls = !f.fallen.empty() && f.fallen[i] != 0 && (i == 0 || f.fallen[i - 1] == 0);
    if (i % every == 0 || falls) keep.push_back(i);
  }
  const auto pick = [&](auto& values) {
    if (values.empty()) return;
    std::remove_reference_t<decltype(values)> kept;
    kept.reserve(keep.size());
    for (const std::size_t i : keep) kept.push_back(values[i]);
    values = std::move(kept);
  };
  for (auto* v : {&f.x, &f.y, &f.z, &f.roll, &f.pitch, &f.yaw}) pick(*v);
  for (auto& q : f.q) pick(q);
  pick(f.fallen);
  for (auto& s : f.state) pick(s.second);
  pick(f.t);
}

value_span find_span(const fs::path& file, const std::string& column, double value) {
  std::ifstream in(file);
  if (!in) throw cosim::validation_error(file.string() + ": cannot open the results file");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = text::csv_fields(line);
  const auto at = std::find(header.begin(), header.end(), column);
  if (at == header.end()) throw cosim::validation_error(file.string() + " has no column " + column);
  const std::size_t c = static_cast<std::size_t>(at - header.begin());
  std::optional<value_span> found;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = text::csv_fields(line);
    if (fields.size() != header.size()) continue;
    const auto v = text::parse_double(fields[c]);
    const auto t = text::parse_double(fields[0]);
    if (!v || !t || *v != value) {
      if (found) break;  // the span has ended
      continue;
    }
    if (!found) found = value_span{value, *t, *t};
    found->to = *t;
  }
  if (!found) {
    throw cosim::validation_error(file.string() + ": no row with " + column + " = " +
                                  text::format_double(value));
  }
  return *found;
}

}  // namespace stride::viewer
