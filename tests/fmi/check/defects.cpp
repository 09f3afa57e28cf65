#include "defects.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "test_support.hpp"

namespace stride::fmi_check::test {

void PrintTo(const defect& d, std::ostream* os) {
  *os << d.name;
}

const std::string& valid_xml() {
  static const std::string text =
      read_text(std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal.xml");
  return text;
}

const std::string& valid3_xml() {
  static const std::string text =
      read_text(std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_minimal3.xml");
  return text;
}

const std::string& valid_me_xml() {
  static const std::string text =
      read_text(std::filesystem::path(STRIDE_TEST_DATA_DIR) / "valid_me.xml");
  return text;
}

std::string apply(const defect& d, const std::string& base) {
  std::string xml = base;
  for (const auto& [from, to] : d.edits) {
    if (from.starts_with("re:")) {
      const std::regex re(from.substr(3));
      if (!std::regex_search(xml, re)) {
        ADD_FAILURE() << d.name << ": regex matches nothing: " << from;
      }
      xml = std::regex_replace(xml, re, to);
      continue;
    }
    const auto at = xml.find(from);
    if (at == std::string::npos || xml.find(from, at + 1) != std::string::npos) {
      ADD_FAILURE() << d.name << ": edit text must occur exactly once: " << from;
      continue;
    }
    xml.replace(at, from.size(), to);
  }
  return xml;
}

std::string describe(const std::vector<finding>& findings) {
  std::string out;
  for (const auto& f : findings) out += format_finding("md", f) + "\n";
  return out.empty() ? "(no findings)\n" : out;
}

bool has_rule(const std::vector<finding>& findings, std::string_view rule,
              finding::severity level) {
  return std::any_of(findings.begin(), findings.end(),
                     [&](const finding& f) { return f.rule == rule && f.level == level; });
}

std::string defect_name(const testing::TestParamInfo<defect>& info) {
  return info.param.name;
}

}  // namespace stride::fmi_check::test
