// `show`: what a keystore or one of its identities holds, read back from the files and checked
// (signatures against the CA, the key file's mode), for people.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "keystore_documents.hpp"
#include "keystore_io.hpp"
#include "keystore_x509.hpp"
#include "stride/common/files.hpp"
#include "stride/remote/keystore.hpp"

namespace stride::remote::keystore {
namespace {

namespace fs = std::filesystem;
using sys_clock = std::chrono::system_clock;

std::string status(const certificate_info& c) {
  const auto now = sys_clock::now();
  if (now < c.not_before) return "not yet valid";
  if (now >= c.not_after) return "expired";
  return "valid";
}

std::string validity(const certificate_info& c) {
  return io::date(c.not_before) + " to " + io::date(c.not_after) + " (" + status(c) + ")";
}

// "mode 0600", with what to do when others can read the key
std::string key_mode(const fs::path& key) {
  std::error_code ec;
  const auto st = fs::status(key, ec);
  if (ec || !fs::exists(st)) throw std::runtime_error(key.string() + ": missing");
  const unsigned mode = static_cast<unsigned>(st.permissions() & fs::perms::all);
  char octal[8];
  std::snprintf(octal, sizeof octal, "%04o", mode);
  std::string text = key.filename().string() + ", mode " + octal;
  if (mode != 0600) text += " (should be 0600: run chmod 600 " + key.string() + ")";
  return text;
}

// the text of a signed document, verified against `ca`
std::string verified_text(const fs::path& file, const fs::path& ca) {
  const std::string signed_text = common::read_file(file);
  const std::string ca_text = common::read_file(ca);
  return io::about(file, [&] {
    const x509::cert_ptr signer =
        io::about(ca, [&] { return x509::certificate_from_pem(ca_text); });
    return x509::smime_content(signed_text, signer.get());
  });
}

void row(std::ostringstream& out, const char* label, const std::string& value) {
  char padded[16];
  std::snprintf(padded, sizeof padded, "%-12s", label);
  out << padded << value << '\n';
}

std::vector<fs::path> identity_dirs(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory() && fs::exists(entry.path() / "cert.pem"))
      found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::string show_keystore(const fs::path& dir) {
  const fs::path ca = dir / "ca.cert.pem";
  const fs::path governance_file = dir / "governance.p7s";
  const certificate_info info = read_certificate(ca);
  const std::string governance_xml = verified_text(governance_file, ca);
  const auto governance =
      io::about(governance_file, [&] { return documents::read_governance(governance_xml); });
  std::ostringstream out;
  row(out, "keystore", dir.string());
  row(out, "CA", info.subject);
  row(out, "valid", validity(info));
  row(out, "CA key", "private/" + key_mode(dir / "private" / "ca.key.pem"));
  row(out, "domains", format_domains(governance.domains) + " (governance.p7s, signed by the CA)");
  row(out, "protection",
      std::string(governance.level == protection::encrypt ? "encrypt" : "sign") +
          (governance.protected_inside
               ? ", each message's submessages and payloads protected again inside it (11-17 % "
                 "slower, and no safer than a new keystore of `stride security init`, which "
                 "protects each message once; docs/distributed.md)"
               : ""));
  const auto identities = identity_dirs(dir);
  row(out, "identities",
      identities.empty() ? "none (add one with `stride security add`)"
                         : std::to_string(identities.size()));
  for (const fs::path& id : identities) {
    const certificate_info c = read_certificate(id / "cert.pem");
    const bool ours = issued_by(id / "cert.pem", ca);
    out << "  " << id.filename().string() << ": " << c.subject << ", until "
        << io::date(c.not_after) << " (" << status(c) << (ours ? "" : ", NOT issued by this CA")
        << ")\n";
  }
  return out.str();
}

std::string show_identity(const fs::path& dir) {
  const fs::path cert = dir / "cert.pem";
  const fs::path permissions = dir / "permissions.p7s";
  const certificate_info info = read_certificate(cert);
  const bool issued = issued_by(cert, dir / "identity_ca.cert.pem");
  const fs::path permissions_ca = dir / "permissions_ca.cert.pem";
  // first for its message when the signature does not verify
  const std::vector<int> domains = permitted_domains(permissions, permissions_ca);
  const std::string permissions_xml = verified_text(permissions, permissions_ca);
  const auto subjects =
      io::about(permissions, [&] { return documents::permissions_subjects(permissions_xml); });
  const bool granted = std::find(subjects.begin(), subjects.end(), info.subject) != subjects.end();
  std::ostringstream out;
  row(out, "identity", dir.string());
  row(out, "subject", info.subject);
  row(out, "issuer", info.issuer);
  row(out, "valid", validity(info));
  row(out, "issued by", std::string("identity_ca.cert.pem: ") + (issued ? "yes" : "NO"));
  row(out, "domains",
      format_domains(domains) +
          " (permissions.p7s, signature verified against permissions_ca.cert.pem)");
  row(out, "grant", granted ? "for this subject" : "NOT for this subject (permissions.p7s)");
  row(out, "key", key_mode(dir / "key.pem"));
  return out.str();
}

}  // namespace

std::string show(const fs::path& dir_or_identity) {
  const fs::path& p = dir_or_identity;
  std::error_code ec;
  if (!fs::is_directory(p, ec)) {
    throw std::runtime_error(p.string() + ": not a folder (give a keystore or an identity in it)");
  }
  if (fs::exists(p / "ca.cert.pem") && fs::exists(p / "private")) return show_keystore(p);
  if (fs::exists(p / "cert.pem")) return show_identity(p);
  throw std::runtime_error(p.string() +
                           ": neither a keystore (no ca.cert.pem) nor an identity (no cert.pem)");
}

}  // namespace stride::remote::keystore
