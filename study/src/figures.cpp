#include "stride/study/figures.hpp"

#include "axis_units.hpp"
#include "stride/cosim/gnuplot.hpp"
#include "stride/learner/artefacts.hpp"
#include "stride/study/run_folder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace stride::study {

namespace fs = std::filesystem;

namespace {

using csv_table = learner::csv_columns;

csv_table read_csv(const fs::path& file) {
  return learner::read_csv_log(file);
}

namespace gnuplot = cosim::gnuplot;
using gnuplot::num;
using gnuplot::quote;
using gnuplot::write_text;

const char* k_terminal = gnuplot::k_png_terminal;

// moving average over the last `n` values (fewer at the start)
std::vector<double> moving_average(const std::vector<double>& v, std::size_t n) {
  std::vector<double> out(v.size());
  double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    sum += v[i];
    if (i >= n) sum -= v[i - n];
    out[i] = sum / static_cast<double>(std::min(i + 1, n));
  }
  return out;
}

struct figure_context {
  fs::path run;      // folder with the learner's artefacts
  fs::path figures;  // where PNGs go
  std::string prefix;
  std::vector<fs::path>* written;
};

void heatmap(const figure_context& fc, const fs::path& table_file, const std::string& title,
             const std::string& name) {
  const csv_table t = read_csv(table_file);
  const int dims = static_cast<int>(t.header.size()) - 1;
  if (dims < 2 || t.rows.empty()) return;
  // max over the dimensions beyond the first two
  std::map<std::pair<double, double>, double> cells;
  for (const auto& r : t.rows) {
    const auto key = std::make_pair(r[1], r[0]);
    const double v = r[static_cast<std::size_t>(dims)];
    const auto it = cells.find(key);
    if (it == cells.end() || v > it->second) cells[key] = v;
  }
  std::string dat;
  double prev_y = std::nan("");
  double best_v = -INFINITY, best_x = 0, best_y = 0;
  for (const auto& [key, v] : cells) {
    if (!std::isnan(prev_y) && key.first != prev_y) dat += "\n";
    prev_y = key.first;
    dat += num(key.second) + " " + num(key.first) + " " + num(v) + "\n";
    if (v > best_v) {
      best_v = v;
      best_x = key.second;
      best_y = key.first;
    }
  }
  const fs::path base = fc.figures / (fc.prefix + name);
  write_text(base.string() + ".dat", dat);
  std::string gp = k_terminal;
  gp += "set output " + quote(base.string() + ".png") + "\n";
  gp += "set title " + quote(title + (dims > 2 ? " (max over the other parameters)" : "")) + "\n";
  gp += "set xlabel " + quote(t.header[0] + unit_of(t.header[0])) + "\n";
  gp += "set ylabel " + quote(t.header[1] + unit_of(t.header[1])) + "\n";
  gp += "set cblabel 'V(s)'\nset palette rgb 33,13,10\nset autoscale fix\nset key below\n";
  // a few deep falls would take the whole colour scale: below -max V all is one colour
  double lowest = INFINITY;
  for (const auto& [key, v] : cells) lowest = std::min(lowest, v);
  if (best_v > 0 && lowest < -best_v) {
    gp += "set cbrange [" + num(-best_v) + ":" + num(best_v) + "]\n";
    char label[80];
    std::snprintf(label, sizeof label, "set cblabel 'V(s); %.4g and below in one colour'\n",
                  -best_v);
    gp += label;
  }
  gp += "plot " + quote(base.string() + ".dat") +
        " using 1:2:3 with image notitle, '-' using 1:2 "
        "with points pt 6 ps 3 lw 2 lc rgb 'white' title " +
        quote("best: " + num(best_x) + ", " + num(best_y)) + "\n" + num(best_x) + " " +
        num(best_y) + "\ne\n";
  write_text(base.string() + ".gp", gp);
  gnuplot::run(base.string() + ".gp");
  fc.written->push_back(base.string() + ".png");
}

void profiles(const figure_context& fc, const csv_table& t) {
  const std::size_t dims = t.header.size() - 1;
  if (dims < 1 || t.rows.empty()) return;
  const fs::path base = fc.figures / (fc.prefix + "v_profile");
  std::string gp = k_terminal;
  gp += "set output " + quote(base.string() + ".png") + "\n";
  gp += "set multiplot layout 1," + std::to_string(dims) +
        " title 'max V over the other "
        "parameters, per parameter'\nset grid\n";
  for (std::size_t d = 0; d < dims; ++d) {
    std::map<double, double> best;
    for (const auto& r : t.rows) {
      const auto it = best.find(r[d]);
      if (it == best.end() || r[dims] > it->second) best[r[d]] = r[dims];
    }
    std::string dat;
    for (const auto& [x, v] : best) dat += num(x) + " " + num(v) + "\n";
    const std::string file = base.string() + "_" + std::to_string(d + 1) + ".dat";
    write_text(file, dat);
    gp += "set xlabel " + quote(t.header[d] + unit_of(t.header[d])) + "\nset ylabel 'max V'\n";
    gp += "plot " + quote(file) + " using 1:2 with linespoints pt 7 ps 0.6 lw 2 notitle\n";
  }
  gp += "unset multiplot\n";
  write_text(base.string() + ".gp", gp);
  gnuplot::run(base.string() + ".gp");
  fc.written->push_back(base.string() + ".png");
}

void episode_series(const figure_context& fc, const csv_table& t, const std::string& column,
                    const std::string& name, const std::string& title, const std::string& label) {
  const int e = t.column("episode"), c = t.column(column);
  if (e < 0 || c < 0 || t.rows.empty()) return;
  std::vector<double> ys;
  for (const auto& r : t.rows) ys.push_back(r[static_cast<std::size_t>(c)]);
  const auto avg = moving_average(ys, 50);
  std::string dat;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    dat +=
        num(t.rows[i][static_cast<std::size_t>(e)]) + " " + num(ys[i]) + " " + num(avg[i]) + "\n";
  }
  const fs::path base = fc.figures / (fc.prefix + name);
  write_text(base.string() + ".dat", dat);
  std::string gp = k_terminal;
  gp += "set output " + quote(base.string() + ".png") + "\n";
  gp += "set title " + quote(title) + "\nset xlabel 'episode'\nset ylabel " + quote(label) +
        "\nset grid\nset key top right\n";
  gp += "plot " + quote(base.string() + ".dat") +
        " using 1:2 with lines lc rgb '#a0a0a0' title 'per episode', '' using 1:3 with lines lw "
        "3 lc rgb '#c03020' title '50-episode moving average'\n";
  write_text(base.string() + ".gp", gp);
  gnuplot::run(base.string() + ".gp");
  fc.written->push_back(base.string() + ".png");
}

// x-y paths: one block per walk segment (a new one after a fall or at a new episode)
std::string path_blocks(const csv_table& t, std::size_t max_segments, std::size_t* segments) {
  const int ce = t.column("episode"), cx = t.column("x"), cy = t.column("y"),
            cf = t.column("fallen");
  if (ce < 0 || cx < 0 || cy < 0 || cf < 0) return {};
  std::vector<std::string> blocks;
  std::string block;
  double episode = std::nan("");
  for (const auto& r : t.rows) {
    const double ep = r[static_cast<std::size_t>(ce)];
    if (ep != episode && !block.empty()) {
      blocks.push_back(block);
      block.clear();
    }
    episode = ep;
    block += num(r[static_cast<std::size_t>(cx)]) + " " + num(r[static_cast<std::size_t>(cy)]) +
             " " + num(ep) + "\n";
    if (r[static_cast<std::size_t>(cf)] != 0) {
      blocks.push_back(block);
      block.clear();
    }
  }
  if (!block.empty()) blocks.push_back(block);
  // the latest segments when there are too many
  const std::size_t first = blocks.size() > max_segments ? blocks.size() - max_segments : 0;
  std::string dat;
  for (std::size_t i = first; i < blocks.size(); ++i) dat += blocks[i] + "\n";
  *segments = blocks.size() - first;
  return dat;
}

void paths_figure(const figure_context& fc, const fs::path& paths_file) {
  const csv_table t = read_csv(paths_file);
  std::size_t segments = 0;
  const std::string dat = path_blocks(t, 3000, &segments);
  if (segments == 0) return;
  const fs::path base = fc.figures / (fc.prefix + "paths");
  write_text(base.string() + ".dat", dat);
  std::string gp = k_terminal;
  gp += "set output " + quote(base.string() + ".png") + "\n";
  gp += "set title " +
        quote("travelled torso paths (" + std::to_string(segments) +
              " walks from the origin; colour: episode)") +
        "\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset grid\n"
        "set cblabel 'episode'\nset palette rgb 30,31,32\n";
  gp += "plot " + quote(base.string() + ".dat") + " using 1:2:3 with lines lc palette notitle\n";
  write_text(base.string() + ".gp", gp);
  gnuplot::run(base.string() + ".gp");
  fc.written->push_back(base.string() + ".png");
}

struct evaluation_row {
  std::string name;
  learner::evaluation_result result;
};

std::vector<evaluation_row> read_evaluations(const fs::path& dir) {
  std::vector<evaluation_row> rows;
  for (const auto& d : run_folders(dir)) {
    const fs::path file = d / learner::run_files::evaluation;
    if (!fs::exists(file)) continue;
    rows.push_back({d == dir ? dir.filename().string() : d.filename().string(),
                    learner::read_evaluation(file)});
  }
  return rows;
}

// evaluation runs of the same point (several starts) form one group
struct point_group {
  std::string label;  // the first run's name without its "-s<start>" suffix, and the point
  std::string title;  // the same on one line
  std::vector<const evaluation_row*> runs;
};

std::vector<point_group> group_by_point(const std::vector<evaluation_row>& rows) {
  std::vector<point_group> groups;
  for (const auto& r : rows) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const point_group& g) {
      return g.runs.front()->result.point == r.result.point;
    });
    if (it == groups.end()) {
      const std::string name = r.name.substr(0, r.name.rfind("-s"));
      std::string label = name, values;
      for (const auto& [k, v] : r.result.point) {
        label += "\\n" + learner::format_number(v);
        values += (values.empty() ? "" : "/") + learner::format_number(v);
      }
      groups.push_back({label, name + " (" + values + ")", {}});
      it = groups.end() - 1;
    }
    it->runs.push_back(&r);
  }
  return groups;
}

void evaluation_figures(const fs::path& dir, const fs::path& figures,
                        const std::vector<evaluation_row>& rows, std::vector<fs::path>* written) {
  if (rows.empty()) return;
  const std::vector<point_group> groups = group_by_point(rows);
  // per point: the mean over its starts, the lowest and highest, and the falls of all starts
  std::string dat;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    std::int64_t falls = 0;
    for (const auto* r : groups[i].runs) {
      sum += r->result.mean_speed;
      lo = std::min(lo, r->result.mean_speed);
      hi = std::max(hi, r->result.mean_speed);
      falls += r->result.falls;
    }
    const double n = static_cast<double>(groups[i].runs.size());
    dat += std::to_string(i) + " \"" + groups[i].label + "\" " + num(sum / n) + " " + num(lo) +
           " " + num(hi) + " " + std::to_string(falls) + " " + num(n) + "\n";
  }
  const fs::path base = figures / "evaluation";
  write_text(base.string() + ".dat", dat);
  std::string gp = k_terminal;
  gp += "set output " + quote(base.string() + ".png") + "\n";
  std::string names;
  for (const auto& [k, v] : rows[0].result.point) names += (names.empty() ? "" : ", ") + k;
  gp += "set title " +
        quote("mean speed per point (" + names + "), " +
              std::string(learner::to_string(rows[0].result.rules)) +
              " protocol: mean of the starts, lowest to highest") +
        "\nset ylabel 'mean speed (cm/s)'\nset style fill solid 0.6\nset boxwidth 0.6\n"
        "set yrange [0:*]\nset grid y\nset bmargin 6\n";
  gp += "plot " + quote(base.string() + ".dat") +
        " using 1:3:xtic(2) with boxes lc rgb '#3070b0' notitle, '' using 1:3:4:5 with "
        "yerrorbars lc rgb 'black' pt 0 notitle, '' using 1:5:(sprintf('%d falls, %d starts', "
        "$6, $7)) with labels offset 0,1 notitle\n";
  write_text(base.string() + ".gp", gp);
  gnuplot::run(base.string() + ".gp");
  written->push_back(base.string() + ".png");

  // the evaluators' paths in one figure, one colour per point
  std::string plots;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    bool titled = false;
    for (const auto* r : groups[g].runs) {
      const fs::path p =
          (r->name == dir.filename().string() ? dir : dir / r->name) / learner::run_files::paths;
      if (!fs::exists(p)) continue;
      std::size_t segments = 0;
      const std::string blocks = path_blocks(read_csv(p), 200, &segments);
      if (segments == 0) continue;
      const std::string file = (figures / ("eval_paths_" + r->name + ".dat")).string();
      write_text(file, blocks);
      plots += std::string(plots.empty() ? "" : ", ") + quote(file) +
               " using 1:2 with lines lw 2 lt " + std::to_string(g + 1) +
               (titled ? " notitle" : " title " + quote(groups[g].title));
      titled = true;
    }
  }
  if (!plots.empty()) {
    const fs::path pb = figures / "eval_paths";
    std::string g = k_terminal;
    g += "set output " + quote(pb.string() + ".png") +
         "\nset title 'travelled torso paths per evaluation point (each start from the origin)'"
         "\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset grid\nset key outside right\n"
         "set size ratio -1\n";
    g += "plot " + plots + "\n";
    write_text(pb.string() + ".gp", g);
    gnuplot::run(pb.string() + ".gp");
    written->push_back(pb.string() + ".png");
  }
}

}  // namespace

std::vector<fs::path> write_figures(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw std::runtime_error(dir.string() + " is not a folder");
  const fs::path figures = dir / "figures";
  fs::create_directories(figures);
  std::vector<fs::path> written;
  bool found = false;
  for (const auto& d : run_folders(dir)) {
    if (!fs::exists(d / learner::run_files::value_table)) continue;
    found = true;
    figure_context fc{d, figures, d == dir ? "" : d.filename().string() + "_", &written};
    const csv_table v = read_csv(d / learner::run_files::value_table);
    std::string steps = "the run";
    if (fs::exists(d / learner::run_files::best)) {
      steps =
          std::to_string(learner::read_best(d / learner::run_files::best).rl_steps) + " RL steps";
    }
    heatmap(fc, d / learner::run_files::value_table, "V(s) after " + steps, "v_heatmap");
    // snapshots, in step order
    std::vector<std::pair<long long, fs::path>> snaps;
    for (const auto& e : fs::directory_iterator(d)) {
      const long long n = learner::run_files::snapshot_step(e.path().filename().string());
      if (n >= 0) snaps.emplace_back(n, e.path());
    }
    std::sort(snaps.begin(), snaps.end());
    for (const auto& [n, p] : snaps) {
      heatmap(fc, p, "V(s) after " + std::to_string(n) + " RL steps",
              "v_heatmap_" + std::to_string(n));
    }
    profiles(fc, v);
    if (fs::exists(d / learner::run_files::episodes)) {
      const csv_table e = read_csv(d / learner::run_files::episodes);
      episode_series(fc, e, "sum_abs_dv", "convergence",
                     "convergence: sum of |V change| per episode", "sum |dV|");
      episode_series(fc, e, "reward", "reward", "accumulated reward per episode", "reward");
    }
    if (fs::exists(d / learner::run_files::paths)) paths_figure(fc, d / learner::run_files::paths);
  }
  const auto evals = read_evaluations(dir);
  if (!evals.empty()) found = true;
  evaluation_figures(dir, figures, evals, &written);
  if (!found) {
    throw std::runtime_error(dir.string() +
                             ": no learner artefacts (v_table.csv or evaluation.csv) here or in "
                             "the folders below");
  }
  if (written.empty()) {
    std::error_code ec;
    fs::remove(figures, ec);  // only if empty: figures of an earlier call stay
    throw std::runtime_error(dir.string() +
                             ": no figure could be drawn: the learner files here do not hold the "
                             "columns expected (docs/learner.md, \"Artefacts\")");
  }
  return written;
}

}  // namespace stride::study
