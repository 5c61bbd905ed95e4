#include "metrics/glare_rating.h"

#include <algorithm>
#include <cmath>

namespace candela {

std::optional<VeilingSource> veilingSource(const Vec3& eyeM, const Vec3& sight, const Vec3& sourceM,
                                           double intensityCd, double transmittance) {
  const Vec3 to = sourceM - eyeM;
  const double d2 = glm::dot(to, to);
  if (!(d2 > 0.0) || !(intensityCd > 0.0) || !(transmittance > 0.0)) return std::nullopt;
  const double cosTheta = std::min(1.0, glm::dot(to, sight) / std::sqrt(d2));
  if (!(cosTheta > 0.0)) return std::nullopt;
  return VeilingSource{transmittance * intensityCd * cosTheta / d2, std::acos(cosTheta) * 180.0 / kPi};
}

double luminairesVeilingLuminance(const std::vector<VeilingSource>& sources) {
  double sum = 0.0;
  for (const VeilingSource& s : sources) sum += s.eyeLux / (s.angleDeg * s.angleDeg);
  return 10.0 * sum;
}

double environmentVeilingLuminance(double reflectance, double averageHorizontalLux) {
  return 0.035 * reflectance * averageHorizontalLux / kPi;
}

std::optional<double> glareRating(double luminairesVeilCdM2, double environmentVeilCdM2) {
  if (!(luminairesVeilCdM2 > 0.0) || !(environmentVeilCdM2 > 0.0)) return std::nullopt;
  return 27.0 + 24.0 * std::log10(luminairesVeilCdM2 / std::pow(environmentVeilCdM2, 0.9));
}

Vec3 lineOfSight(double azimuthDeg, double inclinationDeg) {
  const double a = azimuthDeg * kPi / 180.0, e = inclinationDeg * kPi / 180.0;
  return {std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e)};
}

std::vector<double> viewAzimuthsDeg(double stepDeg) {
  std::vector<double> out;
  if (!(stepDeg > 0.0)) return out;
  for (int k = 0; k * stepDeg < 360.0 - 1e-9; ++k) out.push_back(k * stepDeg);
  return out;
}

}  // namespace candela
