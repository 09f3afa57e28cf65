#include "stride/learner/grid.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "stride/common/text.hpp"

namespace stride::learner {
namespace {

using text::trim;

// decimal places written in a plain decimal number ("15" -> 0, "0.25" -> 2); exponent forms
// ("1e-3") count their significant digits too
int decimals_of(std::string_view text) {
  const auto e = text.find_first_of("eE");
  std::string_view mantissa = text.substr(0, e);
  int exponent = 0;
  if (e != std::string_view::npos) {
    std::from_chars(text.data() + e + 1 + (text[e + 1] == '+' ? 1 : 0), text.data() + text.size(),
                    exponent);
  }
  const auto dot = mantissa.find('.');
  const int frac = dot == std::string_view::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return std::max(0, frac - exponent);
}

bool valid_name(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '.' || c == '[' || c == ']';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

std::string format_number(double v) {
  return text::format_double(v);
}

double parse_number(std::string_view input, std::string_view what) {
  const auto v = text::parse_double(input);
  if (!v || !std::isfinite(*v)) {
    throw learner_error(std::string(what) + ": '" + std::string(trim(input)) +
                        "' is not a finite number");
  }
  return *v;
}

std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == ',' || text[i] == ';') {
      items.emplace_back(trim(text.substr(begin, i - begin)));
      begin = i + 1;
    }
  }
  return items;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view what) {
  std::vector<double> out;
  if (trim(text).empty()) return out;
  for (const std::string& item : split_list(text)) out.push_back(parse_number(item, what));
  return out;
}

std::vector<std::int64_t> parse_step_list(std::string_view text, std::string_view what) {
  std::vector<std::int64_t> out;
  if (trim(text).empty()) return out;
  for (const std::string& item : split_list(text)) {
    const auto v = text::parse_integer(item);
    if (!v || *v <= 0) {
      throw learner_error(std::string(what) + ": '" + item + "' is not a positive whole number");
    }
    out.push_back(*v);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double grid_dimension::value(int i) const {
  const double v = min + static_cast<double>(i) * step;
  if (decimals <= 0) return v;  // whole numbers are exact
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

state_grid state_grid::parse(std::string_view text, std::string_view what) {
  const std::string where(what);
  if (trim(text).empty()) {
    throw learner_error(where + ": empty; expected name:min:max:step[,name:min:max:step...]");
  }
  state_grid g;
  for (const std::string& item : split_list(text)) {
    const std::string at = where + " dimension '" + item + "'";
    if (item.empty())
      throw learner_error(where + ": empty dimension in '" + std::string(text) + "'");
    std::vector<std::string_view> fields = text::split(item, ':');
    for (std::string_view& f : fields) f = trim(f);
    if (fields.size() != 4) {
      throw learner_error(at + ": expected name:min:max:step (4 fields, got " +
                          std::to_string(fields.size()) + ")");
    }
    grid_dimension d;
    d.name = std::string(fields[0]);
    if (!valid_name(d.name)) throw learner_error(at + ": '" + d.name + "' is not a valid name");
    for (const auto& other : g.dims_) {
      if (other.name == d.name) throw learner_error(at + ": parameter '" + d.name + "' repeated");
    }
    d.min = parse_number(fields[1], at + " min");
    d.max = parse_number(fields[2], at + " max");
    d.step = parse_number(fields[3], at + " step");
    if (d.step <= 0) throw learner_error(at + ": step must be > 0");
    if (d.max < d.min) throw learner_error(at + ": max < min");
    const double n = (d.max - d.min) / d.step;
    const double rounded = std::round(n);
    if (std::abs(n - rounded) > 1e-9 * std::max(1.0, rounded)) {
      throw learner_error(at + ": (max - min) / step = " + format_number(n) +
                          " is not a whole number");
    }
    if (rounded + 1 > static_cast<double>(k_max_states)) {
      throw learner_error(at + ": too many values");
    }
    d.count = static_cast<int>(rounded) + 1;
    d.decimals = std::max({decimals_of(fields[1]), decimals_of(fields[2]), decimals_of(fields[3])});
    d.decimals = std::min(d.decimals, 12);
    g.dims_.push_back(std::move(d));
    if (g.dims_.size() > k_max_dimensions) {
      throw learner_error(where + ": more than " + std::to_string(k_max_dimensions) +
                          " dimensions");
    }
  }
  std::size_t size = 1;
  for (const auto& d : g.dims_) {
    g.strides_.push_back(size);
    const auto count = static_cast<std::size_t>(d.count);
    if (size > k_max_states / count) {
      throw learner_error(where + ": more than " + std::to_string(k_max_states) + " states");
    }
    size *= count;
  }
  g.size_ = size;
  return g;
}

std::optional<std::size_t> state_grid::dimension(std::string_view name) const {
  for (std::size_t d = 0; d < dims_.size(); ++d) {
    if (dims_[d].name == name) return d;
  }
  return std::nullopt;
}

std::size_t state_grid::index(const std::vector<int>& coords) const {
  if (coords.size() != dims_.size())
    throw learner_error("state_grid::index: wrong dimension count");
  std::size_t s = 0;
  for (std::size_t d = 0; d < dims_.size(); ++d) {
    if (coords[d] < 0 || coords[d] >= dims_[d].count) {
      throw learner_error("state_grid::index: coordinate " + std::to_string(coords[d]) +
                          " out of range for " + dims_[d].name);
    }
    s += static_cast<std::size_t>(coords[d]) * strides_[d];
  }
  return s;
}

int state_grid::coord(std::size_t index, std::size_t d) const {
  return static_cast<int>((index / strides_[d]) % static_cast<std::size_t>(dims_[d].count));
}

std::vector<int> state_grid::coords(std::size_t index) const {
  std::vector<int> c(dims_.size());
  for (std::size_t d = 0; d < dims_.size(); ++d) c[d] = coord(index, d);
  return c;
}

std::size_t state_grid::neighbour(std::size_t index, std::size_t d, int delta) const {
  const int c = coord(index, d) + delta;
  if (c < 0 || c >= dims_[d].count) return index;
  return delta > 0 ? index + strides_[d] : index - strides_[d];
}

std::vector<double> state_grid::values(std::size_t index) const {
  std::vector<double> v(dims_.size());
  for (std::size_t d = 0; d < dims_.size(); ++d) v[d] = dims_[d].value(coord(index, d));
  return v;
}

std::size_t state_grid::find(const std::vector<double>& values, std::string_view what) const {
  if (values.size() != dims_.size()) {
    throw learner_error(std::string(what) + ": " + std::to_string(values.size()) +
                        " values for a grid of " + std::to_string(dims_.size()) + " dimensions");
  }
  std::vector<int> c(dims_.size());
  for (std::size_t d = 0; d < dims_.size(); ++d) {
    const grid_dimension& dim = dims_[d];
    const double i = std::round((values[d] - dim.min) / dim.step);
    if (i < 0 || i >= dim.count || std::abs(dim.value(static_cast<int>(i)) - values[d]) > 1e-9) {
      throw learner_error(std::string(what) + ": " + dim.name + " = " + format_number(values[d]) +
                          " is not a value of the grid (" + format_number(dim.min) + ":" +
                          format_number(dim.max) + ":" + format_number(dim.step) + ")");
    }
    c[d] = static_cast<int>(i);
  }
  return index(c);
}

std::string state_grid::str() const {
  std::string s;
  for (const auto& d : dims_) {
    if (!s.empty()) s += ',';
    s += d.name + ":" + format_number(d.min) + ":" + format_number(d.max) + ":" +
         format_number(d.step);
  }
  return s;
}

}  // namespace stride::learner
