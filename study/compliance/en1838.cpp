#include "study/compliance/en1838.h"

#include "engine/materials/family.h"
#include "engine/tracer.h"
#include "reports/en1838_report.h"
#include "study/case/case_scene.h"
#include "study/compliance/en1838_grids.h"
#include "study/finite_results.h"
#include "study/grids/plan_section.h"

#include <algorithm>
#include <chrono>

namespace candela {

const ComplianceSpec* en1838Entry(const CaseFile& c) {
  for (const ComplianceSpec& s : c.compliance)
    if (s.standard == ComplianceStandard::kEn1838) return &s;
  return nullptr;
}

std::unique_ptr<Scene> loadEmergencyScene(const CaseFile& c, double maintenanceFactor,
                                          const std::vector<std::string>& leaveOut, const FileLoc& leaveOutLoc) {
  CaseFile e = c;
  e.luminaires.clear();
  for (const LuminairePlacement& l : c.luminaires) {
    if (!l.emergency) continue;
    LuminairePlacement q = l;
    q.multiplier = l.multiplier * l.emergencyFactor;
    q.maintenanceFactor = maintenanceFactor;
    e.luminaires.push_back(std::move(q));
  }
  auto scene = std::make_unique<Scene>();
  readCaseGeometry(e, *scene);
  std::vector<bool> used(leaveOut.size(), false);
  removeSurfaces(*scene, leaveOut, used);
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k])
      throw InputError(leaveOutLoc, "'leave_out': no surface of the scene is named '" + leaveOut[k] + "'");
  placeLuminaires(*scene, e.luminaires);
  for (Material& m : scene->materials) blackOutReflection(m);
  return scene;
}

bool blackOutReflection(Material& m) {
  // Opaque surfaces that only reflect (their family neither emits nor lets light through): black.
  // Zero diffuse bounces leave out their diffuse reflection, but not a mirror's virtual sources
  // nor a glossy lobe's direct light at a hemisphere ray's hit (tests/study/en1838_test.cpp
  // MirrorsAndGlossChangeNothing). Emitters stay sources; glazing and translucent materials pass
  // light (their transmission of the luminaires' light is direct light where it is specular).
  const MaterialFamily& family = familyOf(m);
  const bool reflects = family.role() == HitRole::kScatter || family.role() == HitRole::kSpecular;
  if (!reflects || family.emits() || family.transmitting()) return false;
  const std::string name = m.name;
  const FileLoc loc = m.loc;
  const int clipBit = m.clipBit;
  MaterialParameters black;
  black.type = MaterialType::kPlastic;
  black.clipBit = clipBit;
  deriveMaterial(black);
  static_cast<MaterialParameters&>(m) = black;
  m.name = name;
  m.loc = loc;
  return true;
}

TraceSettings directOnlySettings(TraceSettings s) {
  s.maxBounces = 0;
  s.method = Method::kPath;
  s.targetRelativeError = 0.0;
  s.gridTargetRelativeError = 0.0;
  return s;
}

namespace {

using Span = En1838Points::Span;

Span addPlan(std::vector<SensorPoint>& out, const std::vector<Vec2>& plan, double z) {
  Span s{out.size(), plan.size()};
  for (const Vec2& p : plan) out.push_back(SensorPoint{Vec3(p, z), Vec3(0.0, 0.0, 1.0)});
  return s;
}

std::vector<double> valuesOf(const std::vector<double>& lux, const Span& s) {
  return {lux.begin() + static_cast<std::ptrdiff_t>(s.first), lux.begin() + static_cast<std::ptrdiff_t>(s.first + s.count)};
}

std::vector<Vec2> counterClockwise(std::vector<Vec2> poly) {
  double area = 0.0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2 &a = poly[k], &b = poly[(k + 1) % poly.size()];
    area += a.x * b.y - a.y * b.x;
  }
  if (area < 0.0) std::reverse(poly.begin(), poly.end());
  return poly;
}


}  // namespace

En1838Points en1838Points(const CaseFile& c) {
  En1838Points p;
  for (const EscapeRouteSpec& r : c.emergency.routes) {
    p.routeCentre.emplace_back();
    p.routeBand.emplace_back();
    for (const RouteStripPoints& s : routeStrips(r)) {
      p.routeCentre.back().push_back(addPlan(p.sensors, s.centreLine, r.heightM));
      p.routeBand.back().push_back(addPlan(p.sensors, s.band, r.heightM));
    }
  }
  for (const OpenAreaSpec& a : c.emergency.openAreas) {
    p.cores.push_back(insetPolygon(a.outline, kEn1838BorderM, a.spacingM));
    p.openAreas.push_back(addPlan(p.sensors, polygonPoints(p.cores.back(), a.spacingM), a.heightM));
  }
  for (const TaskAreaSpec& a : c.taskAreas)
    if (a.emergencyHighRisk)
      p.highRisk.push_back(addPlan(p.sensors, polygonPoints(a.outline, a.spacingM.value_or(kHighRiskSpacingM)), a.heightM));
  for (const SafetyPointSpec& s : c.emergency.safetyPoints) {
    p.safetyPoints.push_back({p.sensors.size(), 1});
    p.sensors.push_back(SensorPoint{s.positionM, Vec3(s.facing, 0.0)});
  }
  return p;
}

En1838Result computeEn1838(const CaseFile& c, const ComplianceSpec& entry, const Scene& emergencyScene,
                           const TraceSettings& settings, int threads) {
  const En1838Points pts = en1838Points(c);
  const Tracer tracer(emergencyScene);
  const std::vector<IrradianceEstimate> est = computeIrradiance(tracer, pts.sensors, directOnlySettings(settings), threads);
  checkFinite(est.data(), est.size(), "the emergency lighting's illuminance", 0);
  std::vector<double> lux(est.size());
  for (std::size_t i = 0; i < est.size(); ++i) lux[i] = est[i].illuminanceLux();

  En1838Result r;
  r.maintenanceFactor = entry.emergencyMaintenanceFactor;
  r.leftOut = entry.emergencyLeaveOut;
  auto keep = [&](const char* part, const std::string& name, const En1838Points::Span& span) {
    for (std::size_t i = span.first; i < span.first + span.count; ++i)
      r.points.push_back({part, name, pts.sensors[i].position, pts.sensors[i].normal, lux[i]});
  };
  for (std::size_t k = 0; k < c.emergency.routes.size(); ++k)
    for (std::size_t s = 0; s < pts.routeCentre[k].size(); ++s) {
      keep("centre line", c.emergency.routes[k].name, pts.routeCentre[k][s]);
      keep("central band", c.emergency.routes[k].name, pts.routeBand[k][s]);
    }
  for (std::size_t k = 0; k < c.emergency.openAreas.size(); ++k)
    keep("open area core", c.emergency.openAreas[k].name, pts.openAreas[k]);
  std::size_t risk = 0;
  for (const TaskAreaSpec& spec : c.taskAreas)
    if (spec.emergencyHighRisk) keep("high-risk area", spec.name, pts.highRisk[risk++]);
  for (std::size_t k = 0; k < c.emergency.safetyPoints.size(); ++k)
    keep("safety point", c.emergency.safetyPoints[k].name, pts.safetyPoints[k]);
  for (std::size_t k = 0; k < c.emergency.routes.size(); ++k) {
    const EscapeRouteSpec& spec = c.emergency.routes[k];
    EscapeRouteResult e;
    e.name = spec.name;
    e.widthM = spec.widthM;
    e.heightM = spec.heightM;
    e.path = spec.path;
    const std::vector<RouteStripPoints> strips = routeStrips(spec);
    for (std::size_t s = 0; s < strips.size(); ++s)
      e.strips.push_back({strips[s].offsetM, strips[s].widthM, en1838Stats(valuesOf(lux, pts.routeCentre[k][s])),
                          en1838Stats(valuesOf(lux, pts.routeBand[k][s]))});
    judgeEscapeRoute(e);
    for (std::size_t s = 0; s < e.strips.size(); ++s)
      if (e.strips[s].centreLine.minLux == e.minCentreLineLux) {
        e.minCentreLineAtM = pts.sensors[pts.routeCentre[k][s].first + e.strips[s].centreLine.minIndex].position;
        break;
      }
    r.routes.push_back(std::move(e));
  }
  for (std::size_t k = 0; k < c.emergency.openAreas.size(); ++k) {
    OpenAreaResult a;
    a.name = c.emergency.openAreas[k].name;
    a.heightM = c.emergency.openAreas[k].heightM;
    a.outline = c.emergency.openAreas[k].outline;
    a.core = pts.cores[k];
    a.stats = en1838Stats(valuesOf(lux, pts.openAreas[k]));
    a.minAtM = pts.sensors[pts.openAreas[k].first + a.stats.minIndex].position;
    judgeOpenArea(a);
    r.openAreas.push_back(std::move(a));
  }
  std::size_t h = 0;
  for (const TaskAreaSpec& spec : c.taskAreas) {
    if (!spec.emergencyHighRisk) continue;
    HighRiskAreaResult a;
    a.name = spec.name;
    a.heightM = spec.heightM;
    a.outline = counterClockwise(spec.outline);
    a.maintainedLux = spec.maintainedLux;
    a.stats = en1838Stats(valuesOf(lux, pts.highRisk[h]));
    a.minAtM = pts.sensors[pts.highRisk[h++].first + a.stats.minIndex].position;
    judgeHighRiskArea(a);
    r.highRiskAreas.push_back(std::move(a));
  }
  for (std::size_t k = 0; k < c.emergency.safetyPoints.size(); ++k) {
    const SafetyPointSpec& spec = c.emergency.safetyPoints[k];
    SafetyPointResult p;
    p.name = spec.name;
    p.positionM = spec.positionM;
    p.facing = spec.facing;
    p.verticalLux = lux[pts.safetyPoints[k].first];
    for (const LuminairePlacement& l : c.luminaires)
      if (l.emergency)
        p.nearestLuminaireM = std::min(p.nearestLuminaireM, glm::length(Vec2(l.positionM) - Vec2(spec.positionM)));
    judgeSafetyPoint(p);
    r.safetyPoints.push_back(std::move(p));
  }
  for (const LuminairePlacement& l : c.luminaires) {
    r.luminaires.push_back({l.name, Vec2(l.positionM), l.emergency});
    r.emergencyLuminaires += l.emergency;
  }
  judgeEn1838(r);
  return r;
}

std::optional<Warning> noEmergencyLuminaireWarning(const CaseFile& c) {
  const ComplianceSpec* entry = en1838Entry(c);
  if (!entry) return std::nullopt;
  if (std::any_of(c.luminaires.begin(), c.luminaires.end(), [](const LuminairePlacement& l) { return l.emergency; }))
    return std::nullopt;
  return Warning{"no_emergency_luminaire",
                 "standard = \"en1838\" checks the emergency luminaires, but no [[luminaire]] has emergency = true: "
                 "every emergency illuminance is 0 lx",
                 entry->loc};
}

void addEn1838Compliance(const CaseFile& c, const ResolvedTrace& trace, ReportData& data) {
  const ComplianceSpec* entry = en1838Entry(c);
  if (!entry) return;
  const auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<Scene> scene =
      loadEmergencyScene(c, entry->emergencyMaintenanceFactor, entry->emergencyLeaveOut, entry->emergencyLeaveOutLoc);
  En1838Result r = computeEn1838(c, *entry, *scene, trace.settings, trace.threads);
  // The plan's walls: the scene cut 1 m above the floor (z = 0), as an architect's plan.
  std::optional<PlanSection> section;
  if (!scene->bounds().empty()) section = planSection(*scene, SectionRequest{kFloorPlanCutM, 0.0});
  ComplianceReport report;
  report.name = entry->name;
  report.standard = "en1838";
  report.verdict = r.verdict == Verdict::kFail ? "fail" : "pass";
  auto count = [](const auto& parts, const char* what) {
    std::size_t pass = 0;
    for (const auto& p : parts) pass += p.verdict == Verdict::kPass;
    return std::to_string(pass) + " of " + std::to_string(parts.size()) + " " + what + " pass";
  };
  if (!r.routes.empty()) report.verdictLines.push_back(count(r.routes, "escape routes"));
  if (!r.openAreas.empty()) report.verdictLines.push_back(count(r.openAreas, "anti-panic open areas"));
  if (!r.highRiskAreas.empty()) report.verdictLines.push_back(count(r.highRiskAreas, "high-risk task areas"));
  if (!r.safetyPoints.empty()) report.verdictLines.push_back(count(r.safetyPoints, "safety points"));
  report.timesS.emplace_back("emergency", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  report.section = std::make_shared<En1838Section>(std::move(r), std::move(section));
  data.compliance.push_back(std::move(report));
}

}  // namespace candela
