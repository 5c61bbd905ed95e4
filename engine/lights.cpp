#include "engine/lights.h"

#include "engine/light_selection.h"
#include "engine/materials/family.h"
#include "engine/materials/pattern_hook.h"
#include "engine/sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {

namespace {

// Clips a polygon to the half-space (y − p)·n ≥ 0 (Sutherland–Hodgman, one plane).
std::vector<Vec3> clipToHorizon(const std::vector<Vec3>& poly, const Vec3& p, const Vec3& n) {
  std::vector<Vec3> out;
  out.reserve(poly.size() + 2);
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec3& a = poly[i];
    const Vec3& b = poly[(i + 1) % poly.size()];
    const double da = glm::dot(a - p, n), db = glm::dot(b - p, n);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
  }
  return out;
}

// Uniform point on a triangulated area: u1 picks a triangle by area and is rescaled within that
// triangle's interval (which keeps the stratification of (u1, u2)); k receives the triangle.
Vec3 pointOnTriangles(const std::vector<std::array<Vec3, 3>>& tris, const std::vector<double>& cumulative,
                      double u1, double u2, size_t& k) {
  const double target = u1 * cumulative.back();
  k = std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin();
  k = std::min(k, tris.size() - 1);
  const double lo = k == 0 ? 0.0 : cumulative[k - 1];
  const double span = cumulative[k] - lo;
  const double v1 = span > 0.0 ? std::clamp((target - lo) / span, 0.0, 1.0) : 0.5;
  return sampleTriangle(tris[k][0], tris[k][1], tris[k][2], v1, u2);
}

// A uniformly sampled point y (front normal ny) of a source of the given area and radiance, seen
// from p: direction, distance and weight L f s cos θ_l A / d² (f the distribution's factor, s the
// spotlight's, 1 without them); false behind the one-sided source.
bool areaSample(const Vec3& y, const Vec3& ny, const Vec3& p, const Light& light, double areaM2,
                LightSample& out) {
  const Vec3 e = y - p;
  const double dist2 = glm::dot(e, e);
  if (dist2 <= 0.0) return false;
  const double dist = std::sqrt(dist2);
  out.dir = e / dist;
  out.distance = dist;
  const double cosL = -glm::dot(ny, out.dir);  // emission from the front only
  if (cosL <= 0.0) return false;
  out.weight = light.radiance * (cosL * areaM2 / dist2);
  out.solidAngleSr = std::min(kTwoPi, cosL * areaM2 / dist2);
  if (light.distribution) out.weight *= light.distribution->factor(out.dir, cosL);
  if (light.spot) out.weight *= light.spot->spotFactor(-out.dir, dist);
  return true;
}

// Cosine-weighted solid angle of a circular cap of half-angle α whose axis makes angle θ with the
// normal, when the cap is wholly above the horizon: π sin²α cos θ.
bool capProjectedSolidAngle(const Vec3& axis, double sinAlpha, const Vec3& n, double& out) {
  const double cosTheta = glm::dot(axis, n);
  if (cosTheta < sinAlpha) return false;  // part of the cap below the horizon
  out = kPi * sinAlpha * sinAlpha * cosTheta;
  return true;
}

// A sphere enclosing shape s (centre, radius in m), for the small-emitter and radius rules of
// glowSampledFrom: the shape itself for a sphere; the vertices' mean and farthest vertex for a
// polygon; the centre and outer radius for a ring; the axis midpoint for a cone.
void boundingSphere(const Shape& s, const VertexStore& vertices, Vec3& centre, double& radiusM) {
  switch (s.type) {
    case ShapeType::kSphere:
      centre = s.a;
      radiusM = s.r0;
      return;
    case ShapeType::kRing:
      centre = s.a;
      radiusM = s.r1;
      return;
    case ShapeType::kCone: {
      centre = s.a + 0.5 * s.d * s.n;
      const double half = 0.5 * s.d, r = std::max(s.r0, s.r1);
      radiusM = std::sqrt(half * half + r * r);
      return;
    }
    case ShapeType::kTriangle:
    case ShapeType::kPolygon: {
      const std::vector<Vec3> pts = polygonOutline(s, vertices);
      centre = Vec3(0.0);
      for (const Vec3& v : pts) centre += v;
      centre /= static_cast<double>(pts.size());
      radiusM = 0.0;
      for (const Vec3& v : pts) radiusM = std::max(radiusM, glm::length(v - centre));
      return;
    }
  }
}

}  // namespace

std::vector<std::array<Vec3, 3>> triangulatePolygon(const std::vector<Vec3>& poly, const Vec3& normal) {
  std::vector<std::array<Vec3, 3>> tris;
  std::vector<size_t> idx(poly.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  auto isConvex = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::dot(glm::cross(b - a, c - b), normal) > 0.0;
  };
  auto inTriangle = [&](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::dot(glm::cross(b - a, p - a), normal) >= 0.0 && glm::dot(glm::cross(c - b, p - b), normal) >= 0.0 &&
           glm::dot(glm::cross(a - c, p - c), normal) >= 0.0;
  };
  size_t guard = 0;
  while (idx.size() > 3 && guard++ < 10 * poly.size() * poly.size()) {
    bool clipped = false;
    for (size_t i = 0; i < idx.size(); ++i) {
      const size_t ip = idx[(i + idx.size() - 1) % idx.size()], ic = idx[i], in = idx[(i + 1) % idx.size()];
      const Vec3 &a = poly[ip], &b = poly[ic], &c = poly[in];
      if (!isConvex(a, b, c)) continue;
      bool ear = true;
      for (size_t k : idx)
        if (k != ip && k != ic && k != in && inTriangle(poly[k], a, b, c)) { ear = false; break; }
      if (!ear) continue;
      tris.push_back({a, b, c});
      idx.erase(idx.begin() + static_cast<long>(i));
      clipped = true;
      break;
    }
    if (!clipped) break;  // numerically degenerate remainder: fan it
  }
  for (size_t i = 1; i + 1 < idx.size(); ++i) tris.push_back({poly[idx[0]], poly[idx[i]], poly[idx[i + 1]]});
  return tris;
}

std::vector<Light> collectLights(const Scene& scene) {
  std::vector<Light> lights;
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& s = scene.shapes[i];
    const Material& m = scene.materials[s.material];
    const bool glow = m.isEmitter() && !m.isSampledSource();
    if (!m.isEmitter() || photopic(m.color) <= 0.0) continue;
    // A glow of negative radius lights nothing (pathRadiance); an inward sphere (bubble) has no
    // outside to sample from: hemisphere rays find it.
    if (glow && (m.glowRadiusM < 0.0 || (s.type == ShapeType::kSphere && s.inward))) continue;
    Light l;
    l.kind = Light::Kind::kArea;
    l.shape = i;
    l.ownShape = i;
    l.radiance = m.color;
    l.areaM2 = shapeArea(s, scene.vertices);
    l.distribution = sourceDistributionOf(scene, m);
    l.pattern = functionPatternOf(scene, m);
    if (m.spot) l.spot = &m;
    if (l.distribution && !l.distribution->emits()) continue;
    if (glow) {
      l.glow = true;
      l.glowRadiusM = m.glowRadiusM;
      boundingSphere(s, scene.vertices, l.boundCentre, l.boundRadiusM);
      l.sphereGlow = s.type == ShapeType::kSphere;
    }
    if (s.type == ShapeType::kTriangle || s.type == ShapeType::kPolygon) {
      l.outline = polygonOutline(s, scene.vertices);
      l.normal = s.n;
      l.triangles = triangulatePolygon(l.outline, s.n);
      double acc = 0.0;
      for (const auto& t : l.triangles) {
        acc += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        l.cumulativeArea.push_back(acc);
      }
    }
    lights.push_back(std::move(l));
  }
  for (uint32_t i = 0; i < scene.luminaires.size(); ++i) {
    Light l;
    l.kind = Light::Kind::kLuminaire;
    l.luminaire = i;
    l.ownShape = scene.luminaires[i].openingShape;
    lights.push_back(std::move(l));
  }
  for (uint32_t i = 0; i < scene.distant.size(); ++i) {
    const Material& m = scene.materials[scene.distant[i].material];
    if (!m.isSampledSource() || photopic(m.color) <= 0.0) continue;
    Light l;
    l.kind = Light::Kind::kDistant;
    l.distant = i;
    l.radiance = m.color;
    l.pattern = functionPatternOf(scene, m);
    lights.push_back(std::move(l));
  }
  return lights;
}

namespace {

// A luminaire seen from p: a uniformly sampled point y of its luminous opening (at every
// distance), which carries I(p − y)/A per unit area — so E = E_y[I(ω_y) cos ι / r²], the
// point-source law averaged over the opening. For a flat Lambertian opening this is exactly the
// area source of luminance I/A·cosθ; far away it tends to the point law, but a screen hiding part
// of the opening hides that part only (a penumbra, not the hard shadow of the centre's one ray).
// A point luminaire (no opening) is its centre.
bool sampleLuminaire(const LuminaireSource& lum, const Vec3& p, double u1, double u2, LightSample& out) {
  Vec3 y = lum.position;
  if (lum.sizeM() > 0.0) {
    if (lum.circular) {
      const Vec2 q = sampleAnnulus(0.0, 0.5 * lum.widthM, u1, u2);
      y += q.x * lum.axisX + q.y * lum.axisY;
    } else {
      y += (u1 - 0.5) * lum.widthM * lum.axisX + (u2 - 0.5) * lum.lengthM * lum.axisY;
    }
  }
  const Vec3 e = p - y;
  const double d2 = glm::dot(e, e);
  if (d2 <= 0.0) return false;
  const double d = std::sqrt(d2);
  out.dir = -e / d;
  out.distance = d;
  // Candela to Radiance's radiometric units: lux / 179 on a white (1, 1, 1) source.
  out.weight = Rgb(lum.intensityCd(e / d) / (kLumensPerWatt * d2));
  return true;
}

// Whether the whole opening lies on or below the plane through p with normal n (so that no
// point of it sends light to the receiver's front): the farthest corner, or for a disc its
// centre's height plus R·sin of the angle between the planes.
bool openingBelowHorizon(const LuminaireSource& lum, const Vec3& p, const Vec3& n) {
  const double centre = glm::dot(lum.position - p, n);
  double reach;
  if (lum.circular) {
    const double nz = glm::dot(n, lum.axisZ);
    reach = 0.5 * lum.widthM * std::sqrt(std::max(0.0, 1.0 - nz * nz));
  } else {
    reach = 0.5 * (lum.widthM * std::abs(glm::dot(n, lum.axisX)) + lum.lengthM * std::abs(glm::dot(n, lum.axisY)));
  }
  return centre + reach <= 0.0;
}

}  // namespace

namespace {

// sampleLight without the light's function pattern; y and ny receive the sampled point and its
// front normal (a distant source: 10^10 m along the ray, facing back along it), where the
// pattern is evaluated.
bool sampleUnpatterned(const Light& light, const Scene& scene, const Vec3& p, double u1, double u2, LightSample& out,
                       Vec3& y, Vec3& ny) {
  if (light.kind == Light::Kind::kLuminaire) return sampleLuminaire(scene.luminaires[light.luminaire], p, u1, u2, out);
  if (light.kind == Light::Kind::kDistant) {
    const DistantSource& d = scene.distant[light.distant];
    const Frame f = Frame::fromNormal(d.direction);
    out.dir = f.toWorld(sampleUniformCone(u1, u2, d.cosHalfAngle));
    out.distance = std::numeric_limits<double>::infinity();
    out.weight = light.radiance * d.solidAngleSr;
    out.solidAngleSr = d.solidAngleSr;
    y = p + kDistantPointM * out.dir;
    ny = -out.dir;
    return true;
  }
  const Shape& s = scene.shapes[light.shape];
  switch (s.type) {
    case ShapeType::kTriangle:
    case ShapeType::kPolygon: {
      size_t k;
      y = pointOnTriangles(light.triangles, light.cumulativeArea, u1, u2, k);
      ny = s.n;
      break;
    }
    case ShapeType::kSphere: {
      // Uniform over the cone of directions the sphere subtends (pdf 1/Ω): weight L·Ω.
      const Vec3 toC = s.a - p;
      const double d2 = glm::dot(toC, toC);
      const double r2 = s.r0 * s.r0;
      if (d2 <= r2 || s.inward) return false;
      const double dist = std::sqrt(d2);
      const double cosMax = std::sqrt(std::max(0.0, 1.0 - r2 / d2));
      const Vec3 dir = Frame::fromNormal(toC / dist).toWorld(sampleUniformCone(u1, u2, cosMax));
      // Distance to the near side of the sphere along dir.
      const double b = glm::dot(dir, toC);
      const double disc = std::max(0.0, b * b - (d2 - r2));
      out.dir = dir;
      out.distance = b - std::sqrt(disc);
      out.weight = light.radiance * (kTwoPi * (1.0 - cosMax));
      out.solidAngleSr = kTwoPi * (1.0 - cosMax);
      y = p + out.distance * dir;
      ny = (y - s.a) / s.r0;
      if (light.distribution) out.weight *= light.distribution->factor(dir, -glm::dot(dir, ny));
      if (light.spot) out.weight *= light.spot->spotFactor(-dir, out.distance);
      return true;
    }
    case ShapeType::kRing: {
      const Frame f = Frame::fromNormal(s.n);
      const Vec2 q = sampleAnnulus(s.r0, s.r1, u1, u2);
      y = s.a + q.x * f.t + q.y * f.b;
      ny = s.n;
      break;
    }
    case ShapeType::kCone: {
      // Uniform in area: the slant position z has density ∝ r(z); invert the quadratic CDF.
      const double r0 = s.r0, r1 = s.r1;
      double frac;
      if (std::abs(r1 - r0) < 1e-12 * (r0 + r1)) {
        frac = u1;
      } else {
        frac = (std::sqrt(r0 * r0 + u1 * (r1 * r1 - r0 * r0)) - r0) / (r1 - r0);
      }
      const double r = r0 + frac * (r1 - r0);
      const Frame f = Frame::fromNormal(s.n);
      const double phi = kTwoPi * u2;
      y = s.a + frac * s.d * s.n + r * (std::cos(phi) * f.t + std::sin(phi) * f.b);
      ny = shapeNormal(s, y);
      break;
    }
  }
  return areaSample(y, ny, p, light, light.areaM2, out);
}

// The light's function pattern where the sample out meets it at y (front normal ny).
void patternAt(const Light& light, PatternEvaluator* patterns, const Vec3& y, const Vec3& ny, LightSample& out) {
  if (light.pattern < 0) return;
  if (!patterns) throw std::logic_error("a light with a function pattern is sampled without an evaluator");
  const double t = std::isinf(out.distance) ? kDistantPointM : out.distance;
  out.pattern = glm::max(patterns->colour(light.pattern, {y, out.dir, ny, t}), Rgb(0.0));
}

}  // namespace

bool sampleLight(const Light& light, const Scene& scene, const Vec3& p, double u1, double u2, LightSample& out,
                 PatternEvaluator* patterns) {
  Vec3 y(0.0), ny(0.0);
  if (!sampleUnpatterned(light, scene, p, u1, u2, out, y, ny)) return false;
  patternAt(light, patterns, y, ny, out);
  return true;
}

double polygonProjectedSolidAngle(const std::vector<Vec3>& poly, const Vec3& p, const Vec3& n) {
  double sum = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec3 a = poly[i] - p;
    const Vec3 b = poly[(i + 1) % poly.size()] - p;
    const Vec3 c = glm::cross(a, b);
    const double cl = glm::length(c);
    if (cl <= 0.0) continue;
    const double theta = std::atan2(cl, glm::dot(a, b));
    sum += theta * glm::dot(n, c) / cl;
  }
  return 0.5 * std::abs(sum);
}

void diskVectorIrradiance(double radiusM, double hM, double rhoM, double& alongAxis, double& towardsAxis) {
  const double r2 = radiusM * radiusM, h2 = hM * hM, p2 = rhoM * rhoM;
  const double a = h2 + p2 + r2;
  const double root = std::sqrt(std::max(0.0, a * a - 4.0 * r2 * p2));
  alongAxis = 0.5 * kPi * (1.0 - (h2 + p2 - r2) / root);
  towardsAxis = rhoM > 1e-12 * radiusM ? 0.5 * kPi * hM / rhoM * (a / root - 1.0) : 0.0;
}

bool sampleClippedPolygon(const Light& light, const std::vector<std::array<Vec3, 3>>& tris,
                          const std::vector<double>& cumulative, const Vec3& p, double u1, double u2,
                          LightSample& out, PatternEvaluator* patterns) {
  if (tris.empty()) return false;
  const double area = cumulative.back();
  size_t k;
  const Vec3 y = pointOnTriangles(tris, cumulative, u1, u2, k);
  // The clipped part lies in the source's plane and p in front of it (unoccludedIrradiance).
  if (!areaSample(y, light.normal, p, light, area, out)) return false;
  patternAt(light, patterns, y, light.normal, out);
  return true;
}

bool unoccludedIrradiance(const Light& light, const Scene& scene, const Vec3& p, const Vec3& n, Rgb& out,
                          std::vector<Vec3>* clipped) {
  if (light.kind == Light::Kind::kLuminaire) {
    // A point luminaire: the point-source law is exact for the estimator above (one point). An
    // opening has no closed form for a general web (the samples estimate E; the point law is off
    // by O((size/d)²), 0.7 % for a cos^1.2 panel at 3–4.6 m, and blind to partial occlusion).
    const LuminaireSource& lum = scene.luminaires[light.luminaire];
    if (openingBelowHorizon(lum, p, n)) {  // exactly nothing reaches this side
      out = Rgb(0.0);
      return true;
    }
    const Vec3 e = p - lum.position;
    const double d = glm::length(e);
    if (d <= 0.0 || lum.sizeM() > 0.0) return false;
    const double cosI = -glm::dot(n, e) / d;
    out = Rgb(cosI > 0.0 ? lum.intensityCd(e / d) * cosI / (kLumensPerWatt * d * d) : 0.0);
    return true;
  }
  if (light.kind == Light::Kind::kDistant) {
    const DistantSource& d = scene.distant[light.distant];
    double psa;
    if (!capProjectedSolidAngle(d.direction, std::sin(d.halfAngleRad), n, psa)) return false;
    out = light.radiance * psa;
    return true;
  }
  // A distribution varies the radiance over the source: no closed form; the samples estimate it.
  if (light.distribution || light.spot) return false;
  const Shape& s = scene.shapes[light.shape];
  if (s.type == ShapeType::kSphere) {
    const Vec3 toC = s.a - p;
    const double d = glm::length(toC);
    if (d <= s.r0 || s.inward) return false;
    double psa;
    if (!capProjectedSolidAngle(toC / d, s.r0 / d, n, psa)) return false;
    out = light.radiance * psa;
    return true;
  }
  if (s.type == ShapeType::kRing) {
    const Vec3 rel = p - s.a;
    const double h = glm::dot(rel, s.n);
    if (h <= 0.0) {  // behind the one-sided source
      out = Rgb(0.0);
      return true;
    }
    // Wholly above the receiver's horizon: (centre − p)·n ≥ R √(1 − (n·m)²).
    const double nm = glm::dot(n, s.n);
    if (glm::dot(s.a - p, n) < s.r1 * std::sqrt(std::max(0.0, 1.0 - nm * nm))) return false;
    const Vec3 radial = rel - h * s.n;
    const double rho = glm::length(radial);
    const Vec3 eRho = rho > 0.0 ? radial / rho : Vec3(0.0);
    auto disk = [&](double radius) {
      double along, towards;
      diskVectorIrradiance(radius, h, rho, along, towards);
      return glm::dot(n, -s.n * along - eRho * towards);
    };
    out = light.radiance * std::max(0.0, disk(s.r1) - (s.r0 > 0.0 ? disk(s.r0) : 0.0));
    return true;
  }
  if (light.outline.empty()) return false;
  // One-sided source: nothing reaches a receiver behind its plane.
  if (glm::dot(p - light.outline[0], s.n) <= 0.0) {
    out = Rgb(0.0);
    if (clipped) clipped->clear();
    return true;
  }
  std::vector<Vec3> local;
  std::vector<Vec3>& c = clipped ? *clipped : local;
  c = clipToHorizon(light.outline, p, n);
  out = c.size() < 3 ? Rgb(0.0) : light.radiance * polygonProjectedSolidAngle(c, p, n);
  return true;
}

}  // namespace candela

namespace candela {
namespace {

// A source distribution's part of the importance: its factor along e (from p to the source's
// centre) times the emission cosine, plus 5 % of its typical value so that no part of the source
// that can reach p gets a zero probability.
double distributionImportance(const SourceDistribution& dist, const Vec3& e, double cosL) {
  const double d = glm::length(e);
  const double f = d > 0.0 && cosL > 0.0 ? dist.factor(e / d, cosL) * cosL : 0.0;
  return f + 0.05 * dist.typicalIntensityFactor();
}

}  // namespace

double lightImportance(const Light& light, const Scene& scene, const Vec3& p, const Vec3& n) {
  if (light.kind == Light::Kind::kLuminaire) return luminaireImportance(scene.luminaires[light.luminaire], p, n);
  const double y = photopic(light.radiance);
  if (light.kind == Light::Kind::kDistant) {
    const DistantSource& d = scene.distant[light.distant];
    return y * d.solidAngleSr * (std::max(0.0, glm::dot(n, d.direction)) + 0.05);
  }
  const Shape& s = scene.shapes[light.shape];
  Vec3 centre, normal(0.0);
  switch (s.type) {
    case ShapeType::kSphere: {
      const Vec3 e = s.a - p;
      const double d2 = std::max(glm::dot(e, e), s.r0 * s.r0);
      const double f = light.distribution ? distributionImportance(*light.distribution, e, 1.0) : 1.0;
      return y * f * kPi * s.r0 * s.r0 / d2 * (std::max(0.0, glm::dot(n, e) / std::sqrt(d2)) + 0.05);
    }
    case ShapeType::kRing:
      centre = s.a;
      normal = s.n;
      break;
    case ShapeType::kCone:
      centre = 0.5 * (s.a + s.b);
      break;
    default: {
      centre = Vec3(0.0);
      for (const Vec3& v : light.outline) centre += v;
      centre /= static_cast<double>(std::max<size_t>(1, light.outline.size()));
      normal = s.n;
      // One-sided: nothing reaches a receiver behind the source's plane.
      if (glm::dot(p - light.outline[0], s.n) <= 0.0) return 0.0;
      break;
    }
  }
  const Vec3 e = centre - p;
  const double d2 = std::max(glm::dot(e, e), light.areaM2);
  const double d = std::sqrt(glm::dot(e, e));
  const double cosL = glm::length(normal) > 0.0 && d > 0.0 ? std::max(0.0, -glm::dot(normal, e) / d) : 0.5;
  const double cosI = d > 0.0 ? std::max(0.0, glm::dot(n, e) / d) : 1.0;
  if (light.distribution)
    return y * light.areaM2 * distributionImportance(*light.distribution, e, cosL) * (cosI + 0.05) / d2;
  return y * light.areaM2 * (cosL + 0.05) * (cosI + 0.05) / d2;
}

SampledSources collectSampledSources(const Scene& scene) {
  SampledSources out;
  out.lights = collectLights(scene);
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& sh = scene.shapes[i];
    if (isFlat(sh) && familyOf(scene.materials[sh.material]).mirrorsSources()) out.mirrors.push_back(i);
  }
  out.isMirrorImage.assign(scene.shapes.size(), 0);
  for (uint32_t i : out.mirrors) out.isMirrorImage[i] = 1;
  for (size_t l = 0; l < out.lights.size(); ++l) {
    if (!out.lights[l].glow) continue;
    if (out.glowLight.empty()) out.glowLight.assign(scene.shapes.size(), -1);
    out.glowLight[out.lights[l].shape] = static_cast<int32_t>(l);
  }
  return out;
}

}  // namespace candela
