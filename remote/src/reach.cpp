#include "stride/remote/reach.hpp"

#include <tinyxml2.h>

#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

#include "stride/common/files.hpp"

namespace stride::remote {

namespace {

// Cyclone expands ${NAME} in its configuration from the environment: so do we
std::string expand(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::size_t close = text.find('}', i);
    if (text.substr(i, 2) == "${" && close != std::string_view::npos) {
      const char* v = std::getenv(std::string(text.substr(i + 2, close - i - 2)).c_str());
      out += v != nullptr ? v : "";
      i = close;
    } else {
      out += text[i];
    }
  }
  return out;
}

bool is_loopback(const std::string& where) {
  return where.starts_with("127.") || where == "::1" || where == "[::1]" || where == "localhost" ||
         where == "lo" || where.starts_with("localhost:") || where.starts_with("127.0.0.1:");
}

// what one configuration text says: the interfaces and peers it names
struct findings {
  std::vector<std::string> interfaces;
  std::vector<std::string> peers;
  bool autodetermine = false;
};

void scan(const tinyxml2::XMLElement* e, findings& f) {
  for (; e != nullptr; e = e->NextSiblingElement()) {
    const std::string_view name = e->Name();
    if (name == "NetworkInterface") {
      const char* address = e->Attribute("address");
      const char* iface = e->Attribute("name");
      if (address != nullptr) f.interfaces.push_back(expand(address));
      if (iface != nullptr) f.interfaces.push_back(expand(iface));
      if (e->BoolAttribute("autodetermine", false) || (address == nullptr && iface == nullptr))
        f.autodetermine = true;
    } else if (name == "NetworkInterfaceAddress" && e->GetText() != nullptr) {
      f.interfaces.push_back(expand(e->GetText()));
    } else if (name == "Peer" && e->Attribute("address") != nullptr) {
      f.peers.push_back(expand(e->Attribute("address")));
    }
    scan(e->FirstChildElement(), f);
  }
}

// the configuration texts in effect: a file, or CYCLONEDDS_URI's items (files or inline XML)
std::vector<std::pair<std::string, std::string>> config_texts(const dds_settings& s) {
  std::vector<std::string> files;
  std::vector<std::pair<std::string, std::string>> texts;  // (where, text)
  if (!s.config_file.empty()) {
    files.push_back(s.config_file.string());
  } else if (const char* uri = std::getenv("CYCLONEDDS_URI"); uri != nullptr && *uri != '\0') {
    const std::string value = expand(uri);
    if (value.find('<') != std::string::npos) {
      texts.emplace_back("CYCLONEDDS_URI", "<root>" + value + "</root>");
    } else {
      std::stringstream items(value);
      for (std::string item; std::getline(items, item, ',');) {
        if (item.starts_with("file://")) item = item.substr(7);
        if (!item.empty()) files.push_back(item);
      }
    }
  }
  for (const std::string& file : files) {
    try {
      texts.emplace_back(file, common::read_file(file));
    } catch (const std::runtime_error&) {
      texts.emplace_back(file, std::string());  // unreadable: said by the caller
    }
  }
  return texts;
}

}  // namespace

std::string reach_beyond_loopback(const dds_settings& settings) {
  const auto texts = config_texts(settings);
  if (texts.empty()) return "";  // the shipped loopback configuration
  findings f;
  for (const auto& [where, text] : texts) {
    tinyxml2::XMLDocument doc;
    if (text.empty() || doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
      return "its DDS configuration " + where + " cannot be read to check where it reaches";
    }
    scan(doc.FirstChildElement(), f);
  }
  const std::string source = texts.front().first;
  if (f.autodetermine || f.interfaces.empty()) {
    return "its DDS configuration " + source +
           " does not restrict DDS to the loopback interface (Cyclone then picks a network "
           "interface)";
  }
  for (const auto& i : f.interfaces) {
    if (!is_loopback(i)) {
      return "its DDS configuration " + source + " uses network interface '" + i + "'";
    }
  }
  for (const auto& p : f.peers) {
    if (!is_loopback(p)) return "its DDS configuration " + source + " names peer '" + p + "'";
  }
  return "";
}

}  // namespace stride::remote
