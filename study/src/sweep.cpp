#include "stride/study/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "axis_units.hpp"
#include "stride/cosim/gnuplot.hpp"
#include "stride/learner/artefacts.hpp"

namespace stride::study {

namespace fs = std::filesystem;
namespace gnuplot = cosim::gnuplot;
using gnuplot::num;
using gnuplot::quote;

namespace {

enum speed_map_column { k_windows, k_falls, k_mean_speed, k_mean_reward };

void require_2d(const grid_table& t) {
  if (t.axes.size() != 2) throw std::runtime_error("a heat map needs a grid of two axes");
}

// "x y v1 v2 ..." per cell, rows of equal y in blocks (gnuplot's `with image` needs the full
// grid: a cell without a row is NaN)
std::string cells(const grid_table& t) {
  std::vector<double> xs, ys;
  std::map<std::pair<double, double>, std::size_t> row_of;
  for (std::size_t r = 0; r < t.axis_values.size(); ++r) {
    xs.push_back(t.axis_values[r][0]);
    ys.push_back(t.axis_values[r][1]);
    row_of[{t.axis_values[r][1], t.axis_values[r][0]}] = r;
  }
  for (auto* v : {&xs, &ys}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  std::string dat;
  for (std::size_t j = 0; j < ys.size(); ++j) {
    if (j > 0) dat += "\n";
    for (double x : xs) {
      dat += num(x) + " " + num(ys[j]);
      const auto it = row_of.find({ys[j], x});
      for (std::size_t c = 0; c < t.columns.size(); ++c) {
        dat += " " + (it == row_of.end() ? std::string("NaN") : num(t.values[it->second][c]));
      }
      dat += "\n";
    }
  }
  return dat;
}

std::string axis_labels(const grid_table& t) {
  return "set xlabel " + quote(t.axes[0] + unit_of(t.axes[0])) + "\nset ylabel " +
         quote(t.axes[1] + unit_of(t.axes[1])) + "\n";
}

fs::path sibling(const fs::path& png, const std::string& suffix) {
  return png.parent_path() / (png.stem().string() + suffix);
}

// the rows of `pool` by `key`, largest first (ties in grid order), at most `n`
std::vector<std::size_t> top(const grid_table& t, std::vector<std::size_t> pool, int key,
                             std::size_t n) {
  auto value = [&](std::size_t row) {
    const double v = t.values[row][static_cast<std::size_t>(key)];
    return std::isnan(v) ? -INFINITY : v;  // NaN would break the ordering
  };
  std::stable_sort(pool.begin(), pool.end(),
                   [&](std::size_t a, std::size_t b) { return value(a) > value(b); });
  if (pool.size() > n) pool.resize(n);
  return pool;
}

std::string state_name(const grid_table& t, std::size_t row) {
  std::string s;
  for (double v : t.axis_values[row]) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    s += (s.empty() ? "" : "/") + std::string(buf);
  }
  return s;
}

void require_speed_map(const grid_table& t) {
  if (t.columns.size() < 4 ||
      !std::equal(t.columns.begin(), t.columns.begin() + 4, speed_map_columns().begin())) {
    throw std::runtime_error("not a speed map table (columns windows, falls, mean_speed, ...)");
  }
}

}  // namespace

std::vector<std::string> speed_map_columns() {
  return {"windows", "falls", "mean_speed", "mean_reward"};
}

std::vector<double> read_speed_map_point(const fs::path& dir) {
  const learner::evaluation_result r =
      learner::read_evaluation(dir / learner::run_files::evaluation);
  const learner::csv_columns steps = learner::read_csv_log(dir / learner::run_files::steps);
  const int reward = steps.column("reward");
  if (reward < 0) {
    throw std::runtime_error((dir / learner::run_files::steps).string() + ": no column 'reward'");
  }
  double sum = 0;
  for (const auto& row : steps.rows) sum += row[static_cast<std::size_t>(reward)];
  const std::int64_t walked = r.windows - r.falls;  // the evaluator counts a fall as a window
  return {static_cast<double>(walked), static_cast<double>(r.falls),
          walked > 0 ? r.mean_speed : std::nan(""),
          steps.rows.empty() ? std::nan("") : sum / static_cast<double>(steps.rows.size())};
}

std::vector<std::string> speed_map_overrides(const std::string& variable,
                                             const std::string& grid_text) {
  static const std::string k_suffix = ".eval_point";
  if (variable.size() <= k_suffix.size() ||
      variable.compare(variable.size() - k_suffix.size(), k_suffix.size(), k_suffix) != 0) {
    throw std::runtime_error(
        "--collect speed-map: sweep one learner's eval_point (e.g. --grid "
        "eval.eval_point=period_time:450:960:15,swing_right_left:15:39:2), not " +
        variable);
  }
  return {variable.substr(0, variable.size() - k_suffix.size()) + ".grid=" + grid_text};
}

std::string summarize_speed_map(const grid_table& t) {
  require_speed_map(t);
  std::vector<std::size_t> walked, steady;
  std::size_t fell = 0;
  for (std::size_t r = 0; r < t.values.size(); ++r) {
    if (t.values[r][k_falls] > 0) ++fell;
    if (t.values[r][k_windows] > 0) {
      walked.push_back(r);
      if (t.values[r][k_falls] == 0) steady.push_back(r);
    }
  }
  std::string out = std::to_string(t.values.size()) + " states, " + std::to_string(fell) +
                    " fell at least once\n";
  auto line = [&](const char* title, const std::vector<std::size_t>& rows) {
    out += std::string(title) + ": ";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& v = t.values[rows[i]];
      char buf[160];
      std::snprintf(buf, sizeof buf, " %.2f cm/s (%.0f falls, reward %.1f)", v[k_mean_speed],
                    v[k_falls], v[k_mean_reward]);
      out += (i ? "; " : "") + state_name(t, rows[i]) + buf;
    }
    out += "\n";
  };
  line("fastest without falls", top(t, steady, k_mean_speed, 5));
  line("highest mean reward", top(t, walked, k_mean_reward, 5));
  return out;
}

void write_speed_map_figure(const grid_table& t, const fs::path& png) {
  require_2d(t);
  require_speed_map(t);
  const fs::path dat = sibling(png, ".dat"), falls = sibling(png, "_falls.dat");
  gnuplot::write_text(dat, cells(t));
  std::string fell;
  std::vector<std::size_t> steady;
  for (std::size_t r = 0; r < t.values.size(); ++r) {
    const auto& v = t.values[r];
    if (v[k_falls] > 0) {
      fell +=
          num(t.axis_values[r][0]) + " " + num(t.axis_values[r][1]) + " " + num(v[k_falls]) + "\n";
    }
    if (v[k_falls] == 0 && v[k_windows] > 0) steady.push_back(r);
  }
  gnuplot::write_text(falls, fell);
  const auto best = top(t, steady, k_mean_speed, 1);
  const std::string fall_plot =
      fell.empty() ? ""
                   : ", " + quote(falls.string()) +
                         " using 1:2 with points pt 2 ps 0.5 lc rgb 'black' title 'fell at least "
                         "once'";
  std::string mark, mark_data;
  if (!best.empty()) {
    const double bx = t.axis_values[best[0]][0], by = t.axis_values[best[0]][1];
    mark = ", '-' using 1:2 with points pt 6 ps 3 lw 2 lc rgb 'white' title " +
           quote("fastest without falls: " + num(bx) + ", " + num(by));
    mark_data = num(bx) + " " + num(by) + "\ne\n";
  }
  std::string gp = "set terminal pngcairo size 1400,600 noenhanced font ',11'\n";
  gp += "set output " + quote(png.string()) + "\n";
  gp += "set multiplot layout 1,2\nset autoscale fix\nset key below\n" + axis_labels(t);
  gp += "set palette rgb 33,13,10\n";
  gp += "set title 'mean speed over the W-footstep windows (cm/s)'\n";
  gp += "plot " + quote(dat.string()) + " using 1:2:5 with image notitle" + fall_plot + mark +
        "\n" + mark_data;
  gp += "set title 'mean reward per RL step (falls included)'\n";
  gp += "plot " + quote(dat.string()) + " using 1:2:6 with image notitle" + fall_plot + "\n";
  gp += "unset multiplot\n";
  const fs::path script = sibling(png, ".gp");
  gnuplot::write_text(script, gp);
  gnuplot::run(script);
}

void write_grid_heat_map(const grid_table& t, const fs::path& png) {
  require_2d(t);
  if (t.columns.empty()) throw std::runtime_error("a heat map needs a column of values");
  const std::size_t panels = t.columns.size();
  const std::size_t across = std::min<std::size_t>(panels, 3);
  const std::size_t down = (panels + across - 1) / across;
  const fs::path dat = sibling(png, ".dat");
  gnuplot::write_text(dat, cells(t));
  std::string gp = "set terminal pngcairo size " + std::to_string(700 * across) + "," +
                   std::to_string(600 * down) + " noenhanced font ',11'\n";
  gp += "set output " + quote(png.string()) + "\n";
  gp += "set multiplot layout " + std::to_string(down) + "," + std::to_string(across) + "\n";
  gp += "set autoscale fix\nset palette rgb 33,13,10\n" + axis_labels(t);
  for (std::size_t c = 0; c < panels; ++c) {
    gp += "set title " + quote(t.columns[c]) + "\n";
    gp += "plot " + quote(dat.string()) + " using 1:2:" + std::to_string(c + 3) +
          " with image notitle\n";
  }
  gp += "unset multiplot\n";
  const fs::path script = sibling(png, ".gp");
  gnuplot::write_text(script, gp);
  gnuplot::run(script);
}

}  // namespace stride::study
