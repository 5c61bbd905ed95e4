// The glare rating GR of CIE 112-1994 (outdoor sports and area lighting), the glare criterion of
// EN 12464-2:2014 for outdoor work places (docs/outdoor.md): the veiling luminance the
// luminaires throw on the eye against the veiling luminance of the lit surroundings,
//
//   GR   = 27 + 24 · log10(L_vl / L_ve^0.9)
//   L_vl = 10 · Σ_k E_eye,k / θ_k²      (cd/m²; θ_k in degrees)
//   L_ve = 0.035 · ρ · E_hav / π        (cd/m²)
//
// with E_eye,k the illuminance (lux) luminaire k gives at the eye on the plane perpendicular to the
// line of sight, θ_k the angle (degrees) between the line of sight and the direction to luminaire
// k, ρ the average reflectance of the area and E_hav its average horizontal illuminance (lux).
// Pure functions: the study (study/compliance/en12464_2.h) finds the luminaires and the light.
#pragma once

#include "base/math.h"

#include <optional>
#include <vector>

namespace candela {

// One luminaire as the eye sees it: its illuminance on the plane perpendicular to the line of
// sight (lux) and its angle from the line of sight (degrees, in (0, 90)).
struct VeilingSource {
  double eyeLux = 0.0;
  double angleDeg = 0.0;
};

// A luminaire of intensity `intensityCd` towards the eye (cd, with whatever reaches the eye of
// it: `transmittance` in [0, 1]) at `sourceM`, seen from `eyeM` along the unit line of sight
// `sight`: E_eye = τ I cos θ / d², θ the angle between the sight and the direction to the source.
// Unset when the source is not in front of the eye (θ ≥ 90°: it lights no part of the plane
// facing the sight) or gives no light.
std::optional<VeilingSource> veilingSource(const Vec3& eyeM, const Vec3& sight, const Vec3& sourceM,
                                           double intensityCd, double transmittance = 1.0);

// L_vl = 10 Σ E_eye,k / θ_k² in cd/m² (CIE 112: θ in degrees).
double luminairesVeilingLuminance(const std::vector<VeilingSource>& sources);

// L_ve = 0.035 ρ E_hav / π in cd/m²: ρ the area's average reflectance in [0, 1], E_hav its average
// horizontal illuminance in lux.
double environmentVeilingLuminance(double reflectance, double averageHorizontalLux);

// GR = 27 + 24 log10(L_vl / L_ve^0.9); unset when L_vl = 0 (no luminaire in front of the eye:
// no glare to rate) or L_ve = 0 (a black or unlit area: the rating is unbounded).
std::optional<double> glareRating(double luminairesVeilCdM2, double environmentVeilCdM2);

// The line of sight of an observer looking towards plan azimuth `azimuthDeg` (degrees clockwise
// from plan +Y: 0 +Y, 90 +X) at `inclinationDeg` above the horizontal (negative: below it).
Vec3 lineOfSight(double azimuthDeg, double inclinationDeg);

// The azimuths of an observer who looks all around in steps of `stepDeg` (in (0, 360]), from 0:
// 0, 45, …, 315 for 45°.
std::vector<double> viewAzimuthsDeg(double stepDeg);

}  // namespace candela
