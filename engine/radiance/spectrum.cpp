#include "engine/radiance/spectrum.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

// A Gaussian lobe with different widths below and above its centre (the fit's g).
double lobe(double nm, double mu, double invSigmaBelow, double invSigmaAbove) {
  const double t = (nm - mu) * (nm < mu ? invSigmaBelow : invSigmaAbove);
  return std::exp(-0.5 * t * t);
}

// XYZ → Radiance RGB for its primaries and the equal-energy white (the usual derivation: the
// primaries' XYZ columns scaled so that they sum to the white's XYZ, then inverted).
glm::dmat3 xyzToRgb() {
  const double xr = 0.640, yr = 0.330, xg = 0.290, yg = 0.600, xb = 0.150, yb = 0.060;
  auto column = [](double x, double y) { return Vec3(x / y, 1.0, (1.0 - x - y) / y); };
  const glm::dmat3 p(column(xr, yr), column(xg, yg), column(xb, yb));
  const Vec3 scale = glm::inverse(p) * Vec3(1.0, 1.0, 1.0);  // white E: X = Y = Z
  const glm::dmat3 rgbToXyz(p[0] * scale.x, p[1] * scale.y, p[2] * scale.z);
  return glm::inverse(rgbToXyz);
}

}  // namespace

Rgb xyzToRadianceRgb(const Vec3& xyz) {
  static const glm::dmat3 m = xyzToRgb();
  return m * xyz;
}

Vec3 cieColourMatching(double nm) {
  const double x = 1.056 * lobe(nm, 599.8, 0.0264, 0.0323) + 0.362 * lobe(nm, 442.0, 0.0624, 0.0374) -
                   0.065 * lobe(nm, 501.1, 0.0490, 0.0382);
  const double y = 0.821 * lobe(nm, 568.8, 0.0213, 0.0247) + 0.286 * lobe(nm, 530.9, 0.0613, 0.0322);
  const double z = 1.217 * lobe(nm, 437.0, 0.0845, 0.0278) + 0.681 * lobe(nm, 459.0, 0.0385, 0.0725);
  return Vec3(x, y, z);
}

Rgb spectrumToRgb(const std::function<double(double nm)>& s, double nmA, double nmB) {
  Vec3 sum(0.0), norm(0.0);
  const double lo = std::min(nmA, nmB), hi = std::max(nmA, nmB);
  for (int nm = 380; nm <= 780; ++nm) {
    const Vec3 cmf = cieColourMatching(nm);
    norm += cmf;
    if (nm >= lo && nm <= hi) sum += cmf * s(nm);
  }
  static const glm::dmat3 m = xyzToRgb();
  return m * (sum / norm);
}

std::vector<Rgb> spectrumNodeWeights(const std::vector<double>& nodesNm) {
  const std::vector<double>& x = nodesNm;
  std::vector<Rgb> w(x.size(), Rgb(0.0));
  const size_t n = x.size();
  for (size_t k = 0; k < n; ++k) {
    // The hat of node k: 1 at x_k, 0 at its neighbours and beyond.
    const auto hat = [&](double nm) {
      if (k > 0 && nm >= x[k - 1] && nm <= x[k]) return (nm - x[k - 1]) / (x[k] - x[k - 1]);
      if (k + 1 < n && nm >= x[k] && nm <= x[k + 1]) return (x[k + 1] - nm) / (x[k + 1] - x[k]);
      return nm == x[k] ? 1.0 : 0.0;
    };
    w[k] = spectrumToRgb(hat, x.front(), x.back());
  }
  return w;
}

}  // namespace candela
