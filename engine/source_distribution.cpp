#include "engine/source_distribution.h"

#include "engine/radiance/file_lookup.h"
#include "engine/radiance/transform.h"
#include "engine/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace candela {
namespace {

constexpr double kRadToDeg = 180.0 / kPi;
constexpr double kFtiny = 1e-6;  // Radiance's FTINY for double precision (src/common/fvect.h)

// The coordinate expressions ies2rad writes (src/cv/ies2rad.c, dosource), by name.
bool angleByName(const std::string& s, SourceAngle& out) {
  static const struct {
    const char* name;
    SourceAngle angle;
  } kNames[] = {{"src_theta", SourceAngle::kTheta},       {"src_phi", SourceAngle::kPhi},
                {"src_phi2", SourceAngle::kPhi2},         {"src_phi2+90", SourceAngle::kPhi2Plus90},
                {"src_phi4", SourceAngle::kPhi4},         {"srcB_vert", SourceAngle::kBVert},
                {"srcB_vert2", SourceAngle::kBVert2},     {"srcB_horiz", SourceAngle::kBHoriz},
                {"srcB_horiz2", SourceAngle::kBHoriz2}};
  for (const auto& n : kNames)
    if (s == n.name) {
      out = n.angle;
      return true;
    }
  return false;
}

SourceCorrection correctionByName(const std::string& s) {
  if (s == "flatcorr") return SourceCorrection::kFlat;
  if (s == "boxcorr") return SourceCorrection::kBox;
  if (s == "cylcorr") return SourceCorrection::kCylinder;
  return SourceCorrection::kNone;  // corr (the reader passes only the four names)
}

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// The real arguments: A1 the multiplier, then the box's or cylinder's dimensions in metres.
void readReals(const ScenePattern& p, const std::string& what, SourceCorrection c, double& a1, double& a2,
               double& a3, double& a4) {
  const size_t need = c == SourceCorrection::kBox ? 4 : c == SourceCorrection::kCylinder ? 3 : 0;
  const char* fn = c == SourceCorrection::kBox ? "boxcorr" : "cylcorr";
  if (p.reals.size() < need)
    throw InputError(p.loc, what + ": " + fn + " needs " + std::to_string(need) + " real arguments (the multiplier" +
                                (need == 4 ? " and the box's x, y and z sizes in metres" :
                                             " and the cylinder's diameter and height in metres") +
                                "), got " + std::to_string(p.reals.size()));
  a1 = p.reals.empty() ? 1.0 : p.reals[0];
  if (!(a1 >= 0.0) || !std::isfinite(a1))
    throw InputError(p.loc, what + ": the multiplier (first real argument) must be a number ≥ 0, got " + number(a1));
  // Sizes from a micrometre to 10^7 m: below, the correction's division overflows (1e-200 did).
  for (size_t i = 1; i < need; ++i)
    if (!(p.reals[i] > 0.0) || !std::isfinite(p.reals[i]) || p.reals[i] < 1e-6 || p.reals[i] > 1e7)
      throw InputError(p.loc, what + ": real argument " + std::to_string(i + 1) + " (a size in metres) must be > 0" +
                                  (p.reals[i] > 0.0 ? ", from 1e-6 to 1e7 m" : "") + ", got " + number(p.reals[i]));
  a2 = need > 1 ? p.reals[1] : 0.0;
  a3 = need > 2 ? p.reals[2] : 0.0;
  a4 = need > 3 ? p.reals[3] : 0.0;
}

}  // namespace

double sourceAngleDeg(SourceAngle a, const Vec3& d) {
  switch (a) {
    case SourceAngle::kTheta:
      if (d.z >= 1.0) return 0.0;
      if (d.z <= -1.0) return 180.0;
      return kRadToDeg * std::acos(d.z);
    case SourceAngle::kBVert:
      return kRadToDeg * std::atan2(-d.x, d.z);
    case SourceAngle::kBVert2:
      return std::abs(kRadToDeg * std::atan2(-d.x, d.z));
    case SourceAngle::kBHoriz:
      return kRadToDeg * std::atan2(d.y, d.z);
    case SourceAngle::kBHoriz2:
      return std::abs(kRadToDeg * std::atan2(d.y, d.z));
    default:
      break;
  }
  // Azimuth of the emitted direction −d, 0–360 (func.c, l_source_angle).
  double phi = kRadToDeg * std::atan2(-d.y, -d.x);
  if (phi < 0.0) phi += 360.0;
  switch (a) {
    case SourceAngle::kPhi4:
      if (phi >= 180.0) phi -= 180.0;
      return phi < 90.0 ? phi : 180.0 - phi;
    case SourceAngle::kPhi2:
      return phi < 180.0 ? phi : 360.0 - phi;
    case SourceAngle::kPhi2Plus90:
      return (phi < 180.0 ? phi : 360.0 - phi) + 90.0;
    default:
      return phi;
  }
}

const SourceDistribution* sourceDistributionOf(const Scene& scene, const Material& m) {
  if (m.pattern < 0) return nullptr;
  return scene.patterns[static_cast<size_t>(m.pattern)].source.get();
}

Rgb emittedRadiance(const Scene& scene, const Material& m, const Vec3& rayDir, double cosEmit) {
  if (!m.emitsTowards(-rayDir)) return Rgb(0.0);
  const SourceDistribution* s = sourceDistributionOf(scene, m);
  return s ? m.color * s->factor(rayDir, cosEmit) : m.color;
}

double SourceDistribution::factor(const Vec3& rayDir, double cosEmit) const {
  const Vec3 d = toPattern_ * rayDir;
  double pt[kMaxDataDimensions];
  for (size_t i = 0; i < angles_.size(); ++i) pt[i] = sourceAngleDeg(angles_[i], d);
  const double v = multiplier_ * data_.value(pt);
  if (!(v > 0.0)) return 0.0;
  switch (correction_) {
    case SourceCorrection::kNone:
      return v;
    case SourceCorrection::kFlat:
      return cosEmit > 0.0 ? v / cosEmit : 0.0;
    case SourceCorrection::kBox:
      return v / (std::abs(d.x) * a3_ * a4_ + std::abs(d.y) * a2_ * a4_ + std::abs(d.z) * a2_ * a3_);
    case SourceCorrection::kCylinder: {
      const double dz = std::min(d.z, 1.0 - kFtiny);  // func.c keeps the side term from vanishing
      return v / (a2_ * a3_ * std::sqrt(std::max(0.0, 1.0 - dz * dz)) + 0.25 * kPi * a2_ * a2_ * std::abs(dz));
    }
  }
  return 0.0;
}

double SourceDistribution::typicalIntensityFactor() const {
  const double v = multiplier_ * data_.maxAbsValue();
  switch (correction_) {
    case SourceCorrection::kBox:
      return v / std::min({a2_ * a3_, a2_ * a4_, a3_ * a4_});
    case SourceCorrection::kCylinder:
      return v / std::min(a2_ * a3_, 0.25 * kPi * a2_ * a2_);
    default:
      return v;
  }
}

SourceDistribution SourceDistribution::parse(const ScenePattern& p) {
  const std::string what = p.type + " '" + p.name + "'";
  SourceDistribution s;
  s.correction_ = correctionByName(p.strings.at(0));
  readReals(p, what, s.correction_, s.multiplier_, s.a2_, s.a3_, s.a4_);
  const std::filesystem::path dat =
      findSceneFile(p.strings.at(1), std::filesystem::path(p.loc.file).parent_path(), p.loc, what, "data file");
  s.data_ = readRadDataFile(dat, p.loc);
  const size_t nd = static_cast<size_t>(s.data_.dimensions());
  // strings: function, data file, source.cal, one coordinate per data dimension, transform.
  if (p.strings.size() < 3 + nd)
    throw InputError(p.loc, what + ": its data file '" + p.strings[1] + "' has " + std::to_string(nd) +
                                " dimensions, so it needs " + std::to_string(nd) +
                                " coordinates after source.cal, got " + std::to_string(p.strings.size() - 3));
  for (size_t i = 0; i < nd; ++i) {
    SourceAngle a;
    if (!angleByName(p.strings[3 + i], a))
      throw InputError(p.loc, what + ": coordinate '" + p.strings[3 + i] +
                                  "' is not one candela evaluates (src_theta, src_phi, src_phi2, src_phi2+90, "
                                  "src_phi4, srcB_vert, srcB_vert2, srcB_horiz, srcB_horiz2)");
    s.angles_.push_back(a);
  }
  RadTransform xf;
  const size_t end = parseRadTransform(p.strings, 3 + nd, xf, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] + "' after its " + std::to_string(nd) +
                                " coordinates is neither a coordinate nor a transform option");
  // Radiance divides the inverse transform of a direction by its scale (func.c, chanvalue):
  // the pattern sees a unit direction, rotated and mirrored only.
  const RadTransform inv = xf.inverse();
  s.toPattern_ = glm::dmat3(inv.matrix) / std::abs(inv.scale);
  // The largest factor the distribution can give must stay a number through the light's products
  // (.dat values of 1e308 with a multiplier of 1e10 overflowed into an internal error): at most
  // 1e30, as a light's radiance (engine/materials/family.h, expectRadiance).
  const double peak = s.typicalIntensityFactor();
  if (!std::isfinite(peak) || peak > 1e30)
    throw InputError(p.loc, what + ": the multiplier times the data's largest value over the smallest size (" +
                                number(peak) + ") is beyond 1e30: the light would overflow");
  return s;
}

}  // namespace candela
