#include "study/compliance/en13201.h"

#include "base/units.h"
#include "engine/accelerator.h"
#include "engine/response.h"
#include "reports/en13201_report.h"
#include "study/case/case_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace candela {

namespace {

constexpr double kDegPerRad = 180.0 / kPi;
// Shadow rays leave the road this far above it, so that a road surface modelled in the scene
// (a polygon at z = 0) does not hide the point from its own luminaires.
constexpr double kLiftM = 1e-4;
// CIE 140 / EN 13201-3: the first threshold increment observer stands 2.75 (H − 1.5) m before the
// field (where the first luminaire of the field is at the screening angle: cot 20° = 2.75) and
// moves forward over one spacing in steps of D.
constexpr double kTiObserverFactor = 2.75;

double angleBetweenDeg(const Vec3& a, const Vec3& b) {
  const double c = glm::dot(a, b) / (glm::length(a) * glm::length(b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * kDegPerRad;
}

double ratioOr0(double num, double den) { return den > 0.0 ? num / den : 0.0; }

}  // namespace

const ComplianceSpec* en13201Entry(const CaseFile& c) {
  for (const ComplianceSpec& s : c.compliance)
    if (s.standard == ComplianceStandard::kEn13201) return &s;
  return nullptr;
}

RoadLight::RoadLight(const Scene& scene, const Tracer* tracer, std::vector<double> maintenanceFactors)
    : scene_(scene), tracer_(tracer), maintenance_(std::move(maintenanceFactors)) {
  maintenance_.resize(scene_.luminaires.size(), 1.0);
}

double RoadLight::visibility(const Vec3& from, std::size_t k) const {
  if (!tracer_) return 1.0;
  const LuminaireSource& l = scene_.luminaires[k];
  const Vec3 d = l.position - from;
  const double dist = glm::length(d);
  if (!(dist > 0.0)) return 1.0;
  return photopic(tracer_->transmittance(from, d / dist, dist * (1.0 - 1e-9), kNoShape, l.openingShape));
}

template <class Fn>
void RoadLight::eachLuminaire(const Vec3& point, Fn&& fn) const {
  for (std::size_t k = 0; k < scene_.luminaires.size(); ++k) {
    const LuminaireSource& l = scene_.luminaires[k];
    const Vec3 v = l.position - point;  // point → luminaire
    const double d2 = glm::dot(v, v);
    if (!(d2 > 0.0)) continue;
    const Vec3 s = v / std::sqrt(d2);
    const double i = l.intensityCd(-s) * maintenance_[k];
    if (i > 0.0) fn(k, s, d2, i);
  }
}

double RoadLight::illuminanceLux(const Vec2& p) const {
  // Point law: E = I cos ι / d², cos ι = s_z (the luminaire's height over d) on the horizontal road.
  const Vec3 point(p, 0.0);
  double e = 0.0;
  eachLuminaire(point, [&](std::size_t k, const Vec3& s, double d2, double i) {
    if (s.z > 0.0) e += i * s.z / d2 * visibility(point + Vec3(0.0, 0.0, kLiftM), k);
  });
  return e;
}

double RoadLight::hemisphericalLux(const Vec2& p) const {
  // E_hs = Σ I w(s) / d², w = (1 + cos ε)/4 the hemispherical response (engine/response.h).
  const Response hemisphere{Quantity::kHemispherical, Vec3(0.0, 0.0, 1.0), Vec3(1.0, 0.0, 0.0)};
  const Vec3 point(p, 0.0);
  double e = 0.0;
  eachLuminaire(point, [&](std::size_t k, const Vec3& s, double d2, double i) {
    const double w = hemisphere.weight(s);
    if (w > 0.0) e += i * w / d2 * visibility(point + Vec3(0.0, 0.0, kLiftM), k);
  });
  return e;
}

std::array<RoadLight::Facing, 2> RoadLight::facingLux(const Vec2& p, const Vec2& along) const {
  // The semi-cylindrical response sin ε (1 + cos α)/π and the vertical plane's max(0, n·s), facing
  // `along` and its opposite (engine/response.h).
  const Vec3 up(0.0, 0.0, 1.0);
  const std::array<Response, 2> half = {Response{Quantity::kSemiCylindrical, up, Vec3(along, 0.0)},
                                        Response{Quantity::kSemiCylindrical, up, Vec3(-along, 0.0)}};
  const std::array<Response, 2> plane = {Response::planar(Vec3(along, 0.0)), Response::planar(Vec3(-along, 0.0))};
  const Vec3 point(p, kFacialHeightM);
  std::array<Facing, 2> out{};
  eachLuminaire(point, [&](std::size_t k, const Vec3& s, double d2, double i) {
    const double seen = visibility(point, k);
    for (std::size_t side = 0; side < 2; ++side) {
      out[side].semiCylindrical += i * half[side].weight(s) / d2 * seen;
      out[side].vertical += i * plane[side].weight(s) / d2 * seen;
    }
  });
  return out;
}

RoadLight::Luminance RoadLight::luminanceCdM2(const Vec2& p, const Vec3& eye, const RTable& table, double q0) const {
  const Vec3 point(p, 0.0);
  const double scale = q0 / table.q0;
  const Vec2 view = p - Vec2(eye);  // observer → point, in plan
  Luminance out;
  for (std::size_t k = 0; k < scene_.luminaires.size(); ++k) {
    const LuminaireSource& l = scene_.luminaires[k];
    const double h = l.position.z;
    if (!(h > 0.0)) continue;
    const Vec2 foot = Vec2(l.position) - p;  // point → the luminaire's foot, in plan
    const double tanGamma = glm::length(foot) / h;
    // β: 0 when the luminaire stands beyond the point as the observer looks (docs/road.md).
    const double beta = glm::length(foot) > 0.0 && glm::length(view) > 0.0
                            ? angleBetweenDeg(Vec3(view, 0.0), Vec3(foot, 0.0))
                            : 0.0;
    const double r = reducedLuminanceCoefficient(table, beta, tanGamma) * scale;
    if (!(r > 0.0)) continue;
    const Vec3 v = point - l.position;
    const double initial = l.intensityCd(glm::normalize(v));
    if (!(initial > 0.0)) continue;
    const double lum = roadPointLuminanceCdM2(initial, r, h) * visibility(point + Vec3(0.0, 0.0, kLiftM), k);
    out.initial += lum;
    out.maintained += lum * maintenance_[k];
  }
  return out;
}

double RoadLight::veilingLuminanceCdM2(const Vec3& eye, const Vec2& along) const {
  const double down = kLineOfSightDownDeg / kDegPerRad;
  const Vec3 sight(along * std::cos(down), -std::sin(down));
  double lv = 0.0;
  for (std::size_t k = 0; k < scene_.luminaires.size(); ++k) {
    const LuminaireSource& l = scene_.luminaires[k];
    const Vec3 v = l.position - eye;  // eye → luminaire
    const double ahead = glm::dot(Vec2(v), along);
    if (!(ahead > 0.0) || ahead > kVeilingReachM) continue;
    // The screening plane: through the eye, across the road, 20° above the line of sight.
    const double elevationDeg = std::atan2(v.z, ahead) * kDegPerRad + kLineOfSightDownDeg;
    if (elevationDeg > kScreeningAngleDeg) continue;
    const double theta = angleBetweenDeg(sight, v);
    if (theta < kVeilingMinAngleDeg || theta > kVeilingMaxAngleDeg) continue;
    const double d2 = glm::dot(v, v), d = std::sqrt(d2);
    // The illuminance at the eye on the plane normal to the line of sight: I cos θ / d².
    const double i = l.intensityCd(-v / d);
    if (!(i > 0.0)) continue;
    const double e = i * std::cos(theta / kDegPerRad) / d2 * visibility(eye, k);
    lv += candela::veilingLuminanceCdM2(e, theta);
  }
  return lv;
}

double RoadLight::meanMountingHeightM() const {
  if (scene_.luminaires.empty()) return 0.0;
  double sum = 0.0;
  for (const LuminaireSource& l : scene_.luminaires) sum += l.position.z;
  return sum / static_cast<double>(scene_.luminaires.size());
}

namespace {

double meanIlluminance(const RoadGrids& g, const std::vector<double>& acrossM, const RoadLight& light) {
  std::vector<double> lux;
  for (const Vec2& p : g.points(acrossM)) lux.push_back(light.illuminanceLux(p));
  return roadStats(lux).average;
}

// The luminance observer of lane `lane`: the road's luminance from its eye, and its lane's
// threshold increment.
RoadObserverResult observe(const RoadSpec& road, const RoadGrids& g, const RoadLight& light, int lane) {
  RoadObserverResult o;
  o.eyeM = g.observers[static_cast<std::size_t>(lane)];
  const RTable& table = *findRTable(road.surface);
  const std::size_t across = g.luminanceAcrossM.size();
  std::vector<double> maintained, initial, centre;
  for (std::size_t i = 0; i < g.alongM.size(); ++i)
    for (std::size_t j = 0; j < across; ++j) {
      const RoadLight::Luminance l = light.luminanceCdM2(g.plan(g.alongM[i], g.luminanceAcrossM[j]), o.eyeM, table, road.q0);
      maintained.push_back(l.maintained);
      initial.push_back(l.initial);
      // The lane's centre line: the middle of its three points.
      if (j == static_cast<std::size_t>(3 * lane + 1)) centre.push_back(l.maintained);
    }
  const RoadStats all = roadStats(maintained), line = roadStats(centre);
  o.averageLuminanceCdM2 = all.average;
  o.minLuminanceCdM2 = all.min;
  o.overallUniformity = ratioOr0(all.min, all.average);
  o.longitudinalUniformity = ratioOr0(line.min, line.max);
  o.initialAverageLuminanceCdM2 = roadStats(initial).average;
  // Threshold increment: the observer in the lane's middle, moved over one spacing in steps of D
  // from 2.75 (H − 1.5) m before the field; the largest veiling luminance.
  const double laneM = road.widthM / road.lanes;
  const double firstM = -kTiObserverFactor * std::max(light.meanMountingHeightM() - kObserverEyeHeightM, 0.0);
  for (std::size_t k = 0; k < g.alongM.size(); ++k) {
    const Vec3 eye(g.plan(firstM + static_cast<double>(k) * g.spacingAlongM, (lane + 0.5) * laneM), kObserverEyeHeightM);
    o.veilingLuminanceCdM2 = std::max(o.veilingLuminanceCdM2, light.veilingLuminanceCdM2(eye, g.along));
  }
  o.thresholdIncrementPct = thresholdIncrementPct(o.veilingLuminanceCdM2, o.initialAverageLuminanceCdM2);
  return o;
}

}  // namespace

RoadResult computeRoad(const RoadSpec& road, const RoadLight& light) {
  const RoadGrids g = roadGrids(road);
  RoadResult r;
  r.name = road.name;
  r.roadClass = road.roadClass;
  r.surface = road.surface;
  r.q0 = road.q0;
  r.start = g.start;
  r.along = g.along;
  r.across = g.across;
  r.lengthM = road.lengthM;
  r.widthM = road.widthM;
  r.lanes = road.lanes;
  r.illuminancePoints = g.points(g.illuminanceAcrossM);
  for (const Vec2& p : r.illuminancePoints) r.illuminanceLux.push_back(light.illuminanceLux(p));
  const RoadStats e = roadStats(r.illuminanceLux);
  r.averageLux = e.average;
  r.minLux = e.min;
  r.maxLux = e.max;
  r.illuminanceUniformity = ratioOr0(e.min, e.average);
  if (road.roadClass.family == RoadClassFamily::kHS) {
    for (const Vec2& p : r.illuminancePoints) r.hemisphericalLux.push_back(light.hemisphericalLux(p));
    const RoadStats hs = roadStats(r.hemisphericalLux);
    r.averageHemisphericalLux = hs.average;
    r.minHemisphericalLux = hs.min;
    r.hemisphericalUniformity = ratioOr0(hs.min, hs.average);
  }
  r.additional = road.additional;
  if (!r.additional.empty()) {
    for (const Vec2& p : r.illuminancePoints) {
      const std::array<RoadLight::Facing, 2> f = light.facingLux(p, g.along);
      r.semiCylindricalLux.push_back(std::min(f[0].semiCylindrical, f[1].semiCylindrical));
      r.verticalLux.push_back(std::min(f[0].vertical, f[1].vertical));
    }
    r.minSemiCylindricalLux = roadStats(r.semiCylindricalLux).min;
    r.minVerticalLux = roadStats(r.verticalLux).min;
  }
  if (road.roadClass.family == RoadClassFamily::kM) {
    r.luminancePoints = g.points(g.luminanceAcrossM);
    for (int lane = 0; lane < road.lanes; ++lane) r.observers.push_back(observe(road, g, light, lane));
    r.stripWidthM = g.stripWidthM;
    r.edgeRatioNearSide = ratioOr0(meanIlluminance(g, g.nearOutsideM, light), meanIlluminance(g, g.nearInsideM, light));
    r.edgeRatioFarSide = ratioOr0(meanIlluminance(g, g.farOutsideM, light), meanIlluminance(g, g.farInsideM, light));
    r.edgeIlluminanceRatio = std::min(r.edgeRatioNearSide, r.edgeRatioFarSide);
  }
  judgeRoad(r);
  return r;
}

std::unique_ptr<Scene> loadRoadScene(const CaseFile& c, std::vector<double>& maintenanceFactors) {
  CaseFile initial = c;
  maintenanceFactors.clear();
  for (LuminairePlacement& l : initial.luminaires) {
    maintenanceFactors.push_back(l.maintenanceFactor);
    l.maintenanceFactor = 1.0;
  }
  return loadCaseScene(initial, /*withDaylight=*/false);
}

std::vector<RoadResult> computeEn13201(const CaseFile& c, const Scene& scene, const std::vector<double>& maintenanceFactors) {
  const Tracer tracer(scene);
  const RoadLight light(scene, &tracer, maintenanceFactors);
  std::vector<RoadResult> out;
  for (const RoadSpec& road : c.roadLighting.roads) out.push_back(computeRoad(road, light));
  return out;
}

void addEn13201Compliance(const CaseFile& c, ReportData& data) {
  const ComplianceSpec* entry = en13201Entry(c);
  if (!entry) return;
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = loadRoadScene(c, factors);
  En13201Report report;
  report.roads = computeEn13201(c, *scene, factors);
  for (const LuminairePlacement& l : c.luminaires) report.luminaires.push_back({l.name, l.positionM});
  ComplianceReport entryReport;
  entryReport.name = entry->name;
  entryReport.standard = "en13201";
  std::size_t pass = 0;
  for (const RoadResult& r : report.roads) pass += r.verdict == Verdict::kPass;
  entryReport.verdict = pass == report.roads.size() ? "pass" : "fail";
  entryReport.verdictLines.push_back(std::to_string(pass) + " of " + std::to_string(report.roads.size()) +
                                     " roads meet their EN 13201-2 class");
  entryReport.timesS.emplace_back("roads", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  entryReport.section = std::make_shared<En13201Section>(std::move(report));
  data.compliance.push_back(std::move(entryReport));
}

}  // namespace candela
