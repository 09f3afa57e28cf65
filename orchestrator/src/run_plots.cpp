#include "stride/cosim/run_plots.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "run_files.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/gnuplot.hpp"
#include "stride/cosim/observers.hpp"

namespace stride::cosim {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view k_x = ".base_x", k_y = ".base_y";

// a name usable in file names: letters, digits, '.', '-' and '_' kept, anything else '_'
std::string file_name_part(const std::string& s) {
  std::string out = s;
  for (char& c : out) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '-' || c == '_';
    if (!keep) c = '_';
  }
  return out;
}

struct results_table {
  std::vector<std::string> header;
  std::vector<std::string> columns;         // the columns read, in `header` order
  std::vector<std::vector<double>> values;  // values[k][row] of columns[k]
};

std::vector<std::string> read_header(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::string line;
  std::getline(in, line);
  const auto fields = text::csv_fields(line);
  if (fields.empty() || fields[0] != "time") {
    throw std::runtime_error(file.string() +
                             ":1: not a results file (the first column is not "
                             "'time')");
  }
  return fields;
}

results_table read_columns(const fs::path& file, const std::vector<std::string>& wanted) {
  results_table t;
  t.header = read_header(file);
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < t.header.size(); ++i) {
    if (std::find(wanted.begin(), wanted.end(), t.header[i]) != wanted.end()) {
      index.push_back(i);
      t.columns.push_back(t.header[i]);
    }
  }
  t.values.resize(index.size());
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::getline(in, line);
  for (std::size_t line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty() || line == "\r") continue;
    const auto fields = text::csv_fields(line);
    for (std::size_t k = 0; k < index.size(); ++k) {
      const std::size_t i = index[k];
      const auto v = i < fields.size() ? text::parse_double(fields[i]) : std::nullopt;
      if (!v) {
        throw std::runtime_error(file.string() + ":" + std::to_string(line_no) + ": column '" +
                                 t.header[i] + "': '" + (i < fields.size() ? fields[i] : "") +
                                 "' is not a number");
      }
      t.values[k].push_back(*v);
    }
  }
  return t;
}

const std::vector<double>& column(const results_table& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  return t.values.at(static_cast<std::size_t>(it - t.columns.begin()));
}

struct figure_writer {
  fs::path figures;
  std::vector<fs::path>* written;

  // writes NAME.dat (header `# columns`, then the rows) and NAME.gp, runs gnuplot
  void draw(const std::string& name, const std::vector<std::string>& heads,
            const std::vector<const std::vector<double>*>& data, const std::string& script) {
    fs::create_directories(figures);
    const fs::path base = figures / name;
    std::string dat = "#";
    for (const auto& h : heads) dat += " " + h;
    dat += "\n";
    const std::size_t rows = data.empty() ? 0 : data[0]->size();
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t k = 0; k < data.size(); ++k) {
        dat += (k ? " " : "") + gnuplot::num((*data[k])[r]);
      }
      dat += "\n";
    }
    gnuplot::write_text(base.string() + ".dat", dat);
    std::string gp = gnuplot::k_png_terminal;
    gp += "set output " + gnuplot::quote(base.string() + ".png") + "\n";
    gp += script;
    gnuplot::write_text(base.string() + ".gp", gp);
    gnuplot::run(base.string() + ".gp");
    written->push_back(base.string() + ".png");
  }
};

void plot_run(const fs::path& results, const std::string& prefix,
              const std::vector<std::string>& patterns, figure_writer& out) {
  const std::vector<std::string> header = read_header(results);
  const std::vector<std::string> names(header.begin() + 1, header.end());
  const std::vector<std::string> poses = pose_prefixes(names);
  std::vector<std::string> signals;
  for (const auto& p : patterns) {
    bool matched = false;
    for (const auto& n : names) {
      if (!glob_match(p, n)) continue;
      matched = true;
      if (std::find(signals.begin(), signals.end(), n) == signals.end()) signals.push_back(n);
    }
    if (!matched) {
      std::string known;
      for (std::size_t i = 0; i < names.size() && i < 12; ++i) {
        known += (i ? ", " : "") + names[i];
      }
      if (names.size() > 12) known += ", ...";
      throw validation_error("--signals: pattern '" + p + "' matches no column of " +
                             results.string() + " (columns: " + known + ")");
    }
  }
  if (poses.empty() && signals.empty()) return;
  std::vector<std::string> wanted = {"time"};
  for (const auto& p : poses) {
    wanted.push_back(p + std::string(k_x));
    wanted.push_back(p + std::string(k_y));
  }
  wanted.insert(wanted.end(), signals.begin(), signals.end());
  const results_table t = read_columns(results, wanted);
  const std::string source = results.filename().string();
  for (const auto& p : poses) {
    const std::string x = p + std::string(k_x), y = p + std::string(k_y);
    const std::string name = prefix + "path_" + file_name_part(p);
    std::string gp = "set title " + gnuplot::quote("x-y path of " + p + " (" + source + ")") + "\n";
    gp += "set xlabel " + gnuplot::quote(x) + "\nset ylabel " + gnuplot::quote(y) + "\n";
    gp += "set size ratio -1\nset grid\nset key below\n";
    const std::string dat = gnuplot::quote((out.figures / name).string() + ".dat");
    gp += "plot " + dat + " using 2:3 with lines lw 2 title 'path', " + dat +
          " every ::0::0 using 2:3 with points pt 7 ps 1.5 title 'start'\n";
    out.draw(name, {"time", x, y}, {&column(t, "time"), &column(t, x), &column(t, y)}, gp);
  }
  for (const auto& s : signals) {
    const std::string name = prefix + "signal_" + file_name_part(s);
    std::string gp = "set title " + gnuplot::quote(s + " (" + source + ")") + "\n";
    gp += "set xlabel 'time (s)'\nset ylabel " + gnuplot::quote(s) + "\nset grid\n";
    gp += "plot " + gnuplot::quote((out.figures / name).string() + ".dat") +
          " using 1:2 with lines lw 2 notitle\n";
    out.draw(name, {"time", s}, {&column(t, "time"), &column(t, s)}, gp);
  }
}

}  // namespace

fs::path run_results_file(const fs::path& dir) {
  const fs::path manifest = dir / "manifest.json";
  if (fs::is_regular_file(manifest)) {
    const std::string named = read_manifest_field(manifest, "results");
    if (!named.empty() && fs::is_regular_file(dir / named)) return dir / named;
  }
  if (fs::is_regular_file(dir / "results.csv")) return dir / "results.csv";
  return {};
}

std::vector<std::string> pose_prefixes(const std::vector<std::string>& columns) {
  std::vector<std::string> out;
  for (const auto& c : columns) {
    if (c.size() <= k_x.size() || !c.ends_with(k_x)) continue;
    const std::string p = c.substr(0, c.size() - k_x.size());
    if (std::find(columns.begin(), columns.end(), p + std::string(k_y)) != columns.end() &&
        std::find(out.begin(), out.end(), p) == out.end()) {
      out.push_back(p);
    }
  }
  return out;
}

std::vector<std::string> split_signal_patterns(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const auto& v : values) {
    for (const auto part : text::split(v, ',')) {
      const std::string_view p = text::trim(part);
      if (p.empty()) throw validation_error("--signals '" + v + "': empty pattern");
      out.emplace_back(p);
    }
  }
  return out;
}

std::vector<fs::path> write_run_plots(const fs::path& dir,
                                      const std::vector<std::string>& signal_patterns) {
  if (!fs::is_directory(dir)) throw validation_error(dir.string() + " is not a folder");
  std::vector<std::pair<fs::path, std::string>> runs;  // results file, file name prefix
  if (const fs::path r = run_results_file(dir); !r.empty()) runs.emplace_back(r, "");
  std::vector<fs::path> below;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_directory() && e.path().filename() != "figures") below.push_back(e.path());
  }
  std::sort(below.begin(), below.end());
  for (const auto& d : below) {
    if (const fs::path r = run_results_file(d); !r.empty()) {
      runs.emplace_back(r, file_name_part(d.filename().string()) + "_");
    }
  }
  if (runs.empty() && !signal_patterns.empty()) {
    throw validation_error("--signals: " + dir.string() +
                           " holds no results CSV (manifest.json's \"results\" or results.csv)");
  }
  const fs::path figures = dir / "figures";
  const bool existed = fs::exists(figures);
  std::vector<fs::path> written;
  figure_writer out{figures, &written};
  try {
    for (const auto& [file, prefix] : runs) plot_run(file, prefix, signal_patterns, out);
  } catch (...) {
    std::error_code ec;
    if (!existed) fs::remove_all(figures, ec);  // made by this call: no half-drawn folder stays
    throw;
  }
  return written;
}

}  // namespace stride::cosim
