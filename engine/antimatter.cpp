#include "engine/antimatter.h"

#include "engine/scene.h"
#include "engine/tracer.h"

#include <algorithm>

namespace candela {

ClipResult clipStep(const Material& m, const Vec3& d, const Vec3& ng, ClipState& st) {
  const bool front = glm::dot(d, ng) < 0.0;
  // raycont: a surface of a clipped material is passed (checked before its material is asked
  // anything, so an antimatter listed by another is passed too). Its crossing is what m_clip's
  // walk up the ray tree counts: front +1, back −1 (saturated: a path crosses far fewer).
  if (m.clipBit >= 0 && (st.clipped >> m.clipBit & 1u)) {
    st.cross(m.clipBit, front ? 1 : -1);
    return {ClipAction::kPass, -1, st.clipped};
  }
  if (m.type != MaterialType::kAntimatter) return {};
  // m_clip: entering on the front (outward normals) adds the listed materials, leaving takes them out.
  const uint16_t beyond = front ? static_cast<uint16_t>(st.clipped | m.clipMask)
                                : static_cast<uint16_t>(st.clipped & ~m.clipMask);
  if (m.shownMaterial >= 0) {
    // Inside an object of the listed materials (more front faces than back ones passed): the
    // antimatter surface is that object's inside, seen as the first listed material.
    int inside = 0;
    for (int b = 0; b < kMaxClippedMaterials; ++b)
      if (m.clipMask >> b & 1u) inside += st.crossings(b);
    if (inside > 0) return {ClipAction::kShown, m.shownMaterial, beyond};
  }
  st.clipped = beyond;
  return {ClipAction::kPass, -1, beyond};
}

bool firstSeen(const RayAccelerator& accel, const Scene& scene, const Vec3& o, const Vec3& d, uint32_t skip,
               ClipState& st, RayHit& hit, ClipResult& result, uint64_t& rays) {
  double tMin = 0.0;
  uint32_t passed = kNoShape;  // the flat surface last passed (not to be met again)
  // As many surfaces as a path follows (engine/integrator_path.cpp): beyond, the ray is lost.
  for (int i = 0; i < 64; ++i) {
    ++rays;
    if (!accel.intersect(o, d, tMin, std::numeric_limits<double>::infinity(), hit, skip, passed)) return false;
    const Shape s = scene.surface(hit.shape);
    const Vec3 x = o + hit.t * d;
    result = clipStep(scene.materials[s.material], d, shapeNormal(s, x), st);
    if (result.action != ClipAction::kPass) return true;
    tMin = hit.t + Tracer::originOffset(x);
    passed = isFlat(s) ? hit.shape : kNoShape;
  }
  return false;
}

bool hasAntimatter(const std::vector<Material>& materials) {
  return std::any_of(materials.begin(), materials.end(),
                     [](const Material& m) { return m.type == MaterialType::kAntimatter; });
}

}  // namespace candela
