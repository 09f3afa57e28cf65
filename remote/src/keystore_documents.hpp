// The texts of a keystore's governance and permissions documents (OMG DDS Security 1.1, builtin
// access control), in the element order of the spec's schemas and with only the attributes Cyclone
// DDS's parser accepts, and reading the domains back from them.
#ifndef STRIDE_REMOTE_KEYSTORE_DOCUMENTS_HPP
#define STRIDE_REMOTE_KEYSTORE_DOCUMENTS_HPP

#include <chrono>
#include <string>
#include <vector>

#include "stride/remote/keystore.hpp"

namespace stride::remote::keystore::documents {

/// One domain rule for `domains`: authenticated participants only, join access control, and
/// discovery, liveliness, RTPS messages and every topic's metadata and data protected at `level`.
std::string governance_xml(const std::vector<int>& domains, protection level);

struct grant {
  std::string name;     ///< the grant's name attribute
  std::string subject;  ///< the certificate's subject exactly as Cyclone prints it (RFC 2253)
  std::chrono::system_clock::time_point not_before, not_after;
  std::vector<int> domains;
};

/// One grant: publish and subscribe of exactly stride_topics() in every partition on the domains,
/// everything else denied.
std::string permissions_xml(const grant& g);

/// UTC as the documents' validity wants it: YYYY-MM-DDTHH:MM:SS.
std::string xml_date(std::chrono::system_clock::time_point t);

/// The domains of a permissions document's allow rules (all grants); throws std::runtime_error
/// saying what is wrong.
std::vector<int> permissions_domains(const std::string& xml);
/// The subject_name of every grant.
std::vector<std::string> permissions_subjects(const std::string& xml);

struct governance_summary {
  std::vector<int> domains;
  protection level = protection::encrypt;
  // submessages or payloads protected again inside each protected message, as keystores made
  // before each message was protected once did: slower, no safer (governance_xml)
  bool protected_inside = false;
};
/// The domains and protection of a governance document's domain rules.
governance_summary read_governance(const std::string& xml);

}  // namespace stride::remote::keystore::documents

#endif  // STRIDE_REMOTE_KEYSTORE_DOCUMENTS_HPP
