// The learner's random numbers: xoshiro256** seeded through splitmix64, with our own uniform
// mappings, so a seed gives the same sequence on every platform and standard library (the
// std:: distributions are implementation-defined). The state is trivially copyable: it is saved
// in FMU states and checkpoints.
#pragma once

#include <cstdint>

namespace stride::learner {

struct rng_state {
  std::uint64_t s[4] = {};
};

/// Its fields, for state images (stride/sdk/state_fields.hpp).
template <class F>
void state_fields(rng_state& r, F&& f) {
  f(r.s);
}

/// The state for a seed (any value, 0 included).
rng_state seed_rng(std::uint64_t seed);

/// The seed of agent `agent` (1-based) of a run seeded with `seed`: agent 1 uses `seed` itself
/// (one agent learns exactly as without sharing), the others seeds mixed from both.
std::uint64_t agent_seed(std::uint64_t seed, int agent);

/// Next 64 random bits.
std::uint64_t next_u64(rng_state& r);

/// Uniform integer in [0, n), n > 0, without modulo bias (Lemire's method with rejection).
std::uint64_t uniform_below(rng_state& r, std::uint64_t n);

/// Uniform double in [0, 1) with 53 random bits.
double uniform01(rng_state& r);

}  // namespace stride::learner
