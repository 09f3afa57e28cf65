// DDS Security keystores for Stride's workers (docs/distributed.md): one CA that is both the
// identity CA and the permissions CA, a signed governance document, and one self-contained folder
// per identity (certificate, private key, signed permissions) in the layout Cyclone DDS's builtin
// security plugins read. Like ROS 2's SROS2 keystores, made with OpenSSL.
#ifndef STRIDE_REMOTE_KEYSTORE_HPP
#define STRIDE_REMOTE_KEYSTORE_HPP

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stride::remote::keystore {

/// How the governance protects discovery, liveliness, RTPS messages and topic data.
enum class protection { encrypt, sign };

struct init_options {
  std::vector<int> domains{0};  ///< DDS domain ids 0..230 the keystore governs
  protection level = protection::encrypt;
  int valid_days = 3650;  ///< validity of the CA, 1..36500
};

struct identity_options {
  int valid_days = 365;  ///< 1..36500; cut to the CA's expiry if it would outlive the CA
  /// Start of the validity; default now (an identity that is not valid yet, or expired, for tests).
  std::optional<std::chrono::system_clock::time_point> not_before;
};

/// Creates a keystore in `dir` (must not exist or be empty): refuses to overwrite. Returns the
/// lines to print, one per file made. Throws std::runtime_error naming the file on any failure,
/// after removing what it made.
std::vector<std::string> init(const std::filesystem::path& dir, const init_options& o);

/// Adds identity NAME under dir/NAME/ (refuses if it exists). NAME: [A-Za-z0-9_.-]+ only.
/// Returns the lines to print, one per file made.
std::vector<std::string> add(const std::filesystem::path& dir, const std::string& name,
                             const identity_options& o);

/// Human-readable description of a keystore dir (CA subject, validity, domains, protection,
/// identities) or of one identity dir (subject, issuer, validity, domains of its permissions,
/// whether the key file mode is 0600). Throws naming the file when something is missing or
/// unreadable.
std::string show(const std::filesystem::path& dir_or_identity);

struct certificate_info {
  std::string subject;  ///< RFC 2253, as Cyclone DDS prints it (e.g. "CN=alice,O=...")
  std::string issuer;   ///< RFC 2253
  std::chrono::system_clock::time_point not_before, not_after;
};

/// The subject, issuer and validity of a PEM certificate; throws naming the file.
certificate_info read_certificate(const std::filesystem::path& pem);

/// Whether the certificate's signature verifies against that CA alone (no other trust anchor;
/// validity times are not checked: read_certificate gives them). Throws naming an unreadable file.
bool issued_by(const std::filesystem::path& cert_pem, const std::filesystem::path& ca_pem);

/// The domain ids a permissions document (the signed .p7s, or the .xml) allows, verified against
/// `permissions_ca` when given (a .xml cannot be). Throws naming the file if the signature does not
/// verify or it cannot be read.
std::vector<int> permitted_domains(const std::filesystem::path& permissions,
                                   const std::filesystem::path& permissions_ca = {});

/// Stride's DDS topics: stride_remote_request, stride_remote_reply, stride_remote_worker_info,
/// stride_table_update, stride_table_state.
const std::vector<std::string>& stride_topics();

/// Parses a domain list such as "0,3-5" (ids 0..230) into sorted unique ids; throws
/// std::invalid_argument saying what is wrong.
std::vector<int> parse_domains(const std::string& list);

/// The inverse of parse_domains: "0,3-5".
std::string format_domains(const std::vector<int>& domains);

/// Whether `name` can name an identity: [A-Za-z0-9_.-]+, not "." or "..", at most 64 characters.
bool valid_identity_name(const std::string& name);

/// Checks the identity in `dir` for a participant on `domain`: certificate and CA within their
/// validity, the certificate issued by the identity CA, permissions signed by the permissions CA
/// and covering `domain`. \throws std::runtime_error naming the file and what to do.
void check_identity(const std::filesystem::path& dir, int domain);

}  // namespace stride::remote::keystore

#endif  // STRIDE_REMOTE_KEYSTORE_HPP
