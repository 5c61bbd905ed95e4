// The photometric summary of a luminaire that designers read first: flux, LOR, peak intensity,
// beam and field angles in the two main planes, zonal lumens and efficacy.
#pragma once

#include "photometry/photometric_web.h"

#include <string>
#include <vector>

namespace candela {

// Intensity along one vertical plane: angleDeg in -180..180 measured from nadir, positive on the
// cDeg side, negative on the opposite (cDeg + 180) side. Samples every stepDeg.
struct PlaneCurve {
  std::vector<double> angleDeg;
  std::vector<double> intensityCd;
};
PlaneCurve planeCurve(const PhotometricWeb& web, double cDeg, double stepDeg = 1.0);

// Full angle in degrees between the two directions, either side of the plane's peak, where
// the intensity falls to `fraction` of the plane's peak (linear interpolation between 0.05 deg
// samples of the interpolated web). 0.5: beam angle; 0.1: field angle (IES/CIE definitions
// relative to the maximum intensity). 360 when it never falls that low.
double spreadAngleDeg(const PhotometricWeb& web, double cDeg, double fraction);

struct LuminaireSummary {
  std::string fileName, format, luminaire, manufacturer;
  PhotometricType type = PhotometricType::kC;
  double totalLumens = 0.0;       // lm, integrated from the web
  double lampLumens = -1.0;       // lm, rated; <= 0 for absolute photometry
  double lightOutputRatio = 0.0;  // fraction; NaN when absolute
  double maxIntensityCd = 0.0;
  CGamma maxDirection;
  double beamC0Deg = 0.0, beamC90Deg = 0.0;    // 50 % of the plane maximum, C0-C180 / C90-C270
  double fieldC0Deg = 0.0, fieldC90Deg = 0.0;  // 10 %
  std::vector<double> zonalLumens;             // 10 deg zones from nadir
  double downwardLumens = 0.0, upwardLumens = 0.0;
  double inputWatts = 0.0;                     // W; 0 when unknown
  double efficacyLmPerW = 0.0;                 // luminaire lm/W; NaN when watts unknown
  double openingWidthM = 0.0, openingLengthM = 0.0, openingHeightM = 0.0;
  OpeningShape openingShape = OpeningShape::kPoint;
};

LuminaireSummary summarizeLuminaire(const PhotometricWeb& web);

// Plain-text report, one item per line (the output of `candela luminaire`).
std::string formatSummary(const LuminaireSummary& s);

}  // namespace candela
