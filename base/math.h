// GLM aliases and small geometric helpers shared by every layer.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <optional>

namespace candela {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Mat3 = glm::dmat3;
using Vec3f = glm::vec3;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kInvPi = 1.0 / kPi;

inline double degToRad(double deg) { return deg * (kPi / 180.0); }
inline double radToDeg(double rad) { return rad * (180.0 / kPi); }

// Right-handed orthonormal basis (t, b, n) around unit vector n, continuous except at n = -z
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
struct Frame {
  Vec3 t, b, n;
  static Frame fromNormal(const Vec3& n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double bb = n.x * n.y * a;
    Frame f;
    f.n = n;
    f.t = Vec3(1.0 + sign * n.x * n.x * a, sign * bb, -sign * n.x);
    f.b = Vec3(bb, sign + n.y * n.y * a, -n.y);
    return f;
  }
  Vec3 toWorld(const Vec3& v) const { return v.x * t + v.y * b + v.z * n; }
  Vec3 toLocal(const Vec3& v) const { return Vec3(glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)); }
};

// `v` scaled to unit length, or nothing when it cannot be: a component not finite, the zero
// vector, or a squared length that overflows or underflows in double (a component of 1e200 or
// 1e-200). glm::normalize gives (0, 0, 0) or NaN for those, and Embree aborts on such a ray
// direction, so a direction from input is checked here and refused at its line.
template <class V>
std::optional<V> unitDirection(const V& v) {
  const double squared = glm::dot(v, v);
  if (!std::isfinite(squared) || !(squared >= std::numeric_limits<double>::min())) return std::nullopt;
  return v / std::sqrt(squared);
}

// Axis-aligned box.
struct Box {
  Vec3 lo{1e300}, hi{-1e300};
  void extend(const Vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  void extend(const Box& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return 0.5 * (lo + hi); }
  Vec3 size() const { return hi - lo; }
};

}  // namespace candela
