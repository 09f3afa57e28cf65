#include "stride/study/run_folder.hpp"

#include <algorithm>
#include <cstdio>

#include "stride/learner/artefacts.hpp"

namespace stride::study {

namespace fs = std::filesystem;
namespace files = learner::run_files;

std::vector<fs::path> run_folders(const fs::path& dir) {
  std::vector<fs::path> dirs{dir};
  std::vector<fs::path> subs;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_directory() && e.path().filename() != "figures") subs.push_back(e.path());
  }
  std::sort(subs.begin(), subs.end());
  dirs.insert(dirs.end(), subs.begin(), subs.end());
  return dirs;
}

bool has_learner_artefacts(const fs::path& dir) {
  if (!fs::is_directory(dir)) return false;
  for (const auto& d : run_folders(dir)) {
    if (fs::exists(d / files::value_table) || fs::exists(d / files::evaluation)) return true;
  }
  return false;
}

std::string summarize_run(const fs::path& dir) {
  std::string out;
  std::string table;
  for (const auto& d : run_folders(dir)) {
    const std::string name = d == dir ? dir.filename().string() : d.filename().string();
    if (fs::exists(d / files::best)) {
      if (d != dir) out += name + ":\n";
      out += learner::read_best(d / files::best).text;
    }
    if (!fs::exists(d / files::evaluation)) continue;
    const learner::evaluation_result r = learner::read_evaluation(d / files::evaluation);
    std::string point;
    for (const auto& [k, v] : r.point) {
      point += (point.empty() ? "" : ", ") + k + " = " + learner::format_number(v);
    }
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  ": %lld windows, %lld falls, %.3f m in %.1f s, %.2f cm/s (%s; physical %.2f)\n",
                  static_cast<long long>(r.windows), static_cast<long long>(r.falls), r.distance,
                  r.measured_time, r.mean_speed, std::string(learner::to_string(r.rules)).c_str(),
                  r.physical_speed);
    table += "  " + name + " (" + point + ")" + buf;
  }
  if (!table.empty()) {
    out += "evaluation (point: windows, falls, distance, measured time, mean speed):\n" + table;
  }
  return out;
}

}  // namespace stride::study
