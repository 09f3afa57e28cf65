#include "fmi3_values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim::fmi3 {

namespace {

std::size_t cell_size(kind k) {
  switch (k) {
    case kind::float32:
    case kind::int32:
    case kind::uint32:
      return 4;
    case kind::float64:
    case kind::int64:
    case kind::uint64:
    case kind::enumeration:
      return 8;
    case kind::int16:
    case kind::uint16:
      return 2;
    case kind::int8:
    case kind::uint8:
      return 1;
    case kind::boolean:
      return sizeof(fmi3Boolean);
    default:
      return 0;  // String and Binary are kept as text
  }
}

bool is_text(kind k) {
  return k == kind::string || k == kind::binary;
}

// Calls `f` with a value of the C type of the numeric or Boolean kind `k`.
template <class F>
decltype(auto) with_type(kind k, F&& f) {
  switch (k) {
    case kind::float32:
      return f(fmi3Float32{});
    case kind::float64:
      return f(fmi3Float64{});
    case kind::int8:
      return f(fmi3Int8{});
    case kind::uint8:
      return f(fmi3UInt8{});
    case kind::int16:
      return f(fmi3Int16{});
    case kind::uint16:
      return f(fmi3UInt16{});
    case kind::int32:
      return f(fmi3Int32{});
    case kind::uint32:
      return f(fmi3UInt32{});
    case kind::uint64:
      return f(fmi3UInt64{});
    case kind::boolean:
      return f(fmi3Boolean{});
    default:  // Int64 and Enumeration (fmi3Get/SetInt64)
      return f(fmi3Int64{});
  }
}

template <class T>
T read_cell(const std::byte* cell) {
  T v;
  std::memcpy(&v, cell, sizeof v);
  return v;
}
template <class T>
void write_cell(std::byte* cell, T v) {
  std::memcpy(cell, &v, sizeof v);
}

// A start text (already checked by the reader) as the cell of type T.
template <class T>
void parse_cell(std::byte* cell, const std::string& text) {
  if constexpr (std::is_same_v<T, fmi3Boolean>) {
    write_cell<T>(cell, text == "true" || text == "1");
  } else if constexpr (std::is_floating_point_v<T>) {
    write_cell<T>(cell, static_cast<T>(text::parse_double(text).value_or(0.0)));
  } else {
    T v{};
    std::from_chars(text.data(), text.data() + text.size(), v);
    write_cell<T>(cell, v);
  }
}

std::string to_hex(const std::string& bytes) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() * 2);
  for (const unsigned char b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::optional<std::string> from_hex(const std::string& text) {
  if (text.size() % 2 != 0) return std::nullopt;
  std::string out;
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int hi = hex_digit(text[i]);
    const int lo = hex_digit(text[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out += static_cast<char>(hi * 16 + lo);
  }
  return out;
}

}  // namespace

value_io::value_io(const binary& bin, std::string component_name, checker check, void* context)
    : bin_(bin),
      d_(bin.description),
      name_(std::move(component_name)),
      check_(check),
      context_(context) {
  cells_.resize(d_.variables.size());
  texts_.resize(d_.variables.size());
  for (std::size_t i = 0; i < d_.variables.size(); ++i) {
    const auto& v = d_.variables[i];
    if (v.kind == kind::string) {
      texts_[i] = v.start.empty() ? std::vector<std::string>(v.size()) : v.start;
    } else if (v.kind == kind::binary) {
      texts_[i].resize(v.size());
      for (std::size_t k = 0; k < v.start.size(); ++k) {
        texts_[i][k] = from_hex(v.start[k]).value_or("");
      }
    } else {
      cells_[i].assign(v.size() * cell_size(v.kind), std::byte{0});
      for (std::size_t k = 0; k < v.start.size(); ++k) {
        with_type(v.kind, [&](auto t) {
          parse_cell<decltype(t)>(cells_[i].data() + k * sizeof t, v.start[k]);
        });
      }
    }
  }
}

std::vector<value_io::touch> value_io::touches(const variable_refs& refs) const {
  std::vector<touch> out;
  out.reserve(refs.size());
  const auto add = [&](const std::vector<value_reference>& list, variable_type channel) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const value_reference r = list[i];
      if (r >= d_.ports.size() ||
          exchange_type(d_.scalar.variables[r].type) != exchange_type(channel)) {
        throw component_error("component '" + name_ + "': value reference " + std::to_string(r) +
                              " is not a port of type " + std::string(to_string(channel)) + " in " +
                              bin_.file.string());
      }
      out.push_back({d_.ports[r].variable, d_.ports[r].element, channel, i});
    }
  };
  add(refs.reals, variable_type::real);
  add(refs.integers, variable_type::integer);
  add(refs.booleans, variable_type::boolean);
  add(refs.strings, variable_type::string);
  return out;
}

// The distinct variables of `ts`, grouped by kind so that each kind is one FMI call.
namespace {
std::vector<std::size_t> variables_of(const std::vector<value_io::touch>& ts,
                                      const description& d) {
  std::vector<std::size_t> vars;
  vars.reserve(ts.size());
  for (const auto& t : ts) vars.push_back(t.variable);
  std::sort(vars.begin(), vars.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(d.variables[a].kind, a) < std::pair(d.variables[b].kind, b);
  });
  vars.erase(std::unique(vars.begin(), vars.end()), vars.end());
  return vars;
}
}  // namespace

void value_io::set(fmi3Instance instance, const variable_refs& refs, const value_block& values) {
  const auto ts = touches(refs);
  const auto vars = variables_of(ts, d_);
  // a value refused half-way leaves the copies as they were: nothing reached the FMU
  std::vector<std::vector<std::byte>> cells;
  std::vector<std::vector<std::string>> texts;
  for (const std::size_t v : vars) {
    cells.push_back(cells_[v]);
    texts.push_back(texts_[v]);
  }
  try {
    for (const auto& t : ts) store(t, values);
  } catch (...) {
    for (std::size_t i = 0; i < vars.size(); ++i) {
      cells_[vars[i]] = std::move(cells[i]);
      texts_[vars[i]] = std::move(texts[i]);
    }
    throw;
  }
  set_variables(instance, vars);
}

void value_io::get(fmi3Instance instance, const variable_refs& refs, value_block& values) {
  values.resize_for(refs);
  const auto ts = touches(refs);
  get_variables(instance, variables_of(ts, d_));
  for (const auto& t : ts) load(t, values);
}

void value_io::refresh(fmi3Instance instance) {
  std::vector<std::size_t> arrays;
  for (std::size_t i = 0; i < d_.ports.size(); ++i) {
    const auto& p = d_.ports[i];
    const auto c = d_.scalar.variables[i].causality;
    const bool settable = c == causality::input || c == causality::parameter;
    if (p.element == 0 && settable && !d_.variables[p.variable].dimensions.empty()) {
      arrays.push_back(p.variable);
    }
  }
  std::sort(arrays.begin(), arrays.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(d_.variables[a].kind, a) < std::pair(d_.variables[b].kind, b);
  });
  get_variables(instance, arrays);
}

namespace {

fmi3Status call_set(const functions& fn, kind k, fmi3Instance inst, const fmi3ValueReference* vr,
                    std::size_t nvr, const void* v, std::size_t n) {
  switch (k) {
    case kind::float32:
      return fn.fmi3SetFloat32(inst, vr, nvr, static_cast<const fmi3Float32*>(v), n);
    case kind::float64:
      return fn.fmi3SetFloat64(inst, vr, nvr, static_cast<const fmi3Float64*>(v), n);
    case kind::int8:
      return fn.fmi3SetInt8(inst, vr, nvr, static_cast<const fmi3Int8*>(v), n);
    case kind::uint8:
      return fn.fmi3SetUInt8(inst, vr, nvr, static_cast<const fmi3UInt8*>(v), n);
    case kind::int16:
      return fn.fmi3SetInt16(inst, vr, nvr, static_cast<const fmi3Int16*>(v), n);
    case kind::uint16:
      return fn.fmi3SetUInt16(inst, vr, nvr, static_cast<const fmi3UInt16*>(v), n);
    case kind::int32:
      return fn.fmi3SetInt32(inst, vr, nvr, static_cast<const fmi3Int32*>(v), n);
    case kind::uint32:
      return fn.fmi3SetUInt32(inst, vr, nvr, static_cast<const fmi3UInt32*>(v), n);
    case kind::uint64:
      return fn.fmi3SetUInt64(inst, vr, nvr, static_cast<const fmi3UInt64*>(v), n);
    case kind::boolean:
      return fn.fmi3SetBoolean(inst, vr, nvr, static_cast<const fmi3Boolean*>(v), n);
    default:
      return fn.fmi3SetInt64(inst, vr, nvr, static_cast<const fmi3Int64*>(v), n);
  }
}

fmi3Status call_get(const functions& fn, kind k, fmi3Instance inst, const fmi3ValueReference* vr,
                    std::size_t nvr, void* v, std::size_t n) {
  switch (k) {
    case kind::float32:
      return fn.fmi3GetFloat32(inst, vr, nvr, static_cast<fmi3Float32*>(v), n);
    case kind::float64:
      return fn.fmi3GetFloat64(inst, vr, nvr, static_cast<fmi3Float64*>(v), n);
    case kind::int8:
      return fn.fmi3GetInt8(inst, vr, nvr, static_cast<fmi3Int8*>(v), n);
    case kind::uint8:
      return fn.fmi3GetUInt8(inst, vr, nvr, static_cast<fmi3UInt8*>(v), n);
    case kind::int16:
      return fn.fmi3GetInt16(inst, vr, nvr, static_cast<fmi3Int16*>(v), n);
    case kind::uint16:
      return fn.fmi3GetUInt16(inst, vr, nvr, static_cast<fmi3UInt16*>(v), n);
    case kind::int32:
      return fn.fmi3GetInt32(inst, vr, nvr, static_cast<fmi3Int32*>(v), n);
    case kind::uint32:
      return fn.fmi3GetUInt32(inst, vr, nvr, static_cast<fmi3UInt32*>(v), n);
    case kind::uint64:
      return fn.fmi3GetUInt64(inst, vr, nvr, static_cast<fmi3UInt64*>(v), n);
    case kind::boolean:
      return fn.fmi3GetBoolean(inst, vr, nvr, static_cast<fmi3Boolean*>(v), n);
    default:
      return fn.fmi3GetInt64(inst, vr, nvr, static_cast<fmi3Int64*>(v), n);
  }
}

// Set and Get names for messages; Enumeration uses the Int64 functions.
std::string function_name(const char* verb, kind k) {
  const kind shown = k == kind::enumeration ? kind::int64 : k;
  return std::string("fmi3") + verb + std::string(to_string(shown));
}

}  // namespace

void value_io::set_variables(fmi3Instance instance, const std::vector<std::size_t>& vars) {
  for (std::size_t begin = 0; begin < vars.size();) {
    const kind k = d_.variables[vars[begin]].kind;
    std::size_t end = begin;
    vrs_.clear();
    scratch_.clear();
    std::size_t count = 0;
    std::vector<const char*> pointers;
    std::vector<std::size_t> sizes;
    for (; end < vars.size() && d_.variables[vars[end]].kind == k; ++end) {
      const std::size_t i = vars[end];
      vrs_.push_back(d_.variables[i].reference);
      count += d_.variables[i].size();
      scratch_.insert(scratch_.end(), cells_[i].begin(), cells_[i].end());
      for (const auto& t : texts_[i]) {
        pointers.push_back(t.c_str());
        sizes.push_back(t.size());
      }
    }
    const std::string fn_name = function_name("Set", k);
    fmi3Status s = fmi3OK;
    if (k == kind::string) {
      s = bin_.fn.fmi3SetString(instance, vrs_.data(), vrs_.size(), pointers.data(), count);
    } else if (k == kind::binary) {
      std::vector<fmi3Binary> data(pointers.size());
      for (std::size_t j = 0; j < data.size(); ++j) {
        data[j] = reinterpret_cast<fmi3Binary>(pointers[j]);
      }
      s = bin_.fn.fmi3SetBinary(instance, vrs_.data(), vrs_.size(), sizes.data(), data.data(),
                                count);
    } else {
      s = call_set(bin_.fn, k, instance, vrs_.data(), vrs_.size(), scratch_.data(), count);
    }
    check_(context_, fn_name.c_str(), s);
    begin = end;
  }
}

void value_io::get_variables(fmi3Instance instance, const std::vector<std::size_t>& vars) {
  for (std::size_t begin = 0; begin < vars.size();) {
    const kind k = d_.variables[vars[begin]].kind;
    std::size_t end = begin;
    vrs_.clear();
    std::size_t count = 0;
    for (; end < vars.size() && d_.variables[vars[end]].kind == k; ++end) {
      vrs_.push_back(d_.variables[vars[end]].reference);
      count += d_.variables[vars[end]].size();
    }
    const std::string fn_name = function_name("Get", k);
    if (is_text(k)) {
      std::vector<fmi3String> strings(count, nullptr);
      std::vector<fmi3Binary> data(count, nullptr);
      std::vector<std::size_t> sizes(count, 0);
      check_(context_, fn_name.c_str(),
             k == kind::string
                 ? bin_.fn.fmi3GetString(instance, vrs_.data(), vrs_.size(), strings.data(), count)
                 : bin_.fn.fmi3GetBinary(instance, vrs_.data(), vrs_.size(), sizes.data(),
                                         data.data(), count));
      std::size_t at = 0;
      for (std::size_t j = begin; j < end; ++j) {
        for (auto& t : texts_[vars[j]]) {
          if (k == kind::string) {
            t = strings[at] ? strings[at] : "";
          } else {
            const auto* p = reinterpret_cast<const char*>(data[at]);
            t = p ? std::string(p, sizes[at]) : std::string();
          }
          ++at;
        }
      }
    } else {
      scratch_.assign(count * cell_size(k), std::byte{0});
      check_(context_, fn_name.c_str(),
             call_get(bin_.fn, k, instance, vrs_.data(), vrs_.size(), scratch_.data(), count));
      std::size_t at = 0;
      for (std::size_t j = begin; j < end; ++j) {
        auto& cells = cells_[vars[j]];
        std::copy_n(scratch_.begin() + static_cast<std::ptrdiff_t>(at), cells.size(),
                    cells.begin());
        at += cells.size();
      }
    }
    begin = end;
  }
}

std::string value_io::port_name(const touch& t) const {
  for (std::size_t i = 0; i < d_.ports.size(); ++i) {
    if (d_.ports[i].variable == t.variable && d_.ports[i].element == t.element) {
      return name_ + "." + d_.scalar.variables[i].name;
    }
  }
  return name_ + "." + d_.variables[t.variable].name;
}

void value_io::range_error(const touch& t, const std::string& value,
                           const std::string& target) const {
  throw component_error("component '" + name_ + "': value " + value + " of " + port_name(t) +
                        " does not fit " + target);
}

void value_io::store(const touch& t, const value_block& values) {
  const kind k = d_.variables[t.variable].kind;
  if (k == kind::string) {
    texts_[t.variable][t.element] = values.strings[t.position];
    return;
  }
  if (k == kind::binary) {
    const auto bytes = from_hex(values.strings[t.position]);
    if (!bytes) {
      throw component_error("component '" + name_ + "': \"" + values.strings[t.position] +
                            "\" for the Binary variable " + port_name(t) +
                            " is not hex text (two digits per byte)");
    }
    texts_[t.variable][t.element] = *bytes;
    return;
  }
  std::byte* cell = cells_[t.variable].data() + t.element * cell_size(k);
  with_type(k, [&](auto zero) {
    using T = decltype(zero);
    if constexpr (std::is_same_v<T, fmi3Boolean>) {
      write_cell<T>(cell, values.booleans[t.position]);
    } else if constexpr (std::is_floating_point_v<T>) {
      const double x = values.reals[t.position];
      if (std::isfinite(x) && std::fabs(x) > static_cast<double>(std::numeric_limits<T>::max())) {
        range_error(t, text::format_double(x), "FMI 3 " + std::string(to_string(k)));
      }
      write_cell<T>(cell, static_cast<T>(x));
    } else {
      const long long x = values.integers[t.position];
      if (!std::in_range<T>(x)) {
        range_error(t, std::to_string(x), "FMI 3 " + std::string(to_string(k)));
      }
      write_cell<T>(cell, static_cast<T>(x));
    }
  });
}

void value_io::load(const touch& t, value_block& values) const {
  const kind k = d_.variables[t.variable].kind;
  if (is_text(k)) {
    const std::string& text = texts_[t.variable][t.element];
    values.strings[t.position] = k == kind::string ? text : to_hex(text);
    return;
  }
  const std::byte* cell = cells_[t.variable].data() + t.element * cell_size(k);
  with_type(k, [&](auto zero) {
    using T = decltype(zero);
    const T v = read_cell<T>(cell);
    if constexpr (std::is_same_v<T, fmi3Boolean>) {
      values.booleans[t.position] = v;
    } else if constexpr (std::is_floating_point_v<T>) {
      // an infinity or NaN ends the run here instead of flowing into other components
      if (!std::isfinite(v)) {
        const char* text = std::isnan(v) ? "NaN" : v > 0 ? "inf" : "-inf";
        throw component_error("component '" + name_ + "': " + function_name("Get", k) + " gave " +
                              port_name(t) + " = " + text +
                              ", not a finite number (non-finite values are not passed on)");
      }
      values.reals[t.position] = static_cast<double>(v);
    } else {
      if (!std::in_range<int>(v)) {
        range_error(t, std::to_string(v), "Stride's 32-bit integers");
      }
      values.integers[t.position] = static_cast<int>(v);
    }
  });
}

}  // namespace stride::cosim::fmi3
