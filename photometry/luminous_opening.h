// The luminous opening of a photometric file as an observer sees it: its area projected on a
// plane normal to the line of sight, for luminances L = I / A_projected (CIE 117-1995 §4.2: the
// luminance of the luminous parts towards the eye, and ω = A_projected / d²).
#pragma once

#include "base/math.h"
#include "photometry/photometric_web.h"

namespace candela {

// Area in m² of the opening of `info` (shape and dimensions as the file gives them, axes of
// photometric_web.h: width along X = C0-C180, length along Y = C90-C270, height along Z)
// projected along the luminaire-local direction `dirLocal` (any length > 0; the sign does not
// matter). Flat shapes: A |d·n|; boxes and cylinders: the bottom plus the sides seen; sphere and
// ellipsoid: their silhouette, π √((bc dx)² + (ac dy)² + (ab dz)²). A shape LM-63 does not
// define (kOther) is taken by its plan footprint width × length, as the engine takes it
// (luminaire_source.h). 0 for a point opening.
double projectedOpeningAreaM2(const PhotometricInfo& info, const Vec3& dirLocal);

// True when the opening has an area seen obliquely from below, along (1, 1, −1): every shape but a
// point (or a footprint of zero area). A UGR needs a luminance, hence an area.
bool hasLuminousArea(const PhotometricInfo& info);

}  // namespace candela
