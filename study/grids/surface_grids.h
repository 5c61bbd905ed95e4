// [[surface_grid]]: grids on the scene's walls and ceilings (EN 12464-1:2021), made once the
// scene is read: the flat surfaces whose identifiers match the entry's patterns, grouped by the
// plane they lie in, one plane grid each with its sensors facing the room (docs/en12464.md).
#pragma once

#include "engine/scene.h"
#include "study/case/case_file.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// Whether `name` matches the glob `pattern`: '*' any run of characters (none included), '?' one
// character, anything else itself (case-sensitive, as Radiance identifiers are).
bool globMatch(const std::string& pattern, const std::string& name);

// The grids of one [[surface_grid]] over `scene`, in the order the scene first names their
// surfaces. Throws InputError at the entry when a pattern matches no surface, a matched surface
// is not flat (a sphere, cone or ring), the surfaces lie in more than kMaxSurfaceGridPlanes
// planes, or every grid is left without a point (surfaces narrower than the spacing).
inline constexpr std::size_t kMaxSurfaceGridPlanes = 256;
std::vector<GridSpec> surfaceGridSpecs(const SurfaceGridSpec& s, const Scene& scene);

// The case with every [[surface_grid]]'s grids appended to its grids (names checked unique).
CaseFile withSurfaceGrids(const CaseFile& c, const Scene& scene);

// The side a surface's grid faces: the unit normal `front` or its opposite, whichever points
// towards `inside`; none when `inside` lies within 1 cm of the plane through `onPlane`.
std::optional<Vec3> sideFacing(const Vec3& front, const Vec3& onPlane, const Vec3& inside);

}  // namespace candela
