// write_view: the run folder's frames and robot model into one page.
#include "stride/viewer/view.hpp"

#include <algorithm>
#include <fstream>

#include "page.hpp"
#include "page_data.hpp"
#include "recorded_frames.hpp"
#include "robot_urdf.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/observers.hpp"
#include "stride/cosim/run_plots.hpp"
#include "stride/robot/robot_model.hpp"

namespace stride::viewer {

namespace fs = std::filesystem;

std::vector<std::string> view_signal_patterns() {
  return {"*.base_x",         "*.base_y", "*.base_z",  "*.roll",    "*.pitch",   "*.yaw",
          "*.joint_angle[*]", "*.fallen", "*.episode", "*.rl_step", "*.value[*]"};
}

namespace {

const char* k_how_to_record =
    "record them with `stride run SYSTEM --record-view` (docs/viewer.md), or --record "
    "'P.base_?,P.roll,P.pitch,P.yaw,P.joint_angle[*],P.fallen' for the plant component P";

// the CSVs that may hold the frames: --record-view's file first, then the results
std::vector<fs::path> candidate_files(const fs::path& run_dir) {
  std::vector<fs::path> files;
  if (fs::is_regular_file(run_dir / k_view_file)) files.push_back(run_dir / k_view_file);
  const fs::path results = cosim::run_results_file(run_dir);
  if (!results.empty() && fs::is_regular_file(results) &&
      std::find(files.begin(), files.end(), results) == files.end()) {
    files.push_back(results);
  }
  return files;
}

struct chosen_source {
  fs::path file;
  std::string prefix;
};

chosen_source choose_source(const view_options& o) {
  const std::vector<fs::path> files = candidate_files(o.run_dir);
  if (files.empty()) {
    throw cosim::validation_error(o.run_dir.string() + " holds no recorded signals (" +
                                  k_view_file + " or the results CSV): " + k_how_to_record);
  }
  std::vector<std::string> seen;  // every pose recorded, once
  for (const auto& f : files) {
    const std::vector<std::string> prefixes = full_pose_prefixes(csv_header(f));
    for (const auto& p : prefixes) {
      if (std::find(seen.begin(), seen.end(), p) == seen.end()) seen.push_back(p);
    }
    if (o.robot.empty() && !prefixes.empty()) return {f, prefixes.front()};
    if (std::find(prefixes.begin(), prefixes.end(), o.robot) != prefixes.end()) {
      return {f, o.robot};
    }
  }
  std::string names;
  for (const auto& f : files) names += (names.empty() ? "" : ", ") + f.filename().string();
  if (!o.robot.empty()) {
    std::string poses;
    for (const auto& p : seen) poses += (poses.empty() ? "" : ", ") + p;
    throw cosim::validation_error(o.run_dir.string() + ": no pose of '" + o.robot + "' in " +
                                  names + " (recorded poses: " + (poses.empty() ? "none" : poses) +
                                  ")");
  }
  throw cosim::validation_error(
      o.run_dir.string() + ": " + names +
      " records no robot pose: the viewer needs P.base_x, P.base_y, P.base_z, P.roll, P.pitch, "
      "P.yaw and P.joint_angle[ID] of one plant component P; " +
      k_how_to_record);
}

// the first column matching one of `patterns`, or every one
std::vector<std::string> matching(const std::vector<std::string>& columns,
                                  const std::vector<std::string>& patterns, bool first) {
  std::vector<std::string> out;
  for (const auto& c : columns) {
    for (const auto& p : patterns) {
      if (c != "time" && cosim::glob_match(p, c)) {
        out.push_back(c);
        if (first) return out;
        break;
      }
    }
  }
  return out;
}

std::vector<int> servo_ids(const robot::robot_model& model) {
  std::vector<int> ids;
  for (const auto& j : model.joints) {
    if (j.servo_id > 0) ids.push_back(j.servo_id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

view_report write_view(const view_options& o) {
  if (!fs::is_directory(o.run_dir)) {
    throw cosim::validation_error(o.run_dir.string() + " is not a folder");
  }
  if (o.from && o.to && *o.to < *o.from) {
    throw cosim::validation_error("--to must not be before --from");
  }
  const chosen_source source = choose_source(o);

  urdf_source urdf;
  if (!o.urdf.empty()) {
    std::ifstream in(o.urdf, std::ios::binary);
    if (!in) throw cosim::validation_error(o.urdf.string() + ": cannot open the URDF");
    urdf.text.assign(std::istreambuf_iterator<char>(in), {});
    urdf.label = o.urdf.string();
  } else {
    urdf = find_run_urdf(o.run_dir, source.prefix);
  }
  // the plant's own reader: what it could not load (meshes, ...) is refused here the same way
  const robot::robot_model model = robot::parse_robot_model(urdf.text, urdf.label);

  // a learner's episodes and state, when recorded (view_signal_patterns records them)
  const std::vector<std::string> columns = csv_header(source.file);
  frame_selection selection;
  selection.from = o.from;
  selection.to = o.to;
  selection.fps = o.fps;
  selection.span_column = o.episodes;
  if (selection.span_column.empty()) {
    const auto found = matching(columns, {"*.episode"}, true);
    if (!found.empty()) selection.span_column = found.front();
  }
  if (o.episode) {
    if (selection.span_column.empty()) {
      throw cosim::validation_error("--episode: " + source.file.string() +
                                    " has no episode column (name one with --episodes)");
    }
    const value_span span = find_span(source.file, selection.span_column, *o.episode);
    selection.from = span.from;
    selection.to = span.to;
  }
  const std::vector<std::string> state = matching(
      columns,
      o.state.empty() ? std::vector<std::string>{"*.episode", "*.rl_step", "*.value[*]"} : o.state,
      false);
  if (!o.state.empty() && state.empty()) {
    throw cosim::validation_error("--state: no column of " + source.file.string() + " matches");
  }
  recorded_frames frames;
  try {
    frames = read_frames(source.file, source.prefix, servo_ids(model), state, selection);
    thin_frames(frames, o.max_frames);
  } catch (const cosim::validation_error& e) {
    throw cosim::validation_error(std::string(e.what()) + ", which the joints of " + urdf.label +
                                  " need: " + k_how_to_record);
  }
  if (frames.t.empty()) {
    throw cosim::validation_error(source.file.string() + ": no recorded row inside the window");
  }

  page_content content;
  content.title =
      fs::absolute(o.run_dir).lexically_normal().filename().string() + " — " + source.prefix;
  if (content.title.starts_with(" — ")) content.title = source.prefix;
  content.parameters = other_parameters(o.run_dir, source.prefix);
  // a state column is named by what it drives, when a connection says so (learner.value[1]
  // drives gait.period_time)
  const auto targets = connection_targets(o.run_dir);
  if (o.state.empty()) {
    // by default a learner's values that drive nothing (unused grid dimensions) are left out
    std::erase_if(frames.state, [&](const auto& s) {
      return cosim::glob_match("*.value[*]", s.first) && !targets.contains(s.first);
    });
  }
  for (auto& [name, values] : frames.state) {
    if (const auto it = targets.find(name); it != targets.end()) name = it->second;
  }
  for (const value_span& span : frames.spans) {
    content.episodes.push_back(
        {selection.span_column + " " + text::format_double(span.value), span.from, span.to});
  }
  const std::string html = render_page(content.title, page_json(model, frames, content));

  view_report r;
  r.output = o.output.empty() ? o.run_dir / "view.html" : o.output;
  if (r.output.has_parent_path()) fs::create_directories(r.output.parent_path());
  {
    std::ofstream out(r.output, std::ios::binary | std::ios::trunc);
    out << html;
    out.close();
    if (!out) throw std::runtime_error(r.output.string() + ": cannot write");
  }
  r.results = source.file;
  r.urdf = urdf.label;
  r.robot = source.prefix;
  r.frames = frames.t.size();
  r.bytes = html.size();
  r.falls = frames.falls;
  r.episodes = content.episodes.size();
  return r;
}

}  // namespace stride::viewer
