#include "stride/study/suite_assertions.hpp"

#include <cmath>
#include <stdexcept>

#include "stride/common/text.hpp"
#include "stride/learner/artefacts.hpp"

namespace stride::study {

namespace fs = std::filesystem;

namespace {

double number(const std::string& input, const std::string& what) {
  const auto v = text::parse_double(input);
  if (!v || !std::isfinite(*v))
    throw std::invalid_argument(what + ": '" + input + "' is not a number");
  return *v;
}

// "name=value, name=value" (values may be "lo..hi")
std::vector<std::pair<std::string, std::string>> assignments(const std::string& text,
                                                             const std::string& what) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& item : learner::split_list(text)) {
    const auto eq = item.find('=');
    if (item.empty() || eq == std::string::npos) {
      throw std::invalid_argument(what + ": '" + item + "' is not name=value");
    }
    out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  if (out.empty()) throw std::invalid_argument(what + " is empty");
  return out;
}

struct range {
  std::string name;
  double lo = 0, hi = 0;
};

std::vector<range> region_of(const suite::assertion_spec& a) {
  std::vector<range> out;
  for (const auto& [name, value] : assignments(a.get("region").value_or(""), "region")) {
    const auto dots = value.find("..");
    if (dots == std::string::npos) {
      throw std::invalid_argument("region " + name + "=" + value + ": expected lo..hi");
    }
    out.push_back({name, number(value.substr(0, dots), "region " + name),
                   number(value.substr(dots + 2), "region " + name)});
    if (out.back().lo > out.back().hi) throw std::invalid_argument("region " + name + ": lo > hi");
  }
  return out;
}

learner::csv_columns v_table(const suite::assertion_spec& a, const suite::case_output& out) {
  const fs::path file = out.dir / a.get("folder").value_or("") / learner::run_files::value_table;
  if (!fs::exists(file)) throw std::runtime_error("no V table " + file.string());
  return learner::read_csv_log(file);
}

std::string num(double v) {
  return learner::format_number(v);
}

std::vector<std::string> no_signals(const suite::assertion_spec&, const fs::path&) {
  return {};
}

}  // namespace

suite::assertion_registry learner_assertions() {
  suite::assertion_registry r;
  r["best_state"] = {
      {"region", "folder"},
      [](const suite::assertion_spec& a, const fs::path&) { region_of(a); },
      no_signals,
      [](const suite::assertion_spec& a, const suite::case_output& out) -> suite::outcome {
        const auto table = v_table(a, out);
        if (table.rows.empty()) return {false, "the V table is empty"};
        std::size_t best = 0;
        for (std::size_t s = 0; s < table.rows.size(); ++s) {
          // a NaN never compares greater: left in, a NaN first row would be "the best"
          if (std::isnan(table.rows[s].back())) {
            return {false, "V is NaN in row " + std::to_string(s + 1) + " of the V table"};
          }
          if (table.rows[s].back() > table.rows[best].back()) best = s;
        }
        std::string state;
        bool inside = true;
        for (const range& r : region_of(a)) {
          const int c = table.column(r.name);
          if (c < 0) return {false, "the V table has no dimension " + r.name};
          const double v = table.rows[best][static_cast<std::size_t>(c)];
          inside = inside && v >= r.lo && v <= r.hi;
        }
        for (std::size_t d = 0; d + 1 < table.header.size(); ++d) {
          state += (state.empty() ? "" : ", ") + table.header[d] + " = " + num(table.rows[best][d]);
        }
        if (inside) return {true, {}};
        return {false, "the best state is " + state + " (V = " + num(table.rows[best].back()) +
                           "), outside " + a.get("region").value_or("")};
      }};
  r["value_at"] = {
      {"state", "min", "max", "folder"},
      [](const suite::assertion_spec& a, const fs::path&) {
        for (const auto& [name, value] : assignments(a.get("state").value_or(""), "state")) {
          number(value, "state " + name);
        }
        if (!a.get("min") && !a.get("max")) throw std::invalid_argument("needs min, max or both");
        if (a.get("min")) number(*a.get("min"), "min");
        if (a.get("max")) number(*a.get("max"), "max");
      },
      no_signals,
      [](const suite::assertion_spec& a, const suite::case_output& out) -> suite::outcome {
        const auto table = v_table(a, out);
        const auto state = assignments(*a.get("state"), "state");
        for (const auto& row : table.rows) {
          bool match = true;
          for (const auto& [name, value] : state) {
            const int c = table.column(name);
            if (c < 0) return {false, "the V table has no dimension " + name};
            match =
                match && std::abs(row[static_cast<std::size_t>(c)] - number(value, name)) < 1e-9;
          }
          if (!match) continue;
          const double v = row.back();
          const double lo = a.get("min") ? number(*a.get("min"), "min") : -INFINITY;
          const double hi = a.get("max") ? number(*a.get("max"), "max") : INFINITY;
          if (v >= lo && v <= hi) return {true, {}};
          return {false, "V(" + *a.get("state") + ") = " + num(v) + ", not within [" + num(lo) +
                             ", " + num(hi) + "]"};
        }
        return {false, "no state " + *a.get("state") + " in the V table"};
      }};
  return r;
}

}  // namespace stride::study
