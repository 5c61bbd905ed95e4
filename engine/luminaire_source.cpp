#include "engine/luminaire_source.h"

#include <cmath>

namespace candela {

void orientLuminaire(LuminaireSource& l, const Vec3& aim, double spinDeg) {
  const Vec3 z = -glm::normalize(aim);
  // C0 reference: world +X projected onto the luminaire's plane (world +Y if aiming along X).
  Vec3 ref = std::abs(z.x) < 0.999 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  Vec3 x0 = glm::normalize(ref - glm::dot(ref, z) * z);
  Vec3 y0 = glm::cross(z, x0);
  const double s = degToRad(spinDeg);
  l.axisZ = z;
  l.axisX = std::cos(s) * x0 + std::sin(s) * y0;
  l.axisY = glm::cross(z, l.axisX);
}

void tabulatePeakIntensity(LuminaireSource& l) {
  const int n = LuminaireSource::kCosBins;
  for (int b = 0; b < n; ++b) {
    double peak = 0.0;
    for (double f : {0.0, 0.5, 1.0}) {
      const double cosG = std::clamp(-1.0 + 2.0 * (b + f) / n, -1.0, 1.0);
      const double gammaDeg = radToDeg(std::acos(cosG));
      for (int c = 0; c < 360; c += 5) peak = std::max(peak, l.web->intensityCd(c, gammaDeg));
    }
    l.peakByCosGamma[b] = l.scale * peak;
  }
  l.peakTabulated = true;
}

void setOpeningFromWeb(LuminaireSource& l) {
  const double w = std::abs(l.web->openingWidthM()), len = std::abs(l.web->openingLengthM());
  switch (l.web->openingShape()) {
    case OpeningShape::kPoint:
      l.widthM = l.lengthM = 0.0;
      break;
    case OpeningShape::kCircular:
    case OpeningShape::kSphere:
    case OpeningShape::kVerticalCylinder:
      l.widthM = l.lengthM = w;
      l.circular = true;
      break;
    default:
      l.widthM = w;
      l.lengthM = len > 0.0 ? len : w;
      break;
  }
}

LuminaireSource placeLuminaire(std::shared_ptr<const PhotometricWeb> web, const LuminaireMounting& m) {
  LuminaireSource l;
  l.web = std::move(web);
  l.name = m.name;
  l.position = m.positionM;
  l.scale = m.scale;
  orientLuminaire(l, m.aim, m.spinDeg);
  setOpeningFromWeb(l);
  tabulatePeakIntensity(l);
  return l;
}

}  // namespace candela
