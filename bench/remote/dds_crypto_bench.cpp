// What Cyclone DDS's builtin crypto plugin spends per message with the keystores' protection
// (each RTPS message encrypted once, AES-256-GCM), as the OpenSSL calls it makes (facts in
// docs/distributed.md, "Speed"): the receiver derives the message's session key, a one-shot
// HMAC-SHA256, for every message it decodes (it keeps no derived key), and both sides set up a
// fresh AES-GCM context per message. OpenSSL 3 looks each algorithm up anew on every such call.
// Sizes: the walk's step request (≈ 0.5 KB) and reply (≈ 1.4 KB).
#include <benchmark/benchmark.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace {

constexpr std::size_t k_key = 32;  // AES-256, as ENCRYPT protection uses
constexpr int k_iv = 12;
constexpr int k_tag = 16;

std::array<unsigned char, k_key> filled_key() {
  std::array<unsigned char, k_key> key{};
  for (std::size_t i = 0; i < key.size(); ++i) key[i] = static_cast<unsigned char>(7 * i + 1);
  return key;
}

const std::array<unsigned char, k_key> k_master = filled_key();

void bm_session_key(benchmark::State& state) {
  // the derivation's input: the label "SessionKey", the master salt and the session id
  const std::vector<unsigned char> input(10 + k_key + 4, 0x5a);
  std::array<unsigned char, EVP_MAX_MD_SIZE> out{};
  for (auto _ : state) {
    if (HMAC(EVP_sha256(), k_master.data(), static_cast<int>(k_master.size()), input.data(),
             input.size(), out.data(), nullptr) == nullptr) {
      throw std::runtime_error("HMAC-SHA256 failed");
    }
    benchmark::DoNotOptimize(out);
  }
}

// one message through a fresh AES-256-GCM context, as the plugin does; false when OpenSSL fails
// (or, decrypting, when the tag does not match)
bool gcm(bool encrypt, const std::vector<unsigned char>& in, std::vector<unsigned char>& out,
         std::array<unsigned char, k_tag>& tag) {
  const std::array<unsigned char, k_iv> iv{};
  EVP_CIPHER_CTX* ctx = EVP_CIPHER_CTX_new();
  int n = 0;
  int last = 0;
  bool ok = EVP_CipherInit_ex(ctx, EVP_aes_256_gcm(), nullptr, nullptr, nullptr, encrypt) == 1 &&
            EVP_CIPHER_CTX_ctrl(ctx, EVP_CTRL_GCM_SET_IVLEN, k_iv, nullptr) == 1 &&
            EVP_CipherInit_ex(ctx, nullptr, nullptr, k_master.data(), iv.data(), encrypt) == 1 &&
            EVP_CipherUpdate(ctx, out.data(), &n, in.data(), static_cast<int>(in.size())) == 1;
  if (ok && !encrypt) ok = EVP_CIPHER_CTX_ctrl(ctx, EVP_CTRL_GCM_SET_TAG, k_tag, tag.data()) == 1;
  ok = ok && EVP_CipherFinal_ex(ctx, out.data() + n, &last) == 1;
  if (ok && encrypt) ok = EVP_CIPHER_CTX_ctrl(ctx, EVP_CTRL_GCM_GET_TAG, k_tag, tag.data()) == 1;
  EVP_CIPHER_CTX_free(ctx);
  return ok;
}

void bm_encrypt(benchmark::State& state) {
  const std::vector<unsigned char> plain(static_cast<std::size_t>(state.range(0)), 0x33);
  std::vector<unsigned char> cipher(plain.size());
  std::array<unsigned char, k_tag> tag{};
  for (auto _ : state) {
    if (!gcm(true, plain, cipher, tag)) throw std::runtime_error("AES-256-GCM encryption failed");
    benchmark::DoNotOptimize(cipher);
  }
}

void bm_decrypt(benchmark::State& state) {
  const std::vector<unsigned char> plain(static_cast<std::size_t>(state.range(0)), 0x33);
  std::vector<unsigned char> cipher(plain.size());
  std::vector<unsigned char> back(plain.size());
  std::array<unsigned char, k_tag> tag{};
  if (!gcm(true, plain, cipher, tag)) throw std::runtime_error("AES-256-GCM encryption failed");
  for (auto _ : state) {
    if (!gcm(false, cipher, back, tag)) throw std::runtime_error("AES-256-GCM decryption failed");
    benchmark::DoNotOptimize(back);
  }
  if (back != plain) throw std::runtime_error("AES-256-GCM gave back other bytes");
}

}  // namespace

BENCHMARK(bm_session_key);
BENCHMARK(bm_encrypt)->Arg(500)->Arg(1450);
BENCHMARK(bm_decrypt)->Arg(500)->Arg(1450);
