// Discomfort glare: UGR (CIE 117-1995) from luminaires and DGP (Wienold & Christoffersen 2006)
// from a fisheye luminance image. Directions are in the observer's view frame: x right, y up,
// z along the line of sight (forward).
#pragma once

#include "base/math.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace candela {

// One glare source as the observer sees it.
struct GlareSource {
  double luminanceCdM2 = 0.0;  // mean luminance of the source towards the eye, cd/m²
  double solidAngleSr = 0.0;   // solid angle it subtends at the eye, sr
  double positionIndex = 1.0;  // P: 1 on the line of sight, growing towards the periphery
};

// Luckiesh–Guth position index in the closed form of the IES Lighting Handbook (as used by
// CIE 117 and by evalglare): ln P = (35.2 − 0.31889 τ − 1.22 e^(−2τ/9))·10⁻³ σ
// + (21 + 0.26667 τ − 0.002963 τ²)·10⁻⁵ σ², τ (degrees) the angle from the vertical of the plane
// through the line of sight and the source, σ (degrees) the angle between the line of sight and
// the source. For sources above the line of sight.
double guthPositionIndex(double tauDeg, double sigmaDeg);

// Position index of a view-frame direction: Guth's form above the line of sight (y ≥ 0); below
// it Iwata's (as quoted by Einhorn and used in evalglare): P = 1 + 0.8 R/D for R/D < 0.6, else
// 1 + 1.2 R/D with R/D = tan σ capped at 3. Capped at 16 (evalglare). Directions at or behind
// 90° from the line of sight return 16 (outside the field that counts).
double positionIndex(const Vec3& directionView);

// Unified glare rating, CIE 117-1995 eq. (1): UGR = 8 log10( 0.25/Lb · Σ L² ω / P² ),
// Lb the background luminance in cd/m² (the indirect illuminance at the eye / π). Valid for
// sources of 3·10⁻⁴ to 0.1 sr (CIE 117); returns −∞ without sources.
double unifiedGlareRating(double backgroundLuminanceCdM2, const std::vector<GlareSource>& sources);

// Wienold's low-light correction factor (evalglare ≥ 1.03, Wienold 2009): e^(0.024 Ev − 4) /
// (1 + e^(0.024 Ev − 4)) for Ev below `limitLux`, else 1. It is 0.975 at 320 lx and 1 − 2·10⁻⁹
// at 1000 lx.
double lowLightCorrection(double verticalIlluminanceLux, double limitLux = 1000.0);

// Daylight glare probability, Wienold & Christoffersen 2006, Energy and Buildings 38, eq. (7):
// DGP = 5.87·10⁻⁵ Ev + 9.18·10⁻² log10(1 + Σ Ls² ωs / (Ev^1.87 P²)) + 0.16, Ev the vertical
// illuminance at the eye in lux; then times the low-light correction when asked; at most 1.
double daylightGlareProbability(double verticalIlluminanceLux, const std::vector<GlareSource>& sources,
                                bool lowLight = true);

// How glare sources are found in an image: pixels brighter than `thresholdCdM2` when it is
// positive, else than `averageFactor` × the image's mean luminance (evalglare 1.x's default of 5 ×;
// evalglare 2.x defaults to a fixed 2000 cd/m², per its author on the Radiance forum).
struct GlareDetection {
  double thresholdCdM2 = 0.0;
  double averageFactor = 5.0;
  bool lowLightCorrection = true;
};

struct ImageGlare {
  double verticalIlluminanceLux = 0.0;  // Σ L cos θ ω over the forward hemisphere
  double averageLuminanceCdM2 = 0.0;    // solid-angle weighted mean over the image
  double thresholdCdM2 = 0.0;
  std::vector<GlareSource> sources;     // one per 8-connected group of pixels above the threshold
  double dgp = 0.0;
  double dgpUncorrected = 0.0;          // without the low-light correction
};

// A pixel's view-frame direction (x right, y up, z forward; need not be unit) and solid angle
// (sr; 0 for a pixel without a ray), by row-major index: computed when asked, so that a large
// image needs no geometry arrays.
using PixelGeometry = std::function<void(std::size_t pixel, Vec3& directionView, double& solidAngleSr)>;

// The solid angle of pixel i if it belongs to a glare source of evaluateImageGlare (brighter than
// the threshold, with a ray, in front of the eye), else 0.
double glareSourceSolidAngle(const std::vector<float>& luminanceCdM2, const PixelGeometry& geometry, std::size_t i,
                             double thresholdCdM2);

// Evaluates a luminance image given each pixel's luminance (cd/m², row-major, width × height)
// and geometry. A source's luminance is its pixels' solid-angle weighted mean, its position
// index that of its solid-angle weighted mean direction.
ImageGlare evaluateImageGlare(const std::vector<float>& luminanceCdM2, const PixelGeometry& geometry, int width,
                              int height, const GlareDetection& detection = {});

}  // namespace candela
