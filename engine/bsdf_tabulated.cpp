#include "engine/bsdf_tabulated.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela {
namespace {

int sideOf(const Vec3& v) { return v.z > 0.0 ? 1 : (v.z < 0.0 ? -1 : 0); }

// Radiance's threshold below which a component's minimum is not taken out as its diffuse part
// (src/common/bsdf_m.c, subtract_min: Y ≤ 0.01/π).
double diffuseOfMin(double minY) { return minY > 0.01 * kInvPi ? minY : 0.0; }

}  // namespace

BsdfLookup TabulatedBsdf::lookup(const Vec3& in, const Vec3& out) const {
  const int si = sideOf(in), so = sideOf(out);
  BsdfLookup l;
  if (si == 0 || so == 0) return l;
  if (si == so) {
    const BsdfPart p = si > 0 ? BsdfPart::ReflPlusZ : BsdfPart::ReflMinusZ;
    if (hasPart(p)) l.part = static_cast<int>(p);
    return l;
  }
  const BsdfPart direct = si > 0 ? BsdfPart::TransFromPlusZ : BsdfPart::TransFromMinusZ;
  const BsdfPart other = si > 0 ? BsdfPart::TransFromMinusZ : BsdfPart::TransFromPlusZ;
  if (hasPart(direct)) {
    l.part = static_cast<int>(direct);
  } else if (hasPart(other)) {
    l.part = static_cast<int>(other);
    l.reversed = true;
  }
  return l;
}

BsdfLookup TabulatedBsdf::lookupToward(const Vec3& out, bool transmitted) const {
  const int so = sideOf(out);
  if (so == 0) return {};
  const Vec3 in(0.0, 0.0, transmitted ? -so : so);
  return lookup(in, out);
}

Rgb TabulatedBsdf::evalFull(const Vec3& in, const Vec3& out) const {
  const BsdfLookup l = lookup(in, out);
  if (l.part < 0) return Rgb(0.0);
  return l.reversed ? partValue(l.part, out, in) : partValue(l.part, in, out);
}

// Without the peak, the BTDF in the peak's cells is its surround. (Radiance, sampling light
// sources, uses the surround inside a disc around the peak, m_bsdf.c; here the cells
// themselves, so that the albedo without the peak is exact and the draws' weights average to it.)
Rgb TabulatedBsdf::eval(const Vec3& in, const Vec3& out, bool withoutPeak) const {
  if (withoutPeak && sideOf(in) * sideOf(out) < 0) {
    const BsdfPeak p = peakFor(-out);
    const BsdfLookup l = lookup(in, out);
    if (p.found && l.part >= 0) {
      double psa = 0.0;
      const long c = freeCell(l.part, l.reversed, out, in, psa);
      for (int k = 0; k < p.cells; ++k)
        if (p.cell[k] == c) return p.surround;
    }
  }
  return evalFull(in, out);
}

double TabulatedBsdf::pdfFull(const Vec3& in, const Vec3& out) const {
  const BsdfLookup l = lookup(in, out);
  if (l.part < 0) return 0.0;
  double total = 0.0;
  for (bool t : {false, true}) {
    const BsdfLookup lt = lookupToward(out, t);
    if (lt.part >= 0) total += samplingTotal(lt.part, lt.reversed, out);
  }
  if (!(total > 0.0)) return 0.0;
  return pdfFree(l.part, l.reversed, out, in) * samplingTotal(l.part, l.reversed, out) / total;
}

bool TabulatedBsdf::sampleIn(const Vec3& out, const Vec2& u, double pick, Sample& s, bool withoutPeak) const {
  s = Sample{};
  std::array<BsdfLookup, 2> ls{lookupToward(out, false), lookupToward(out, true)};
  std::array<double, 2> totals{0.0, 0.0};
  for (int k = 0; k < 2; ++k)
    if (ls[k].part >= 0) totals[k] = samplingTotal(ls[k].part, ls[k].reversed, out);
  const double total = totals[0] + totals[1];
  if (!(total > 0.0)) return false;
  double x = std::clamp(pick, 0.0, 1.0) * total;
  int k = (x < totals[0] && totals[0] > 0.0) ? 0 : 1;
  if (totals[k] <= 0.0) k = 1 - k;
  if (k == 1) x -= totals[0];
  const double subPick = std::clamp(x / totals[k], 0.0, 1.0);
  Vec3 in;
  double pdfPart = 0.0;
  if (!sampleFree(ls[k].part, ls[k].reversed, out, u, subPick, in, pdfPart) || !(pdfPart > 0.0)) return false;
  s.in = in;
  s.pdf = pdfPart * totals[k] / total;
  s.weight = eval(in, out, withoutPeak) * (std::abs(in.z) / s.pdf);
  return true;
}

double TabulatedBsdf::pdfIn(const Vec3& in, const Vec3& out, bool withoutPeak) const {
  return pdfFull(in, out);
}

Rgb TabulatedBsdf::albedoToward(const Vec3& out, bool transmitted, bool withoutPeak) const {
  const BsdfLookup l = lookupToward(out, transmitted);
  if (l.part < 0) return Rgb(0.0);
  Rgb a = integrateFree(l.part, l.reversed, out);
  if (!withoutPeak || !transmitted) return a;
  const BsdfPeak p = peakFor(-out);
  if (!p.found) return a;
  for (int k = 0; k < p.cells; ++k) a -= (p.cellValue[k] - p.surround) * p.cellProjSA[k];
  return a;
}

Rgb TabulatedBsdf::hemispherical(const Vec3& in, bool transmitted) const {
  const int si = sideOf(in);
  if (si == 0) return Rgb(0.0);
  const Vec3 out(0.0, 0.0, transmitted ? -si : si);
  const BsdfLookup l = lookup(in, out);
  if (l.part < 0) return Rgb(0.0);
  return integrateFree(l.part, !l.reversed, in);
}

// Radiance's aBSDF peak search (src/rt/m_bsdf.c, compute_through): for a viewer along −in, the
// BTDF is evaluated for light from 29 directions around in, spaced by √Ω_min in the projected
// plane; in
// descending order of Y, the distinct values whose cells are not larger than 1.5·Ω_min and not
// far below the mean of those before (8×) form the peak, the rest its surround. No peak when the
// brightest fails, when nothing surrounds it, or when it passes less than 0.05 % above the
// diffuse part.
BsdfPeak TabulatedBsdf::peakFor(const Vec3& in) const {
  static constexpr int kN = 29;
  static constexpr float kOffsets[kN][2] = {
      {0, 0},       {-0.6, 0},    {0, 0.6},    {0, -0.6},   {0.6, 0},     {-0.6, 0.6}, {-0.6, -0.6}, {0.6, 0.6},
      {0.6, -0.6},  {-1.2, 0},    {0, 1.2},    {0, -1.2},   {1.2, 0},     {-1.2, 1.2}, {-1.2, -1.2}, {1.2, 1.2},
      {1.2, -1.2},  {-1.8, 0},    {0, 1.8},    {0, -1.8},   {1.8, 0},     {-1.8, 1.8}, {-1.8, -1.8}, {1.8, 1.8},
      {1.8, -1.8},  {-2.4, 0},    {0, 2.4},    {0, -2.4},   {2.4, 0}};
  BsdfPeak peak;
  if (sideOf(in) == 0) return peak;
  const Vec3 out = -in;
  const BsdfLookup l = lookup(in, out);
  if (l.part < 0) return peak;
  const double minPsa = minProjSA(l.part);
  const double search = std::sqrt(minPsa);
  struct Probe {
    double y;
    Vec3 dir;
    Rgb value;
  };
  std::array<Probe, kN> probes;
  for (int i = 0; i < kN; ++i) {
    const Vec3 t = glm::normalize(Vec3(in.x + kOffsets[i][0] * search, in.y + kOffsets[i][1] * search, in.z));
    const Rgb v = evalFull(t, out);
    probes[i] = {photopic(v), t, v};
  }
  // Descending Y, by insertion (stable, and no buffer as std::stable_sort may take).
  for (int i = 1; i < kN; ++i)
    for (int j = i; j > 0 && probes[j - 1].y < probes[j].y; --j) std::swap(probes[j - 1], probes[j]);
  if (probes[0].y <= 1e-9) return peak;
  Rgb sum(0.0), surround(0.0);
  double yPeak = 0.0, omegaPeak = 0.0, omegaSurround = 0.0;
  int n = 0;
  for (int i = 0; i < kN; ++i) {
    if (i > 0 && probes[i].y == probes[i - 1].y) continue;  // the same cell again
    const double omega = l.reversed ? pairProjSA(l.part, out, probes[i].dir) : pairProjSA(l.part, probes[i].dir, out);
    const Rgb v = probes[i].value * omega;
    if (omega > 1.5 * minPsa || yPeak > 8.0 * probes[i].y * n) {
      if (i == 0) return BsdfPeak{};
      surround += v;
      omegaSurround += omega;
      continue;
    }
    double cellPsa = 0.0;
    const long c = freeCell(l.part, l.reversed, out, probes[i].dir, cellPsa);
    bool seen = false;
    for (int k = 0; k < peak.cells; ++k) seen = seen || peak.cell[k] == c;
    if (!seen && c >= 0) {
      peak.cell[peak.cells] = c;
      peak.cellProjSA[peak.cells] = cellPsa;
      peak.cellValue[peak.cells] = probes[i].value;
      ++peak.cells;
    }
    sum += v;
    omegaPeak += omega;
    yPeak += probes[i].y;
    ++n;
  }
  if (omegaSurround <= 1e-9) return BsdfPeak{};
  if ((yPeak / n - diffuseOfMin(minValueY(l.part))) * omegaPeak < 0.0005) return BsdfPeak{};
  peak.found = true;
  peak.through = sum;
  peak.surround = surround / omegaSurround;
  return peak;
}

Rgb TabulatedBsdf::peakThrough(const Vec3& in) const { return peakFor(in).through; }

bool TabulatedBsdf::reflects(bool plusZSide) const {
  return hasPart(plusZSide ? BsdfPart::ReflPlusZ : BsdfPart::ReflMinusZ);
}

bool TabulatedBsdf::transmits() const {
  return hasPart(BsdfPart::TransFromPlusZ) || hasPart(BsdfPart::TransFromMinusZ);
}

}  // namespace candela
