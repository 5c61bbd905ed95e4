// Solid noise for the function language's noise3, noise3x/y/z and fnoise3: a gradient noise on
// the integer lattice (a pseudo-random unit gradient at each lattice point, blended with the
// quintic fade 6t⁵ − 15t⁴ + 10t³ so that the gradient is continuous), scaled into (−1, 1).
// Radiance's own noise3 is a different lattice noise: patterns that use noise have the same
// character (scale, range, smoothness) but not Radiance's exact values (docs/engine.md).
#include "engine/radiance/cal/cal_impl.h"

#include <algorithm>
#include <cmath>

namespace candela::cal {
namespace {

uint64_t hash3(int64_t x, int64_t y, int64_t z) {
  uint64_t h = static_cast<uint64_t>(x) * 0x9e3779b97f4a7c15ULL ^ static_cast<uint64_t>(y) * 0xc2b2ae3d27d4eb4fULL ^
               static_cast<uint64_t>(z) * 0x165667b19e3779f9ULL;
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

// The lattice point's gradient: one of the 12 directions to the edges' midpoints of a cube.
void gradient(int64_t x, int64_t y, int64_t z, double g[3]) {
  static constexpr double kDirs[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1},
                                          {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
  const double* d = kDirs[hash3(x, y, z) % 12];
  g[0] = d[0];
  g[1] = d[1];
  g[2] = d[2];
}

double fade(double t) { return t * t * t * (t * (6 * t - 15) + 10); }
double fadeSlope(double t) { return 30 * t * t * (t * (t - 2) + 1); }

// Value and gradient of the noise at (x, y, z).
double noiseWithGradient(double x, double y, double z, double out[3]) {
  // Beyond 2^50 (and for NaN) the lattice has no meaning left in double precision: no noise.
  constexpr double kLimit = 1125899906842624.0;
  if (!(std::abs(x) < kLimit && std::abs(y) < kLimit && std::abs(z) < kLimit)) {
    out[0] = out[1] = out[2] = 0.0;
    return 0.0;
  }
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy), iz = static_cast<int64_t>(fz);
  const double t[3] = {x - fx, y - fy, z - fz};
  const double w[3] = {fade(t[0]), fade(t[1]), fade(t[2])};
  const double dw[3] = {fadeSlope(t[0]), fadeSlope(t[1]), fadeSlope(t[2])};
  double value = 0.0;
  out[0] = out[1] = out[2] = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int bx = c & 1, by = (c >> 1) & 1, bz = (c >> 2) & 1;
    double g[3];
    gradient(ix + bx, iy + by, iz + bz, g);
    const double d[3] = {t[0] - bx, t[1] - by, t[2] - bz};
    const double dot = g[0] * d[0] + g[1] * d[1] + g[2] * d[2];
    const double wx = bx ? w[0] : 1 - w[0], wy = by ? w[1] : 1 - w[1], wz = bz ? w[2] : 1 - w[2];
    const double sx = bx ? dw[0] : -dw[0], sy = by ? dw[1] : -dw[1], sz = bz ? dw[2] : -dw[2];
    const double weight = wx * wy * wz;
    value += weight * dot;
    out[0] += weight * g[0] + sx * wy * wz * dot;
    out[1] += weight * g[1] + wx * sy * wz * dot;
    out[2] += weight * g[2] + wx * wy * sz * dot;
  }
  return value;
}

}  // namespace

double noise3(double x, double y, double z) {
  double g[3];
  return std::clamp(noiseWithGradient(x, y, z, g), -1.0, 1.0);
}

void noise3Gradient(double x, double y, double z, double g[3]) { noiseWithGradient(x, y, z, g); }

double fractalNoise3(double x, double y, double z) {
  // Octaves of halving amplitude and doubling frequency, normalised into (−1, 1).
  double sum = 0.0, amplitude = 1.0, total = 0.0;
  for (int octave = 0; octave < 6; ++octave) {
    sum += amplitude * noise3(x, y, z);
    total += amplitude;
    x *= 2.0;
    y *= 2.0;
    z *= 2.0;
    amplitude *= 0.5;
  }
  return sum / total;
}

}  // namespace candela::cal
