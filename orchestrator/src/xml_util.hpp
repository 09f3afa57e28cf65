// Small tinyxml2 helpers shared by the modelDescription and system XML readers.
#ifndef STRIDE_COSIM_SRC_XML_UTIL_HPP
#define STRIDE_COSIM_SRC_XML_UTIL_HPP

#include <tinyxml2.h>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace stride::cosim::detail {

/// `text` with every byte outside printable ASCII written as \xHH, for error messages about
/// text that cannot be shown as it is.
inline std::string printable(std::string_view text) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b >= 0x20 && b < 0x7f) {
      out += ch;
    } else {
      out += "\\x";
      out += hex[b >> 4];
      out += hex[b & 15];
    }
  }
  return out;
}

/// The 1-based line of the first byte of `text` that is not part of well-formed UTF-8 (XML's
/// default encoding), or 0 when all of it is. Overlong forms, surrogates and code points above
/// U+10FFFF are not well formed.
inline int first_line_not_utf8(std::string_view text) {
  int line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      if (b == '\n') ++line;
      ++i;
      continue;
    }
    std::size_t n = 0;
    unsigned min = 0;
    unsigned cp = 0;
    if ((b & 0xE0) == 0xC0) {
      n = 1, min = 0x80, cp = b & 0x1F;
    } else if ((b & 0xF0) == 0xE0) {
      n = 2, min = 0x800, cp = b & 0x0F;
    } else if ((b & 0xF8) == 0xF0) {
      n = 3, min = 0x10000, cp = b & 0x07;
    } else {
      return line;
    }
    for (std::size_t k = 1; k <= n; ++k) {
      if (i + k >= text.size()) return line;
      const auto c = static_cast<unsigned char>(text[i + k]);
      if ((c & 0xC0) != 0x80) return line;
      cp = (cp << 6) | (c & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return line;
    i += n + 1;
  }
  return 0;
}

/// The attribute's text, or nullopt.
inline std::optional<std::string> attribute(const tinyxml2::XMLElement* e, const char* name) {
  const char* v = e->Attribute(name);
  if (v == nullptr) return std::nullopt;
  return std::string(v);
}

/// The attribute's text, or `fallback`.
inline std::string attribute_or(const tinyxml2::XMLElement* e, const char* name,
                                std::string fallback = {}) {
  const char* v = e->Attribute(name);
  return v != nullptr ? std::string(v) : std::move(fallback);
}

/// A short description of a tinyxml2 parse error: "mismatched element (XMLElement
/// name=parameter)".
inline std::string describe_error(const tinyxml2::XMLDocument& doc) {
  std::string name = doc.ErrorName() ? doc.ErrorName() : "error";
  if (name.rfind("XML_ERROR_", 0) == 0) name = name.substr(10);
  if (name.rfind("XML_", 0) == 0) name = name.substr(4);
  for (char& c : name)
    c = c == '_' ? ' ' : static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  const std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
  const auto line = full.find("Line number=");
  const auto detail = line == std::string::npos ? std::string::npos : full.find(": ", line);
  if (detail != std::string::npos && detail + 2 < full.size()) {
    name += " (" + full.substr(detail + 2) + ")";
  }
  return name;
}

/// Why `file` cannot be the results file of <record file> (or of Stride's record annotation in
/// an SSP), or "": it must stay inside the output folder and not be a file the run writes itself.
inline std::string record_file_problem(const std::string& file) {
  const std::filesystem::path p(file);
  if (file.empty() || p.is_absolute() || *p.lexically_normal().begin() == "..") {
    return "file=\"" + file + "\" must be a relative path inside the output folder";
  }
  const std::filesystem::path normal = p.lexically_normal();
  if (normal == "manifest.json" || normal == "system.xml") {
    return "file=\"" + file + "\" is a file the run writes itself (manifest.json, system.xml)";
  }
  return {};
}

}  // namespace stride::cosim::detail

#endif  // STRIDE_COSIM_SRC_XML_UTIL_HPP
