// resources/plant.xml of a generated plant FMU: which URDF and profile the binary loads.
#include <tinyxml2.h>

#include <sstream>

#include "stride/robot/plant_fmu.hpp"

namespace stride::robot {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string write_plant_manifest(const plant_manifest& m) {
  std::ostringstream out;
  out.precision(17);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<stride_plant model_name=\"" << escape(m.model_name) << "\" model_identifier=\""
      << escape(m.model_identifier) << "\" urdf=\"" << escape(m.urdf) << "\" profile=\""
      << escape(m.profile) << "\" default_step=\"" << m.default_step << "\">\n";
  if (!m.description.empty()) {
    out << "  <description>" << escape(m.description) << "</description>\n";
  }
  for (const std::string& p : m.package_path) {
    out << "  <package_path folder=\"" << escape(p) << "\"/>\n";
  }
  out << "</stride_plant>\n";
  return out.str();
}

plant_manifest read_plant_manifest(const std::string& path) {
  const auto fail = [&](const std::string& what) -> void {
    throw sdk::model_error(path + ": " + what);
  };
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    fail("cannot read the plant manifest (" + std::string(doc.ErrorStr()) +
         "); is this a plant FMU made by `stride robot-fmu`?");
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (root == nullptr || std::string(root->Name()) != "stride_plant") {
    fail("the root element must be <stride_plant>");
  }
  plant_manifest m;
  const auto text = [&](const char* name, bool required) {
    const char* v = root->Attribute(name);
    if (v == nullptr && required) fail(std::string("<stride_plant> has no ") + name);
    return std::string(v ? v : "");
  };
  m.model_name = text("model_name", true);
  m.model_identifier = text("model_identifier", true);
  m.urdf = text("urdf", true);
  m.profile = text("profile", false);
  if (root->QueryDoubleAttribute("default_step", &m.default_step) != tinyxml2::XML_SUCCESS ||
      !(m.default_step > 0)) {
    fail("<stride_plant default_step> must be a positive number");
  }
  if (const auto* d = root->FirstChildElement("description"); d && d->GetText()) {
    m.description = d->GetText();
  }
  for (const auto* p = root->FirstChildElement("package_path"); p;
       p = p->NextSiblingElement("package_path")) {
    const char* folder = p->Attribute("folder");
    if (folder == nullptr) fail("<package_path> has no folder");
    m.package_path.emplace_back(folder);
  }
  return m;
}

}  // namespace stride::robot
