// Splitting a polygon outline into triangles, by vertex index: OBJ faces (engine/obj_reader.h)
// and non-planar Radiance polygons under --nonplanar triangulate (engine/radiance/reader.h).
#pragma once

#include "base/math.h"

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace candela {

// Ear clipping (Meisters 1975, "Polygons have ears") of the outline `pts` seen along `normal`
// (the Newell normal: for a non-planar outline, the plane it is projected on). Every simple
// outline, convex or concave, has an ear while it has more than three vertices, so the
// triangles cover the projected outline exactly and keep its orientation (counter-clockwise
// about `normal`). A remainder with no ear (collinear or self-touching vertices, where the
// outline is not simple) is fanned from its first vertex. Appends triangles of indices into
// `pts`; triangles of zero area are left out. O(n²) for convex outlines, O(n³) at worst: returns
// false (with `out` partly filled) when more than `maxTests` point-in-triangle tests would be
// needed, so that time stays bounded (10⁸ tests: about a third of a second). `used`, when given,
// receives the tests made (a file's readers bound their sum).
bool splitPolygon(const std::vector<Vec3>& pts, const Vec3& normal, std::vector<std::array<uint32_t, 3>>& out,
                  uint64_t maxTests = 100000000, uint64_t* used = nullptr);

// The first two edges (by their first vertices) of the closed plane outline `pts` that cross or
// touch each other (not neighbours; two collinear edges overlapping are not counted), or none:
// an outline without them is simple. O(n²).
std::optional<std::pair<size_t, size_t>> outlineSelfCrossing(const std::vector<glm::dvec2>& pts);

// The largest distance of a vertex from the plane through the centroid with unit normal `n`
// (m), and the vertex (0-based) where it occurs.
double planeDeviation(const std::vector<Vec3>& pts, const Vec3& n, size_t* worst = nullptr);

}  // namespace candela
