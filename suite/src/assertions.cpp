#include "stride/suite/assertions.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <variant>

#include "stride/cosim/observers.hpp"

namespace stride::suite {

namespace fs = std::filesystem;

namespace {

constexpr double k_inf = std::numeric_limits<double>::infinity();

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::optional<double> number_attribute(const assertion_spec& a, const std::string& name) {
  const auto text = a.get(name);
  if (!text) return std::nullopt;
  double v = 0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
  if (ec != std::errc() || end != text->data() + text->size() || !std::isfinite(v)) {
    throw std::invalid_argument(name + "=\"" + *text + "\" is not a finite number");
  }
  return v;
}

std::string required(const assertion_spec& a, const std::string& name) {
  const auto v = a.get(name);
  if (!v || v->empty()) throw std::invalid_argument("needs a " + name + " attribute");
  return *v;
}

struct window {
  double from = -k_inf;
  double to = k_inf;
  std::string str() const {
    return "[" + (std::isinf(from) ? std::string("start") : num(from) + " s") + ", " +
           (std::isinf(to) ? std::string("end") : num(to) + " s") + "]";
  }
};

window window_of(const assertion_spec& a) {
  window w;
  if (const auto f = number_attribute(a, "from")) w.from = *f;
  if (const auto t = number_attribute(a, "to")) w.to = *t;
  if (w.from > w.to) throw std::invalid_argument("from is after to");
  return w;
}

struct bounds {
  double min = -k_inf;
  double max = k_inf;
  bool contains(double v) const { return v >= min && v <= max; }
  std::string str() const {
    if (std::isinf(min)) return "at most " + num(max);
    if (std::isinf(max)) return "at least " + num(min);
    return "within [" + num(min) + ", " + num(max) + "]";
  }
};

bounds bounds_of(const assertion_spec& a, bool required_one = true) {
  bounds b;
  if (const auto v = number_attribute(a, "min")) b.min = *v;
  if (const auto v = number_attribute(a, "max")) b.max = *v;
  if (required_one && std::isinf(b.min) && std::isinf(b.max)) {
    throw std::invalid_argument("needs min, max or both");
  }
  if (b.min > b.max) throw std::invalid_argument("min is above max");
  return b;
}

// the samples of a signal inside a window: indices into the time axis
struct series {
  const std::vector<double>* values = nullptr;
  std::vector<std::size_t> rows;
};

// a signal's samples in the window, or the reason it has none
std::variant<series, std::string> samples(const case_output& out, const std::string& signal,
                                          const window& w) {
  const recorded_signals& r = *out.signals;
  const auto c = r.column(signal);
  if (!c) return "signal " + signal + " was not recorded (results: " + r.file.string() + ")";
  if (r.is_text[*c]) return "signal " + signal + " holds text, not numbers";
  series s{&r.values[*c], {}};
  for (std::size_t i = 0; i < r.time.size(); ++i) {
    if (r.time[i] >= w.from && r.time[i] <= w.to) s.rows.push_back(i);
  }
  if (s.rows.empty()) return "no sample of " + signal + " in " + w.str();
  return s;
}

outcome fail(std::string message) {
  return {false, std::move(message)};
}

std::string at(const case_output& out, std::size_t row) {
  return "t = " + num(out.signals->time[row]) + " s";
}

// the first NaN among the samples, as a failure message
std::optional<std::string> nan_in(const case_output& out, const std::string& signal,
                                  const series& s) {
  for (std::size_t i : s.rows) {
    if (std::isnan((*s.values)[i])) return signal + " is NaN at " + at(out, i);
  }
  return std::nullopt;
}

// the signal named by `attribute` in the window, checked for NaN; or the failure
template <class F>
outcome with_samples(const assertion_spec& a, const case_output& out, const char* attribute,
                     F&& check) {
  const std::string signal = required(a, attribute);
  const window w = window_of(a);
  auto s = samples(out, signal, w);
  if (auto* why = std::get_if<std::string>(&s)) return fail(*why);
  const series& ser = std::get<series>(s);
  if (auto why = nan_in(out, signal, ser)) return fail(*why);
  return check(signal, ser, w);
}

std::vector<std::string> one_signal(const assertion_spec& a, const fs::path&) {
  return {required(a, "signal")};
}

void check_window_and_bounds(const assertion_spec& a, bool need_bounds) {
  window_of(a);
  bounds_of(a, need_bounds);
}

std::vector<std::string> split_patterns(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  for (char c : text + " ") {
    if (c == ' ' || c == ',' || c == '\t') {
      if (!item.empty()) out.push_back(item);
      item.clear();
    } else {
      item += c;
    }
  }
  return out;
}

// the reference columns an assertion compares, in the reference's order
std::vector<std::string> reference_columns(const assertion_spec& a, const fs::path& suite_dir,
                                           const recorded_signals& ref) {
  const auto patterns =
      a.get("signals") ? split_patterns(*a.get("signals")) : std::vector<std::string>{"*"};
  std::vector<std::string> out;
  for (const auto& name : ref.names) {
    for (const auto& p : patterns) {
      if (cosim::glob_match(p, name)) {
        out.push_back(name);
        break;
      }
    }
  }
  if (out.empty()) {
    throw std::invalid_argument("no column of " + (suite_dir / required(a, "file")).string() +
                                " matches signals=\"" + a.get("signals").value_or("*") + "\"");
  }
  return out;
}

recorded_signals read_reference(const assertion_spec& a, const fs::path& suite_dir) {
  const fs::path file = suite_dir / required(a, "file");
  if (!fs::exists(file))
    throw std::invalid_argument("reference file " + file.string() + " not found");
  recorded_signals ref;
  try {
    ref = read_recorded_signals(file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  // no time point would compare nothing and pass
  if (ref.time.empty())
    throw std::invalid_argument("reference file " + file.string() + " has no rows");
  return ref;
}

// linear interpolation of a recorded column at time t (times ascending)
std::optional<double> value_at(const recorded_signals& r, std::size_t column, double t) {
  const auto& time = r.time;
  if (time.empty() || t < time.front() || t > time.back()) return std::nullopt;
  const auto hi =
      static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), t) - time.begin());
  if (time[hi] == t) return r.values[column][hi];
  const std::size_t lo = hi - 1;
  const double f = (t - time[lo]) / (time[hi] - time[lo]);
  return r.values[column][lo] + f * (r.values[column][hi] - r.values[column][lo]);
}

outcome compare_with_reference(const assertion_spec& a, const case_output& out) {
  const recorded_signals ref = read_reference(a, out.suite_dir);
  const double absolute = number_attribute(a, "absolute").value_or(0.0);
  const double relative = number_attribute(a, "relative").value_or(0.0);
  const recorded_signals& run = *out.signals;
  std::string worst;
  double worst_excess = -1;
  std::size_t outside = 0, points = 0;
  for (const auto& name : reference_columns(a, out.suite_dir, ref)) {
    const auto rc = ref.column(name);
    const auto c = run.column(name);
    if (!c)
      return fail("signal " + name + " was not recorded (results: " + run.file.string() + ")");
    if (run.is_text[*c] || ref.is_text[*rc]) return fail("signal " + name + " holds text");
    for (std::size_t i = 0; i < ref.time.size(); ++i) {
      const double t = ref.time[i];
      const auto v = value_at(run, *c, t);
      if (!v) {
        return fail("the run did not record " + name + " at the reference's t = " + num(t) +
                    " s (recorded " + num(run.time.empty() ? 0 : run.time.front()) + " .. " +
                    num(run.time.empty() ? 0 : run.time.back()) + " s)");
      }
      const double r = ref.values[*rc][i];
      ++points;
      if (std::isnan(*v) || std::isnan(r)) {
        return fail(name + " is NaN at t = " + num(t) + " s (" +
                    (std::isnan(*v) ? "run" : "reference") + ")");
      }
      const double error = std::abs(*v - r);
      const double allowed = absolute + relative * std::abs(r);
      if (error <= allowed) continue;
      ++outside;
      const double excess = allowed > 0 ? error / allowed : error;
      if (excess > worst_excess) {
        worst_excess = excess;
        worst = name + " differs from the reference by " + num(error) + " at t = " + num(t) +
                " s (run " + num(*v) + ", reference " + num(r) + ", allowed " + num(allowed) + ")";
      }
    }
  }
  if (outside == 0) return {true, {}};
  return fail(worst + "; " + std::to_string(outside) + " of " + std::to_string(points) +
              " points outside the tolerance");
}

}  // namespace

assertion_registry builtin_assertions() {
  assertion_registry r;
  const auto window_only = [](const assertion_spec& a, const fs::path&) { window_of(a); };
  const auto with_bounds = [](const assertion_spec& a, const fs::path&) {
    check_window_and_bounds(a, true);
  };

  r["never"] = {{"signal", "from", "to"},
                window_only,
                one_signal,
                [](const assertion_spec& a, const case_output& out) {
                  return with_samples(
                      a, out, "signal",
                      [&](const std::string& sig, const series& s, const window& w) {
                        for (std::size_t i : s.rows) {
                          if ((*s.values)[i] != 0) {
                            return fail(sig + " is " + num((*s.values)[i]) + " at " + at(out, i) +
                                        " (never allowed in " + w.str() + ")");
                          }
                        }
                        return outcome{true, {}};
                      });
                }};
  r["eventually"] = {{"signal", "from", "to"},
                     window_only,
                     one_signal,
                     [](const assertion_spec& a, const case_output& out) {
                       return with_samples(
                           a, out, "signal",
                           [&](const std::string& sig, const series& s, const window& w) {
                             for (std::size_t i : s.rows) {
                               if ((*s.values)[i] != 0) return outcome{true, {}};
                             }
                             return fail(sig + " never became true in " + w.str());
                           });
                     }};
  r["bounds"] = {
      {"signal", "min", "max", "from", "to"},
      with_bounds,
      one_signal,
      [](const assertion_spec& a, const case_output& out) {
        const bounds b = bounds_of(a);
        return with_samples(
            a, out, "signal", [&](const std::string& sig, const series& s, const window& w) {
              std::size_t outside = 0, worst = 0;
              double worst_excess = -1;
              for (std::size_t i : s.rows) {
                const double v = (*s.values)[i];
                if (b.contains(v)) continue;
                ++outside;
                const double excess = v < b.min ? b.min - v : v - b.max;
                if (excess > worst_excess) {
                  worst_excess = excess;
                  worst = i;
                }
              }
              if (outside == 0) return outcome{true, {}};
              return fail(sig + " = " + num((*s.values)[worst]) + " at " + at(out, worst) +
                          ", not " + b.str() + " (" + std::to_string(outside) + " of " +
                          std::to_string(s.rows.size()) + " samples in " + w.str() + " outside)");
            });
      }};
  r["final"] = {
      {"signal", "value", "tolerance", "min", "max", "from", "to"},
      [](const assertion_spec& a, const fs::path&) {
        window_of(a);
        const bool has_value = a.get("value").has_value();
        const bounds b = bounds_of(a, !has_value);
        if (has_value && (a.get("min") || a.get("max"))) {
          throw std::invalid_argument("takes value and tolerance, or min and max; not both");
        }
        if (has_value) {
          number_attribute(a, "value");
          if (number_attribute(a, "tolerance").value_or(0) < 0) {
            throw std::invalid_argument("tolerance is negative");
          }
        } else if (a.get("tolerance")) {
          throw std::invalid_argument("tolerance goes with value");
        }
        (void)b;
      },
      one_signal,
      [](const assertion_spec& a, const case_output& out) {
        bounds b = bounds_of(a, false);
        if (const auto v = number_attribute(a, "value")) {
          const double tol = number_attribute(a, "tolerance").value_or(0);
          b = {*v - tol, *v + tol};
        }
        return with_samples(a, out, "signal",
                            [&](const std::string& sig, const series& s, const window&) {
                              const std::size_t last = s.rows.back();
                              const double v = (*s.values)[last];
                              if (b.contains(v)) return outcome{true, {}};
                              return fail("final " + sig + " = " + num(v) + " at " + at(out, last) +
                                          ", not " + b.str());
                            });
      }};
  r["mean"] = {{"signal", "min", "max", "from", "to"},
               with_bounds,
               one_signal,
               [](const assertion_spec& a, const case_output& out) {
                 const bounds b = bounds_of(a);
                 return with_samples(a, out, "signal",
                                     [&](const std::string& sig, const series& s, const window& w) {
                                       double sum = 0;
                                       for (std::size_t i : s.rows) sum += (*s.values)[i];
                                       const double mean = sum / static_cast<double>(s.rows.size());
                                       if (b.contains(mean)) return outcome{true, {}};
                                       return fail("mean of " + sig + " over " + w.str() + " = " +
                                                   num(mean) + ", not " + b.str());
                                     });
               }};
  r["rate"] = {{"signal", "min", "max", "from", "to"},
               with_bounds,
               one_signal,
               [](const assertion_spec& a, const case_output& out) {
                 const bounds b = bounds_of(a);
                 return with_samples(
                     a, out, "signal",
                     [&](const std::string& sig, const series& s, const window& w) {
                       if (s.rows.size() < 2)
                         return fail("one sample of " + sig + " in " + w.str());
                       const std::size_t i0 = s.rows.front(), i1 = s.rows.back();
                       const auto& t = out.signals->time;
                       const double rate = ((*s.values)[i1] - (*s.values)[i0]) / (t[i1] - t[i0]);
                       if (b.contains(rate)) return outcome{true, {}};
                       return fail("rate of " + sig + " from t = " + num(t[i0]) + " to " +
                                   num(t[i1]) + " s = " + num(rate) + " per s, not " + b.str());
                     });
               }};
  r["speed"] = {{"x", "y", "min", "max", "from", "to"},
                with_bounds,
                [](const assertion_spec& a, const fs::path&) {
                  return std::vector<std::string>{required(a, "x"), required(a, "y")};
                },
                [](const assertion_spec& a, const case_output& out) {
                  const bounds b = bounds_of(a);
                  const window w = window_of(a);
                  const std::string xs = required(a, "x"), ys = required(a, "y");
                  auto sx = samples(out, xs, w);
                  auto sy = samples(out, ys, w);
                  if (auto* why = std::get_if<std::string>(&sx)) return fail(*why);
                  if (auto* why = std::get_if<std::string>(&sy)) return fail(*why);
                  const series& x = std::get<series>(sx);
                  const series& y = std::get<series>(sy);
                  if (auto why = nan_in(out, xs, x)) return fail(*why);
                  if (auto why = nan_in(out, ys, y)) return fail(*why);
                  if (x.rows.size() < 2) return fail("one sample of " + xs + " in " + w.str());
                  const std::size_t i0 = x.rows.front(), i1 = x.rows.back();
                  const auto& t = out.signals->time;
                  const double d = std::hypot((*x.values)[i1] - (*x.values)[i0],
                                              (*y.values)[i1] - (*y.values)[i0]);
                  const double speed = d / (t[i1] - t[i0]);
                  if (b.contains(speed)) return outcome{true, {}};
                  return fail("speed from (" + xs + ", " + ys + ") between t = " + num(t[i0]) +
                              " and " + num(t[i1]) + " s = " + num(speed) + ", not " + b.str());
                }};
  r["reference"] = {{"file", "signals", "absolute", "relative"},
                    [](const assertion_spec& a, const fs::path& suite_dir) {
                      if (number_attribute(a, "absolute").value_or(0) < 0 ||
                          number_attribute(a, "relative").value_or(0) < 0) {
                        throw std::invalid_argument("tolerances must not be negative");
                      }
                      reference_columns(a, suite_dir, read_reference(a, suite_dir));
                    },
                    [](const assertion_spec& a, const fs::path& suite_dir) {
                      return reference_columns(a, suite_dir, read_reference(a, suite_dir));
                    },
                    compare_with_reference};
  return r;
}

}  // namespace stride::suite
