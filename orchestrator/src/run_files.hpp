// What a run writes into its folder besides results: JSON text and whole files.
#ifndef STRIDE_COSIM_RUN_FILES_HPP
#define STRIDE_COSIM_RUN_FILES_HPP

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include "stride/common/files.hpp"
#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"

namespace stride::cosim {

inline std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

inline std::string json_number(double d) {
  std::ostringstream s;
  s.precision(6);
  s << d;
  return s.str();
}

inline std::string utc_now() {
  return text::utc_text(std::chrono::system_clock::now(), "%Y-%m-%dT%H:%M:%SZ");
}

/// Creates the output folder `dir` (and its parents). \throws error naming it and the reason.
inline void create_output_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw error("cannot create the output folder " + dir.string() + ": " + ec.message());
}

/// Writes a whole file atomically (see common::write_file_atomically). \throws error.
/// The value of a top-level field of a manifest.json as written above: a string without its
/// quotes, a number as written; "" when the field is absent or the file unreadable.
inline std::string read_manifest_field(const std::filesystem::path& manifest,
                                       const std::string& key) {
  std::ifstream in(manifest, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::string quoted = "\n  \"" + key + "\": ";
  const auto at = s.find(quoted);
  if (at == std::string::npos) return {};
  auto begin = at + quoted.size();
  if (begin < s.size() && s[begin] == '"') {
    ++begin;
    std::string value;
    for (auto i = begin; i < s.size() && s[i] != '"'; ++i) {
      if (s[i] == '\\' && i + 1 < s.size()) ++i;  // \" and \\ as json_string writes them
      value += s[i];
    }
    return value;
  }
  const auto end = s.find_first_of(",\n}", begin);
  return s.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

inline void write_file(const std::filesystem::path& file, const std::string& text) {
  try {
    common::write_file_atomically(file, text);
  } catch (const std::runtime_error& e) {
    throw error(e.what());
  }
}

}  // namespace stride::cosim

#endif  // STRIDE_COSIM_RUN_FILES_HPP
