// Material events along a path: which way a ray leaves a mirror, thin glass or a dielectric
// boundary, and the direction of a sample of the glossy (Ward) lobe. The weights are chosen so
// that each event carries the estimator unbiased; the path integrator (engine/integrator_path.h)
// decides what a path counts after them.
#pragma once

#include "base/math.h"
#include "base/rng.h"
#include "base/units.h"
#include "engine/scene.h"

namespace candela {

// Whether the irradiance cache serves diffuse reflection off m (opaque, diffusely reflecting).
bool isCacheable(const Material& m);

// Mirror direction of d about unit normal n.
inline Vec3 mirrorDirection(const Vec3& d, const Vec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// Thin glass met along d (geometric normal ng): transmitted straight on or reflected, chosen by
// the photopic shares of the two, the weight (transmittance or reflectance over its probability)
// multiplied into beta.
enum class GlassEvent { kAbsorbed, kTransmitted, kReflected };
GlassEvent sampleThinGlass(const Material& m, const Vec3& d, const Vec3& ng, Rng& rng, Rgb& beta);

// A smooth dielectric boundary met along d (nf facing the ray; front: entering the medium):
// the new direction, reflected or refracted.
struct DielectricEvent {
  Vec3 dir{0.0};
  bool reflected = false;
};
DielectricEvent sampleDielectric(const Material& m, const Vec3& d, const Vec3& nf, bool front, Rng& rng);
// Beer–Lambert absorption of a ray that travelled distanceM inside dielectric m, multiplied into
// beta.
void absorbInDielectric(const Material& m, double distanceM, Rgb& beta);

// One direction of the glossy (Ward) lobe of m for a ray arriving along inDir on the side of nf;
// false when the sample is lost (arrival from behind, or eight draws below the surface).
bool sampleWardLobe(const Material& m, const Vec3& inDir, const Vec3& nf, Rng& rng, Vec3& out);

}  // namespace candela
