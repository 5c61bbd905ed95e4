// Surface primitives of the Radiance scene language and their ray intersections.
// Conventions (Radiance's): a polygon's front is the side from which its vertices run
// counter-clockwise; spheres, cones and cylinders face outward; bubble, cup and tube face inward.
#pragma once

#include "base/math.h"

#include <cstdint>
#include <vector>

namespace candela {

enum class ShapeType : uint8_t { kTriangle, kPolygon, kSphere, kRing, kCone };

struct Shape {
  ShapeType type = ShapeType::kPolygon;
  bool inward = false;         // bubble, cup, tube: normal points to the inside
  uint32_t material = 0;       // index into Scene::materials
  uint32_t firstVertex = 0;    // polygon: first vertex in Scene::vertices / projected 2D coords
  uint32_t vertexCount = 0;
  uint8_t axisU = 0, axisV = 1;  // polygon: the two coordinates kept when projecting to 2D
  // Triangle: a = v0, b = v1 - v0, c = v2 - v0, n = unit normal.
  // Polygon: a = first vertex, n = unit normal (Newell), d = n·a.
  // Sphere: a = centre, r0 = radius (m).
  // Ring: a = centre, n = unit normal, r0 = inner radius, r1 = outer radius (m).
  // Cone/cylinder: a = first end, b = second end, n = unit axis a→b, d = length, r0/r1 = radii (m).
  Vec3 a{0.0}, b{0.0}, c{0.0}, n{0.0};
  double d = 0.0, r0 = 0.0, r1 = 0.0;
};

// Polygon vertex storage shared by all shapes of a scene (3D and projected 2D coordinates).
struct VertexStore {
  std::vector<Vec3> points;
  std::vector<Vec2> projected;
};

// Möller & Trumbore (1997), "Fast, minimum storage ray-triangle intersection": the ray o + t·dir
// against the triangle (v0, v0 + e1, v0 + e2) for t in (tMin, tMax). Shared by intersectShape and
// the octree's compact triangles, so both give the same t to the last bit.
[[gnu::always_inline]] inline bool intersectTriangle(const Vec3& v0, const Vec3& e1, const Vec3& e2, const Vec3& o, const Vec3& dir,
                              double tMin, double tMax, double& t) {
  const Vec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return false;
  const double inv = 1.0 / det;
  const Vec3 tv = o - v0;
  const double u = glm::dot(tv, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 q = glm::cross(tv, e1);
  const double v = glm::dot(dir, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  const double tt = glm::dot(e2, q) * inv;
  if (tt <= tMin || tt >= tMax) return false;
  t = tt;
  return true;
}

// Nearest intersection of the ray o + t·dir with the shape for t in (tMin, tMax); dir need not be
// unit length for polygons but must be for spheres/cones (the integrator always passes unit
// vectors). Returns true and sets t on a hit.
// 7 parameters: a ray query's own (shape, vertices, ray, interval, result).
bool intersectShape(const Shape& s, const VertexStore& vs, const Vec3& o, const Vec3& dir, double tMin,
                    double tMax, double& t);

// Unit normal of the shape at a point on it, facing the shape's front (Radiance orientation).
Vec3 shapeNormal(const Shape& s, const Vec3& p);
// Triangles, polygons and rings: a ray leaving one cannot meet it again (so it is skipped), and a
// flat mirror among them has virtual sources.
inline bool isFlat(const Shape& s) {
  return s.type == ShapeType::kTriangle || s.type == ShapeType::kPolygon || s.type == ShapeType::kRing;
}

// The vertices of a triangle or polygon, in order; empty for every other shape.
std::vector<Vec3> polygonOutline(const Shape& s, const VertexStore& vs);

// Axis-aligned bounds of the shape.
Box shapeBounds(const Shape& s, const VertexStore& vs);

// Exact overlap of the shape's surface with the closed cube [lo, lo + size]³ (see octree.cpp for
// where a test is conservative instead). Used by the octree's AddSurface.
bool shapeOverlapsBox(const Shape& s, const VertexStore& vs, const Vec3& lo, double size);

// Surface area in m².
double shapeArea(const Shape& s, const VertexStore& vs);

}  // namespace candela
