// EmbreeAccelerator against brute force over intersectShape (the octree's own reference, see
// octree_test.cpp) and against the octree inside the tracer.
//
// Embree traverses and tests triangles in float; the accelerator then recomputes t in double,
// so whenever it returns a shape its t must be intersectShape's, bit for bit. Which shape is
// nearest can differ from the double answer only where float cannot tell: the double hit lies
// within float tolerance of a triangle's edge (the float test may miss it, the double one hit
// it), two surfaces lie within float tolerance of each other along the ray, or the hit lies
// within float tolerance of tMin. Such rays must be rare (≤ 0.1 %) and every other ray exact.
//
// Float tolerance, in metres: coordinates here are within ~25 m of the scene centre (rays from
// outside the cube start up to 1.5 cube sizes away), where a float ulp is 2^-24·32 m ≈ 1.9e-6 m;
// Embree's float ray (origin and direction rounded, error ≤ 1 ulp of |o| plus 2^-24·t ≈ 2.4e-6 m
// at t = 40 m) and vertices (≤ 6e-7 m) add up to under 5e-6 m. kFloatTolM = 2e-5 m is four
// times that, still far below the 0.05–0.6 m sizes of the shapes.
#include "engine/embree_accelerator.h"
#include "tests/engine/ray_query_support.h"
#include "engine/octree.h"
#include "engine/tracer.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

namespace candela {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFloatTolM = 2e-5;

using test_support::BruteHit;
using test_support::Ray;
using test_support::bruteHits;
using test_support::randomUnit;

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + s * ab));
}

// Whether float arithmetic may legitimately disagree with the double test about hit h of ray r
// (see the file comment): a triangle hit within kFloatTolM of an edge, or a hit within float
// tolerance of tMin or of `other` (the t Embree returned instead, or kInf).
bool floatAmbiguous(const Scene& sc, const Ray& r, const BruteHit& h, double other) {
  if (std::abs(h.t - other) <= kFloatTolM || h.t - r.tMin <= kFloatTolM) return true;
  const Shape& s = sc.shapes[h.shape];
  if (s.type != ShapeType::kTriangle) return false;
  const Vec3 p = r.o + h.t * r.d, v0 = s.a, v1 = s.a + s.b, v2 = s.a + s.c;
  return std::min({segmentDistance(p, v0, v1), segmentDistance(p, v1, v2), segmentDistance(p, v2, v0)}) <= kFloatTolM;
}

struct Tally {
  int rays = 0, hits = 0, ambiguous = 0;
};

// Checks one intersect answer against the sorted brute-force hits with shapes sa/sb skipped.
void checkNearest(const Scene& sc, const Ray& r, const std::vector<BruteHit>& bh, uint32_t sa, uint32_t sb, bool got,
                  const RayHit& h, Tally& tally, const std::string& where) {
  ++tally.rays;
  std::vector<BruteHit> want;
  for (const BruteHit& x : bh)
    if (x.shape != sa && x.shape != sb) want.push_back(x);
  if (got) {
    ++tally.hits;
    ASSERT_NE(h.shape, sa) << where;
    ASSERT_NE(h.shape, sb) << where;
    // The shape returned is hit by the double test, at exactly its t.
    const auto it = std::find_if(want.begin(), want.end(), [&](const BruteHit& x) { return x.shape == h.shape; });
    ASSERT_NE(it, want.end()) << where << ": shape " << h.shape << " is not hit in double";
    EXPECT_EQ(h.t, it->t) << where;
  }
  const double gotT = got ? h.t : kInf;
  // Every double hit nearer than the answer (beyond a tie to 1e-9) was lost to float rounding.
  bool exact = true;
  for (const BruteHit& x : want) {
    if (x.t >= gotT - 1e-9 * std::max(1.0, gotT)) break;
    exact = false;
    EXPECT_TRUE(floatAmbiguous(sc, r, x, gotT))
        << where << ": missed shape " << x.shape << " at t=" << x.t << ", got " << (got ? h.shape : kNoShape)
        << " at t=" << gotT;
  }
  if (!exact) ++tally.ambiguous;
}

// Same for occluded: a false "occluded" is impossible (every candidate is confirmed in double);
// a false "clear" needs every double hit to be float-ambiguous.
void checkOccluded(const Scene& sc, const Ray& r, const std::vector<BruteHit>& bh, uint32_t sa, uint32_t sb,
                   bool got, Tally& tally, const std::string& where) {
  ++tally.rays;
  bool any = false, allAmbiguous = true;
  for (const BruteHit& x : bh)
    if (x.shape != sa && x.shape != sb) {
      any = true;
      allAmbiguous = allAmbiguous && (floatAmbiguous(sc, r, x, kInf) || r.tMax - x.t <= kFloatTolM);
    }
  if (got) {
    ++tally.hits;
    EXPECT_TRUE(any) << where << ": occluded, but no double hit";
  } else if (any) {
    ++tally.ambiguous;
    EXPECT_TRUE(allAmbiguous) << where << ": not occluded, but hit in double";
  }
}

// 2000 small shapes of every kind in [0, 10]³ (as octree_test.cpp), plus pairs of coplanar
// triangles sharing an edge, so that rays cross shared edges.
Scene randomScene(uint64_t seed, int n, const Vec3& shift = Vec3(0.0)) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Scene sc;
  sc.addPolygon({shift, shift + Vec3(0.01, 0, 0), shift + Vec3(0, 0.01, 0)}, 0);
  sc.addPolygon({shift + Vec3(10), shift + Vec3(9.99, 10, 10), shift + Vec3(10, 9.99, 10)}, 0);
  while (static_cast<int>(sc.shapes.size()) < n) {
    const Vec3 c = shift + Vec3(0.7 + 8.6 * U(g), 0.7 + 8.6 * U(g), 0.7 + 8.6 * U(g));
    const double s = 0.1 + 0.5 * U(g);
    switch (sc.shapes.size() % 6) {
      case 0:
        sc.addPolygon({c, c + s * randomUnit(g), c + s * randomUnit(g)}, 0);
        break;
      case 1: {  // a parallelogram as one 4-vertex polygon (user geometry) or as two triangles
        const Vec3 e1 = s * randomUnit(g), e2 = s * randomUnit(g);
        if (U(g) < 0.5) {
          sc.addPolygon({c, c + e1, c + e1 + e2, c + e2}, 0);
        } else {
          sc.addPolygon({c, c + e1, c + e1 + e2}, 0);
          sc.addPolygon({c, c + e1 + e2, c + e2}, 0);
        }
        break;
      }
      case 2:
        sc.addSphere(c, 0.3 * s, 0, U(g) < 0.3);
        break;
      case 3: {
        const double r0 = 0.3 * s * U(g);
        sc.addRing(c, randomUnit(g), r0, r0 + 0.05 + 0.3 * s, 0);
        break;
      }
      case 4: {
        const double ra = 0.2 * s * U(g), rb = U(g) < 0.3 ? ra : 0.2 * s * U(g);
        sc.addCone(c, c + s * randomUnit(g), ra + 0.01, rb, 0, U(g) < 0.3);
        break;
      }
      case 5: {  // axis-aligned squares (two triangles) in the planes x, y or z = 5
        const int axis = static_cast<int>(3 * U(g)) % 3;
        Vec3 p = c, e1(0.0), e2(0.0);
        p[axis] = 5.0 + shift[axis];
        e1[(axis + 1) % 3] = s;
        e2[(axis + 2) % 3] = s;
        sc.addPolygon({p, p + e1, p + e1 + e2}, 0);
        sc.addPolygon({p, p + e1 + e2, p + e2}, 0);
        break;
      }
    }
  }
  return sc;
}

std::vector<Ray> randomRays(uint64_t seed, int n) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto inside = [&] { return 10.0 * Vec3(U(g), U(g), U(g)); };
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    Ray r;
    switch (i % 5) {
      case 0:
      case 1:  // inside, random direction
        r.o = inside();
        r.d = randomUnit(g);
        break;
      case 2: {  // from outside the cube, aimed inside
        r.o = Vec3(-10.0) + 30.0 * Vec3(U(g), U(g), U(g));
        r.d = glm::normalize(inside() - r.o);
        break;
      }
      case 3: {  // axis-aligned or in an axis plane, through the squares at x, y or z = 5
        r.o = inside();
        Vec3 d(0.0);
        const int a = static_cast<int>(3 * U(g)) % 3;
        d[a] = U(g) < 0.5 ? -1.0 : 1.0;
        if (U(g) < 0.5) d[(a + 1) % 3] = 2.0 * U(g) - 1.0;
        r.d = glm::normalize(d);
        break;
      }
      case 4:  // restricted intervals
        r.o = inside();
        r.d = randomUnit(g);
        r.tMin = 2.0 * U(g);
        r.tMax = U(g) < 0.5 ? kInf : r.tMin + 4.0 * U(g);
        break;
    }
    rays.push_back(r);
  }
  return rays;
}

// Embree against brute force on every ray (nearest, occluded, skips), and against the octree:
// the same shape and the same t on at least 99.9 % of rays. `minHitFraction` guards against a
// test that passes because nothing is hit.
void compareWithBruteForce(const Scene& sc, const RayAccelerator& acc, const std::vector<Ray>& rays,
                           const char* label, double minHitFraction) {
  const Octree octree(sc);
  Tally nearest, shadow, skipped;
  int sameAsOctree = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    const std::vector<BruteHit> bh = bruteHits(sc, r);
    const std::string where = std::string(label) + " ray " + std::to_string(i);
    RayHit h;
    const bool got = acc.intersect(r.o, r.d, r.tMin, r.tMax, h);
    checkNearest(sc, r, bh, kNoShape, kNoShape, got, h, nearest, where);
    RayHit ho;
    const bool gotOctree = octree.intersect(r.o, r.d, r.tMin, r.tMax, ho);
    // Coplanar overlapping squares (case 5 of randomScene) give exact ties, resolved either way.
    sameAsOctree += got == gotOctree && (!got || std::abs(h.t - ho.t) <= 1e-9 * std::max(1.0, ho.t));
    checkOccluded(sc, r, bh, kNoShape, kNoShape, acc.occluded(r.o, r.d, r.tMin, r.tMax), shadow, where);
    // Skip the nearest one or two shapes (in either argument): the next one must come out.
    if (!bh.empty() && i % 3 == 0) {
      const uint32_t a = bh[0].shape, b = bh.size() > 1 ? bh[1].shape : kNoShape;
      const uint32_t skips[3][2] = {{a, kNoShape}, {kNoShape, a}, {a, b}};
      for (const auto& sk : skips) {
        RayHit hs;
        const bool gs = acc.intersect(r.o, r.d, r.tMin, r.tMax, hs, sk[0], sk[1]);
        checkNearest(sc, r, bh, sk[0], sk[1], gs, hs, skipped, where + " (skips)");
        checkOccluded(sc, r, bh, sk[0], sk[1], acc.occluded(r.o, r.d, r.tMin, r.tMax, sk[0], sk[1]), skipped,
                      where + " (skips)");
      }
    }
  }
  std::printf("[ tally    ] %-22s nearest: %d/%d hits, %d float-ambiguous; shadow: %d/%d, %d; skips: %d rays, %d;"
              " same as octree: %d\n",
              label, nearest.hits, nearest.rays, nearest.ambiguous, shadow.hits, shadow.rays, shadow.ambiguous,
              skipped.rays, skipped.ambiguous, sameAsOctree);
  for (const Tally* t : {&nearest, &shadow, &skipped})
    EXPECT_LE(t->ambiguous, t->rays / 1000) << label << ": more than 0.1 % of rays differ";
  EXPECT_GE(sameAsOctree, static_cast<int>(rays.size() - rays.size() / 1000)) << label;
  EXPECT_GT(nearest.hits, minHitFraction * nearest.rays) << label << ": too few hits to mean anything";
  EXPECT_GT(shadow.hits, minHitFraction * shadow.rays) << label << ": too few hits to mean anything";
}

TEST(EmbreeAccelerator, MatchesBruteForceOnRandomMixedScene) {
  const Scene sc = randomScene(42, 2000);
  const std::vector<Ray> rays = randomRays(43, 20000);
  const EmbreeAccelerator acc(sc);
  const EmbreeStats st = acc.stats();
  EXPECT_EQ(st.triangles + st.userShapes, sc.shapes.size());
  EXPECT_GT(st.triangles, 0u);
  EXPECT_GT(st.userShapes, 0u);
  EXPECT_GT(st.memoryBytes, 36 * st.triangles);  // at least the float vertices
  compareWithBruteForce(sc, acc, rays, "default options", 0.2);
  const EmbreeAccelerator fast(sc, EmbreeOptions{false, false, false});
  compareWithBruteForce(sc, fast, rays, "not robust, medium", 0.2);
  const EmbreeAccelerator compact(sc, EmbreeOptions{true, true, true});
  compareWithBruteForce(sc, compact, rays, "compact", 0.2);
}

// The scene far from the origin: float coordinates relative to the scene centre keep the
// precision; absolute float coordinates (ulp 2^-24·1e5 m ≈ 6 mm) would not.
TEST(EmbreeAccelerator, MatchesBruteForceFarFromTheOrigin) {
  const Vec3 shift(1e5, -2e5, 50.0);
  const Scene sc = randomScene(7, 1000, shift);
  std::vector<Ray> rays = randomRays(8, 5000);
  for (Ray& r : rays) r.o += shift;
  const EmbreeAccelerator acc(sc);
  compareWithBruteForce(sc, acc, rays, "shifted by 1e5 m", 0.1);
}

// 10⁴ coplanar triangles sharing edges and vertices; rays straight down through the shared
// vertices and edges, where the float test may pick a neighbour of the double one (and the
// accelerator must then find the double one), and grazing rays in the plane.
TEST(EmbreeAccelerator, MatchesBruteForceOnTessellatedFloor) {
  Scene sc;
  const double cell = 0.1;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 100; ++j) {
      const Vec3 p(i * cell, j * cell, 0.0), ex(cell, 0, 0), ey(0, cell, 0);
      sc.addPolygon({p, p + ex, p + ex + ey}, 0);
      sc.addPolygon({p, p + ex + ey, p + ey}, 0);
    }
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Ray> rays;
  for (int k = 0; k < 20000; ++k) {
    Ray r;
    switch (k % 3) {
      case 0:  // from above, downwards
        r.o = Vec3(-1 + 7 * U(g), -1 + 12 * U(g), 0.01 + 3 * U(g));
        r.d = randomUnit(g);
        r.d.z = -std::abs(r.d.z);
        break;
      case 1:  // straight down through grid vertices or edge midpoints
        r.o = Vec3(cell * static_cast<int>(50 * U(g)), cell * static_cast<int>(100 * U(g)) + (k % 2 ? 0.05 : 0.0), 1.0);
        r.d = Vec3(0, 0, -1);
        break;
      case 2:  // grazing, in the plane
        r.o = Vec3(5 * U(g), 10 * U(g), 0.0);
        r.d = glm::normalize(Vec3(2 * U(g) - 1, 2 * U(g) - 1, 0.0));
        break;
    }
    rays.push_back(r);
  }
  compareWithBruteForce(sc, EmbreeAccelerator(sc), rays, "tessellated floor", 0.3);
}

// Closed forms on a single sphere: t, tMin/tMax, skips, empty scene.
TEST(EmbreeAccelerator, SingleShapesAndEmptyScene) {
  const Scene empty;
  const EmbreeAccelerator ae(empty);
  RayHit h;
  EXPECT_FALSE(ae.intersect({0, 0, 0}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_FALSE(ae.occluded({0, 0, 0}, {0, 0, 1}, 0.0, kInf));

  Scene one;
  one.addSphere({1, 2, 3}, 0.5, 0);
  const EmbreeAccelerator a1(one);
  ASSERT_TRUE(a1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_EQ(h.t, 2.5);  // exact in double; in float too, but the value comes from intersectShape
  EXPECT_EQ(h.shape, 0u);
  ASSERT_TRUE(a1.intersect({1, 2, 0}, {0, 0, 1}, 2.6, kInf, h));  // the far side
  EXPECT_EQ(h.t, 3.5);
  EXPECT_FALSE(a1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, 2.4, h));
  EXPECT_FALSE(a1.intersect({1, 2, 0}, {0, 0, 1}, 0.0, kInf, h, 0));
  EXPECT_TRUE(a1.occluded({1, 2, 0}, {0, 0, 1}, 0.0, kInf));
  EXPECT_FALSE(a1.occluded({1, 2, 0}, {0, 0, 1}, 0.0, 2.4));
  EXPECT_FALSE(a1.occluded({1, 2, 0}, {0, 0, 1}, 0.0, kInf, kNoShape, 0));
  EXPECT_TRUE(a1.intersect({1, 2, -100}, {0, 0, 1}, 0.0, kInf, h));
  EXPECT_EQ(h.t, 102.5);

  // A triangle whose float t differs from the double one: t must be the double value.
  Scene tri;
  tri.addPolygon({{-1, -1, 0.1}, {1, -1, 0.1}, {0, 1, 0.1}}, 0);
  const EmbreeAccelerator at(tri);
  double want;
  ASSERT_TRUE(intersectShape(tri.shapes[0], tri.vertices, {0, 0, 1}, {0, 0, -1}, 0.0, kInf, want));
  ASSERT_TRUE(at.intersect({0, 0, 1}, {0, 0, -1}, 0.0, kInf, h));
  EXPECT_EQ(h.t, want);
  EXPECT_NE(h.t, static_cast<double>(static_cast<float>(want)));  // 0.9 is not a float
  // tMax just beyond and just before the double t (closer than a float ulp of 0.9).
  EXPECT_TRUE(at.intersect({0, 0, 1}, {0, 0, -1}, 0.0, want * (1 + 1e-12), h));
  EXPECT_FALSE(at.intersect({0, 0, 1}, {0, 0, -1}, 0.0, want, h));
  EXPECT_TRUE(at.occluded({0, 0, 1}, {0, 0, -1}, 0.0, want * (1 + 1e-12)));
  EXPECT_FALSE(at.occluded({0, 0, 1}, {0, 0, -1}, 0.0, want));
}

// Many threads querying one accelerator get the same answers as one thread.
TEST(EmbreeAccelerator, ConcurrentQueriesAgree) {
  const Scene sc = randomScene(11, 1000);
  const std::vector<Ray> rays = randomRays(12, 4000);
  const EmbreeAccelerator acc(sc);
  std::vector<RayHit> serial(rays.size());
  for (size_t i = 0; i < rays.size(); ++i)
    acc.intersect(rays[i].o, rays[i].d, rays[i].tMin, rays[i].tMax, serial[i], 3, 5);
  std::vector<RayHit> parallel(rays.size());
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      for (size_t i = k; i < rays.size(); i += 4)
        acc.intersect(rays[i].o, rays[i].d, rays[i].tMin, rays[i].tMax, parallel[i], 3, 5);
    });
  for (std::thread& t : threads) t.join();
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(serial[i].shape, parallel[i].shape) << i;
    EXPECT_EQ(serial[i].t, parallel[i].t) << i;
  }
}

// A furnished room lit by a ceiling light: the tracer gives the same illuminance with either
// accelerator, within 4 standard errors of the difference of two independent estimates.
TEST(EmbreeAccelerator, TracerAgreesWithOctreeInARoom) {
  Scene sc;
  Material grey{{MaterialType::kPlastic, Rgb(0.5)}, "grey", {}}, lamp{{MaterialType::kLight, Rgb(100.0)}, "lamp", {}};
  const uint32_t wall = sc.addMaterial(grey), light = sc.addMaterial(lamp);
  const double W = 4.0, D = 5.0, H = 3.0;
  // Floor as 2·20·25 triangles (Embree triangles), walls and ceiling as quads (user geometry),
  // all facing inwards.
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 25; ++j) {
      const Vec3 p(0.2 * i, 0.2 * j, 0.0), ex(0.2, 0, 0), ey(0, 0.2, 0);
      sc.addPolygon({p, p + ex, p + ex + ey}, wall);
      sc.addPolygon({p, p + ex + ey, p + ey}, wall);
    }
  sc.addPolygon({{0, 0, H}, {0, D, H}, {W, D, H}, {W, 0, H}}, wall);
  sc.addPolygon({{0, 0, 0}, {0, 0, H}, {W, 0, H}, {W, 0, 0}}, wall);
  sc.addPolygon({{0, D, 0}, {W, D, 0}, {W, D, H}, {0, D, H}}, wall);
  sc.addPolygon({{0, 0, 0}, {0, D, 0}, {0, D, H}, {0, 0, H}}, wall);
  sc.addPolygon({{W, 0, 0}, {W, 0, H}, {W, D, H}, {W, D, 0}}, wall);
  sc.addPolygon({{1.5, 2, H - 0.01}, {1.5, 3, H - 0.01}, {2.5, 3, H - 0.01}, {2.5, 2, H - 0.01}}, light);
  sc.addSphere({1.0, 1.5, 0.4}, 0.4, wall);  // furniture casting shadows
  sc.addCone({3.0, 3.5, 0.0}, {3.0, 3.5, 1.2}, 0.3, 0.3, wall);

  const Tracer withOctree(sc), withEmbree(sc, std::make_unique<EmbreeAccelerator>(sc));
  TraceSettings s;
  s.hemisphereSamples = 256;
  s.lightSamples = 16;
  s.maxBounces = 4;
  s.firstBounceSplit = 4;
  const Vec3 points[] = {{2.0, 2.5, 0.8}, {0.5, 0.5, 0.8}, {1.6, 1.5, 0.8}, {3.5, 4.5, 0.8}, {3.0, 2.8, 0.8}};
  for (size_t k = 0; k < std::size(points); ++k) {
    TraceSettings s1 = s, s2 = s;
    s1.seed = 1;
    s2.seed = 2;
    const IrradianceEstimate a = estimateIrradiance(withOctree, points[k], {0, 0, 1}, k, s1);
    const IrradianceEstimate b = estimateIrradiance(withEmbree, points[k], {0, 0, 1}, k, s2);
    const IrradianceEstimate bSame = estimateIrradiance(withEmbree, points[k], {0, 0, 1}, k, s1);
    const double se = std::hypot(a.standardErrorLux(), b.standardErrorLux());
    std::printf("[ measured ] point %zu: octree %.5g lux, Embree %.5g lux (same seed %.10g vs %.10g), se %.3g lux\n", k,
                a.illuminanceLux(), b.illuminanceLux(), a.illuminanceLux(), bSame.illuminanceLux(), se);
    EXPECT_GT(se, 0.0);
    EXPECT_NEAR(a.illuminanceLux(), b.illuminanceLux(), 4.0 * se) << "point " << k;
  }
}

}  // namespace
}  // namespace candela
