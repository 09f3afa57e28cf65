#include "stride/suite/suite.hpp"

#include <tinyxml2.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "stride/cosim/error.hpp"
#include "stride/cosim/time.hpp"

namespace stride::suite {

namespace fs = std::filesystem;

std::optional<std::string> assertion_spec::get(const std::string& name) const {
  const auto it = attributes.find(name);
  if (it == attributes.end()) return std::nullopt;
  return it->second;
}

namespace {

class reader {
 public:
  explicit reader(fs::path file) : file_(std::move(file)) {}

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw cosim::validation_error(cosim::source_location{file_.string(), line}.str() + ": " +
                                  message);
  }
  cosim::source_location at(const tinyxml2::XMLElement* e) const {
    return {file_.string(), e->GetLineNum()};
  }
  std::string required(const tinyxml2::XMLElement* e, const char* name) const {
    const char* v = e->Attribute(name);
    if (v == nullptr || *v == '\0') {
      fail(e->GetLineNum(), std::string("<") + e->Name() + "> needs a " + name + " attribute");
    }
    return v;
  }
  void only(const tinyxml2::XMLElement* e, std::initializer_list<std::string_view> allowed) const {
    for (auto* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
      bool ok = false;
      for (auto n : allowed) ok = ok || n == a->Name();
      if (!ok) {
        fail(e->GetLineNum(),
             std::string("unknown attribute '") + a->Name() + "' on <" + e->Name() + ">");
      }
    }
  }

  suite_spec read(const tinyxml2::XMLDocument& doc) const {
    if (doc.Error()) {
      fail(doc.ErrorLineNum(),
           std::string("malformed XML: ") + (doc.ErrorStr() ? doc.ErrorStr() : ""));
    }
    const auto* root = doc.RootElement();
    if (root == nullptr || std::string_view(root->Name()) != "suite") {
      fail(root ? root->GetLineNum() : 0, "the root element must be <suite>");
    }
    only(root, {"name", "version"});
    if (const char* v = root->Attribute("version"); v && std::string_view(v) != "1") {
      fail(root->GetLineNum(),
           std::string("unsupported suite format version \"") + v + "\" (expected 1)");
    }
    suite_spec s;
    s.file = file_;
    s.name = root->Attribute("name") ? root->Attribute("name") : file_.stem().string();
    check_folder_name(root->GetLineNum(), "suite", s.name);
    std::set<std::string> names;
    for (auto* e = root->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      if (std::string_view(e->Name()) != "case") {
        fail(e->GetLineNum(),
             std::string("unknown element <") + e->Name() + "> in <suite> (expected case)");
      }
      case_spec c = read_case(e);
      if (!names.insert(c.name).second) {
        fail(e->GetLineNum(), "duplicate case name \"" + c.name + "\"");
      }
      s.cases.push_back(std::move(c));
    }
    if (s.cases.empty()) fail(root->GetLineNum(), "the suite has no <case>");
    return s;
  }

  // a time attribute checked before anything runs (the run checks it against the system again)
  std::optional<std::string> seconds(const tinyxml2::XMLElement* e, const char* name,
                                     bool positive) const {
    const char* v = e->Attribute(name);
    if (v == nullptr) return std::nullopt;
    try {
      const cosim::duration d = cosim::parse_duration(v);
      if (positive ? d.count() <= 0 : d.count() < 0) {
        fail(e->GetLineNum(), std::string(name) + "=\"" + v + "\" must be " +
                                  (positive ? "positive" : "at least 0"));
      }
    } catch (const std::logic_error& x) {
      fail(e->GetLineNum(),
           std::string(name) + "=\"" + v + "\" is not a time in seconds (" + x.what() + ")");
    }
    return std::string(v);
  }

  // names that become folder names (the cases' runs, the default output folder)
  void check_folder_name(int line, const char* what, const std::string& name) const {
    if (name.empty() ||
        name.find_first_not_of(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") !=
            std::string::npos ||
        name.front() == '.') {
      fail(line, std::string(what) + " name \"" + name +
                     "\" may hold only letters, digits, '_', '-' and '.' (it names a folder)");
    }
  }

  case_spec read_case(const tinyxml2::XMLElement* e) const {
    only(e, {"name", "system", "stop", "interval"});
    case_spec c;
    c.where = at(e);
    c.name = required(e, "name");
    check_folder_name(e->GetLineNum(), "case", c.name);
    c.system = file_.parent_path() / required(e, "system");
    c.stop_time = seconds(e, "stop", false);
    c.record_interval = seconds(e, "interval", true);
    for (auto* a = e->FirstChildElement(); a != nullptr; a = a->NextSiblingElement()) {
      if (std::string_view(a->Name()) == "set") {
        only(a, {"variable", "value"});
        const char* value = a->Attribute("value");
        if (value == nullptr) fail(a->GetLineNum(), "<set> needs a value attribute");
        c.sets.push_back(required(a, "variable") + "=" + value);
        continue;
      }
      assertion_spec s;
      s.kind = a->Name();
      s.where = at(a);
      for (auto* attr = a->FirstAttribute(); attr != nullptr; attr = attr->Next()) {
        s.attributes[attr->Name()] = attr->Value();
      }
      c.assertions.push_back(std::move(s));
    }
    if (c.assertions.empty()) fail(e->GetLineNum(), "case \"" + c.name + "\" has no assertion");
    return c;
  }

 private:
  fs::path file_;
};

}  // namespace

suite_spec parse_suite_text(const std::string& xml, const fs::path& file) {
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  return reader(file).read(doc);
}

suite_spec parse_suite_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw cosim::validation_error(file.string() + ": cannot open the suite file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_suite_text(text.str(), file);
}

}  // namespace stride::suite
