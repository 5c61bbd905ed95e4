#include "metrics/glare.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

namespace {

// evalglare caps the position index at 16: beyond it a source hardly matters.
constexpr double kMaxPositionIndex = 16.0;

}  // namespace

double guthPositionIndex(double tauDeg, double sigmaDeg) {
  const double t = tauDeg, s = sigmaDeg;
  const double lnP = (35.2 - 0.31889 * t - 1.22 * std::exp(-2.0 * t / 9.0)) * 1e-3 * s +
                     (21.0 + 0.26667 * t - 0.002963 * t * t) * 1e-5 * s * s;
  return std::exp(lnP);
}

double positionIndex(const Vec3& directionView) {
  const Vec3 d = glm::normalize(directionView);
  if (d.z <= 0.0) return kMaxPositionIndex;
  const double sigma = std::acos(std::clamp(d.z, -1.0, 1.0));
  double p;
  if (d.y >= 0.0) {
    // τ: angle between the vertical (y) and the plane through the line of sight and the source,
    // i.e. the source's bearing on the image measured from straight up.
    const double tau = std::atan2(std::abs(d.x), d.y);
    p = guthPositionIndex(radToDeg(tau), radToDeg(sigma));
  } else {
    const double rd = std::min(std::tan(sigma), 3.0);
    p = 1.0 + (rd < 0.6 ? 0.8 : 1.2) * rd;
  }
  return std::min(p, kMaxPositionIndex);
}

double unifiedGlareRating(double backgroundLuminanceCdM2, const std::vector<GlareSource>& sources) {
  double sum = 0.0;
  for (const GlareSource& s : sources)
    sum += s.luminanceCdM2 * s.luminanceCdM2 * s.solidAngleSr / (s.positionIndex * s.positionIndex);
  if (!(sum > 0.0)) return -std::numeric_limits<double>::infinity();
  return 8.0 * std::log10(0.25 / backgroundLuminanceCdM2 * sum);
}

double lowLightCorrection(double ev, double limitLux) {
  if (ev >= limitLux) return 1.0;
  const double e = std::exp(0.024 * ev - 4.0);
  return e / (1.0 + e);
}

double daylightGlareProbability(double ev, const std::vector<GlareSource>& sources, bool lowLight) {
  if (!(ev > 0.0)) return 0.0;
  double sum = 0.0;
  for (const GlareSource& s : sources)
    sum += s.luminanceCdM2 * s.luminanceCdM2 * s.solidAngleSr / (s.positionIndex * s.positionIndex);
  double dgp = 5.87e-5 * ev + 9.18e-2 * std::log10(1.0 + sum / std::pow(ev, 1.87)) + 0.16;
  if (lowLight) dgp *= lowLightCorrection(ev);
  return std::min(dgp, 1.0);
}

double glareSourceSolidAngle(const std::vector<float>& lum, const PixelGeometry& geometry, std::size_t i,
                             double thresholdCdM2) {
  if (!(lum[i] > thresholdCdM2)) return 0.0;  // the geometry only where the luminance qualifies
  Vec3 dir;
  double omega = 0.0;
  geometry(i, dir, omega);
  return omega > 0.0 && dir.z > 0.0 ? omega : 0.0;
}

ImageGlare evaluateImageGlare(const std::vector<float>& lum, const PixelGeometry& geometry, int width, int height,
                              const GlareDetection& det) {
  ImageGlare out;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  double sumOmega = 0.0, sumLOmega = 0.0;
  Vec3 dir;
  double omega = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    geometry(i, dir, omega);
    if (!(omega > 0.0)) continue;
    sumOmega += omega;
    sumLOmega += lum[i] * omega;
    const double cosTheta = glm::normalize(dir).z;
    if (cosTheta > 0.0) out.verticalIlluminanceLux += lum[i] * cosTheta * omega;
  }
  out.averageLuminanceCdM2 = sumOmega > 0.0 ? sumLOmega / sumOmega : 0.0;
  out.thresholdCdM2 = det.thresholdCdM2 > 0.0 ? det.thresholdCdM2 : det.averageFactor * out.averageLuminanceCdM2;

  // 8-connected groups of pixels above the threshold (iterative flood fill; a bit a pixel for
  // the pixels already grouped).
  std::vector<bool> grouped(n, false);
  std::vector<std::size_t> stack;
  auto bright = [&](std::size_t i) { return glareSourceSolidAngle(lum, geometry, i, out.thresholdCdM2) > 0.0; };
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (grouped[seed] || !bright(seed)) continue;
    double w = 0.0, lw = 0.0;
    Vec3 dsum(0.0);
    stack.assign(1, seed);
    grouped[seed] = true;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      geometry(i, dir, omega);
      w += omega;
      lw += lum[i] * omega;
      dsum += omega * glm::normalize(dir);
      const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const std::size_t j = static_cast<std::size_t>(ny) * width + nx;
          if (!grouped[j] && bright(j)) {
            grouped[j] = true;
            stack.push_back(j);
          }
        }
    }
    GlareSource s;
    s.solidAngleSr = w;
    s.luminanceCdM2 = lw / w;
    s.positionIndex = positionIndex(dsum);
    out.sources.push_back(s);
  }
  out.dgpUncorrected = daylightGlareProbability(out.verticalIlluminanceLux, out.sources, false);
  out.dgp = det.lowLightCorrection ? daylightGlareProbability(out.verticalIlluminanceLux, out.sources, true)
                                   : out.dgpUncorrected;
  return out;
}

}  // namespace candela
