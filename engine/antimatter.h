// Radiance's antimatter (reference manual "Antimatter"; src/rt/m_clip.c and raytrace.c's clipset,
// newcset and raycont): a closed volume bounded by antimatter surfaces subtracts the surfaces of the
// materials it lists. Each ray carries the set of materials currently clipped; a surface of a
// clipped material is passed as if absent; an antimatter surface adds its list to the set when met
// on its front (entering: outward normals) and takes it out when met on its back (leaving). When
// the first listed material is not void and the ray is inside an object of the listed materials
// (it crossed more of their front faces than back faces on its way, while they were clipped), the
// antimatter surface is seen instead as the first material, turned to face the ray: the inside
// wall of the hole it cuts. docs/engine.md#antimatter has the semantics and what differs.
//
// The state is a fixed-size value (no allocation per ray): materials listed by antimatter are
// numbered 0..kMaxClippedMaterials-1 (MaterialParameters::clipBit, given by the reader).
#pragma once

#include "base/math.h"
#include "engine/accelerator.h"
#include "engine/materials/material.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace candela {

struct Scene;

// The most materials the antimatters of one scene may list between them (the reader refuses more).
inline constexpr int kMaxClippedMaterials = 16;

// A ray's antimatter state: the set of clipped materials (bit b: the material whose clipBit is b)
// and, per material, the signed count of its surfaces the ray's path passed while clipped (front
// +1, back −1): Radiance's walk up the ray tree in m_clip.c, kept as a running sum, in 4 bits
// (saturated at −8 and +7: a path passes far fewer). 10 bytes, so that it fits in the padding of
// a path's state (engine/integrator_path.h): scenes without antimatter copy no more bytes.
struct ClipState {
  uint16_t clipped = 0;
  std::array<uint8_t, kMaxClippedMaterials / 2> counts{};  // two 4-bit counts a byte

  int crossings(int b) const {
    const int nibble = (counts[static_cast<size_t>(b / 2)] >> (4 * (b % 2))) & 0xF;
    return nibble >= 8 ? nibble - 16 : nibble;
  }
  void cross(int b, int delta) {
    const int c = std::clamp(crossings(b) + delta, -8, 7);
    uint8_t& byte = counts[static_cast<size_t>(b / 2)];
    const int shift = 4 * (b % 2);
    byte = static_cast<uint8_t>((byte & ~(0xF << shift)) | ((c & 0xF) << shift));
  }
};
static_assert(kMaxClippedMaterials <= 16, "ClipState::clipped holds one bit per clipped material");
static_assert(sizeof(ClipState) == 10 && alignof(ClipState) == 2, "fits the padding of PathState");

// A ray's state as it starts: nothing clipped, nothing crossed.
inline bool isEmpty(const ClipState& st) {
  if (st.clipped != 0) return false;
  for (uint8_t c : st.counts)
    if (c != 0) return false;
  return true;
}

// What a ray does at a surface: kVisible, the surface as it is; kPass, on straight through it (a
// clipped surface, or an antimatter boundary crossed: the state is updated); kShown, an antimatter
// surface seen as the material `shown` with its normal turned (the state is the arriving one, which
// reflected and shadow rays keep; a ray going on straight through takes `beyond`, as newcset).
enum class ClipAction { kVisible, kPass, kShown };
struct ClipResult {
  ClipAction action = ClipAction::kVisible;
  int shown = -1;
  uint16_t beyond = 0;
};

// The step at a surface of material m met along d, geometric normal ng (as stored), state st.
ClipResult clipStep(const Material& m, const Vec3& d, const Vec3& ng, ClipState& st);

// The first surface a ray from o along unit d (skipping `skip` at the origin) sees in state st:
// walks past what clipStep passes (st updated on the way). false: nothing is seen. The queries
// made are added to rays.
// 8 parameters: the ray (accelerator, scene, origin, direction, skip), its state and the results.
bool firstSeen(const RayAccelerator& accel, const Scene& scene, const Vec3& o, const Vec3& d, uint32_t skip,
               ClipState& st, RayHit& hit, ClipResult& result, uint64_t& rays);

// Whether the scene has antimatter materials (then the tracer walks rays through the clip steps).
bool hasAntimatter(const std::vector<Material>& materials);

}  // namespace candela
