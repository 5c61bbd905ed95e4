// Ray–shape intersections, normals, bounds, box overlap and areas, each checked against an
// independent computation written here (world-coordinate quadratics, winding numbers, surface
// point samples), not against the engine's own helpers.
#include "engine/scene.h"
#include "engine/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Closed forms evaluated in doubles by two different routes agree to ~1e-15 relative; 1e-9
// leaves room for cancellation in the quadratic formula without hiding a wrong root.
constexpr double kRel = 1e-9;

std::optional<double> hitT(const Scene& sc, uint32_t i, const Vec3& o, const Vec3& d, double tMin = 0.0,
                           double tMax = kInf) {
  double t = 0.0;
  if (!intersectShape(sc.shapes[i], sc.vertices, o, d, tMin, tMax, t)) return std::nullopt;
  return t;
}

void expectT(std::optional<double> got, double want) {
  ASSERT_TRUE(got.has_value()) << "expected a hit at t = " << want;
  EXPECT_NEAR(*got, want, kRel * std::max(1.0, std::abs(want)));
}

void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// Any orthonormal pair perpendicular to unit n, built without the engine's Frame.
void basis(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  u = glm::normalize(glm::cross(helper, n));
  v = glm::cross(n, u);
}

Vec3 randomUnit(std::mt19937_64& g) {
  std::normal_distribution<double> N;
  for (;;) {
    const Vec3 v(N(g), N(g), N(g));
    const double l = glm::length(v);
    if (l > 1e-6) return v / l;
  }
}

// Winding number of a closed 2D polygon around q (sum of signed angles / 2π): independent of the
// engine's crossing-number test.
int winding(const std::vector<Vec2>& poly, const Vec2& q) {
  double sum = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = poly[i] - q, b = poly[(i + 1) % poly.size()] - q;
    sum += std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
  }
  return static_cast<int>(std::lround(sum / kTwoPi));
}

double distToSegment2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + s * ab));
}

// ---------------------------------------------------------------- triangles

TEST(Shapes, TriangleHitInsideMissOutside) {
  Scene sc;
  const uint32_t tri = sc.addPolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0);
  ASSERT_EQ(sc.shapes[tri].type, ShapeType::kTriangle);
  expectT(hitT(sc, tri, {0.2, 0.3, 1.0}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, tri, {0.2, 0.3, -2.5}, {0, 0, 1}), 2.5);  // from behind: two-sided hit
  EXPECT_FALSE(hitT(sc, tri, {0.8, 0.8, 1.0}, {0, 0, -1}));   // beyond the hypotenuse
  EXPECT_FALSE(hitT(sc, tri, {-0.1, 0.5, 1.0}, {0, 0, -1}));
  EXPECT_FALSE(hitT(sc, tri, {0.2, 0.3, 1.0}, {0, 0, 1}));    // pointing away
  // Oblique ray: plane z = 0 is reached at t = oz / -dz (dir unit).
  const Vec3 d = glm::normalize(Vec3(0.1, 0.2, -1.0));
  const Vec3 o(0.1, 0.1, 2.0);
  expectT(hitT(sc, tri, o, d), 2.0 / -d.z);
  expectVec(shapeNormal(sc.shapes[tri], o + 2.0 / -d.z * d), {0, 0, 1});  // counter-clockwise from +z
}

TEST(Shapes, TriangleRayParallelToItsPlaneMisses) {
  Scene sc;
  const uint32_t tri = sc.addPolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0);
  EXPECT_FALSE(hitT(sc, tri, {-1.0, 0.2, 0.0}, {1, 0, 0}));  // in the plane, through the triangle
  EXPECT_FALSE(hitT(sc, tri, {-1.0, 0.2, 0.5}, {1, 0, 0}));  // parallel above it
}

TEST(Shapes, TriangleRandomRaysMatchPlaneAndBarycentrics) {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 v0(U(g), U(g), U(g)), v1(U(g), U(g), U(g)), v2(U(g), U(g), U(g));
    Scene sc;
    const uint32_t tri = sc.addPolygon({v0, v1, v2}, 0);
    const Vec3 o(2 * U(g), 2 * U(g), 2 * U(g));
    const Vec3 d = randomUnit(g);
    // Independent route: plane through v0 with normal (v1−v0)×(v2−v0), then barycentric areas.
    const Vec3 n = glm::cross(v1 - v0, v2 - v0);
    if (glm::length(n) < 1e-3) continue;  // sliver: barycentrics would be ill-conditioned
    const double denom = glm::dot(n, d);
    if (std::abs(denom) < 1e-6 * glm::length(n)) continue;
    const double t = glm::dot(n, v0 - o) / denom;
    const Vec3 p = o + t * d;
    const double n2 = glm::dot(n, n);
    const double b0 = glm::dot(glm::cross(v1 - p, v2 - p), n) / n2;
    const double b1 = glm::dot(glm::cross(v2 - p, v0 - p), n) / n2;
    const double b2 = 1.0 - b0 - b1;
    const double margin = std::min({b0, b1, b2});
    if (std::abs(margin) < 1e-7) continue;  // too close to an edge to call
    const bool want = t > 0.0 && margin > 0.0;
    const auto got = hitT(sc, tri, o, d);
    ASSERT_EQ(got.has_value(), want) << "trial " << trial;
    if (want) {
      EXPECT_NEAR(*got, t, kRel * std::max(1.0, std::abs(t)));
    }
  }
}

// ---------------------------------------------------------------- polygons

TEST(Shapes, ConvexPolygonHitAndMiss) {
  Scene sc;
  const uint32_t q = sc.addPolygon({{0, 0, 2}, {2, 0, 2}, {2, 1, 2}, {0, 1, 2}}, 0);
  ASSERT_EQ(sc.shapes[q].type, ShapeType::kPolygon);
  expectT(hitT(sc, q, {1.0, 0.5, 0.0}, {0, 0, 1}), 2.0);
  expectT(hitT(sc, q, {1.9, 0.9, 5.0}, {0, 0, -1}), 3.0);
  EXPECT_FALSE(hitT(sc, q, {2.1, 0.5, 0.0}, {0, 0, 1}));
  EXPECT_FALSE(hitT(sc, q, {1.0, 1.1, 0.0}, {0, 0, 1}));
  EXPECT_FALSE(hitT(sc, q, {-1.0, 0.5, 2.0}, {1, 0, 0}));  // in its plane
  expectVec(shapeNormal(sc.shapes[q], {1, 0.5, 2}), {0, 0, 1});
}

// An L-shape: the unit square at (1..2, 1..2) is the notch.
std::vector<Vec3> lShape(double z) {
  return {{0, 0, z}, {2, 0, z}, {2, 1, z}, {1, 1, z}, {1, 2, z}, {0, 2, z}};
}

TEST(Shapes, ConcavePolygonRayThroughNotchMisses) {
  Scene sc;
  const uint32_t l = sc.addPolygon(lShape(0.0), 0);
  EXPECT_FALSE(hitT(sc, l, {1.5, 1.5, 1.0}, {0, 0, -1}));  // the notch
  expectT(hitT(sc, l, {0.5, 1.5, 1.0}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, l, {1.5, 0.5, 1.0}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, l, {0.5, 0.5, 1.0}, {0, 0, -1}), 1.0);
  // A U-shape: the slot x in (1, 2), y in (1, 3) is open.
  const uint32_t u =
      sc.addPolygon({{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}, 0);
  EXPECT_FALSE(hitT(sc, u, {1.5, 2.0, 1.0}, {0, 0, -1}));
  EXPECT_FALSE(hitT(sc, u, {1.5, 2.9, 1.0}, {0, 0, -1}));
  expectT(hitT(sc, u, {1.5, 0.5, 1.0}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, u, {0.5, 2.5, 1.0}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, u, {2.5, 2.5, 1.0}, {0, 0, -1}), 1.0);
}

// Random star-shaped (generally concave) polygons in random planes against random rays; the
// reference uses the plane equation and a winding number in the polygon's own 2D frame.
TEST(Shapes, TiltedConcavePolygonsMatchWindingNumber) {
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 n = randomUnit(g);
    Vec3 eu, ev;
    basis(n, eu, ev);
    const Vec3 centre(U(g), U(g), U(g));
    const int nv = 5 + static_cast<int>(U(g) * 8);
    std::vector<Vec2> poly2;
    std::vector<Vec3> poly3;
    for (int k = 0; k < nv; ++k) {
      const double phi = kTwoPi * (k + 0.3 * U(g)) / nv;
      const double r = 0.2 + U(g);  // star-shaped about the centre, concave in general
      poly2.emplace_back(r * std::cos(phi), r * std::sin(phi));
      poly3.push_back(centre + poly2.back().x * eu + poly2.back().y * ev);
    }
    Scene sc;
    const uint32_t p = sc.addPolygon(poly3, 0);
    for (int r = 0; r < 50; ++r) {
      const Vec3 target = centre + (2.4 * U(g) - 1.2) * eu + (2.4 * U(g) - 1.2) * ev;
      const Vec3 d = randomUnit(g);
      if (std::abs(glm::dot(d, n)) < 0.05) continue;
      const double tTrue = 1.0 + 2.0 * U(g);
      const Vec3 o = target - tTrue * d;
      const Vec2 q(glm::dot(target - centre, eu), glm::dot(target - centre, ev));
      double edge = 1e300;
      for (int k = 0; k < nv; ++k) edge = std::min(edge, distToSegment2(q, poly2[k], poly2[(k + 1) % nv]));
      if (edge < 1e-7) continue;
      const bool want = winding(poly2, q) != 0;
      const auto got = hitT(sc, p, o, d);
      ASSERT_EQ(got.has_value(), want) << "trial " << trial << " ray " << r;
      if (want) {
        EXPECT_NEAR(*got, tTrue, kRel * tTrue);
        ++hits;
      } else {
        ++misses;
      }
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 1000);
}

// ---------------------------------------------------------------- spheres

TEST(Shapes, SphereFromOutsideAndInside) {
  Scene sc;
  const Vec3 c(1, 2, 3);
  const uint32_t s = sc.addSphere(c, 0.5, 0);
  const uint32_t b = sc.addSphere(c, 0.5, 0, /*inward=*/true);
  expectT(hitT(sc, s, {1, 2, 0}, {0, 0, 1}), 2.5);
  expectVec(shapeNormal(sc.shapes[s], {1, 2, 2.5}), {0, 0, -1});
  expectT(hitT(sc, s, c, {0, 0, 1}), 0.5);  // from the centre: the far side
  expectVec(shapeNormal(sc.shapes[s], {1, 2, 3.5}), {0, 0, 1});
  expectVec(shapeNormal(sc.shapes[b], {1, 2, 3.5}), {0, 0, -1});  // bubble: inward
  expectVec(shapeNormal(sc.shapes[b], {1.5, 2, 3}), {-1, 0, 0});
  EXPECT_FALSE(hitT(sc, s, {1.6, 2, 0}, {0, 0, 1}));  // passes beside it
  EXPECT_FALSE(hitT(sc, s, {1, 2, 0}, {0, 0, -1}));   // pointing away
}

TEST(Shapes, SphereHonoursTMinAndTMax) {
  Scene sc;
  const uint32_t s = sc.addSphere({0, 0, 0}, 1.0, 0);
  const Vec3 o(0, 0, -3), d(0, 0, 1);  // hits at t = 2 and t = 4
  expectT(hitT(sc, s, o, d, 0.0, kInf), 2.0);
  EXPECT_FALSE(hitT(sc, s, o, d, 0.0, 1.9));
  expectT(hitT(sc, s, o, d, 2.1, kInf), 4.0);  // the far root once the near one is excluded
  expectT(hitT(sc, s, o, d, 2.1, 4.1), 4.0);
  EXPECT_FALSE(hitT(sc, s, o, d, 2.1, 3.9));
  EXPECT_FALSE(hitT(sc, s, o, d, 4.1, kInf));
}

TEST(Shapes, SphereRandomRaysMatchClosestApproach) {
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> U(-2.0, 2.0);
  Scene sc;
  const Vec3 c(0.3, -0.2, 0.1);
  const double r = 0.7;
  const uint32_t s = sc.addSphere(c, r, 0);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 o(U(g), U(g), U(g));
    const Vec3 d = randomUnit(g);
    // Closest approach: tc = (c − o)·d, squared miss distance m² = |c − o|² − tc².
    const double tc = glm::dot(c - o, d);
    const double m2 = glm::dot(c - o, c - o) - tc * tc;
    std::optional<double> want;
    if (m2 < r * r) {
      const double half = std::sqrt(r * r - m2);
      if (tc - half > 0.0) {
        want = tc - half;
      } else if (tc + half > 0.0) {
        want = tc + half;
      }
    }
    if (std::abs(m2 - r * r) < 1e-9) continue;  // grazing
    const auto got = hitT(sc, s, o, d);
    ASSERT_EQ(got.has_value(), want.has_value()) << i;
    if (want) {
      EXPECT_NEAR(*got, *want, 1e-9 * std::max(1.0, *want));
      expectVec(shapeNormal(sc.shapes[s], o + *got * d), glm::normalize(o + *want * d - c), 1e-8);
    }
  }
}

// ---------------------------------------------------------------- rings

TEST(Shapes, RingHitInAnnulusMissInHoleAndBeyond) {
  Scene sc;
  const uint32_t r = sc.addRing({0, 0, 1}, {0, 0, 1}, 0.5, 1.0, 0);
  expectT(hitT(sc, r, {0.75, 0, 2}, {0, 0, -1}), 1.0);
  expectT(hitT(sc, r, {0, -0.9, 0}, {0, 0, 1}), 1.0);
  EXPECT_FALSE(hitT(sc, r, {0.25, 0, 2}, {0, 0, -1}));  // the hole
  EXPECT_FALSE(hitT(sc, r, {1.2, 0, 2}, {0, 0, -1}));   // beyond the outer radius
  EXPECT_FALSE(hitT(sc, r, {0.75, 0, 2}, {0, 0, -1}, 0.0, 0.9));
  expectVec(shapeNormal(sc.shapes[r], {0.75, 0, 1}), {0, 0, 1});
}

TEST(Shapes, TiltedRingRandomRays) {
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 n = randomUnit(g);
    const Vec3 c(U(g), U(g), U(g));
    const double r0 = 0.5 * U(g), r1 = r0 + 0.1 + U(g);
    Scene sc;
    const uint32_t ring = sc.addRing(c, 3.0 * n, r0, r1, 0);  // normal need not be unit on input
    expectVec(shapeNormal(sc.shapes[ring], c), n);
    Vec3 eu, ev;
    basis(n, eu, ev);
    for (int k = 0; k < 40; ++k) {
      const double rad = 1.5 * r1 * U(g), phi = kTwoPi * U(g);
      if (std::abs(rad - r0) < 1e-7 || std::abs(rad - r1) < 1e-7) continue;
      const Vec3 target = c + rad * (std::cos(phi) * eu + std::sin(phi) * ev);
      const Vec3 d = randomUnit(g);
      if (std::abs(glm::dot(d, n)) < 0.05) continue;
      const double tTrue = 0.5 + U(g);
      const auto got = hitT(sc, ring, target - tTrue * d, d);
      const bool want = rad >= r0 && rad <= r1;
      ASSERT_EQ(got.has_value(), want);
      if (want) {
        EXPECT_NEAR(*got, tTrue, kRel);
      }
    }
  }
}

// ---------------------------------------------------------------- cones and cylinders

// Smallest valid root of the lateral surface in world coordinates: with e = o − a, the surface is
// |e + t d|² − ((e + t d)·n)² = (r0 + k (e + t d)·n)², 0 ≤ (e + t d)·n ≤ h.
std::optional<double> coneReference(const Vec3& a, const Vec3& b, double r0, double r1, const Vec3& o, const Vec3& d,
                                    double tMin, double tMax) {
  const double h = glm::length(b - a);
  const Vec3 n = (b - a) / h;
  const double k = (r1 - r0) / h;
  const Vec3 e = o - a;
  const double en = glm::dot(e, n), dn = glm::dot(d, n);
  const double A = glm::dot(d, d) - dn * dn - k * k * dn * dn;
  const double B = 2.0 * (glm::dot(e, d) - en * dn - k * dn * (r0 + k * en));
  const double C = glm::dot(e, e) - en * en - (r0 + k * en) * (r0 + k * en);
  std::vector<double> roots;
  if (std::abs(A) < 1e-14) {
    if (B != 0.0) roots.push_back(-C / B);
  } else {
    const double disc = B * B - 4 * A * C;
    if (disc < 0.0) return std::nullopt;
    roots.push_back((-B - std::sqrt(disc)) / (2 * A));
    roots.push_back((-B + std::sqrt(disc)) / (2 * A));
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  }
  for (double t : roots) {
    const double z = en + t * dn;
    if (t > tMin && t < tMax && z >= 0.0 && z <= h && r0 + k * z >= 0.0) return t;
  }
  return std::nullopt;
}

TEST(Shapes, ConeHitsSlantNormalAndEnds) {
  Scene sc;
  // Axis along +z from 0 to 2, radius 1 → 0.5: r(z) = 1 − z/4.
  const uint32_t c = sc.addCone({0, 0, 0}, {0, 0, 2}, 1.0, 0.5, 0);
  const uint32_t cup = sc.addCone({0, 0, 0}, {0, 0, 2}, 1.0, 0.5, 0, /*inward=*/true);
  expectT(hitT(sc, c, {5, 0, 1}, {-1, 0, 0}), 5.0 - 0.75);
  // Slant normal: perpendicular to the generator (r1 − r0, 0, h) = (−0.5, 0, 2) in the xz plane,
  // pointing away from the axis.
  const Vec3 want = glm::normalize(Vec3(2.0, 0.0, 0.5));
  expectVec(shapeNormal(sc.shapes[c], {0.75, 0, 1}), want);
  expectVec(shapeNormal(sc.shapes[cup], {0.75, 0, 1}), -want);
  EXPECT_NEAR(glm::dot(shapeNormal(sc.shapes[c], {0.75, 0, 1}), Vec3(-0.5, 0, 2)), 0.0, 1e-12);
  // Normal on the far side and off-plane.
  const double r = 1.0 - 0.3 / 4.0;
  const Vec3 p(r * std::cos(2.0), r * std::sin(2.0), 0.3);
  expectVec(shapeNormal(sc.shapes[c], p), glm::normalize(Vec3(2 * std::cos(2.0), 2 * std::sin(2.0), 0.5)));
  EXPECT_FALSE(hitT(sc, c, {5, 0, 2.1}, {-1, 0, 0}));   // above the narrow end
  EXPECT_FALSE(hitT(sc, c, {5, 0, -0.1}, {-1, 0, 0}));  // below the wide end
  EXPECT_FALSE(hitT(sc, c, {0, 0, 5}, {0, 0, -1}));     // along the axis: open ends, no caps
  expectT(hitT(sc, c, {0, 0, 1}, {1, 0, 0}), 0.75);     // from inside
  expectT(hitT(sc, c, {5, 0, 1}, {-1, 0, 0}, 4.3), 5.0 + 0.75);  // far wall once the near is excluded
}

TEST(Shapes, CylinderAndTube) {
  Scene sc;
  const uint32_t cyl = sc.addCone({1, 1, 0}, {1, 1, 3}, 0.5, 0.5, 0);
  const uint32_t tube = sc.addCone({1, 1, 0}, {1, 1, 3}, 0.5, 0.5, 0, /*inward=*/true);
  expectT(hitT(sc, cyl, {1, -2, 1.5}, {0, 1, 0}), 2.5);
  expectVec(shapeNormal(sc.shapes[cyl], {1, 0.5, 1.5}), {0, -1, 0});
  expectVec(shapeNormal(sc.shapes[tube], {1, 0.5, 1.5}), {0, 1, 0});
  expectT(hitT(sc, tube, {1, 1, 1.5}, {0, 1, 0}), 0.5);
  EXPECT_FALSE(hitT(sc, cyl, {1, -2, 3.01}, {0, 1, 0}));
  EXPECT_FALSE(hitT(sc, cyl, {1, -2, -0.01}, {0, 1, 0}));
  EXPECT_FALSE(hitT(sc, cyl, {1, 1, -1}, {0, 0, 1}));
  EXPECT_FALSE(hitT(sc, cyl, {1, -2, 1.5}, {0, 1, 0}, 0.0, 2.4));
  // Oblique ray from (1, 0, −1) along (0, 1, 1)/√2: it crosses radius 0.5 at y = 0.5 (z = −0.5,
  // below the open bottom end: no hit), enters through that end and leaves through the wall at
  // y = 1.5, z = 0.5, i.e. t = 1.5·√2.
  const Vec3 d = glm::normalize(Vec3(0, 1, 1));
  expectT(hitT(sc, cyl, {1, 0, -1}, d), 1.5 * std::sqrt(2.0));
}

TEST(Shapes, ConesCylindersRandomRaysMatchWorldQuadratic) {
  std::mt19937_64 g(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(U(g), U(g), U(g));
    const Vec3 b = a + (0.5 + U(g)) * randomUnit(g);
    const bool cylinder = trial % 3 == 0;
    const double r0 = 0.05 + 0.5 * U(g);
    const double r1 = cylinder ? r0 : (trial % 3 == 1 ? 0.0 : 0.05 + 0.5 * U(g));  // incl. pointed cones
    Scene sc;
    const uint32_t c = sc.addCone(a, b, r0, r1, 0, trial % 2 == 0);
    for (int k = 0; k < 50; ++k) {
      const Vec3 o = 0.5 * (a + b) + 1.5 * Vec3(2 * U(g) - 1, 2 * U(g) - 1, 2 * U(g) - 1);
      // Aim at a random point near the axis (a third of the rays) or anywhere, so that both hits
      // and misses are common.
      const Vec3 aim = a + (1.4 * U(g) - 0.2) * (b - a) + 0.3 * randomUnit(g);
      const Vec3 d = k % 3 == 0 ? randomUnit(g) : glm::normalize(aim - o);
      const double tMin = k % 5 == 0 ? 0.3 : 0.0;
      const auto want = coneReference(a, b, r0, r1, o, d, tMin, kInf);
      const auto got = hitT(sc, c, o, d, tMin, kInf);
      if (want.has_value() != got.has_value()) {
        // Allow disagreement only for a hit within 1e-9 of an end rim (where rounding decides).
        const double t = want ? *want : *got;
        const double z = glm::dot(o + t * d - a, glm::normalize(b - a));
        ASSERT_TRUE(std::abs(z) < 1e-9 || std::abs(z - glm::length(b - a)) < 1e-9) << trial << " " << k;
        continue;
      }
      if (want) {
        ++hits;
        EXPECT_NEAR(*got, *want, 1e-8 * std::max(1.0, *want)) << trial << " " << k;
        // The hit lies on the surface: distance from the axis equals r(z).
        const Vec3 p = o + *got * d;
        const Vec3 n = glm::normalize(b - a);
        const double z = glm::dot(p - a, n);
        const double rz = r0 + (r1 - r0) * z / glm::length(b - a);
        EXPECT_NEAR(glm::length(p - a - z * n), rz, 1e-9);
      }
    }
  }
  EXPECT_GT(hits, 3000);  // of 10000 rays: the comparison was exercised
}

// ---------------------------------------------------------------- bounds and areas

// Uniform points on a shape's surface, generated here without the engine's samplers.
std::vector<Vec3> surfaceSamples(const Scene& sc, uint32_t i, int n, std::mt19937_64& g) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Shape& s = sc.shapes[i];
  std::vector<Vec3> pts;
  switch (s.type) {
    case ShapeType::kTriangle:
      while (static_cast<int>(pts.size()) < n) {
        double u = U(g), v = U(g);
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        pts.push_back(s.a + u * s.b + v * s.c);
      }
      break;
    case ShapeType::kPolygon: {
      const std::vector<Vec3> poly(sc.vertices.points.begin() + s.firstVertex,
                                   sc.vertices.points.begin() + s.firstVertex + s.vertexCount);
      Vec3 eu, ev;
      basis(s.n, eu, ev);
      std::vector<Vec2> p2;
      Vec2 lo(1e300), hi(-1e300);
      for (const Vec3& p : poly) {
        p2.emplace_back(glm::dot(p - poly[0], eu), glm::dot(p - poly[0], ev));
        lo = glm::min(lo, p2.back());
        hi = glm::max(hi, p2.back());
      }
      while (static_cast<int>(pts.size()) < n) {
        const Vec2 q(lo.x + U(g) * (hi.x - lo.x), lo.y + U(g) * (hi.y - lo.y));
        if (winding(p2, q) != 0) pts.push_back(poly[0] + q.x * eu + q.y * ev);
      }
      break;
    }
    case ShapeType::kSphere:
      for (int k = 0; k < n; ++k) pts.push_back(s.a + s.r0 * randomUnit(g));
      break;
    case ShapeType::kRing: {
      Vec3 eu, ev;
      basis(s.n, eu, ev);
      for (int k = 0; k < n; ++k) {
        const double r = std::sqrt(s.r0 * s.r0 + U(g) * (s.r1 * s.r1 - s.r0 * s.r0)), phi = kTwoPi * U(g);
        pts.push_back(s.a + r * (std::cos(phi) * eu + std::sin(phi) * ev));
      }
      break;
    }
    case ShapeType::kCone: {
      Vec3 eu, ev;
      basis(s.n, eu, ev);
      for (int k = 0; k < n; ++k) {
        const double z = U(g) * s.d, phi = kTwoPi * U(g);
        const double r = s.r0 + (s.r1 - s.r0) * z / s.d;
        pts.push_back(s.a + z * s.n + r * (std::cos(phi) * eu + std::sin(phi) * ev));
      }
      break;
    }
  }
  return pts;
}

// A scene with one of each kind of shape, in general position.
Scene mixedScene() {
  Scene sc;
  sc.addPolygon({{0.1, 0.2, 0.3}, {1.3, 0.1, 0.6}, {0.4, 1.2, 0.9}}, 0);               // triangle
  std::vector<Vec3> l = lShape(0.0);
  const Vec3 n = glm::normalize(Vec3(0.3, -0.4, 1.0));
  Vec3 eu, ev;
  basis(n, eu, ev);
  for (Vec3& p : l) p = Vec3(0.2, 0.1, 0.5) + 0.6 * (p.x * eu + p.y * ev);
  sc.addPolygon(l, 0);                                                                 // tilted L
  sc.addSphere({0.5, 0.4, 0.6}, 0.45, 0);
  sc.addRing({0.6, 0.5, 0.4}, {0.2, 0.9, 0.4}, 0.25, 0.6, 0);
  sc.addCone({0.2, 0.3, 0.1}, {0.9, 0.7, 1.1}, 0.35, 0.1, 0);
  sc.addCone({0.8, 0.1, 0.2}, {0.3, 0.9, 0.8}, 0.2, 0.2, 0, true);                    // tube
  return sc;
}

TEST(Shapes, BoundsContainEverySurfacePointAndAreTight) {
  std::mt19937_64 g(21);
  const Scene sc = mixedScene();
  for (uint32_t i = 0; i < sc.shapes.size(); ++i) {
    const Box b = shapeBounds(sc.shapes[i], sc.vertices);
    Box seen;
    for (const Vec3& p : surfaceSamples(sc, i, 20000, g)) {
      EXPECT_TRUE(p.x >= b.lo.x - 1e-12 && p.y >= b.lo.y - 1e-12 && p.z >= b.lo.z - 1e-12 &&
                  p.x <= b.hi.x + 1e-12 && p.y <= b.hi.y + 1e-12 && p.z <= b.hi.z + 1e-12)
          << "shape " << i;
      seen.extend(p);
    }
    // Tight: 20000 samples come within 2 % of the shape's size of every face of the box.
    const double size = glm::length(b.size());
    for (int a = 0; a < 3; ++a) {
      EXPECT_LT(seen.lo[a] - b.lo[a], 0.02 * size) << "shape " << i << " axis " << a;
      EXPECT_LT(b.hi[a] - seen.hi[a], 0.02 * size) << "shape " << i << " axis " << a;
    }
  }
}

// Conservative property: a box holding any sample point of the surface must be reported as
// overlapping (a test may say "overlap" too often, never too rarely).
TEST(Shapes, OverlapsBoxNeverMissesABoxHoldingSurfacePoints) {
  std::mt19937_64 g(23);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Scene sc = mixedScene();
  for (uint32_t i = 0; i < sc.shapes.size(); ++i) {
    const std::vector<Vec3> pts = surfaceSamples(sc, i, 3000, g);
    const Box b = shapeBounds(sc.shapes[i], sc.vertices);
    int inside = 0, said = 0;
    for (int k = 0; k < 3000; ++k) {
      const double size = (k % 3 == 0 ? 0.02 : k % 3 == 1 ? 0.1 : 0.4) * (0.5 + U(g));
      const Vec3 lo = b.lo - Vec3(size) + Vec3(U(g), U(g), U(g)) * (b.size() + Vec3(size));
      const Vec3 hi = lo + Vec3(size);
      bool any = false;
      for (const Vec3& p : pts)
        if (p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z) {
          any = true;
          break;
        }
      const bool got = shapeOverlapsBox(sc.shapes[i], sc.vertices, lo, size);
      if (any) {
        ++inside;
        EXPECT_TRUE(got) << "shape " << i << " box lo " << lo.x << "," << lo.y << "," << lo.z << " size " << size;
      }
      said += got;
    }
    EXPECT_GT(inside, 300) << "shape " << i;  // the check was exercised
    EXPECT_GE(said, inside);
  }
}

// Exactness where it is claimed (polygons, spheres, rings): boxes that clearly miss the surface.
TEST(Shapes, OverlapsBoxIsExactForPolygonsSpheresRings) {
  Scene sc;
  const uint32_t l = sc.addPolygon(lShape(0.0), 0);
  const uint32_t tri = sc.addPolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0);
  const uint32_t s = sc.addSphere({0, 0, 0}, 1.0, 0);
  const uint32_t r = sc.addRing({0, 0, 0}, {0, 0, 1}, 0.5, 1.0, 0);
  auto overlaps = [&](uint32_t i, Vec3 lo, double size) { return shapeOverlapsBox(sc.shapes[i], sc.vertices, lo, size); };
  // L-shape: a box in the notch (in the plane) misses; in the arms hits; above the plane misses.
  EXPECT_FALSE(overlaps(l, {1.2, 1.2, -0.1}, 0.2));
  EXPECT_TRUE(overlaps(l, {0.2, 1.2, -0.1}, 0.2));
  EXPECT_TRUE(overlaps(l, {1.2, 0.2, -0.1}, 0.2));
  EXPECT_FALSE(overlaps(l, {0.2, 0.2, 0.1}, 0.2));
  EXPECT_TRUE(overlaps(l, {0.9, 0.9, -0.1}, 0.2));  // straddles the re-entrant corner
  EXPECT_TRUE(overlaps(l, {0.5, 0.5, 0.0}, 0.2));   // touches the plane with its lower face
  // Triangle: a box over the hypotenuse's far side misses although the bounding box overlaps.
  EXPECT_FALSE(overlaps(tri, {0.6, 0.6, -0.1}, 0.3));
  EXPECT_TRUE(overlaps(tri, {0.4, 0.4, -0.1}, 0.3));
  // Sphere: a box wholly inside the ball misses the surface; one outside misses; one across hits.
  EXPECT_FALSE(overlaps(s, {-0.3, -0.3, -0.3}, 0.6));
  EXPECT_FALSE(overlaps(s, {0.8, 0.8, 0.8}, 0.5));  // nearest corner at √3·0.8 = 1.39 > 1
  EXPECT_TRUE(overlaps(s, {0.5, -0.1, -0.1}, 0.6));
  EXPECT_TRUE(overlaps(s, {-2.0, -2.0, -2.0}, 4.0));  // encloses the whole sphere
  // Ring: a box in the hole misses, in the annulus hits, beyond the rim misses.
  EXPECT_FALSE(overlaps(r, {-0.2, -0.2, -0.1}, 0.4));
  EXPECT_TRUE(overlaps(r, {0.6, -0.1, -0.1}, 0.2));
  EXPECT_FALSE(overlaps(r, {0.75, 0.75, -0.1}, 0.2));  // nearest point at √2·0.75 = 1.06 > 1
  EXPECT_FALSE(overlaps(r, {0.6, -0.1, 0.05}, 0.2));   // above the plane
}

TEST(Shapes, AreasMatchFormulas) {
  Scene sc;
  const uint32_t tri = sc.addPolygon({{0, 0, 0}, {3, 0, 0}, {0, 4, 1}}, 0);
  // |(3,0,0) × (0,4,1)| / 2 = |(0, −3, 12)| / 2
  EXPECT_NEAR(shapeArea(sc.shapes[tri], sc.vertices), 0.5 * std::sqrt(9.0 + 144.0), 1e-12);
  const uint32_t l = sc.addPolygon(lShape(2.0), 0);
  EXPECT_NEAR(shapeArea(sc.shapes[l], sc.vertices), 3.0, 1e-12);
  // The same L scaled by 0.5 and tilted: area 0.75.
  std::vector<Vec3> tl = lShape(0.0);
  Vec3 eu, ev;
  basis(glm::normalize(Vec3(1, 2, 3)), eu, ev);
  for (Vec3& p : tl) p = Vec3(5, -1, 2) + 0.5 * (p.x * eu + p.y * ev);
  const uint32_t tilted = sc.addPolygon(tl, 0);
  EXPECT_NEAR(shapeArea(sc.shapes[tilted], sc.vertices), 0.75, 1e-12);
  const uint32_t s = sc.addSphere({1, 1, 1}, 0.7, 0);
  EXPECT_NEAR(shapeArea(sc.shapes[s], sc.vertices), 4.0 * kPi * 0.49, 1e-12);
  const uint32_t r = sc.addRing({0, 0, 0}, {1, 1, 0}, 0.3, 0.8, 0);
  EXPECT_NEAR(shapeArea(sc.shapes[r], sc.vertices), kPi * (0.64 - 0.09), 1e-12);
  // Frustum: π (r0 + r1) · slant, slant = √(h² + (r1 − r0)²) = √(4 + 0.25).
  const uint32_t c = sc.addCone({0, 0, 0}, {0, 0, 2}, 1.0, 0.5, 0);
  EXPECT_NEAR(shapeArea(sc.shapes[c], sc.vertices), kPi * 1.5 * std::sqrt(4.25), 1e-12);
  const uint32_t cyl = sc.addCone({0, 0, 0}, {1, 1, 1}, 0.2, 0.2, 0);
  EXPECT_NEAR(shapeArea(sc.shapes[cyl], sc.vertices), kTwoPi * 0.2 * std::sqrt(3.0), 1e-12);
  const uint32_t pointed = sc.addCone({0, 0, 0}, {0, 3, 0}, 0.0, 4.0, 0);  // slant 5
  EXPECT_NEAR(shapeArea(sc.shapes[pointed], sc.vertices), kPi * 4.0 * 5.0, 1e-12);
}

}  // namespace
}  // namespace candela
