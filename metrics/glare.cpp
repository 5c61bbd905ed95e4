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

ImageGlare evaluateImageGlare(const std::vector<double>& lum, const std::vector<Vec3>& dir,
                              const std::vector<double>& omega, int width, int height, const GlareDetection& det) {
  ImageGlare out;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  double sumOmega = 0.0, sumLOmega = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(omega[i] > 0.0)) continue;
    sumOmega += omega[i];
    sumLOmega += lum[i] * omega[i];
    const double cosTheta = glm::normalize(dir[i]).z;
    if (cosTheta > 0.0) out.verticalIlluminanceLux += lum[i] * cosTheta * omega[i];
  }
  out.averageLuminanceCdM2 = sumOmega > 0.0 ? sumLOmega / sumOmega : 0.0;
  out.thresholdCdM2 = det.thresholdCdM2 > 0.0 ? det.thresholdCdM2 : det.averageFactor * out.averageLuminanceCdM2;

  // 8-connected groups of pixels above the threshold (iterative flood fill).
  std::vector<int> label(n, -1);
  std::vector<std::size_t> stack;
  auto bright = [&](std::size_t i) { return omega[i] > 0.0 && lum[i] > out.thresholdCdM2 && dir[i].z > 0.0; };
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (label[seed] >= 0 || !bright(seed)) continue;
    const int id = static_cast<int>(out.sources.size());
    double w = 0.0, lw = 0.0;
    Vec3 dsum(0.0);
    stack.assign(1, seed);
    label[seed] = id;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      w += omega[i];
      lw += lum[i] * omega[i];
      dsum += omega[i] * glm::normalize(dir[i]);
      const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const std::size_t j = static_cast<std::size_t>(ny) * width + nx;
          if (label[j] < 0 && bright(j)) {
            label[j] = id;
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
