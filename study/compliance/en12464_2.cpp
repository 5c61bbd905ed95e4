#include "study/compliance/en12464_2.h"

#include "base/units.h"
#include "engine/materials/family.h"
#include "metrics/glare_rating.h"
#include "reports/en12464_2_report.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace candela {

const ComplianceSpec* en12464_2Entry(const CaseFile& c) {
  for (const ComplianceSpec& s : c.compliance)
    if (s.standard == ComplianceStandard::kEn12464_2) return &s;
  return nullptr;
}

std::vector<std::pair<double, Vec3>> grLinesOfSight(const GrObserverSpec& o) {
  std::vector<double> azimuths;
  if (o.direction) {
    const double a = std::atan2(o.direction->x, o.direction->y) * 180.0 / kPi;
    azimuths.push_back(a < 0.0 ? a + 360.0 : a);
  } else {
    azimuths = viewAzimuthsDeg(o.stepDeg);
  }
  std::vector<std::pair<double, Vec3>> out;
  for (double a : azimuths) out.emplace_back(a, lineOfSight(a, o.inclinationDeg));
  return out;
}

GrViewResult glareRatingView(const Tracer& tracer, const Vec3& eyeM, const Vec3& sight, double azimuthDeg,
                             double environmentVeilCdM2) {
  GrViewResult v;
  v.azimuthDeg = azimuthDeg;
  v.sight = sight;
  std::vector<VeilingSource> sources;
  for (const LuminaireSource& l : tracer.scene().luminaires) {
    const Vec3 to = l.position - eyeM;
    const double d = glm::length(to);
    if (!(d > 0.0) || !(glm::dot(to, sight) > 0.0)) continue;  // behind the eye: no light on the plane facing the sight
    const Vec3 u = to / d;
    const double intensity = l.intensityCd(-u);
    if (!(intensity > 0.0)) continue;
    // What of the luminaire's light passes the scene to the eye (0 behind a wall, τ through glass);
    // the luminaire's own opening surface, if modelled, is no obstruction.
    const double tau = photopic(tracer.transmittance(eyeM, u, d, kNoShape, l.openingShape));
    if (const std::optional<VeilingSource> s = veilingSource(eyeM, sight, l.position, intensity, tau))
      sources.push_back(*s);
  }
  v.luminairesInView = static_cast<int>(sources.size());
  v.luminairesVeilCdM2 = luminairesVeilingLuminance(sources);
  v.gr = glareRating(v.luminairesVeilCdM2, environmentVeilCdM2);
  return v;
}

std::optional<double> sceneGroundReflectance(const Tracer& tracer, const GridSpec& grid) {
  const Scene& scene = tracer.scene();
  double sum = 0.0;
  std::size_t hits = 0;
  for (const SensorPoint& p : makePlaneGrid(grid.plane, grid.loc).points) {
    RayHit hit;
    if (!tracer.accelerator().intersect(p.position + Vec3(0.0, 0.0, 0.5), Vec3(0.0, 0.0, -1.0), 0.0, 1e30, hit))
      continue;
    const Material& m = scene.materials[scene.shapes[hit.shape].material];
    sum += familyOf(m).normalIncidence(m).reflectance;
    ++hits;
  }
  if (hits == 0) return std::nullopt;
  return sum / static_cast<double>(hits);
}

namespace {

const GridReport* gridNamed(const ReportData& data, const std::string& name) {
  for (const GridReport& g : data.grids)
    if (g.name == name) return &g;
  return nullptr;
}

// Ra: the least colour rendering the files of the case's luminaires state (EULUMDAT); not checked
// when a file states none (IES): the lamp's data sheet decides (as EN 12464-1's task areas,
// docs/en12464.md). Outdoor luminaires stand on poles around or beside the area: every luminaire
// of the case counts.
void checkColourRendering(const ReportData& data, OutdoorAreaResult& a) {
  if (!a.ra || !data.installation) return;
  for (const LuminaireTypeReport& t : data.installation->luminaires) {
    if (!t.leastRa) {
      if (std::find(a.raUnknown.begin(), a.raUnknown.end(), t.file) == a.raUnknown.end()) a.raUnknown.push_back(t.file);
      continue;
    }
    a.raLeast = std::min(a.raLeast.value_or(*t.leastRa), *t.leastRa);
  }
  if (!a.raUnknown.empty() || !a.raLeast) {
    a.raLeast.reset();
    return;
  }
  a.raVerdict = *a.raLeast >= *a.ra ? Verdict::kPass : Verdict::kFail;
}

// A luminaire's flux (lm, scaled) above and in all directions, as placed: a midpoint rule over the
// world's sphere in 180 bands of equal solid angle (cos θ from −1 to 1, the horizontal a band
// edge) × 360 azimuths, each cell 4π/64 800 sr. Exact for an intensity constant over each cell.
std::pair<double, double> upwardAndTotalFlux(const LuminaireSource& l) {
  constexpr int kBands = 180, kAzimuths = 360;
  const double cell = 4.0 * kPi / (kBands * kAzimuths);
  double up = 0.0, total = 0.0;
  for (int i = 0; i < kBands; ++i) {
    const double z = -1.0 + (i + 0.5) * 2.0 / kBands, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    double band = 0.0;
    for (int j = 0; j < kAzimuths; ++j) {
      const double phi = (j + 0.5) * 2.0 * kPi / kAzimuths;
      band += l.intensityCd(Vec3(r * std::cos(phi), r * std::sin(phi), z));
    }
    total += band * cell;
    if (z > 0.0) up += band * cell;
  }
  return {up, total};
}

// EN 12464-2's obtrusive light: at each property point the vertical illuminance E_v on the
// point's plane (each luminaire a point source in front of the plane: τ I cos ι / d², τ what of
// it passes the scene) and the largest intensity I of a luminaire it sees; the installation's
// upward light ratio (flux above the horizontal over all the flux, every luminaire as placed;
// luminaires of the same file and orientation integrated once).
ObtrusiveLightResult obtrusiveLight(const ObtrusiveLightSpec& spec, const Tracer& tracer) {
  ObtrusiveLightResult r;
  r.zone = spec.zone;
  if (const std::optional<ObtrusiveLimits> z = obtrusiveZoneLimits(spec.zone)) r.limits = *z;
  if (spec.propertyLux) r.limits.propertyLux = spec.propertyLux;
  if (spec.intensityCd) r.limits.intensityCd = spec.intensityCd;
  if (spec.upwardLightRatio) r.limits.upwardLightRatio = spec.upwardLightRatio;
  const std::vector<LuminaireSource>& luminaires = tracer.scene().luminaires;
  for (const PropertyPointSpec& p : spec.points) {
    PropertyPointResult q;
    q.name = p.name;
    q.positionM = p.positionM;
    q.normal = p.normal;
    // Shadow rays leave just in front of the point (it may lie on a facade of the scene).
    const Vec3 from = p.positionM + Tracer::originOffset(p.positionM) * p.normal;
    for (const LuminaireSource& l : luminaires) {
      const Vec3 to = l.position - p.positionM;
      const double d = glm::length(to);
      if (!(d > 0.0)) continue;
      const Vec3 u = to / d;
      const double cosIncidence = glm::dot(u, p.normal);
      if (!(cosIncidence > 0.0)) continue;  // behind the property's plane
      const double tau = photopic(tracer.transmittance(from, glm::normalize(l.position - from),
                                                       glm::length(l.position - from), kNoShape, l.openingShape));
      if (!(tau > 0.0)) continue;
      const double intensity = l.intensityCd(-u);
      q.illuminanceLux += tau * intensity * cosIncidence / (d * d);
      if (intensity > q.maxIntensityCd) {
        q.maxIntensityCd = intensity;
        q.brightestLuminaire = l.name;
      }
    }
    r.points.push_back(std::move(q));
  }
  struct Integrated {
    const PhotometricWeb* web;
    Vec3 x, y, z;
    double up, total;  // per unit scale
  };
  std::vector<Integrated> done;
  for (const LuminaireSource& l : luminaires) {
    auto same = std::find_if(done.begin(), done.end(), [&](const Integrated& i) {
      return i.web == l.web.get() && i.x == l.axisX && i.y == l.axisY && i.z == l.axisZ;
    });
    if (same == done.end()) {
      LuminaireSource unit = l;
      unit.scale = 1.0;
      const auto [up, total] = upwardAndTotalFlux(unit);
      done.push_back({l.web.get(), l.axisX, l.axisY, l.axisZ, up, total});
      same = std::prev(done.end());
    }
    r.upwardFluxLm += l.scale * same->up;
    r.totalFluxLm += l.scale * same->total;
  }
  r.upwardLightRatio = r.totalFluxLm > 0.0 ? r.upwardFluxLm / r.totalFluxLm : 0.0;
  judgeObtrusiveLight(r);
  return r;
}

}  // namespace

En12464_2Result computeEn12464_2(const CaseFile& c, const Tracer& tracer, const ReportData& data) {
  En12464_2Result r;
  for (const OutdoorTaskAreaSpec& spec : c.outdoor.areas) {
    OutdoorAreaResult a;
    a.name = spec.name;
    a.outline = spec.outline;
    a.heightM = spec.heightM;
    a.maintainedLux = spec.maintainedLux;
    a.uniformityRequired = spec.uniformity;
    a.grLimit = spec.grLimit;
    a.ra = spec.ra;
    if (const GridReport* g = gridNamed(data, spec.name)) {
      a.points = g->stats.count;
      a.averageLux = g->stats.averageLux;
      a.minLux = g->stats.minimumLux;
      a.maxLux = g->stats.maximumLux;
      a.u0 = g->stats.u0;
    }
    checkColourRendering(data, a);
    a.groundReflectance = spec.groundReflectance;
    const bool rated = std::any_of(c.outdoor.observers.begin(), c.outdoor.observers.end(),
                                   [&](const GrObserverSpec& o) { return o.taskArea == spec.name; });
    if (!a.groundReflectance && rated) {
      const auto grid = std::find_if(c.grids.begin(), c.grids.end(), [&](const GridSpec& g) { return g.name == spec.name; });
      if (grid != c.grids.end()) a.groundReflectance = sceneGroundReflectance(tracer, *grid);
      if (!a.groundReflectance)
        throw InputError(spec.loc, "task area '" + spec.name + "': no surface of the scene lies under it to take ρ "
                                   "(GR's L_ve) from: give 'ground_reflectance'");
      a.groundReflectanceFromScene = true;
    }
    r.areas.push_back(std::move(a));
  }
  for (const GrObserverSpec& spec : c.outdoor.observers) {
    const auto area = std::find_if(c.outdoor.areas.begin(), c.outdoor.areas.end(),
                                   [&](const OutdoorTaskAreaSpec& a) { return a.name == spec.taskArea; });
    const auto result = std::find_if(r.areas.begin(), r.areas.end(),
                                     [&](const OutdoorAreaResult& a) { return a.name == spec.taskArea; });
    GrObserverResult o;
    o.name = spec.name;
    o.taskArea = spec.taskArea;
    o.eyeM = spec.eyeM();
    o.fromGrid = spec.fromGrid;
    o.inclinationDeg = spec.inclinationDeg;
    o.groundReflectance = result->groundReflectance.value_or(0.0);  // set above for every rated area
    o.averageHorizontalLux = result->averageLux;
    o.environmentVeilCdM2 = environmentVeilingLuminance(o.groundReflectance, o.averageHorizontalLux);
    o.grLimit = spec.grLimit ? spec.grLimit : area->grLimit;
    for (const auto& [azimuth, sight] : grLinesOfSight(spec))
      o.views.push_back(glareRatingView(tracer, o.eyeM, sight, azimuth, o.environmentVeilCdM2));
    judgeGrObserver(o);
    r.observers.push_back(std::move(o));
  }
  for (OutdoorAreaResult& a : r.areas) judgeOutdoorArea(a, r.observers);
  for (const LuminaireSource& l : tracer.scene().luminaires) r.luminaires.push_back({l.name, l.position});
  if (const ComplianceSpec* entry = en12464_2Entry(c); entry && entry->obtrusive.any())
    r.obtrusive = obtrusiveLight(entry->obtrusive, tracer);
  judgeEn12464_2(r);
  return r;
}

void addEn12464_2Compliance(const CaseFile& c, const Tracer& tracer, ReportData& data) {
  const ComplianceSpec* entry = en12464_2Entry(c);
  if (!entry) return;
  const auto start = std::chrono::steady_clock::now();
  En12464_2Result r = computeEn12464_2(c, tracer, data);
  ComplianceReport report;
  report.name = entry->name;
  report.standard = "en12464-2";
  report.verdict = r.verdict == Verdict::kFail ? "fail" : "pass";
  auto count = [](const auto& parts, const char* what) {
    std::size_t pass = 0, checked = 0;
    for (const auto& p : parts) pass += p.verdict == Verdict::kPass, checked += p.verdict != Verdict::kNotChecked;
    return std::to_string(pass) + " of " + std::to_string(checked) + " checked " + what + " pass";
  };
  if (!r.areas.empty()) report.verdictLines.push_back(count(r.areas, "outdoor task areas"));
  if (!r.observers.empty()) report.verdictLines.push_back(count(r.observers, "GR observers"));
  if (r.obtrusive)
    report.verdictLines.push_back(
        std::string("obtrusive light") + (r.obtrusive->zone.empty() ? "" : " (zone " + r.obtrusive->zone + ")") + ": " +
        (r.obtrusive->verdict == Verdict::kFail ? "fail" : r.obtrusive->verdict == Verdict::kPass ? "pass" : "not checked") +
        ", upward light ratio " + formatFixed(100.0 * r.obtrusive->upwardLightRatio, 1) + " %");
  report.timesS.emplace_back("glare rating", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  report.section = std::make_shared<En12464_2Section>(std::move(r));
  data.compliance.push_back(std::move(report));
}

}  // namespace candela
