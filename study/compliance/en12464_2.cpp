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
  report.verdictLines.push_back(count(r.areas, "outdoor task areas"));
  if (!r.observers.empty()) report.verdictLines.push_back(count(r.observers, "GR observers"));
  report.timesS.emplace_back("glare rating", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  report.section = std::make_shared<En12464_2Section>(std::move(r));
  data.compliance.push_back(std::move(report));
}

}  // namespace candela
