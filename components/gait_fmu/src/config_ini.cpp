#include "stride/gait/config_ini.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "stride/common/files.hpp"
#include "text_util.hpp"

namespace stride::gait {

namespace {

// the framework's config.ini is a few kB; a file a thousand times larger is a mistake
constexpr std::size_t k_max_ini_bytes = 4 * 1024 * 1024;

using detail::iequals;
using detail::trim;

/// Legacy r1 keys (renamed in April 2011) -> current key; ignored like the framework does.
struct legacy_key {
  const char* key;
  const char* replacement;
};
constexpr legacy_key legacy_keys[] = {
    {"a_offset", "yaw_offset"},
    {"p_offset", "pitch_offset"},
    {"r_offset", "roll_offset"},
    {"z_move_amplitude", "foot_height"},
    {"y_swap_amplitude", "swing_right_left"},
    {"z_swap_amplitude", "swing_top_down"},
};

const legacy_key* find_legacy(std::string_view key) {
  for (const legacy_key& k : legacy_keys)
    if (iequals(k.key, key)) return &k;
  return nullptr;
}

ini_line parse_line(std::string text, std::string eol, bool first) {
  ini_line line;
  line.text = std::move(text);
  line.eol = std::move(eol);
  std::string_view view(line.text);
  std::size_t start = 0;
  if (first && view.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // UTF-8 byte order mark
  while (start < view.size() && detail::is_space(view[start])) ++start;
  const std::string_view body = trim(view.substr(start));
  if (body.empty()) {
    line.type = ini_line::kind::blank;
    return line;
  }
  if (body.front() == ';' || body.front() == '#') {
    line.type = ini_line::kind::comment;
    return line;
  }
  if (body.front() == '[') {
    const std::size_t close = body.find(']');
    if (close == std::string_view::npos) {
      line.type = ini_line::kind::invalid;
      return line;
    }
    line.type = ini_line::kind::section;
    line.name = std::string(trim(body.substr(1, close - 1)));
    return line;
  }
  const std::size_t sep = view.find_first_of("=:", start);
  if (sep == std::string_view::npos || trim(view.substr(start, sep - start)).empty()) {
    line.type = ini_line::kind::invalid;
    return line;
  }
  line.type = ini_line::kind::entry;
  line.name = std::string(trim(view.substr(start, sep - start)));
  std::size_t vb = sep + 1;
  while (vb < view.size() && detail::is_space(view[vb])) ++vb;
  // the value ends at a ';' or '#' outside double quotes
  std::size_t ve = vb;
  bool quoted = false;
  for (; ve < view.size(); ++ve) {
    const char c = view[ve];
    if (c == '"') quoted = !quoted;
    if (!quoted && (c == ';' || c == '#')) break;
  }
  while (ve > vb && detail::is_space(view[ve - 1])) --ve;
  line.value_begin = vb;
  line.value_end = ve;
  std::string_view value = view.substr(vb, ve - vb);
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
    value = value.substr(1, value.size() - 2);
  line.value = std::string(value);
  return line;
}

std::string location(const ini_document& doc, std::size_t index) {
  return doc.source() + ":" + std::to_string(index + 1);
}

bool needs_quotes(std::string_view v) {
  return v.find_first_of(";#") != std::string_view::npos ||
         (!v.empty() && (detail::is_space(v.front()) || detail::is_space(v.back())));
}

std::string fixed6(double v) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%f", v);
  return buf;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

ini_document ini_document::parse(std::string_view text, std::string source) {
  ini_document doc;
  doc.source_ = std::move(source);
  std::size_t pos = 0;
  bool first = true;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view eol;
    std::string_view content;
    if (nl == std::string_view::npos) {
      content = text.substr(pos);
      pos = text.size();
    } else {
      content = text.substr(pos, nl - pos);
      eol = "\n";
      if (!content.empty() && content.back() == '\r') {
        content.remove_suffix(1);
        eol = "\r\n";
      }
      pos = nl + 1;
    }
    if (first && !eol.empty()) doc.eol_ = std::string(eol);
    doc.lines_.push_back(parse_line(std::string(content), std::string(eol), first));
    first = false;
  }
  return doc;
}

ini_document ini_document::load(const std::filesystem::path& file) {
  // a device or a pipe (/dev/zero) would be read until memory runs out
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec)) {
    throw config_error(file.string() + ": not a regular file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw config_error(file.string() + ": cannot open file");
  std::string text;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > k_max_ini_bytes) {
      throw config_error(file.string() + ": larger than " + std::to_string(k_max_ini_bytes) +
                         " bytes: not a config.ini");
    }
  }
  if (in.bad()) throw config_error(file.string() + ": read error");
  return parse(text, file.string());
}

void ini_document::save(const std::filesystem::path& file) const {
  try {
    common::write_file_atomically(file, str());
  } catch (const std::runtime_error& e) {
    throw config_error(e.what());
  }
}

std::string ini_document::str() const {
  std::string s;
  for (const ini_line& l : lines_) {
    s += l.text;
    s += l.eol;
  }
  return s;
}

std::optional<std::size_t> ini_document::find_section(std::string_view section) const {
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (lines_[i].type == ini_line::kind::section && iequals(lines_[i].name, section)) return i;
  return std::nullopt;
}

std::optional<std::size_t> ini_document::find_entry(std::string_view section,
                                                    std::string_view key) const {
  const auto header = find_section(section);
  if (!header) return std::nullopt;
  for (std::size_t i = *header + 1; i < lines_.size(); ++i) {
    if (lines_[i].type == ini_line::kind::section) break;
    if (lines_[i].type == ini_line::kind::entry && iequals(lines_[i].name, key)) return i;
  }
  return std::nullopt;
}

std::optional<std::string> ini_document::get(std::string_view section, std::string_view key) const {
  const auto i = find_entry(section, key);
  if (!i) return std::nullopt;
  return lines_[*i].value;
}

void ini_document::set(std::string_view section, std::string_view key, std::string_view value) {
  if (value.find_first_of("\r\n") != std::string_view::npos ||
      key.find_first_of("\r\n=:;#[") != std::string_view::npos || trim(key).empty() ||
      section.find_first_of("\r\n]") != std::string_view::npos)
    throw std::invalid_argument("ini_document::set: invalid section, key or value for key '" +
                                std::string(key) + "'");
  std::string written;
  if (needs_quotes(value)) written += '"';
  written += value;
  if (needs_quotes(value)) written += '"';

  if (const auto i = find_entry(section, key)) {
    ini_line& l = lines_[*i];
    l.text = l.text.substr(0, l.value_begin) + written + l.text.substr(l.value_end);
    l.value_end = l.value_begin + written.size();
    l.value = std::string(value);
    return;
  }
  const std::string text = std::string(key) + "=" + written;
  auto insert_at = [&](std::size_t pos, ini_line line) {
    if (pos > 0 && lines_[pos - 1].eol.empty()) lines_[pos - 1].eol = eol_;
    if (pos < lines_.size() && line.eol.empty()) line.eol = eol_;
    lines_.insert(lines_.begin() + static_cast<std::ptrdiff_t>(pos), std::move(line));
  };
  if (const auto header = find_section(section)) {
    std::size_t pos = *header + 1;  // after the header or the section's last entry
    for (std::size_t i = *header + 1; i < lines_.size(); ++i) {
      if (lines_[i].type == ini_line::kind::section) break;
      if (lines_[i].type == ini_line::kind::entry || lines_[i].type == ini_line::kind::invalid)
        pos = i + 1;
    }
    insert_at(pos, parse_line(text, eol_, false));
    return;
  }
  if (!lines_.empty() && lines_.back().type != ini_line::kind::blank)
    insert_at(lines_.size(), parse_line("", eol_, false));
  std::string header_text(1, '[');
  header_text += section;
  header_text += ']';
  insert_at(lines_.size(), parse_line(header_text, eol_, false));
  insert_at(lines_.size(), parse_line(text, eol_, false));
}

// ---------------------------------------------------------------------------------------------

walking_params read_walking_config(const ini_document& doc, walking_params base,
                                   std::vector<std::string>* warnings) {
  const auto warn = [&](std::string message) {
    if (warnings != nullptr) warnings->push_back(std::move(message));
  };
  const auto header = doc.find_section(walking_config_section);
  if (!header)
    throw config_error(doc.source() + ": no [" + std::string(walking_config_section) + "] section");
  const std::vector<ini_line>& lines = doc.lines();
  std::vector<const param_info*> seen;
  std::vector<std::size_t> seen_line;
  std::size_t i = *header + 1;
  for (; i < lines.size() && lines[i].type != ini_line::kind::section; ++i) {
    const ini_line& l = lines[i];
    if (l.type == ini_line::kind::invalid)
      throw config_error(location(doc, i) + ": expected 'key = value' in [" +
                         std::string(walking_config_section) + "], got '" + l.text + "'");
    if (l.type != ini_line::kind::entry) continue;
    const param_info* info = find_param(l.name);
    if (info == nullptr) {
      if (const legacy_key* legacy = find_legacy(l.name))
        warn(location(doc, i) + ": legacy key '" + l.name + "' is ignored (the framework reads '" +
             legacy->replacement + "' since 2011)");
      else
        warn(location(doc, i) + ": unknown key '" + l.name + "' is ignored");
      continue;
    }
    bool repeated = false;
    for (std::size_t k = 0; k < seen.size(); ++k) {
      if (seen[k] == info) {
        warn(location(doc, i) + ": repeated key '" + l.name + "' is ignored (line " +
             std::to_string(seen_line[k] + 1) + " is used)");
        repeated = true;
      }
    }
    if (repeated) continue;
    seen.push_back(info);
    seen_line.push_back(i);

    const auto value = detail::parse_double(l.value);
    if (!value)
      throw config_error(location(doc, i) + ": key '" + l.name + "': value '" + l.value +
                         "' is not a number");
    if (*value == ini_absent_sentinel) continue;  // framework: -1024 = absent
    try {
      set_param(base, *info, *value);
    } catch (const std::invalid_argument& e) {
      throw config_error(location(doc, i) + ": key '" + l.name + "': " + e.what());
    }
  }
  for (; i < lines.size(); ++i)
    if (lines[i].type == ini_line::kind::section && iequals(lines[i].name, walking_config_section))
      warn(location(doc, i) + ": repeated section [" + lines[i].name +
           "] is ignored (only the first one is read)");
  return base;
}

walking_params read_walking_config(const std::filesystem::path& file, walking_params base,
                                   std::vector<std::string>* warnings) {
  return read_walking_config(ini_document::load(file), base, warnings);
}

std::string format_param_value(const param_info& info, const walking_params& params) {
  if (info.int_member != nullptr) return std::to_string(params.*info.int_member);
  double v = params.*info.real_member;
  if (v == 0) v = 0;  // no "-0.000000"
  const std::string fixed = fixed6(v);
  if (const auto back = detail::parse_double(fixed); back && *back == v) return fixed;
  return detail::format_double(v);
}

void update_walking_config(ini_document& doc, const walking_params& params) {
  const std::string section = doc.find_section(walking_config_section)
                                  ? doc.lines()[*doc.find_section(walking_config_section)].name
                                  : std::string(walking_config_section);
  for (const param_info& info : walking_param_table()) {
    const double v = get_param(params, info);
    if (const auto current = doc.get(section, info.key)) {
      const auto parsed = detail::parse_double(*current);
      if (parsed && *parsed == v && *parsed != ini_absent_sentinel) continue;
    }
    doc.set(section, info.key, format_param_value(info, params));
  }
}

std::string make_walking_config_text(const walking_params& params) {
  std::ostringstream s;
  s << "; DARwIn-OP walking generator parameters, ROBOTIS framework [Walking Config] format.\n"
       "; Lengths in mm, angles in deg, times in ms; a value of -1024 means absent (default).\n"
       "; Written by stride::gait::write_walking_config().\n"
    << "[" << walking_config_section << "]\n";
  for (const param_info& info : walking_param_table())
    s << info.key << "=" << format_param_value(info, params) << "\n";
  return s.str();
}

void write_walking_config(const std::filesystem::path& file, const walking_params& params) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec)) {
    ini_document doc = ini_document::load(file);
    update_walking_config(doc, params);
    doc.save(file);
    return;
  }
  ini_document::parse(make_walking_config_text(params), file.string()).save(file);
}

}  // namespace stride::gait
