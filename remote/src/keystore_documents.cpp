#include "keystore_documents.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "stride/common/text.hpp"

namespace stride::remote::keystore {
namespace {

constexpr int k_max_domain = 230;  // the highest domain id DDS Security documents allow

int parse_domain_id(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 3 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw std::invalid_argument("\"" + text + "\" is not a domain id");
  const int id = std::stoi(text);
  if (id > k_max_domain) {
    throw std::invalid_argument("domain " + text + " is out of range (0..230)");
  }
  return id;
}

}  // namespace

std::vector<int> parse_domains(const std::string& list) {
  std::set<int> ids;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::size_t dash = item.find('-');
    if (dash == std::string::npos) {
      ids.insert(parse_domain_id(item));
    } else {
      const int low = parse_domain_id(item.substr(0, dash));
      const int high = parse_domain_id(item.substr(dash + 1));
      if (high < low) throw std::invalid_argument("domain range " + item + " is empty");
      for (int id = low; id <= high; ++id) ids.insert(id);
    }
    start = comma + 1;
  }
  return {ids.begin(), ids.end()};
}

std::string format_domains(const std::vector<int>& domains) {
  const std::set<int> ids(domains.begin(), domains.end());
  std::string out;
  for (auto it = ids.begin(); it != ids.end();) {
    const int low = *it;
    int high = low;
    while (++it != ids.end() && *it == high + 1) ++high;
    if (!out.empty()) out += ',';
    out += std::to_string(low);
    if (high != low) out += '-' + std::to_string(high);
  }
  return out;
}

namespace documents {
namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

const char* const k_xsi = "http://www.w3.org/2001/XMLSchema-instance";

XMLElement* add(XMLElement* parent, const char* name, const std::string& text = {}) {
  XMLElement* e = parent->InsertNewChildElement(name);
  if (!text.empty()) e->SetText(text.c_str());
  return e;
}

// the root <dds> with the only attributes Cyclone's parser accepts (xmlns:xsi and
// xsi:noNamespaceSchemaLocation)
XMLElement* root(XMLDocument& doc, const char* schema) {
  doc.InsertEndChild(doc.NewDeclaration());
  XMLElement* dds = doc.NewElement("dds");
  dds->SetAttribute("xmlns:xsi", k_xsi);
  dds->SetAttribute("xsi:noNamespaceSchemaLocation", schema);
  doc.InsertEndChild(dds);
  return dds;
}

std::string print(const XMLDocument& doc) {
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

// consecutive ids as one id_range
void add_domains(XMLElement* parent, const std::vector<int>& domains) {
  XMLElement* set = add(parent, "domains");
  const std::set<int> ids(domains.begin(), domains.end());
  for (auto it = ids.begin(); it != ids.end();) {
    const int low = *it;
    int high = low;
    while (++it != ids.end() && *it == high + 1) ++high;
    if (low == high) {
      add(set, "id", std::to_string(low));
    } else {
      XMLElement* range = add(set, "id_range");
      add(range, "min", std::to_string(low));
      add(range, "max", std::to_string(high));
    }
  }
}

// publish or subscribe: Stride's topics in every partition (without <partitions> a rule covers
// only the default partition, and Stride's runs use named ones)
void add_criteria(XMLElement* rule, const char* kind) {
  XMLElement* criteria = add(rule, kind);
  XMLElement* topics = add(criteria, "topics");
  for (const std::string& t : stride_topics()) add(topics, "topic", t);
  add(add(criteria, "partitions"), "partition", "*");
}

void parse(XMLDocument& doc, const std::string& xml, const char* what) {
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error(std::string("not a ") + what + " document: " + doc.ErrorStr());
  }
}

const XMLElement* required(const XMLElement* parent, const char* name) {
  const XMLElement* e = parent != nullptr ? parent->FirstChildElement(name) : nullptr;
  if (e == nullptr) throw std::runtime_error(std::string("no <") + name + "> element");
  return e;
}

std::string text(const XMLElement* e) {
  const char* t = e->GetText();
  std::string s = t != nullptr ? t : "";
  const auto first = s.find_first_not_of(" \t\r\n");
  const auto last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

int domain_value(const XMLElement* e) {
  try {
    return parse_domain_id(text(e));
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(error.what());
  }
}

// <id> and <id_range> (a range without <min> starts at 0, one without <max> ends at 230)
void read_domains(const XMLElement* domains, std::set<int>& ids) {
  for (const XMLElement* e = domains->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name == "id") {
      ids.insert(domain_value(e));
    } else if (name == "id_range") {
      const XMLElement* min = e->FirstChildElement("min");
      const XMLElement* max = e->FirstChildElement("max");
      const int low = min != nullptr ? domain_value(min) : 0;
      const int high = max != nullptr ? domain_value(max) : k_max_domain;
      for (int id = low; id <= high; ++id) ids.insert(id);
    }
  }
}

// whether a domain rule's topic rules protect submessages or payloads (any kind but NONE)
bool protects_inside(const XMLElement* domain_rule) {
  const XMLElement* topics = domain_rule->FirstChildElement("topic_access_rules");
  if (topics == nullptr) return false;
  for (const XMLElement* t = topics->FirstChildElement("topic_rule"); t;
       t = t->NextSiblingElement("topic_rule")) {
    for (const char* layer : {"metadata_protection_kind", "data_protection_kind"}) {
      const XMLElement* kind = t->FirstChildElement(layer);
      if (kind != nullptr && kind->GetText() != nullptr && std::string(kind->GetText()) != "NONE")
        return true;
    }
  }
  return false;
}

}  // namespace

// Every message between two participants is protected once, as a whole (rtps_protection_kind),
// with the sending participant's key; submessages and payloads are not protected again inside it.
// Every identity of a keystore may read and write every Stride topic, so the per-writer keys of
// those inner layers would keep nothing from any peer, while they cost 11-17 % of the secure
// walk's time (docs/distributed.md, "Threat model"). Cyclone DDS drops any message from such a
// participant that is not protected as a whole.
std::string governance_xml(const std::vector<int>& domains, protection level) {
  const std::string kind = level == protection::encrypt ? "ENCRYPT" : "SIGN";
  XMLDocument doc;
  XMLElement* dds =
      root(doc, "http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd");
  XMLElement* rule = add(add(dds, "domain_access_rules"), "domain_rule");
  add_domains(rule, domains);
  add(rule, "allow_unauthenticated_participants", "false");
  add(rule, "enable_join_access_control", "true");
  add(rule, "discovery_protection_kind", kind);
  add(rule, "liveliness_protection_kind", kind);
  add(rule, "rtps_protection_kind", kind);
  XMLElement* topic = add(add(rule, "topic_access_rules"), "topic_rule");
  add(topic, "topic_expression", "*");
  add(topic, "enable_discovery_protection", "true");
  add(topic, "enable_liveliness_protection", "true");
  add(topic, "enable_read_access_control", "true");
  add(topic, "enable_write_access_control", "true");
  add(topic, "metadata_protection_kind", "NONE");
  add(topic, "data_protection_kind", "NONE");
  return print(doc);
}

std::string permissions_xml(const grant& g) {
  XMLDocument doc;
  XMLElement* dds =
      root(doc, "http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd");
  XMLElement* grant = add(add(dds, "permissions"), "grant");
  grant->SetAttribute("name", g.name.c_str());
  add(grant, "subject_name", g.subject);
  XMLElement* validity = add(grant, "validity");
  add(validity, "not_before", xml_date(g.not_before));
  add(validity, "not_after", xml_date(g.not_after));
  XMLElement* rule = add(grant, "allow_rule");
  add_domains(rule, g.domains);
  add_criteria(rule, "publish");  // the schema's order: publish, then subscribe
  add_criteria(rule, "subscribe");
  add(grant, "default", "DENY");
  return print(doc);
}

std::string xml_date(std::chrono::system_clock::time_point t) {
  return text::utc_text(t, "%Y-%m-%dT%H:%M:%S");
}

std::vector<int> permissions_domains(const std::string& xml) {
  XMLDocument doc;
  parse(doc, xml, "permissions");
  const XMLElement* permissions = required(required(doc.RootElement(), "permissions"), "grant");
  std::set<int> ids;
  for (const XMLElement* g = permissions; g; g = g->NextSiblingElement("grant")) {
    for (const XMLElement* r = g->FirstChildElement("allow_rule"); r;
         r = r->NextSiblingElement("allow_rule")) {
      read_domains(required(r, "domains"), ids);
    }
  }
  return {ids.begin(), ids.end()};
}

std::vector<std::string> permissions_subjects(const std::string& xml) {
  XMLDocument doc;
  parse(doc, xml, "permissions");
  std::vector<std::string> subjects;
  for (const XMLElement* g = required(required(doc.RootElement(), "permissions"), "grant"); g;
       g = g->NextSiblingElement("grant")) {
    subjects.push_back(text(required(g, "subject_name")));
  }
  return subjects;
}

governance_summary read_governance(const std::string& xml) {
  XMLDocument doc;
  parse(doc, xml, "governance");
  const XMLElement* rules = required(doc.RootElement(), "domain_access_rules");
  governance_summary summary;
  std::set<int> ids;
  for (const XMLElement* r = required(rules, "domain_rule"); r;
       r = r->NextSiblingElement("domain_rule")) {
    read_domains(required(r, "domains"), ids);
    summary.protected_inside = summary.protected_inside || protects_inside(r);
  }
  const std::string kind = text(required(required(rules, "domain_rule"), "rtps_protection_kind"));
  if (kind.rfind("ENCRYPT", 0) == 0) {
    summary.level = protection::encrypt;
  } else if (kind.rfind("SIGN", 0) == 0) {
    summary.level = protection::sign;
  } else {
    throw std::runtime_error("rtps_protection_kind " + kind + " is neither ENCRYPT nor SIGN");
  }
  summary.domains.assign(ids.begin(), ids.end());
  return summary;
}

}  // namespace documents
}  // namespace stride::remote::keystore
