#include "study/sight_line.h"

#include "base/units.h"
#include "engine/materials/family.h"
#include "engine/shapes.h"

namespace candela {

bool seenThrough(const Scene& scene, const Material& m) {
  // An illum is seen as its alternate, or not at all. An illum's alternate is never another
  // illum's (the reader resolves it to a material defined before), so this recursion ends.
  if (const std::optional<int> other = familyOf(m).seenInstead(m)) {
    if (*other < 0) return true;
    if (*other >= static_cast<int>(scene.materials.size())) return false;
    const Material& alt = scene.materials[static_cast<size_t>(*other)];
    return !familyOf(alt).seenInstead(alt) && seenThrough(scene, alt);
  }
  return familyOf(m).viewTransmittance(m) >= kSeeThroughMinTransmittance;
}

SightLine traceSightLine(const Tracer& tracer, const Vec3& o, const Vec3& dir, double tMax, uint64_t& rays) {
  const Scene& scene = tracer.scene();
  SightLine line;
  double tMin = 0.0;
  for (int i = 0; i < 64; ++i) {
    RayHit h;
    ++rays;
    if (!tracer.accelerator().intersect(o, dir, tMin, tMax, h)) return line;
    const Shape s = scene.surface(h.shape);
    const Vec3 x = o + h.t * dir;
    if (!seenThrough(scene, scene.materials[s.material])) {
      line.blocked = true;
      line.blockedAtM = h.t;
      line.blocker = h.shape;
      line.blockerNormal = shapeNormal(s, x);
      return line;
    }
    if (line.glazingCrossed == 0) line.firstGlazingM = h.t;
    line.lastGlazingM = h.t;
    ++line.glazingCrossed;
    tMin = h.t + Tracer::originOffset(x);
  }
  line.blocked = true;  // a stack of 64 panes: taken as opaque
  line.blockedAtM = tMin;
  return line;
}

}  // namespace candela
