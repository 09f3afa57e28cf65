#include "import_xml.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "stride/common/text.hpp"
#include "stride/cosim/error.hpp"
#include "xml_util.hpp"

namespace stride::cosim::detail {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view k_xsi_ns = "http://www.w3.org/2001/XMLSchema-instance";

std::string read_text(const fs::path& path, const std::string& shown) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw validation_error(shown + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// the namespace bound to `prefix` ("" = the default namespace) where `e` stands
std::string_view resolve_prefix(const tinyxml2::XMLElement* e, std::string_view prefix) {
  const std::string declaration = prefix.empty() ? "xmlns" : "xmlns:" + std::string(prefix);
  for (; e != nullptr; e = e->Parent() != nullptr ? e->Parent()->ToElement() : nullptr) {
    if (const char* uri = e->Attribute(declaration.c_str())) return uri;
  }
  return {};
}

std::string_view prefix_of(std::string_view qualified) {
  const auto colon = qualified.find(':');
  return colon == std::string_view::npos ? std::string_view{} : qualified.substr(0, colon);
}

}  // namespace

xml_file::xml_file(const fs::path& path, std::string shown, fs::path root)
    : path_(path), shown_(std::move(shown)), root_(std::move(root)) {
  parse(read_text(path, shown_));
}

xml_file::xml_file(std::string_view text, const fs::path& path, std::string shown)
    : path_(path), shown_(std::move(shown)) {
  parse(text);
}

void xml_file::parse(std::string_view text) {
  if (const int line = first_line_not_utf8(text); line > 0) {
    throw validation_error(shown_ + ":" + std::to_string(line) +
                           ": not UTF-8 text (XML's encoding); save the file as UTF-8");
  }
  doc_.Parse(text.data(), text.size());
  if (doc_.Error()) {
    throw validation_error(source_location{shown_, doc_.ErrorLineNum()}.str() +
                           ": malformed XML: " + describe_error(doc_));
  }
  if (doc_.RootElement() == nullptr) throw validation_error(shown_ + ": no root element");
}

std::string xml_file::where(const tinyxml2::XMLElement& e) const {
  std::string tag = "<" + std::string(e.Name());
  if (const char* name = e.Attribute("name")) tag += " name=\"" + std::string(name) + "\"";
  return at(e).str() + ": " + tag + ">: ";
}

void xml_file::fail(const tinyxml2::XMLElement& e, const std::string& message) const {
  throw validation_error(where(e) + message);
}

std::string_view xml_file::ns(const tinyxml2::XMLElement& e) const {
  return resolve_prefix(&e, prefix_of(e.Name()));
}

std::string_view xml_file::local(const tinyxml2::XMLElement& e) {
  const std::string_view name = e.Name();
  const auto colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

bool xml_file::is(const tinyxml2::XMLElement& e, std::string_view uri,
                  std::string_view name) const {
  return local(e) == name && ns(e) == uri;
}

void xml_file::allow_attributes(const tinyxml2::XMLElement& e,
                                std::initializer_list<std::string_view> allowed) const {
  for (auto* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (name == "xmlns" || name.starts_with("xmlns:")) continue;
    const std::string_view prefix = prefix_of(name);
    if (!prefix.empty() && resolve_prefix(&e, prefix) == k_xsi_ns) continue;
    bool known = false;
    for (const auto allowed_name : allowed) known = known || allowed_name == name;
    if (!known) fail(e, "unknown attribute '" + std::string(name) + "'");
  }
}

std::optional<std::string> xml_file::attribute(const tinyxml2::XMLElement& e,
                                               const char* name) const {
  return detail::attribute(&e, name);
}

std::string xml_file::required(const tinyxml2::XMLElement& e, const char* name) const {
  const char* v = e.Attribute(name);
  if (v == nullptr || *v == '\0') fail(e, std::string("needs a ") + name + " attribute");
  return v;
}

bool xml_file::boolean(const tinyxml2::XMLElement& e, const char* name, bool fallback) const {
  const char* v = e.Attribute(name);
  if (v == nullptr) return fallback;
  const std::string_view s = text::trim(v);
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  fail(e, std::string(name) + "=\"" + v + "\" is not true or false");
}

std::optional<double> xml_file::real(const tinyxml2::XMLElement& e, const char* name) const {
  const char* v = e.Attribute(name);
  if (v == nullptr) return std::nullopt;
  const auto value = text::parse_double(v);
  if (!value || !std::isfinite(*value)) {
    fail(e, std::string(name) + "=\"" + v + "\" is not a finite number");
  }
  return value;
}

duration xml_file::seconds(const tinyxml2::XMLElement& e, std::string_view text,
                           std::string_view what) const {
  try {
    return parse_duration(text::trim(text));
  } catch (const std::exception& ex) {
    fail(e, std::string(what) + ": " + ex.what());
  }
}

fs::path xml_file::resolve(const tinyxml2::XMLElement& e, std::string_view uri,
                           std::string_view what) const {
  std::string why;
  const auto file = uri_to_path(uri, path_.parent_path(), why);
  const std::string named = std::string(what) + " \"" + std::string(uri) + "\"";
  if (!file) fail(e, named + ": " + why);
  if (!root_.empty()) {
    const fs::path rel = file->lexically_relative(root_);
    if (rel.empty() || *rel.begin() == "..") fail(e, named + " lies outside the archive");
  }
  if (!fs::is_regular_file(*file))
    fail(e, named + " not found (looked for " + file->string() + ")");
  return *file;
}

std::unique_ptr<xml_file> xml_file::open(const fs::path& file) const {
  // named inside the archive or folder as this file is ("pair.ssp/params.ssv")
  const fs::path rel = file.lexically_relative(path_.parent_path());
  const std::string shown = rel.empty() || *rel.begin() == ".."
                                ? file.string()
                                : (fs::path(shown_).parent_path() / rel).string();
  return std::make_unique<xml_file>(file, shown, root_);
}

void xml_file::children(
    const tinyxml2::XMLElement& e, const std::vector<child_rule>& rules,
    const std::function<void(const tinyxml2::XMLElement&, std::string_view)>& visit) const {
  std::vector<int> seen(rules.size(), 0);
  int highest = -1;
  std::string expected;
  for (const auto& r : rules) expected += (expected.empty() ? "" : ", ") + std::string(r.local);
  for (auto* c = e.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    std::size_t k = 0;
    for (const auto& r : rules) {
      if (is(*c, r.ns, r.local)) break;
      ++k;
    }
    if (k == rules.size()) {
      fail(*c, "unknown element here (in <" + std::string(e.Name()) + "> the SSP allows " +
                   (expected.empty() ? "no child elements" : expected) + ")");
    }
    const child_rule& r = rules[k];
    if (r.rank < highest)
      fail(*c, "out of order (in <" + std::string(e.Name()) + ">: " + expected + ")");
    if (seen[k]++ > 0 && !r.repeat) fail(*c, "may appear only once here");
    highest = r.rank;
    visit(*c, r.local);
  }
}

const model_description& fmu_facts::of(const fs::path& fmu, const std::string& where) {
  if (auto it = known_.find(fmu); it != known_.end()) return it->second;
  try {
    // only the description is inflated: the binaries are the run's business
    return known_.emplace(fmu, read_archive_description(fmu)).first->second;
  } catch (const std::exception& e) {
    throw validation_error(where + e.what());
  }
}

std::optional<fs::path> uri_to_path(std::string_view uri, const fs::path& base, std::string& why) {
  const auto scheme_end = uri.find(':');
  const auto path_start = uri.find_first_of("/?#");
  std::string_view rest = uri;
  bool file_uri = false;
  if (scheme_end != std::string_view::npos && scheme_end > 0 && scheme_end < path_start) {
    if (!text::iequals(uri.substr(0, scheme_end), "file")) {
      why = "the URI scheme '" + std::string(uri.substr(0, scheme_end)) +
            ":' is not supported (relative references and file: URIs are)";
      return std::nullopt;
    }
    rest.remove_prefix(scheme_end + 1);
    if (rest.starts_with("//")) {
      const auto slash = rest.find('/', 2);
      const std::string_view host = rest.substr(2, slash - 2);
      if (!host.empty() && host != "localhost") {
        why = "file: URIs of another host are not supported";
        return std::nullopt;
      }
      rest = slash == std::string_view::npos ? std::string_view{} : rest.substr(slash);
    }
    file_uri = true;
  }
  if (rest.find_first_of("?#") != std::string_view::npos) {
    why = "queries and fragments (#...) are not supported";
    return std::nullopt;
  }
  std::string decoded;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] != '%') {
      decoded += rest[i];
      continue;
    }
    const auto hex = [&](std::size_t k) {
      return k < rest.size() && std::isxdigit(static_cast<unsigned char>(rest[k])) != 0;
    };
    if (!hex(i + 1) || !hex(i + 2)) {
      why = "malformed percent-encoding";
      return std::nullopt;
    }
    decoded += static_cast<char>(std::stoi(std::string(rest.substr(i + 1, 2)), nullptr, 16));
    i += 2;
  }
  if (decoded.empty() || (file_uri && decoded.front() != '/')) {
    why = "names no file";
    return std::nullopt;
  }
  const fs::path p(decoded);
  return (p.is_absolute() ? p : base / p).lexically_normal();
}

std::string fmu_reference(const fs::path& file, const fs::path& base) {
  const fs::path rel = file.lexically_relative(base);
  std::string ref = !rel.empty() && *rel.begin() != ".." ? rel.generic_string() : file.string();
  return is_bundled_fmu_name(ref) ? "./" + ref : ref;
}

namespace {

// the length of `name` without a trailing copy index "[k]", or its whole length
std::size_t without_copy_index(std::string_view name) {
  if (!name.ends_with(']')) return name.size();
  const auto open = name.rfind('[');
  if (open == std::string_view::npos || open == 0) return name.size();
  const std::string_view digits = name.substr(open + 1, name.size() - open - 2);
  const bool number = !digits.empty() && digits.front() != '0' &&
                      digits.find_first_not_of("0123456789") == std::string_view::npos;
  return number ? open : name.size();
}

}  // namespace

std::string component_name_problem(std::string_view name, bool copy_index) {
  if (copy_index && !name.empty()) {
    const std::size_t base = without_copy_index(name);
    // a copy's name is right when its member's name is
    if (base < name.size()) return component_name_problem(name.substr(0, base), false);
  }
  if (name.empty()) return "the name is empty";
  if (name.find('.') != std::string_view::npos) {
    return "the name \"" + std::string(name) +
           "\" holds a '.', which Stride keeps for the names of nested systems";
  }
  if (name.find_first_of(" \t\r\n*?[]") != std::string_view::npos) {
    return "the name \"" + std::string(name) +
           "\" holds blanks, '*', '?' or brackets, which Stride's names do not allow";
  }
  return {};
}

std::string default_system_name(const fs::path& shown) {
  const std::string file = shown.filename().string();
  if (file != "SystemStructure.ssd" && file != "OspSystemStructure.xml") {
    return shown.stem().string();
  }
  fs::path parent = shown.parent_path();
  if (parent.empty() || parent.filename() == "." || parent.filename() == "..") {
    parent = fs::absolute(shown).lexically_normal().parent_path();
  }
  const std::string name =
      parent.extension() == ".ssp" ? parent.stem().string() : parent.filename().string();
  return name.empty() ? "system" : name;
}

log_sink sink_or_stderr(const log_sink& log) {
  return log ? log : stderr_log_sink(log_level::warning);
}

}  // namespace stride::cosim::detail
