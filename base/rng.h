// Counter-based random numbers: a stream is a pure function of (seed, stream id), so results do
// not depend on the number of threads or on scheduling.
#pragma once

#include <cstdint>

namespace candela {

// SplitMix64 finaliser (Steele, Lea & Flood 2014), used to decorrelate seeds and stream ids.
inline uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// PCG32 (O'Neill 2014, pcg-random.org, "PCG XSH RR 64/32"): small state, good statistics.
class Rng {
 public:
  Rng(uint64_t seed, uint64_t stream) {
    state_ = 0;
    inc_ = (mix64(stream + 0x9e3779b97f4a7c15ULL * (seed + 1)) << 1u) | 1u;
    next();
    state_ += mix64(seed ^ 0x2545f4914f6cdd1dULL);
    next();
  }
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform double in [0, 1), 53 random bits.
  double uniform() {
    const uint64_t hi = next(), lo = next();
    return static_cast<double>(((hi << 21) ^ lo) & ((1ULL << 53) - 1)) * (1.0 / 9007199254740992.0);
  }

 private:
  uint64_t state_;
  uint64_t inc_;
};

}  // namespace candela
