// The common interface of the sky luminance distributions (uniform, CIE, Perez).
//
// Frame: directions are unit vectors in the TRUE frame, +X east, +Y true north, +Z up. The
// engine rotates model directions by the site's true north first (photometry/site.h,
// modelToTrue). The sun's disk is not part of the sky: it is a separate 0.533 deg source.
//
// Each model supplies a relative luminance; the base class turns it into cd/m2 with a scale
// found by numerically integrating the horizontal illuminance of the sky hemisphere (composite
// Gauss-Legendre in altitude and azimuth, relative accuracy ~1e-6, computed once), and tabulates
// a piecewise-constant 2D distribution over (azimuth, altitude) cells for importance sampling.
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class SkyModel {
 public:
  virtual ~SkyModel() = default;

  // Relative luminance (any unit, >= 0) towards a unit direction with dirTrue.z > 0. Callers use
  // luminance(); this is the model's shape only.
  virtual double relativeLuminance(const Vec3& dirTrue) const = 0;
  // The type name as written in a case file: "uniform", "cie-overcast", "cie:12", "perez".
  virtual std::string name() const = 0;

  // Sky luminance in cd/m2 towards unit direction dirTrue; 0 at and below the horizon.
  double luminance(const Vec3& dirTrue) const {
    return dirTrue.z > 0.0 ? scale_ * relativeLuminance(dirTrue) : 0.0;
  }
  // Factor from relative luminance to cd/m2.
  double scale() const { return scale_; }

  // Illuminance in lux on an unobstructed horizontal plane from the sky hemisphere alone (no
  // sun, no ground); equals the requested diffuse horizontal illuminance.
  double horizontalIlluminanceLux() const { return scale_ * relativeHorizontal_; }
  // Illuminance in lux on an unobstructed plane with unit normal `normal` (true frame) from the
  // sky hemisphere only (directions with z > 0 and dot(normal, dir) > 0); no ground. Numerical
  // integral, relative accuracy ~1e-6; costs ~0.5 M luminance evaluations.
  double illuminanceOnPlane(const Vec3& normal) const;

  // Importance sampling by luminance: (u1, u2) in [0,1)^2 -> unit direction above the horizon,
  // with its probability density per steradian in *pdfSolidAngle. The density is piecewise
  // constant over kSampleAz x kSampleAlt (azimuth, altitude) cells, proportional to the cell's
  // mean luminance plus a small floor, so it is > 0 over the whole upper hemisphere.
  Vec3 sample(double u1, double u2, double* pdfSolidAngle) const;
  // Density per steradian that sample() returns `dirTrue` with; 0 for dirTrue.z <= 0.
  double pdf(const Vec3& dirTrue) const;

  static constexpr int kSampleAz = 256;   // cells in azimuth (1.41 deg)
  static constexpr int kSampleAlt = 64;   // cells in altitude (1.41 deg)

 protected:
  // Derived constructors call this last: sets the scale so that horizontalIlluminanceLux()
  // equals `horizontalLux` (lux, >= 0) and builds the sampling table.
  void calibrate(double horizontalLux);

  // Integral over the sky hemisphere of relativeLuminance * max(0, dot(normal, dir)) d(omega).
  double integrateRelative(const Vec3& normal) const;

 private:
  double scale_ = 0.0;
  double relativeHorizontal_ = 0.0;
  std::vector<double> rowCdf_;   // kSampleAlt + 1 entries, marginal over altitude rows
  std::vector<double> cellCdf_;  // kSampleAlt rows of kSampleAz + 1 entries, conditional
  std::vector<double> cellPdf_;  // density per steradian of each cell, row-major
};

}  // namespace candela
