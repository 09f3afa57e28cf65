// The checks an identity gets before a participant of this process uses it: each names the file
// and what to do, where Cyclone's own refusal would only say that the participant failed.
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "keystore_io.hpp"
#include "stride/remote/identity.hpp"
#include "stride/remote/keystore.hpp"

namespace stride::remote::keystore {

namespace fs = std::filesystem;

namespace {

void check_times(const fs::path& cert, const certificate_info& info) {
  const auto now = std::chrono::system_clock::now();
  if (now < info.not_before) {
    throw std::runtime_error("certificate " + cert.string() + " is not valid before " +
                             io::date(info.not_before) + ": wait, or check this host's clock");
  }
  if (now > info.not_after) {
    throw std::runtime_error("certificate " + cert.string() + " expired on " +
                             io::date(info.not_after) +
                             ": make a new identity with `stride security add KEYSTORE NAME`");
  }
}

}  // namespace

void check_identity(const fs::path& dir, int domain) {
  const identity_files id{dir};
  const certificate_info info = read_certificate(id.certificate());
  check_times(id.certificate(), info);
  check_times(id.identity_ca(), read_certificate(id.identity_ca()));
  if (!issued_by(id.certificate(), id.identity_ca())) {
    throw std::runtime_error("certificate " + id.certificate().string() +
                             " was not issued by the CA in " + id.identity_ca().string() +
                             ": the folder mixes files of two keystores");
  }
  const std::vector<int> domains = permitted_domains(id.permissions(), id.permissions_ca());
  if (std::find(domains.begin(), domains.end(), domain) == domains.end()) {
    throw std::runtime_error("permissions " + id.permissions().string() + " allow DDS domain " +
                             format_domains(domains) + ", not domain " + std::to_string(domain) +
                             ": use --domain " + std::to_string(domains.front()) +
                             " or an identity of a keystore made for domain " +
                             std::to_string(domain) + " (`stride security init DIR --domains " +
                             std::to_string(domain) + "`)");
  }
}

}  // namespace stride::remote::keystore
