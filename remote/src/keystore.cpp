// The keystore's layout and files (keystore.hpp); keys, certificates and signatures are in
// keystore_x509.cpp, the documents' text in keystore_documents.cpp.
#include "stride/remote/keystore.hpp"

#include <stdexcept>

#include "keystore_documents.hpp"
#include "keystore_io.hpp"
#include "keystore_x509.hpp"
#include "stride/common/files.hpp"

namespace stride::remote::keystore {
namespace {

namespace fs = std::filesystem;
using sys_clock = std::chrono::system_clock;

constexpr int k_max_valid_days = 36500;  // Cyclone reads validity dates up to the year 2262

using io::about;
using io::date;
using io::make_directory;
using io::write_new;

void check_valid_days(int days) {
  if (days < 1 || days > k_max_valid_days) {
    throw std::runtime_error("valid days " + std::to_string(days) + " is out of range (1.." +
                             std::to_string(k_max_valid_days) + ")");
  }
}

x509::cert_ptr load_certificate(const fs::path& pem) {
  const std::string text = common::read_file(pem);
  return about(pem, [&] { return x509::certificate_from_pem(text); });
}

std::string made(const fs::path& file, const std::string& what) {
  return "made " + file.string() + " (" + what + ")";
}

// the keystore `dir` as `add` needs it: the CA (certificate and key) and the signed governance
struct keystore_files {
  fs::path dir;
  x509::cert_ptr ca;
  x509::key_ptr ca_key;
  std::string governance_p7s;
  documents::governance_summary governance;
};

keystore_files open_keystore(const fs::path& dir) {
  keystore_files k;
  k.dir = dir;
  const fs::path ca = dir / "ca.cert.pem";
  const fs::path key = dir / "private" / "ca.key.pem";
  const fs::path governance = dir / "governance.p7s";
  if (!fs::exists(ca)) {
    throw std::runtime_error(ca.string() + ": missing; is " + dir.string() +
                             " a keystore? (make one with `stride security init`)");
  }
  k.ca = load_certificate(ca);
  const std::string key_text = common::read_file(key);
  k.ca_key = about(key, [&] { return x509::key_from_pem(key_text); });
  if (!x509::key_matches(k.ca.get(), k.ca_key.get())) {
    throw std::runtime_error(key.string() + ": not the key of " + ca.string());
  }
  k.governance_p7s = common::read_file(governance);
  k.governance = about(governance, [&] {
    return documents::read_governance(x509::smime_content(k.governance_p7s, k.ca.get()));
  });
  return k;
}

// removes what a failed init or add made
template <typename F>
auto or_remove(const fs::path& made_dir, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(made_dir, ignored);
    throw;
  }
}

std::vector<std::string> write_keystore(const fs::path& dir, const init_options& o) {
  const auto now = std::chrono::floor<std::chrono::seconds>(sys_clock::now());
  const std::string id = x509::random_hex(4);
  x509::certificate_request r{"Stride keystore CA " + id, "Stride keystore " + id, now,
                              now + std::chrono::days(o.valid_days), true};
  const x509::key_ptr key = x509::generate_key();
  const x509::cert_ptr ca = x509::make_certificate(r, key.get(), nullptr, key.get());

  std::vector<std::string> lines;
  write_new(dir / "ca.cert.pem", x509::to_pem(ca.get()), 0644);
  lines.push_back(made(dir / "ca.cert.pem", "identity and permissions CA, CN=" + r.common_name +
                                                ", valid until " +
                                                date(x509::not_after(ca.get()))));
  make_directory(dir / "private", 0700);
  write_new(dir / "private" / "ca.key.pem", x509::to_pem(key.get()), 0600);
  lines.push_back(made(dir / "private" / "ca.key.pem", "the CA's private key, mode 0600"));
  const std::string governance = documents::governance_xml(o.domains, o.level);
  write_new(dir / "governance.xml", governance, 0644);
  lines.push_back(
      made(dir / "governance.xml", "domains " + format_domains(o.domains) + ", protection " +
                                       (o.level == protection::encrypt ? "encrypt" : "sign")));
  write_new(dir / "governance.p7s", x509::smime_sign(governance, ca.get(), key.get()), 0644);
  lines.push_back(made(dir / "governance.p7s", "governance.xml signed by the CA"));
  return lines;
}

}  // namespace

const std::vector<std::string>& stride_topics() {
  static const std::vector<std::string> topics{"stride_remote_request", "stride_remote_reply",
                                               "stride_remote_worker_info", "stride_table_update",
                                               "stride_table_state"};
  return topics;
}

bool valid_identity_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name == "." || name == "..") return false;
  return name.find_first_not_of(
             "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") ==
         std::string::npos;
}

std::vector<std::string> init(const fs::path& dir, const init_options& o) {
  check_valid_days(o.valid_days);
  if (o.domains.empty()) throw std::runtime_error("a keystore needs at least one domain");
  for (const int d : o.domains) {
    if (d < 0 || d > 230)
      throw std::runtime_error("domain " + std::to_string(d) + " is out of range (0..230)");
  }
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir)) {
      throw std::runtime_error(dir.string() + ": exists and is not a folder; choose another");
    }
    if (!fs::is_empty(dir)) {
      throw std::runtime_error(
          dir.string() + ": not empty; a keystore is never overwritten (choose a new folder)");
    }
    // made empty by someone else: on failure remove what is inside, keep the folder
    try {
      return write_keystore(dir, o);
    } catch (...) {
      for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
      throw;
    }
  }
  if (!fs::create_directories(dir, ec)) {
    throw std::runtime_error(dir.string() + ": cannot create (" + ec.message() + ")");
  }
  return or_remove(dir, [&] { return write_keystore(dir, o); });
}

namespace {

struct identity_plan {
  std::string name;
  sys_clock::time_point not_before, not_after;
  bool cut_to_ca = false;  // the requested validity would have outlived the CA
};

identity_plan plan_identity(const keystore_files& k, const std::string& name,
                            const identity_options& o) {
  identity_plan p{name, {}, {}, false};
  p.not_before = std::chrono::floor<std::chrono::seconds>(o.not_before.value_or(sys_clock::now()));
  p.not_after = p.not_before + std::chrono::days(o.valid_days);
  const auto ca_end = x509::not_after(k.ca.get());
  if (p.not_after > ca_end) {
    p.not_after = ca_end;
    p.cut_to_ca = true;
  }
  if (p.not_after <= p.not_before) {
    throw std::runtime_error((k.dir / "ca.cert.pem").string() + ": the CA expires (" +
                             date(ca_end) + ") before the identity would start");
  }
  return p;
}

std::vector<std::string> write_identity(const keystore_files& k, const identity_plan& p,
                                        const fs::path& out) {
  const x509::key_ptr key = x509::generate_key();
  const x509::cert_ptr cert = x509::make_certificate(
      {p.name, x509::organization(k.ca.get()), p.not_before, p.not_after, false}, key.get(),
      k.ca.get(), k.ca_key.get());
  const std::string ca_pem = x509::to_pem(k.ca.get());
  // the grant's validity is the certificate's, its subject exactly what Cyclone prints
  documents::grant g{p.name, x509::subject(cert.get()), x509::not_before(cert.get()),
                     x509::not_after(cert.get()), k.governance.domains};
  const std::string permissions = documents::permissions_xml(g);

  std::vector<std::string> lines;
  write_new(out / "cert.pem", x509::to_pem(cert.get()), 0644);
  lines.push_back(made(out / "cert.pem", g.subject + ", valid " + date(g.not_before) + " to " +
                                             date(g.not_after) +
                                             (p.cut_to_ca ? ", cut to the CA's expiry" : "")));
  write_new(out / "key.pem", x509::to_pem(key.get()), 0600);
  lines.push_back(made(out / "key.pem", "private key, mode 0600"));
  for (const char* copy : {"identity_ca.cert.pem", "permissions_ca.cert.pem"}) {
    write_new(out / copy, ca_pem, 0644);
    lines.push_back(made(out / copy, "copy of the CA certificate"));
  }
  write_new(out / "governance.p7s", k.governance_p7s, 0644);
  lines.push_back(made(out / "governance.p7s", "copy of the signed governance"));
  write_new(out / "permissions.xml", permissions, 0644);
  lines.push_back(
      made(out / "permissions.xml",
           "publish and subscribe Stride's topics on domains " + format_domains(g.domains)));
  write_new(out / "permissions.p7s", x509::smime_sign(permissions, k.ca.get(), k.ca_key.get()),
            0644);
  lines.push_back(made(out / "permissions.p7s", "permissions.xml signed by the CA"));
  return lines;
}

}  // namespace

std::vector<std::string> add(const fs::path& dir, const std::string& name,
                             const identity_options& o) {
  if (!valid_identity_name(name)) {
    throw std::runtime_error("identity name \"" + name +
                             "\" is not allowed; use 1 to 64 of A-Z a-z 0-9 _ . -");
  }
  check_valid_days(o.valid_days);
  const keystore_files k = open_keystore(dir);
  const fs::path out = dir / name;
  std::error_code ec;
  if (fs::exists(fs::symlink_status(out, ec))) {
    throw std::runtime_error(out.string() +
                             ": already exists; an identity is never overwritten (choose another "
                             "name)");
  }
  const identity_plan p = plan_identity(k, name, o);
  make_directory(out, 0755);
  return or_remove(out, [&] { return write_identity(k, p, out); });
}

certificate_info read_certificate(const fs::path& pem) {
  const x509::cert_ptr c = load_certificate(pem);
  return about(pem, [&] {
    return certificate_info{x509::subject(c.get()), x509::issuer(c.get()),
                            x509::not_before(c.get()), x509::not_after(c.get())};
  });
}

bool issued_by(const fs::path& cert_pem, const fs::path& ca_pem) {
  const x509::cert_ptr cert = load_certificate(cert_pem);
  const x509::cert_ptr ca = load_certificate(ca_pem);
  return x509::verifies_against(cert.get(), ca.get());
}

namespace {

bool is_smime(const std::string& text) {
  return text.rfind("MIME-Version:", 0) == 0;
}

// the XML of a permissions document, its signature verified against `ca` when given
std::string permissions_text(const fs::path& file, const fs::path& ca) {
  const std::string text = common::read_file(file);
  if (!is_smime(text)) {
    if (!ca.empty()) {
      throw std::runtime_error(file.string() + ": not signed, so it cannot be verified against " +
                               ca.string() + "; give the .p7s");
    }
    return text;
  }
  const x509::cert_ptr signer = ca.empty() ? nullptr : load_certificate(ca);
  return about(file, [&] {
    try {
      return x509::smime_content(text, signer.get());
    } catch (const std::exception& e) {
      if (ca.empty()) throw;
      throw std::runtime_error(std::string(e.what()) + " against " + ca.string() +
                               " (tampered, or signed by another keystore's CA)");
    }
  });
}

}  // namespace

std::vector<int> permitted_domains(const fs::path& permissions, const fs::path& permissions_ca) {
  const std::string xml = permissions_text(permissions, permissions_ca);
  return about(permissions, [&] { return documents::permissions_domains(xml); });
}

}  // namespace stride::remote::keystore
