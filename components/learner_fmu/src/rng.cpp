#include "stride/learner/rng.hpp"

namespace stride::learner {
namespace {

std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

__extension__ typedef unsigned __int128 u128;  // GCC/Clang; __extension__ keeps -Wpedantic quiet

std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

}  // namespace

rng_state seed_rng(std::uint64_t seed) {
  rng_state r;
  std::uint64_t x = seed;
  for (auto& word : r.s) word = splitmix64(x);
  return r;
}

std::uint64_t agent_seed(std::uint64_t seed, int agent) {
  if (agent <= 1) return seed;
  // a constant other than splitmix64's increment, so that agent seeds do not land on the
  // sequence of words seed_rng draws from `seed`
  std::uint64_t x = seed + static_cast<std::uint64_t>(agent) * 0xD1B54A32D192ED03ULL;
  return splitmix64(x);
}

std::uint64_t next_u64(rng_state& r) {
  std::uint64_t* s = r.s;
  const std::uint64_t result = rotl(s[1] * 5, 7) * 9;
  const std::uint64_t t = s[1] << 17;
  s[2] ^= s[0];
  s[3] ^= s[1];
  s[1] ^= s[2];
  s[0] ^= s[3];
  s[2] ^= t;
  s[3] = rotl(s[3], 45);
  return result;
}

std::uint64_t uniform_below(rng_state& r, std::uint64_t n) {
  // Lemire, "Fast random integer generation in an interval" (2019)
  u128 m = static_cast<u128>(next_u64(r)) * n;
  auto low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = static_cast<u128>(next_u64(r)) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return static_cast<std::uint64_t>(m >> 64);
}

double uniform01(rng_state& r) {
  return static_cast<double>(next_u64(r) >> 11) * 0x1.0p-53;
}

}  // namespace stride::learner
