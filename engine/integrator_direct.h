// Direct light from the sources sampled explicitly (Tracer::sources): per-light ratio estimators
// at sensors, one light chosen by importance per sample at path vertices
// (engine/light_selection.h), the sources' images in flat mirrors (virtual sources), and the sky
// by importance sampling of its luminance, weighted against cosine sampling by the power
// heuristic (Veach 1997, "Robust Monte Carlo methods for light transport simulation", §9.2).
#pragma once

#include "engine/trace_context.h"

#include <cstdint>

namespace candela {

// A point receiving light: position, unit normal of the side that receives, and the flat shape
// it lies on (skipped by its shadow rays), or kNoShape.
struct Receiver {
  Vec3 p{0.0};
  Vec3 n{0.0, 0.0, 1.0};
  uint32_t skip = kNoShape;
};

// Direct irradiance at `at` from every sampled source with k stratified samples each; adds the
// variance of its photopic value to *variance when given (sensors; nullptr at path vertices,
// which choose one light per sample instead). With a sky, k sky samples by luminance are taken
// too, weighted against the cosine-sampled rays that accompany them by the power heuristic with
// misRatio = k / (number of cosine-sampled rays). Reports to ctx.tally's sky bins and suns.
Rgb directIrradiance(TraceContext& ctx, const Receiver& at, int k, double* variance, double misRatio);

// Radiance of the sky and the distant sources seen along an escaping ray of direction dir.
// misCosPdf: density (per sr) of the cosine sampling that drew dir (0: not cosine-sampled, the
// sky counts in full); misRatio as for directIrradiance.
Rgb distantRadiance(const Scene& scene, const Vec3& dir, bool countSources, double misCosPdf, double misRatio);

}  // namespace candela
