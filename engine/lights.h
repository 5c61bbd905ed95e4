// Light sources sampled explicitly: `light`/`illum` surfaces (area sources), `light` distant
// sources (e.g. the sun), photometric luminaires, and `glow` surfaces from the points where
// glowSampledFrom says so (elsewhere hemisphere rays find them). Distant glows (a glow sky
// `source`) are never sampled, as in Radiance (src/rt/source.c, distantsources: SSKIP).
#pragma once

#include "engine/scene.h"
#include "engine/source_distribution.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace candela {

class PatternEvaluator;

struct Light {
  enum class Kind { kArea, kDistant, kLuminaire };
  Kind kind = Kind::kArea;
  uint32_t shape = 0;    // Area: index into Scene::shapes
  uint32_t distant = 0;  // Distant: index into Scene::distant
  uint32_t luminaire = 0;  // Luminaire: index into Scene::luminaires
  Rgb radiance{0.0};     // W/sr/m²
  // The shape the light's own shadow rays pass through (they end on it): an area source's shape,
  // a luminaire's opening surface (LuminaireSource::openingShape), else kNoShape.
  uint32_t ownShape = std::numeric_limits<uint32_t>::max();
  // Polygon sources: triangulation (for uniform area sampling) with cumulative areas.
  std::vector<std::array<Vec3, 3>> triangles;
  std::vector<double> cumulativeArea;
  std::vector<Vec3> outline;  // polygon vertices, for Lambert's formula
  Vec3 normal{0.0};           // polygon: unit front normal (the emitting side)
  double areaM2 = 0.0;
  // Area: the source distribution modulating the radiance by direction (ies2rad luminaires;
  // owned by the scene), or none.
  const SourceDistribution* distribution = nullptr;
  // Area: the spotlight material (its cone and focal distance; owned by the scene), or none.
  const Material* spot = nullptr;
  // Area or distant: the function pattern modifying the radiance (an index into Scene::patterns,
  // evaluated at each sample by the caller's PatternEvaluator), or -1.
  int pattern = -1;
  // Area, a `glow` surface: sampled only from the points glowSampledFrom accepts. Its radius
  // argument (Material::glowRadiusM) and a sphere bounding the shape (centre, radius in m).
  bool glow = false;
  double glowRadiusM = 0.0;
  Vec3 boundCentre{0.0};
  double boundRadiusM = 0.0;
  bool sphereGlow = false;  // the bound is the (outward) sphere itself
};

// The small-emitter rule's bound: an emitter whose bounding sphere subtends a cap of solid angle
// below one hemisphere stratum, 2π / hemisphereSamples, is one the stratified hemisphere cannot
// resolve. Returns sin² of that cap's half-angle α (1 − cos α = 1 / hemisphereSamples), so that
// the test is R² < sin²α · d², one product per light and receiver.
inline double smallEmitterSin2(int hemisphereSamples) {
  const double c = 1.0 / static_cast<double>(hemisphereSamples > 1 ? hemisphereSamples : 1);
  return c * (2.0 - c);
}

// Whether `light` is sampled explicitly from point p, so that rays leaving p must not count it
// when they meet it (both sides ask this one function with the same p: no light is counted
// twice or lost). Every source but a glow: always. A glow (Radiance's ray.1 "Glow" and
// src/rt/source.c): with a negative radius never (nor does it light anything: pathRadiance);
// otherwise when p lies within its radius of the glow's bounding sphere (radius > 0; Radiance
// tests the distance to each sample point instead) or when the glow is small from p (its
// bounding sphere within one hemisphere stratum: smallEmitterSin2). Never from inside a
// spherical glow or for an inward one (nothing to sample there).
inline bool glowSampledFrom(const Light& light, const Vec3& p, double smallSin2) {
  if (!light.glow) return true;
  if (light.glowRadiusM < 0.0) return false;
  const Vec3 e = p - light.boundCentre;
  const double d2 = glm::dot(e, e), r = light.boundRadiusM;
  if (light.sphereGlow && d2 <= r * r) return false;
  if (r * r < smallSin2 * d2) return true;
  const double reach = light.glowRadiusM + r;
  return light.glowRadiusM > 0.0 && d2 <= reach * reach;
}

// The explicitly sampled lights of a scene.
std::vector<Light> collectLights(const Scene& scene);

// What the direct integrator samples (engine/integrator_direct.h): the lights, and the flat
// mirrors that show each of them as a virtual source.
struct SampledSources {
  std::vector<Light> lights;
  std::vector<uint32_t> mirrors;    // flat mirror shapes
  std::vector<char> isMirrorImage;  // per shape: 1 for a flat mirror with virtual sources
  // Per shape: the index into `lights` of its glow, or -1; empty when the scene samples no glow.
  std::vector<int32_t> glowLight;
};
SampledSources collectSampledSources(const Scene& scene);

// One sample of a light seen from p: unit direction to the light, distance (infinity for
// distant sources) and the unoccluded contribution w such that irradiance = E[w · P · cos θ · V],
// P the light's function pattern where the sample meets it (1 without one).
struct LightSample {
  Vec3 dir{0.0};
  double distance = 0.0;
  Rgb weight{0.0};
  Rgb pattern{1.0};
  // The solid angle (sr) the whole source subtends from p, as Radiance passes a source's to
  // directional functions (its `omega`): a distant source's cone; a polygon, ring or cone its
  // area times the cosine at the sample over the distance squared (at most 2π); a sphere its cap;
  // 0 for a luminaire (a point, or its opening sampled as one).
  double solidAngleSr = 0.0;
};

// Draws a sample of `light` from p for the stratified pair (u1, u2); false when the sample
// cannot contribute (behind a one-sided source, p inside a spherical source). A light with a
// function pattern gets the pattern at the sampled point in out.pattern, as the shadow ray meets it
// (Radiance's srcvalue: the pattern sees the shadow ray's direction and the source's normal; a
// distant source's point is 10^10 m along the ray and its normal the reverse of the ray):
// `patterns` is then required (std::logic_error without it), else unused (nullptr is fine).
bool sampleLight(const Light& light, const Scene& scene, const Vec3& p, double u1, double u2, LightSample& out,
                 PatternEvaluator* patterns);

// Exact unoccluded irradiance (W/m²) from `light` at p on a surface with normal n, where a closed
// form exists: Lambert's polygon formula on the source clipped to the receiver's horizon (the
// clipped outline is returned in *clipped, to be sampled with sampleClippedPolygon); the
// vector irradiance of a disk or annulus wholly above the horizon; the cap formula
// π L sin²α cos θ for spherical and distant sources wholly above the horizon; a far-field
// luminaire's I cos ι / d² (a point luminaire only: an opening is sampled, lights.cpp). Returns
// false where no closed form applies (and for every source with a distribution or a pattern).
bool unoccludedIrradiance(const Light& light, const Scene& scene, const Vec3& p, const Vec3& n, Rgb& out,
                          std::vector<Vec3>* clipped = nullptr);

// Uniform sample of a polygon source restricted to `tris` (its part above a receiver's horizon,
// triangulated, with cumulative areas `cumulative`).
// 8 parameters: sampleLight's seven with the clipped triangulation in place of the light's own.
bool sampleClippedPolygon(const Light& light, const std::vector<std::array<Vec3, 3>>& tris,
                          const std::vector<double>& cumulative, const Vec3& p, double u1, double u2,
                          LightSample& out, PatternEvaluator* patterns);

// Vector irradiance of a uniform Lambertian disk of radius R (W/m² per unit radiance) at a point
// h in front of its plane and ρ off its axis: the component along the axis towards the disk,
// π/2 (1 − (h² + ρ² − R²)/√((h² + ρ² + R²)² − 4R²ρ²)), and the one towards the axis,
// π h/(2ρ) ((h² + ρ² + R²)/√((h² + ρ² + R²)² − 4R²ρ²) − 1) (e.g. Moon 1936, "The Scientific
// Basis of Illuminating Engineering", ch. 9; the first is Howell's configuration factor B-12).
void diskVectorIrradiance(double radiusM, double hM, double rhoM, double& alongAxis, double& towardsAxis);

// Lambert's formula (Lambert 1760; e.g. Arvo 1994, "The irradiance Jacobian"): the cosine-weighted
// solid angle Σ θ_k (n · Γ_k)/2 of a polygon seen from p, for a polygon wholly above the receiver's
// plane. Multiply by π⁻¹·π L = L to get irradiance of a uniform source of radiance L.
double polygonProjectedSolidAngle(const std::vector<Vec3>& poly, const Vec3& p, const Vec3& n);

// Triangulates a simple (possibly concave) planar polygon by ear clipping.
std::vector<std::array<Vec3, 3>> triangulatePolygon(const std::vector<Vec3>& poly, const Vec3& normal);

}  // namespace candela
