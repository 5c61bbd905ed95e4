#include "engine/bsdf_klems.h"

#include <algorithm>
#include <cmath>
#include <strings.h>

namespace candela {
namespace {

double sq(double x) { return x * x; }

// The index of the cell a pick falls in: the first k with cdf[k] ≤ x < cdf[k + 1] and a
// non-empty cell (cdf has n + 1 entries, cdf[0] = 0, cdf[n] the total).
int pickCell(const double* cdf, int n, double pick) {
  const double x = pick * cdf[n];
  int k = static_cast<int>(std::upper_bound(cdf + 1, cdf + n + 1, x) - (cdf + 1));
  k = std::min(k, n - 1);
  while (k > 0 && !(cdf[k + 1] > cdf[k])) --k;  // x at the very top: the last non-empty cell
  while (k < n - 1 && !(cdf[k + 1] > cdf[k])) ++k;
  return k;
}

}  // namespace

KlemsBasis KlemsBasis::make(std::string name, std::vector<Ring> rings) {
  KlemsBasis b;
  b.name = std::move(name);
  b.rings = std::move(rings);
  for (Ring& r : b.rings) {
    r.first = b.count;
    b.count += r.nPhis;
  }
  return b;
}

std::shared_ptr<const KlemsBasis> KlemsBasis::standard(const std::string& name) {
  // θ bounds (degrees) and azimuth counts of LBNL's bases, as Radiance lists them
  // (src/common/bsdf_m.c, abase_list): (lower θ, nPhis) per ring, closed by (90, 0).
  struct Def {
    const char* name;
    std::vector<std::pair<double, int>> lat;
  };
  static const std::array<std::shared_ptr<const KlemsBasis>, 3> bases = [] {
    const Def defs[3] = {
        {"LBNL/Klems Full",
         {{0, 1}, {5, 8}, {15, 16}, {25, 20}, {35, 24}, {45, 24}, {55, 24}, {65, 16}, {75, 12}, {90, 0}}},
        {"LBNL/Klems Half", {{0, 1}, {6.5, 8}, {19.5, 12}, {32.5, 16}, {46.5, 20}, {61.5, 12}, {76.5, 4}, {90, 0}}},
        {"LBNL/Klems Quarter", {{0, 1}, {9, 8}, {27, 12}, {46, 12}, {66, 8}, {90, 0}}}};
    std::array<std::shared_ptr<const KlemsBasis>, 3> out;
    for (int d = 0; d < 3; ++d) {
      std::vector<Ring> rings;
      for (size_t k = 0; k + 1 < defs[d].lat.size(); ++k)
        rings.push_back({defs[d].lat[k].first, defs[d].lat[k + 1].first, defs[d].lat[k].second, 0});
      out[d] = std::make_shared<const KlemsBasis>(make(defs[d].name, std::move(rings)));
    }
    return out;
  }();
  for (const auto& b : bases)
    if (strcasecmp(b->name.c_str(), name.c_str()) == 0) return b;
  return nullptr;
}

const KlemsBasis::Ring& KlemsBasis::ringOf(int k) const {
  size_t r = 0;
  while (r + 1 < rings.size() && k >= rings[r + 1].first) ++r;
  return rings[r];
}

// Radiance's fo_getndx (bsdf_m.c): the ring whose [θ_lo, θ_hi) holds θ, and the sector whose
// centre is nearest in azimuth.
int KlemsBasis::index(const Vec3& v) const {
  if (!(v.z > 0.0)) return -1;
  const double thetaDeg = radToDeg(std::acos(std::min(v.z, 1.0)));
  for (const Ring& r : rings) {
    if (thetaDeg >= r.thetaHiDeg) continue;
    if (thetaDeg < r.thetaLoDeg) return -1;
    double azDeg = radToDeg(std::atan2(v.y, v.x));
    if (!std::isfinite(azDeg)) return -1;
    if (azDeg < 0.0) azDeg += 360.0;
    int k = static_cast<int>(azDeg / 360.0 * r.nPhis + 0.5);
    if (k >= r.nPhis) k = 0;
    return r.first + k;
  }
  return -1;
}

// Radiance's fo_getvec: cos²θ linear between the ring's bounds (uniform in projected solid
// angle), azimuth uniform over the sector.
Vec3 KlemsBasis::direction(int k, const Vec2& u) const {
  const Ring& r = ringOf(k);
  const double c2 = (1.0 - u.x) * sq(std::cos(degToRad(r.thetaLoDeg))) + u.x * sq(std::cos(degToRad(r.thetaHiDeg)));
  const double cosT = std::sqrt(std::max(c2, 0.0));
  const double sinT = std::sqrt(std::max(1.0 - c2, 0.0));
  const double az = kTwoPi * ((k - r.first) + u.y - 0.5) / r.nPhis;
  return Vec3(std::cos(az) * sinT, std::sin(az) * sinT, cosT);
}

double KlemsBasis::projSA(int k) const {
  const Ring& r = ringOf(k);
  return kPi * (sq(std::cos(degToRad(r.thetaLoDeg))) - sq(std::cos(degToRad(r.thetaHiDeg)))) / r.nPhis;
}

KlemsBsdf::KlemsBsdf(std::array<std::optional<KlemsMatrix>, kBsdfParts> parts, std::string kind)
    : kind_(std::move(kind)) {
  for (int pi = 0; pi < kBsdfParts; ++pi) {
    if (!parts[pi]) continue;
    Part p;
    p.which = static_cast<BsdfPart>(pi);
    p.m = std::move(*parts[pi]);
    const int ni = p.m.in->count, no = p.m.out->count;
    std::vector<double> lamIn(ni), lamOut(no);
    for (int i = 0; i < ni; ++i) lamIn[i] = p.m.in->projSA(i);
    for (int o = 0; o < no; ++o) lamOut[o] = p.m.out->projSA(o);
    p.minProjSA = std::min(*std::min_element(lamIn.begin(), lamIn.end()), *std::min_element(lamOut.begin(), lamOut.end()));
    p.weight.resize(p.m.value.size());
    p.minY = 1e300;
    for (size_t n = 0; n < p.m.value.size(); ++n) {
      const Rgb& v = p.m.value[n];
      p.weight[n] = std::max({v.x, v.y, v.z, 0.0});
      p.minY = std::min(p.minY, photopic(v));
    }
    p.cdfByOut.assign(static_cast<size_t>(no) * (ni + 1), 0.0);
    p.cdfByIn.assign(static_cast<size_t>(ni) * (no + 1), 0.0);
    p.albedoByOut.assign(no, Rgb(0.0));
    p.hemiByIn.assign(ni, Rgb(0.0));
    for (int o = 0; o < no; ++o) {
      double* c = &p.cdfByOut[static_cast<size_t>(o) * (ni + 1)];
      for (int i = 0; i < ni; ++i) {
        const size_t n = static_cast<size_t>(o) * ni + i;
        c[i + 1] = c[i] + p.weight[n] * lamIn[i];
        p.albedoByOut[o] += p.m.value[n] * lamIn[i];
      }
    }
    for (int i = 0; i < ni; ++i) {
      double* c = &p.cdfByIn[static_cast<size_t>(i) * (no + 1)];
      for (int o = 0; o < no; ++o) {
        const size_t n = static_cast<size_t>(o) * ni + i;
        c[o + 1] = c[o] + p.weight[n] * lamOut[o];
        p.hemiByIn[i] += p.m.value[n] * lamOut[o];
      }
    }
    parts_[pi] = std::move(p);
  }
}

// Radiance's fi_/bi_getndx: an incident direction's patch is that of (−x, −y, |z|); and
// fo_/bo_getndx: an outgoing one's is that of (x, y, |z|). Directions on the wrong side: -1.
int KlemsBsdf::inIndex(const Part& p, const Vec3& v) const {
  if (v.z * bsdfInSide(p.which) <= 0.0) return -1;
  return p.m.in->index(Vec3(-v.x, -v.y, std::abs(v.z)));
}

int KlemsBsdf::outIndex(const Part& p, const Vec3& v) const {
  if (v.z * bsdfOutSide(p.which) <= 0.0) return -1;
  return p.m.out->index(Vec3(v.x, v.y, std::abs(v.z)));
}

Rgb KlemsBsdf::hemisphericalPatch(int part, int inPatch) const { return parts_[part]->hemiByIn[inPatch]; }

Rgb KlemsBsdf::partValue(int part, const Vec3& in, const Vec3& out) const {
  const Part& p = *parts_[part];
  const int i = inIndex(p, in), o = outIndex(p, out);
  if (i < 0 || o < 0) return Rgb(0.0);
  return p.m.value[static_cast<size_t>(o) * p.m.in->count + i];
}

double KlemsBsdf::pairProjSA(int part, const Vec3& in, const Vec3& out) const {
  const Part& p = *parts_[part];
  const int i = inIndex(p, in), o = outIndex(p, out);
  double s = 1e300;
  if (i >= 0) s = std::min(s, p.m.in->projSA(i));
  if (o >= 0) s = std::min(s, p.m.out->projSA(o));
  return s < 1e300 ? s : 0.0;
}

Rgb KlemsBsdf::integrateFree(int part, bool fixedIsIn, const Vec3& fixed) const {
  const Part& p = *parts_[part];
  if (fixedIsIn) {
    const int i = inIndex(p, fixed);
    return i < 0 ? Rgb(0.0) : p.hemiByIn[i];
  }
  const int o = outIndex(p, fixed);
  return o < 0 ? Rgb(0.0) : p.albedoByOut[o];
}

double KlemsBsdf::samplingTotal(int part, bool fixedIsIn, const Vec3& fixed) const {
  const Part& p = *parts_[part];
  const int ni = p.m.in->count, no = p.m.out->count;
  if (fixedIsIn) {
    const int i = inIndex(p, fixed);
    return i < 0 ? 0.0 : p.cdfByIn[static_cast<size_t>(i) * (no + 1) + no];
  }
  const int o = outIndex(p, fixed);
  return o < 0 ? 0.0 : p.cdfByOut[static_cast<size_t>(o) * (ni + 1) + ni];
}

bool KlemsBsdf::sampleFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec2& u, double pick, Vec3& free,
                           double& pdf) const {
  const Part& p = *parts_[part];
  const int ni = p.m.in->count, no = p.m.out->count;
  double total = 0.0, w = 0.0;
  if (fixedIsIn) {
    const int i = inIndex(p, fixed);
    if (i < 0) return false;
    const double* c = &p.cdfByIn[static_cast<size_t>(i) * (no + 1)];
    total = c[no];
    if (!(total > 0.0)) return false;
    const int o = pickCell(c, no, pick);
    const Vec3 d = p.m.out->direction(o, u);
    free = Vec3(d.x, d.y, bsdfOutSide(p.which) * d.z);
    w = p.weight[static_cast<size_t>(o) * ni + i];
  } else {
    const int o = outIndex(p, fixed);
    if (o < 0) return false;
    const double* c = &p.cdfByOut[static_cast<size_t>(o) * (ni + 1)];
    total = c[ni];
    if (!(total > 0.0)) return false;
    const int i = pickCell(c, ni, pick);
    const Vec3 d = p.m.in->direction(i, u);
    free = Vec3(-d.x, -d.y, bsdfInSide(p.which) * d.z);
    w = p.weight[static_cast<size_t>(o) * ni + i];
  }
  // Uniform in projected solid angle over the patch: density |cos|/Λ per sr, times the patch's
  // chance w·Λ/total.
  pdf = w * std::abs(free.z) / total;
  return pdf > 0.0;
}

double KlemsBsdf::pdfFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free) const {
  const Part& p = *parts_[part];
  const int ni = p.m.in->count;
  const int i = fixedIsIn ? inIndex(p, fixed) : inIndex(p, free);
  const int o = fixedIsIn ? outIndex(p, free) : outIndex(p, fixed);
  if (i < 0 || o < 0) return 0.0;
  const double total = samplingTotal(part, fixedIsIn, fixed);
  if (!(total > 0.0)) return 0.0;
  return p.weight[static_cast<size_t>(o) * ni + i] * std::abs(free.z) / total;
}

long KlemsBsdf::freeCell(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free, double& projSA) const {
  const Part& p = *parts_[part];
  const int k = fixedIsIn ? outIndex(p, free) : inIndex(p, free);
  projSA = k < 0 ? 0.0 : (fixedIsIn ? p.m.out->projSA(k) : p.m.in->projSA(k));
  return k;
}

}  // namespace candela
