#include "engine/portals.h"

#include "engine/lights.h"
#include "engine/materials/family.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace candela {

double triangleSolidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double num = std::abs(glm::dot(a, glm::cross(b, c)));
  const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(num, den);
}

bool sampleSphericalTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double u1, double u2, Vec3& dir) {
  // Interior angles: at a, the angle between the planes through (a, b) and (a, c), i.e. between
  // their normals a × b and a × c; likewise at b and c.
  Vec3 nab = glm::cross(a, b), nac = glm::cross(a, c), nbc = glm::cross(b, c);
  const double lab = glm::length(nab), lac = glm::length(nac), lbc = glm::length(nbc);
  if (!(lab > 0.0) || !(lac > 0.0) || !(lbc > 0.0)) return false;
  nab /= lab;
  nac /= lac;
  nbc /= lbc;
  auto angle = [](const Vec3& x, const Vec3& y) { return std::acos(std::clamp(glm::dot(x, y), -1.0, 1.0)); };
  const double alpha = angle(nab, nac), beta = angle(nbc, -nab), gamma = angle(nac, nbc);
  const double area = alpha + beta + gamma - kPi;
  if (!(area > 0.0)) return false;
  // Arvo (1995), Fig. 2: the sub-triangle (a, b, c') of area u1·Ω, then a point on the arc
  // from b to c' with the conditional density of the remaining coordinate.
  const double ah = u1 * area;
  const double s = std::sin(ah - alpha), t = std::cos(ah - alpha);
  const double cosA = std::cos(alpha), sinA = std::sin(alpha);
  const double u = t - cosA, v = s + sinA * glm::dot(a, b);
  const double q = std::clamp(((v * t - u * s) * cosA - v) / ((v * s + u * t) * sinA), -1.0, 1.0);
  const Vec3 cPerp = c - glm::dot(c, a) * a;
  const double lp = glm::length(cPerp);
  if (!(lp > 0.0)) return false;
  const Vec3 cp = q * a + std::sqrt(std::max(0.0, 1.0 - q * q)) * (cPerp / lp);
  const double z = 1.0 - u2 * (1.0 - glm::dot(cp, b));
  const Vec3 w = cp - glm::dot(cp, b) * b;
  const double lw = glm::length(w);
  dir = lw > 0.0 ? glm::normalize(z * b + std::sqrt(std::max(0.0, 1.0 - z * z)) * (w / lw)) : b;
  return true;
}

std::string portalOutlineProblem(const std::vector<Vec3>& outline, size_t* badVertex) {
  if (badVertex) *badVertex = outline.size();
  if (outline.size() < 3) return "a portal needs at least 3 vertices, got " + std::to_string(outline.size());
  const Vec3 nn = newellNormal(outline);
  if (!(glm::length(nn) > 0.0)) return "the portal's outline encloses no area";
  // Blamed: the first vertex off the plane of the first three (Newell's plane when those are
  // in a line), beyond 0.1 % of the outline's size.
  Vec3 n = glm::cross(outline[1] - outline[0], outline[2] - outline[0]);
  n = glm::length(n) > 1e-9 * glm::length(nn) ? glm::normalize(n) : glm::normalize(nn);
  Vec3 c(0.0);
  for (const Vec3& v : outline) c += v;
  c /= static_cast<double>(outline.size());
  double size = 0.0;
  for (const Vec3& v : outline) size = std::max(size, glm::length(v - c));
  for (size_t i = 3; i < outline.size(); ++i) {
    const double off = std::abs(glm::dot(outline[i] - outline[0], n));
    if (off > 1e-3 * 2.0 * size) {
      if (badVertex) *badVertex = i;
      char buf[160];
      std::snprintf(buf, sizeof buf, "portal vertex %zu lies %.4g m off the plane of the first three (it must be planar)",
                    i + 1, off);
      return buf;
    }
  }
  return "";
}

PortalSet::PortalSet(const Scene& scene) {
  for (const Portal& p : scene.portals) add(p.outline);
  // Glazing, largest first.
  std::vector<std::pair<double, std::vector<Vec3>>> found;
  for (uint32_t id = 0; id < scene.surfaceCount(); ++id) {
    const Material& m = scene.materials[scene.surfaceMaterial(id)];
    if (!familyOf(m).seeThrough(m)) continue;
    const Shape s = scene.surface(id);
    std::vector<Vec3> outline = polygonOutline(s, scene.vertices);
    if (outline.empty()) continue;
    found.emplace_back(0.5 * glm::length(newellNormal(outline)), std::move(outline));
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  if (found.size() > kMaxFound) found.resize(kMaxFound);
  const size_t declared = portals_.size();
  for (const auto& f : found) add(f.second);
  found_ = portals_.size() - declared;
}

void PortalSet::add(const std::vector<Vec3>& outline) {
  if (outline.size() < 3) return;
  const Vec3 nn = newellNormal(outline);
  if (!(glm::length(nn) > 0.0)) return;
  Entry e;
  e.first = static_cast<uint32_t>(tris_.size());
  for (const auto& t : triangulatePolygon(outline, glm::normalize(nn))) tris_.push_back(t);
  e.count = static_cast<uint32_t>(tris_.size()) - e.first;
  if (e.count == 0) return;
  e.outline = outline;
  portals_.push_back(std::move(e));
}

double PortalSet::weight(const Entry& e, const Vec3& p, const Vec3& n, double* omega) const {
  double h = 0.0;
  for (const Vec3& v : e.outline) {
    const Vec3 d = v - p;
    const double l = glm::length(d);
    if (l > 0.0) h = std::max(h, glm::dot(n, d) / l);
  }
  double om = 0.0;
  if (h > 0.0)
    for (uint32_t i = e.first; i < e.first + e.count; ++i)
      om += triangleSolidAngle(tris_[i][0] - p, tris_[i][1] - p, tris_[i][2] - p);
  if (omega) *omega = om;
  // A receiver in the portal's plane sees no solid angle (a sampled direction would graze it).
  return om > 1e-12 ? om * h : 0.0;
}

void PortalSet::view(const Vec3& p, const Vec3& n, PortalView& v) const {
  v.cumulative.resize(portals_.size());
  double acc = 0.0;
  for (size_t j = 0; j < portals_.size(); ++j) {
    acc += weight(portals_[j], p, n, nullptr);
    v.cumulative[j] = acc;
  }
  v.total = acc;
}

bool PortalSet::sample(const PortalView& v, const Vec3& p, double u1, double u2, Vec3& dir) const {
  if (!(v.total > 0.0)) return false;
  // The portal, then one of its triangles by solid angle, each choice reusing u1 rescaled.
  const double x = u1 * v.total;
  size_t j = std::upper_bound(v.cumulative.begin(), v.cumulative.end(), x) - v.cumulative.begin();
  j = std::min(j, portals_.size() - 1);
  const double lo = j > 0 ? v.cumulative[j - 1] : 0.0, width = v.cumulative[j] - lo;
  if (!(width > 0.0)) return false;
  double r = std::clamp((x - lo) / width, 0.0, std::nextafter(1.0, 0.0));
  const Entry& e = portals_[j];
  double omega = 0.0;
  for (uint32_t i = e.first; i < e.first + e.count; ++i)
    omega += triangleSolidAngle(tris_[i][0] - p, tris_[i][1] - p, tris_[i][2] - p);
  double target = r * omega, acc = 0.0;
  for (uint32_t i = e.first; i < e.first + e.count; ++i) {
    const auto& t = tris_[i];
    const double oi = triangleSolidAngle(t[0] - p, t[1] - p, t[2] - p);
    if (oi <= 0.0) continue;
    if (target < acc + oi || i + 1 == e.first + e.count) {
      const double ut = std::clamp((target - acc) / oi, 0.0, std::nextafter(1.0, 0.0));
      return sampleSphericalTriangle(glm::normalize(t[0] - p), glm::normalize(t[1] - p), glm::normalize(t[2] - p),
                                     ut, u2, dir);
    }
    acc += oi;
  }
  return false;
}

double PortalSet::pdf(const Vec3& p, const Vec3& n, const Vec3& dir, bool* any) const {
  double total = 0.0, hit = 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const Entry& e : portals_) {
    double omega = 0.0;
    const double s = weight(e, p, n, &omega);
    if (!(s > 0.0)) continue;
    total += s;
    for (uint32_t i = e.first; i < e.first + e.count; ++i) {
      const auto& t = tris_[i];
      double tt = 0.0;
      if (intersectTriangle(t[0], t[1] - t[0], t[2] - t[0], p, dir, 0.0, kInf, tt)) {
        hit += s / omega;
        break;
      }
    }
  }
  if (any) *any = total > 0.0;
  return total > 0.0 ? hit / total : 0.0;
}

}  // namespace candela
