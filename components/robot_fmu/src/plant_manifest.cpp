// resources/plant.xml of a generated plant FMU: which URDF and profile the binary loads.
#include <tinyxml2.h>

#include "stride/robot/plant_fmu.hpp"

namespace stride::robot {

std::string write_plant_manifest(const plant_manifest& m) {
  // tinyxml2 writes the escapes
  tinyxml2::XMLPrinter out;
  out.PushHeader(false, true);
  out.OpenElement("stride_plant");
  out.PushAttribute("model_name", m.model_name.c_str());
  out.PushAttribute("model_identifier", m.model_identifier.c_str());
  out.PushAttribute("urdf", m.urdf.c_str());
  out.PushAttribute("profile", m.profile.c_str());
  out.PushAttribute("default_step", m.default_step);
  if (!m.description.empty()) {
    out.OpenElement("description");
    out.PushText(m.description.c_str());
    out.CloseElement();
  }
  for (const std::string& p : m.package_path) {
    out.OpenElement("package_path");
    out.PushAttribute("folder", p.c_str());
    out.CloseElement();
  }
  out.CloseElement();
  return out.CStr();
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
