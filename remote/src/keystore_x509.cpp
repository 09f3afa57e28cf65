#include "keystore_x509.hpp"

#include <openssl/bn.h>
#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/rand.h>
#include <openssl/x509v3.h>

#include <ctime>
#include <stdexcept>
#include <vector>

namespace stride::remote::keystore::x509 {
namespace {

struct bio_free {
  void operator()(BIO* b) const { BIO_free(b); }
};
using bio_ptr = std::unique_ptr<BIO, bio_free>;
struct stack_free {
  void operator()(STACK_OF(X509) * s) const { sk_X509_free(s); }
};

// `what` with the reasons OpenSSL queued, which it then forgets
std::runtime_error openssl_error(const std::string& what) {
  std::string message = what;
  const char* separator = ": ";
  while (const unsigned long e = ERR_get_error()) {
    const char* reason = ERR_reason_error_string(e);
    message += separator;
    message += reason != nullptr ? reason : "error " + std::to_string(e);
    separator = ", ";
  }
  return std::runtime_error(message);
}

void check(int ok, const char* what) {
  if (ok != 1) throw openssl_error(what);
}

bio_ptr memory_bio() {
  bio_ptr b(BIO_new(BIO_s_mem()));
  if (!b) throw openssl_error("BIO_new");
  return b;
}

bio_ptr reading_bio(const std::string& text) {
  bio_ptr b(BIO_new_mem_buf(text.data(), static_cast<int>(text.size())));
  if (!b) throw openssl_error("BIO_new_mem_buf");
  return b;
}

std::string contents(BIO* b) {
  char* data = nullptr;
  const long n = BIO_get_mem_data(b, &data);
  return n > 0 ? std::string(data, static_cast<std::size_t>(n)) : std::string();
}

time_point to_time_point(const ASN1_TIME* t) {
  std::tm tm{};
  check(ASN1_TIME_to_tm(t, &tm), "ASN1_TIME_to_tm");
  return std::chrono::system_clock::from_time_t(timegm(&tm));
}

void add_name_entry(X509_NAME* name, const char* field, const std::string& value) {
  if (value.empty()) return;
  check(
      X509_NAME_add_entry_by_txt(name, field, MBSTRING_UTF8,
                                 reinterpret_cast<const unsigned char*>(value.c_str()), -1, -1, 0),
      "X509_NAME_add_entry_by_txt");
}

// a random positive 127-bit serial number (RFC 5280: unique per CA, at most 20 octets)
void set_random_serial(X509* cert) {
  std::unique_ptr<BIGNUM, decltype(&BN_free)> serial(BN_new(), BN_free);
  if (!serial) throw openssl_error("BN_new");
  check(BN_rand(serial.get(), 127, BN_RAND_TOP_ANY, BN_RAND_BOTTOM_ANY), "BN_rand");
  if (BN_to_ASN1_INTEGER(serial.get(), X509_get_serialNumber(cert)) == nullptr) {
    throw openssl_error("BN_to_ASN1_INTEGER");
  }
}

void add_extension(X509* cert, X509V3_CTX* ctx, int nid, const char* value) {
  X509_EXTENSION* ext = X509V3_EXT_conf_nid(nullptr, ctx, nid, value);
  if (ext == nullptr) throw openssl_error(std::string("extension ") + value);
  const int ok = X509_add_ext(cert, ext, -1);
  X509_EXTENSION_free(ext);
  check(ok, "X509_add_ext");
}

void add_extensions(X509* cert, X509* issuer, bool is_ca) {
  X509V3_CTX ctx;
  X509V3_set_ctx(&ctx, issuer, cert, nullptr, nullptr, 0);
  if (is_ca) {
    add_extension(cert, &ctx, NID_basic_constraints, "critical,CA:TRUE");
    // digitalSignature: the CA also signs the governance and permissions documents
    add_extension(cert, &ctx, NID_key_usage, "critical,keyCertSign,cRLSign,digitalSignature");
  } else {
    add_extension(cert, &ctx, NID_basic_constraints, "critical,CA:FALSE");
    add_extension(cert, &ctx, NID_key_usage, "critical,digitalSignature");
  }
  // the subject key id first: a self-signed certificate's authority key id is its own
  add_extension(cert, &ctx, NID_subject_key_identifier, "hash");
  add_extension(cert, &ctx, NID_authority_key_identifier, "keyid:always");
}

std::string print_name(const X509_NAME* name) {
  bio_ptr out = memory_bio();
  if (X509_NAME_print_ex(out.get(), name, 0, XN_FLAG_RFC2253) < 0) {
    throw openssl_error("X509_NAME_print_ex");
  }
  return contents(out.get());
}

}  // namespace

key_ptr generate_key() {
  key_ptr key(EVP_EC_gen("P-256"));
  if (!key) throw openssl_error("EC key generation on prime256v1");
  return key;
}

cert_ptr make_certificate(const certificate_request& r, EVP_PKEY* key, X509* ca, EVP_PKEY* ca_key) {
  cert_ptr cert(X509_new());
  if (!cert) throw openssl_error("X509_new");
  check(X509_set_version(cert.get(), X509_VERSION_3), "X509_set_version");
  set_random_serial(cert.get());
  X509_NAME* name = X509_get_subject_name(cert.get());
  add_name_entry(name, "O", r.organization);
  add_name_entry(name, "CN", r.common_name);
  check(X509_set_issuer_name(cert.get(), ca != nullptr ? X509_get_subject_name(ca) : name),
        "X509_set_issuer_name");
  if (ASN1_TIME_set(X509_getm_notBefore(cert.get()),
                    std::chrono::system_clock::to_time_t(r.not_before)) == nullptr ||
      ASN1_TIME_set(X509_getm_notAfter(cert.get()),
                    std::chrono::system_clock::to_time_t(r.not_after)) == nullptr) {
    throw openssl_error("ASN1_TIME_set");
  }
  check(X509_set_pubkey(cert.get(), key), "X509_set_pubkey");
  add_extensions(cert.get(), ca != nullptr ? ca : cert.get(), r.is_ca);
  if (X509_sign(cert.get(), ca_key, EVP_sha256()) <= 0) throw openssl_error("X509_sign");
  return cert;
}

std::string to_pem(X509* cert) {
  bio_ptr out = memory_bio();
  check(PEM_write_bio_X509(out.get(), cert), "PEM_write_bio_X509");
  return contents(out.get());
}

std::string to_pem(EVP_PKEY* key) {
  bio_ptr out = memory_bio();
  check(PEM_write_bio_PrivateKey(out.get(), key, nullptr, nullptr, 0, nullptr, nullptr),
        "PEM_write_bio_PrivateKey");
  return contents(out.get());
}

cert_ptr certificate_from_pem(const std::string& pem) {
  bio_ptr in = reading_bio(pem);
  cert_ptr cert(PEM_read_bio_X509(in.get(), nullptr, nullptr, nullptr));
  if (!cert) throw openssl_error("not a PEM certificate");
  return cert;
}

key_ptr key_from_pem(const std::string& pem) {
  bio_ptr in = reading_bio(pem);
  key_ptr key(PEM_read_bio_PrivateKey(in.get(), nullptr, nullptr, nullptr));
  if (!key) throw openssl_error("not a PEM private key");
  return key;
}

std::string subject(X509* cert) {
  return print_name(X509_get_subject_name(cert));
}
std::string issuer(X509* cert) {
  return print_name(X509_get_issuer_name(cert));
}
std::string organization(X509* cert) {
  const X509_NAME* name = X509_get_subject_name(cert);
  const int i = X509_NAME_get_index_by_NID(name, NID_organizationName, -1);
  if (i < 0) return "";
  const ASN1_STRING* value = X509_NAME_ENTRY_get_data(X509_NAME_get_entry(name, i));
  unsigned char* utf8 = nullptr;
  const int n = ASN1_STRING_to_UTF8(&utf8, value);
  if (n < 0) throw openssl_error("ASN1_STRING_to_UTF8");
  std::string out(reinterpret_cast<char*>(utf8), static_cast<std::size_t>(n));
  OPENSSL_free(utf8);
  return out;
}

bool key_matches(X509* cert, EVP_PKEY* key) {
  const bool ok = X509_check_private_key(cert, key) == 1;
  ERR_clear_error();
  return ok;
}

time_point not_before(X509* cert) {
  return to_time_point(X509_get0_notBefore(cert));
}
time_point not_after(X509* cert) {
  return to_time_point(X509_get0_notAfter(cert));
}

bool verifies_against(X509* cert, X509* ca) {
  std::unique_ptr<X509_STORE, decltype(&X509_STORE_free)> store(X509_STORE_new(), X509_STORE_free);
  std::unique_ptr<X509_STORE_CTX, decltype(&X509_STORE_CTX_free)> ctx(X509_STORE_CTX_new(),
                                                                      X509_STORE_CTX_free);
  if (!store || !ctx) throw openssl_error("X509_STORE_new");
  check(X509_STORE_add_cert(store.get(), ca), "X509_STORE_add_cert");
  check(X509_STORE_CTX_init(ctx.get(), store.get(), cert, nullptr), "X509_STORE_CTX_init");
  X509_STORE_CTX_set_flags(ctx.get(), X509_V_FLAG_NO_CHECK_TIME);
  const bool ok = X509_verify_cert(ctx.get()) == 1;
  ERR_clear_error();
  return ok;
}

std::string smime_sign(const std::string& text, X509* cert, EVP_PKEY* key) {
  const int flags = PKCS7_DETACHED | PKCS7_TEXT;
  bio_ptr in = reading_bio(text);
  std::unique_ptr<PKCS7, decltype(&PKCS7_free)> p7(PKCS7_sign(cert, key, nullptr, in.get(), flags),
                                                   PKCS7_free);
  if (!p7) throw openssl_error("PKCS7_sign");
  // PKCS7_sign consumed `in`; the detached text is written again from the start
  bio_ptr again = reading_bio(text);
  bio_ptr out = memory_bio();
  check(SMIME_write_PKCS7(out.get(), p7.get(), again.get(), flags), "SMIME_write_PKCS7");
  return contents(out.get());
}

std::string smime_content(const std::string& smime, X509* signer) {
  bio_ptr in = reading_bio(smime);
  BIO* detached = nullptr;
  std::unique_ptr<PKCS7, decltype(&PKCS7_free)> p7(SMIME_read_PKCS7(in.get(), &detached),
                                                   PKCS7_free);
  bio_ptr content(detached);
  if (!p7) throw openssl_error("not an S/MIME signed document");
  std::unique_ptr<STACK_OF(X509), stack_free> signers(sk_X509_new_null());
  if (!signers) throw openssl_error("sk_X509_new_null");
  int flags = PKCS7_TEXT | PKCS7_NOVERIFY;
  if (signer != nullptr) {
    sk_X509_push(signers.get(), signer);
    flags |= PKCS7_NOINTERN;
  } else {
    flags |= PKCS7_NOSIGS;
  }
  bio_ptr out = memory_bio();
  if (PKCS7_verify(p7.get(), signers.get(), nullptr, content.get(), out.get(), flags) != 1) {
    throw openssl_error("signature does not verify");
  }
  return contents(out.get());
}

std::string random_hex(int n) {
  std::vector<unsigned char> bytes(static_cast<std::size_t>(n));
  check(RAND_bytes(bytes.data(), n), "RAND_bytes");
  static const char digits[] = "0123456789abcdef";
  std::string hex;
  for (const unsigned char b : bytes) {
    hex += digits[b >> 4];
    hex += digits[b & 15];
  }
  return hex;
}

}  // namespace stride::remote::keystore::x509
