// Portals (docs/daylight.md#portals): the openings through which a receiver sees the sky — the
// declared ones (Scene::portals) and the glazing found in the scene — prepared for drawing sky
// directions uniformly over their solid angle as seen from the receiver (Arvo 1995, "Stratified
// sampling of spherical triangles", SIGGRAPH '95, §2). The sky estimator weighs these samples
// against its other strategies by multiple importance sampling (engine/integrator_direct.cpp), so
// a portal in the wrong place costs variance only, never bias.
#pragma once

#include "engine/scene.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// The portals' selection weights as seen from one receiver (PortalSet::view); reused from
// receiver to receiver, so no allocation once warm.
struct PortalView {
  std::vector<double> cumulative;  // running sum of the portals' selection weights
  double total = 0.0;              // the sum: 0 when no portal is above the receiver's horizon
};

class PortalSet {
 public:
  // Glazing found in a scene beyond this many polygons keeps its largest ones: every escaping
  // ray's MIS weight visits every portal.
  static constexpr size_t kMaxFound = 64;

  PortalSet() = default;
  // The declared portals, then the flat surfaces that shadow rays pass (Tracer::transmittance):
  // polygons and triangles of glass, of trans with a specular transmittance, and of illum
  // without an alternate material (kMaxFound at most, the largest). An illum with an alternate
  // and a dielectric stop shadow rays, so sky samples through them could never count; they are
  // not portals.
  explicit PortalSet(const Scene& scene);

  bool empty() const { return portals_.empty(); }
  size_t size() const { return portals_.size(); }
  size_t foundCount() const { return found_; }  // of size(): found in the scene, not declared

  // Fills `view` for a receiver at p with unit normal n. Portal j is chosen with probability
  // s_j / S, s_j = Ω_j · h_j: Ω_j its solid angle from p, h_j the largest cosine (to n) of the
  // directions to its vertices, 0 when wholly below the horizon. S = view.total.
  void view(const Vec3& p, const Vec3& n, PortalView& view) const;
  // A direction from p into one portal: portal by its weight in `view` (view.total > 0), then
  // uniform in its solid angle; u1, u2 in [0, 1). False on a degenerate triangle.
  bool sample(const PortalView& view, const Vec3& p, double u1, double u2, Vec3& dir) const;
  // Density per steradian that sample() draws unit direction dir with, from (p, n):
  // Σ over the portals dir passes through of s_j / (S Ω_j) = h_j / S; 0 when S = 0. *any (when
  // given) tells whether S > 0, i.e. whether a receiver there samples portals at all.
  double pdf(const Vec3& p, const Vec3& n, const Vec3& dir, bool* any = nullptr) const;

 private:
  struct Entry {
    uint32_t first = 0, count = 0;  // its triangles in tris_
    std::vector<Vec3> outline;
  };
  // s_j and Ω_j of portal e from (p, n).
  double weight(const Entry& e, const Vec3& p, const Vec3& n, double* omega) const;
  void add(const std::vector<Vec3>& outline);

  std::vector<Entry> portals_;
  std::vector<std::array<Vec3, 3>> tris_;
  size_t found_ = 0;
};

// What is wrong with a portal's outline as given ("" when nothing): fewer than 3 vertices, no
// area, or a vertex off the polygon's plane by more than 0.1 % of its size (as the scene
// reader's planarity tolerance); *badVertex (when given) the index of the vertex to blame, or
// the vertex count when none is.
std::string portalOutlineProblem(const std::vector<Vec3>& outline, size_t* badVertex = nullptr);

// Solid angle (sr) of the triangle (a, b, c) seen from the origin; a, b, c need not be unit
// (Van Oosterom & Strackee 1983, "The solid angle of a plane triangle", IEEE Trans. Biomed. Eng. 30).
double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c);

// A unit direction uniform in the solid angle of the spherical triangle of unit vertices
// (a, b, c) (Arvo 1995, Fig. 2); false when the triangle is degenerate.
bool sampleSphericalTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double u1, double u2, Vec3& dir);

}  // namespace candela
