// The OpenSSL part of the keystore (keystore.cpp): EC keys, X.509 certificates and S/MIME signed
// documents, in the forms Cyclone DDS's builtin security plugins read. Errors are
// std::runtime_error with OpenSSL's reason; callers add the file name.
#ifndef STRIDE_REMOTE_KEYSTORE_X509_HPP
#define STRIDE_REMOTE_KEYSTORE_X509_HPP

#include <openssl/evp.h>
#include <openssl/x509.h>

#include <chrono>
#include <memory>
#include <string>

namespace stride::remote::keystore::x509 {

struct pkey_free {
  void operator()(EVP_PKEY* k) const { EVP_PKEY_free(k); }
};
struct cert_free {
  void operator()(X509* c) const { X509_free(c); }
};
using key_ptr = std::unique_ptr<EVP_PKEY, pkey_free>;
using cert_ptr = std::unique_ptr<X509, cert_free>;

using time_point = std::chrono::system_clock::time_point;

/// A new EC key on prime256v1 (P-256), which Cyclone's authentication plugin accepts.
key_ptr generate_key();

/// What a new certificate says; the issuer is the CA given to `make_certificate`, or the
/// certificate itself when there is none.
struct certificate_request {
  std::string common_name;
  std::string organization;
  time_point not_before;
  time_point not_after;
  bool is_ca = false;
};

/// A certificate for `key`'s public half, signed with SHA-256 by `ca_key` (whose certificate is
/// `ca`, or, when `ca` is null, self-signed).
cert_ptr make_certificate(const certificate_request& r, EVP_PKEY* key, X509* ca, EVP_PKEY* ca_key);

std::string to_pem(X509* cert);
/// PKCS#8, unencrypted: the plugins read it without a password.
std::string to_pem(EVP_PKEY* key);
cert_ptr certificate_from_pem(const std::string& pem);
key_ptr key_from_pem(const std::string& pem);

/// X509_NAME_print_ex with XN_FLAG_RFC2253: the text Cyclone's access control compares with a
/// permissions grant's subject_name.
std::string subject(X509* cert);
std::string issuer(X509* cert);
/// The subject's O (organization) entry, "" without one.
std::string organization(X509* cert);
time_point not_before(X509* cert);
time_point not_after(X509* cert);
/// Whether `key` is the private half of `cert`'s public key.
bool key_matches(X509* cert, EVP_PKEY* key);
/// Whether `cert` verifies against `ca` as the only trust anchor (times not checked).
bool verifies_against(X509* cert, X509* ca);

/// `text` signed by `key` (certificate `cert`) as S/MIME: detached, text mode (PKCS7_DETACHED |
/// PKCS7_TEXT), what Cyclone verifies.
std::string smime_sign(const std::string& text, X509* cert, EVP_PKEY* key);
/// The signed text of an S/MIME document, verified the way Cyclone does (PKCS7_TEXT |
/// PKCS7_NOVERIFY | PKCS7_NOINTERN: signed by `signer` itself); without a signer the text is only
/// extracted, not verified.
std::string smime_content(const std::string& smime, X509* signer);

/// `n` random bytes as lower-case hex (RAND_bytes).
std::string random_hex(int n);

}  // namespace stride::remote::keystore::x509

#endif  // STRIDE_REMOTE_KEYSTORE_X509_HPP
