// ies2rad's luminaires: a `brightdata` pattern calling one of source.cal's corrections (corr,
// flatcorr, boxcorr, cylcorr) on candela values tabulated in a data file, evaluated natively.
//
//   void brightdata lum_dist
//   5+ flatcorr lum.dat source.cal src_phi4 src_theta [transform]
//   0
//   1+ A1 [A2 A3 [A4]]
//
// The pattern multiplies the radiance of the light it modifies by
//   f = max(0, A1 · data(angles)) / correction,
// for light leaving the surface along −D, D the unit direction of the ray that meets it, taken
// into the pattern's coordinates by the inverse of its transform. Facts from Radiance:
// src/cv/source.cal and src/rt/func.c (l_source_corr, l_source_angle, chanvalue), src/cv/ies2rad.c
// (what it writes). Corrections (Radiance's rod: the cosine between −D and the surface normal):
//   corr      1
//   flatcorr  rod
//   boxcorr   |Dx|·A3·A4 + |Dy|·A2·A4 + |Dz|·A2·A3   (box of A2 × A3 × A4 m)
//   cylcorr   A2·A3·√(1 − Dz²) + π/4·A2²·|Dz|        (cylinder of diameter A2, height A3 m)
// A1 is applied whenever there is a real argument. Radiance 6.1a applies it only when there
// are two or more (func.c: `if (nrargs > 1)`), so the flat and spherical sources ies2rad writes
// (`1 mult/area`) come out without their multiplier there; candela follows source.cal's own
// older definition, corr(v) = noneg(if(AC-.5, A1*v, v)), as the issue asks (docs/luminaires.md).
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "base/units.h"
#include "engine/radiance/data_file.h"

#include <string>
#include <vector>

namespace candela {

struct Material;
struct Scene;
struct ScenePattern;

enum class SourceCorrection { kNone, kFlat, kBox, kCylinder };  // corr, flatcorr, boxcorr, cylcorr

// The coordinates source.cal defines for the data lookup (degrees).
enum class SourceAngle {
  kTheta,        // src_theta: from the −z axis, 0–180
  kPhi,          // src_phi: from +x towards +y, 0–360
  kPhi2,         // src_phi2: bilateral symmetry, 0–180
  kPhi2Plus90,   // src_phi2+90 (ies2rad, data from 90° to 270°)
  kPhi4,         // src_phi4: quadrilateral symmetry, 0–90
  kBVert,        // srcB_vert: type B photometry, atan2(−Dx, Dz)
  kBVert2,       // srcB_vert2: |srcB_vert|
  kBHoriz,       // srcB_horiz: atan2(Dy, Dz)
  kBHoriz2,      // srcB_horiz2: |srcB_horiz|
};

class SourceDistribution {
 public:
  // The factor by which the light's radiance is multiplied for a ray of unit world direction
  // `rayDir` meeting the emitting surface; `cosEmit` = −rayDir · (front normal) there (> 0 on the
  // emitting side; used by flatcorr only). No allocation.
  double factor(const Vec3& rayDir, double cosEmit) const;
  // A typical size of factor × cosEmit (max |data| · A1 over the smallest projected area the
  // correction divides by), for light selection: never zero unless the source is dark.
  double typicalIntensityFactor() const;
  // Whether the pattern can make the light emit anything at all.
  bool emits() const { return typicalIntensityFactor() > 0.0; }

  SourceCorrection correction() const { return correction_; }
  double multiplier() const { return multiplier_; }
  const RadDataArray& data() const { return data_; }

  // Parses a brightdata primitive calling source.cal (kind kSourceDistribution); the data file is
  // resolved relative to the folder of the file the pattern is in (pattern.loc.file). Errors are
  // InputError at the pattern's line, or at the data file's line for a malformed data file.
  static SourceDistribution parse(const ScenePattern& pattern);

 private:
  SourceCorrection correction_ = SourceCorrection::kNone;
  std::vector<SourceAngle> angles_;  // one per data dimension
  RadDataArray data_;
  glm::dmat3 toPattern_{1.0};        // world direction → pattern coordinates (rotation/mirror)
  double multiplier_ = 1.0;          // A1 (1 without real arguments)
  double a2_ = 0.0, a3_ = 0.0, a4_ = 0.0;  // box or cylinder dimensions (m)
};

// The source distribution modifying material m (a light, illum or glow), or none.
const SourceDistribution* sourceDistributionOf(const Scene& scene, const Material& m);

// The radiance m emits towards a ray of unit direction rayDir meeting its front side with
// cosEmit = −rayDir · normal: its colour, times the source distribution's factor if it has one.
Rgb emittedRadiance(const Scene& scene, const Material& m, const Vec3& rayDir, double cosEmit);

// The angle `a` (degrees) for a unit direction d in pattern coordinates (l_source_angle and
// source.cal's type B definitions).
double sourceAngleDeg(SourceAngle a, const Vec3& d);

}  // namespace candela
