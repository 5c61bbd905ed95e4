#include "engine/tracer.h"

#include "engine/embree_accelerator.h"
#include "engine/materials/family.h"
#include "engine/materials/pattern_hook.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {
namespace {

// A shadow ray's geometry (Tracer::transmittance).
struct ShadowRay {
  Vec3 o, dir;
  double tMax;
  uint32_t skipA, skipB;
};

// Tracer::transmittance's walk in a scene with antimatter: the same walk along the one ray, past
// each transmitting surface, through the clip steps too (engine/antimatter.h), from state clip
// (nullptr: empty). Scenes without antimatter keep the walk without them.
Rgb clippedShadowRay(const Tracer& tracer, const ShadowRay& r, uint64_t& rays, uint32_t& firstGlass,
                     PatternEvaluator* patterns, const ClipState* clip) {
  const Scene& scene = tracer.scene();
  Rgb t(1.0);
  double tMin = 0.0;
  std::optional<PatternEvaluator> own;  // made when a patterned surface is met without the caller's
  ClipState clipped = clip ? *clip : ClipState{};
  for (int i = 0; i < 64; ++i) {
    RayHit h;
    if (i > 0) ++rays;
    if (!tracer.accelerator().intersect(r.o, r.dir, tMin, r.tMax, h, r.skipA, r.skipB)) return t;
    const Shape s = scene.surface(h.shape);  // a shape or a mesh triangle
    const Vec3 x = r.o + h.t * r.dir;
    const Material* seen = &scene.materials[s.material];
    Vec3 ng = shapeNormal(s, x);
    // Clipped surfaces and antimatter boundaries are passed; a hole's side is its material.
    const ClipResult step = clipStep(*seen, r.dir, ng, clipped);
    if (step.action == ClipAction::kPass) {
      tMin = h.t + Tracer::originOffset(x);
      continue;
    }
    if (step.action == ClipAction::kShown) {
      seen = &scene.materials[static_cast<size_t>(step.shown)];
      ng = -ng;
    }
    std::optional<Rgb> through;
    if (tracer.hasPatterns()) {
      if (!patterns) patterns = &own.emplace(scene);
      through = straightThrough(scene, *seen, {x, r.dir, ng, h.t}, *patterns);
    } else {
      through = familyOf(*seen).straightTransmittance(*seen, r.dir, ng);
    }
    if (!through) {
      firstGlass = kNoShape;
      return Rgb(0.0);
    }
    t *= *through;
    if (familyOf(*seen).isGlazing() && firstGlass == kNoShape) firstGlass = h.shape;
    if (photopic(t) <= 0.0) {
      firstGlass = kNoShape;
      return Rgb(0.0);
    }
    if (step.action == ClipAction::kShown) clipped.clipped = step.beyond;  // on through: newcset
    tMin = h.t + Tracer::originOffset(x);
  }
  return t;
}

}  // namespace


double Tracer::originOffset(const Vec3& p) {
  // Doubles locate a hit to ~1e-15 of its coordinates; 1e-7 of the larger of 1 m and the
  // coordinates clears that by far while staying far below any modelled gap (≥ 0.1 mm).
  const double m = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 1e-7 * m;
}

AcceleratorKind parseAccelerator(const std::string& s) {
  if (s == "embree") return AcceleratorKind::kEmbree;
  if (s == "octree") return AcceleratorKind::kOctree;
  throw std::invalid_argument("accelerator must be embree or octree, not '" + s + "'");
}

std::unique_ptr<RayAccelerator> makeAccelerator(const Scene& scene, AcceleratorKind kind) {
  if (kind == AcceleratorKind::kOctree) return std::make_unique<Octree>(scene);
  return std::make_unique<EmbreeAccelerator>(scene);
}

Tracer::Tracer(const Scene& scene, AcceleratorKind kind) : Tracer(scene, makeAccelerator(scene, kind)) {}

Tracer::Tracer(const Scene& scene, OctreeOptions octree) : Tracer(scene, std::make_unique<Octree>(scene, octree)) {}

Tracer::Tracer(const Scene& scene, std::unique_ptr<RayAccelerator> accelerator)
    : scene_(scene), accel_(std::move(accelerator)), sources_(collectSampledSources(scene)) {
  if (scene.sky) portals_ = PortalSet(scene);
  for (const Material& m : scene.materials)
    if (familyOf(m).mayPassShadowRays(m)) hasTransmitters_ = true;
  hasAntimatter_ = candela::hasAntimatter(scene.materials);
}

Rgb Tracer::transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB) const {
  uint64_t rays = 0;
  const Rgb t = transmittance(o, dir, tMax, skipA, skipB, rays);
  addRays(rays);
  return t;
}

Rgb Tracer::transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB,
                          uint64_t& rays) const {
  uint32_t firstGlass = kNoShape;
  return transmittance(o, dir, tMax, skipA, skipB, rays, firstGlass);
}

Rgb Tracer::transmittance(const Vec3& o, const Vec3& dir, double tMax, uint32_t skipA, uint32_t skipB,
                          uint64_t& rays, uint32_t& firstGlass, PatternEvaluator* patterns,
                          const ClipState* clip) const {
  firstGlass = kNoShape;
  ++rays;
  if (!hasTransmitters_) return accel_->occluded(o, dir, 0.0, tMax, skipA, skipB) ? Rgb(0.0) : Rgb(1.0);
  if (hasAntimatter_) return clippedShadowRay(*this, {o, dir, tMax, skipA, skipB}, rays, firstGlass, patterns, clip);
  // Walk the hits along the one ray, past each transmitting surface (same origin, growing tMin).
  Rgb t(1.0);
  double tMin = 0.0;
  std::optional<PatternEvaluator> own;  // made when a patterned surface is met without the caller's
  for (int i = 0; i < 64; ++i) {
    RayHit h;
    if (i > 0) ++rays;
    if (!accel_->intersect(o, dir, tMin, tMax, h, skipA, skipB)) return t;
    const Shape s = scene_.surface(h.shape);  // a shape or a mesh triangle
    const Vec3 x = o + h.t * dir;
    const Material& m = scene_.materials[s.material];
    const MaterialFamily& family = familyOf(m);
    // Glass and trans let their straight part through; an illum with no alternate is invisible
    // to all but its own rays; all else is opaque (a dielectric too: it bends light, so no
    // straight shadow ray passes it, as Radiance's source rays; paths find what lies behind it).
    // Function patterns and mixtures are evaluated where the ray crosses (pattern_hook.h).
    std::optional<Rgb> through;
    if (hasPatterns()) {
      if (!patterns) patterns = &own.emplace(scene_);
      through = straightThrough(scene_, m, {x, dir, shapeNormal(s, x), h.t}, *patterns);
    } else {
      through = family.straightTransmittance(m, dir, shapeNormal(s, x));
    }
    if (!through) {
      firstGlass = kNoShape;
      return Rgb(0.0);
    }
    t *= *through;
    if (family.isGlazing() && firstGlass == kNoShape) firstGlass = h.shape;
    if (photopic(t) <= 0.0) {
      firstGlass = kNoShape;
      return Rgb(0.0);
    }
    tMin = h.t + originOffset(x);
  }
  return t;
}

}  // namespace candela
