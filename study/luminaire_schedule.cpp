#include "study/luminaire_schedule.h"

#include "base/units.h"
#include "engine/materials/family.h"
#include "metrics/power_density.h"
#include "photometry/luminaire_summary.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace candela {

namespace {

// Polar curves of the schedule every 2°: smooth at the plot's size, a few kB of SVG each.
constexpr double kPolarStepDeg = 2.0;

// A keyword of the file, its continuation lines ([MORE]) joined by spaces; "" when absent.
std::string keyword(const PhotometricInfo& info, const char* key) {
  const auto it = info.keywords.find(key);
  if (it == info.keywords.end()) return "";
  std::string s = it->second;
  for (char& ch : s)
    if (ch == '\n' || ch == '\r') ch = ' ';
  const std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string lumens(double lm) { return formatNumber(lm, 6) + " lm"; }

// The lamps as the file gives them. IES: the [LAMP] (and [LAMPCAT]) keywords, and the number of
// lamps and their rated flux unless the photometry is absolute. EULUMDAT: lamp set 1, the one
// the intensities are for (number, type, total flux, colour, colour rendering).
std::string lampText(const PhotometricWeb& web) {
  const PhotometricInfo& info = web.info();
  std::vector<std::string> parts;
  if (!info.lampSets.empty()) {
    const LampSet& s = info.lampSets.front();
    std::string lamp = std::to_string(std::abs(s.count)) + " × " + (s.type.empty() ? "lamp" : s.type);
    parts.push_back(lamp);
    if (s.totalFluxLm > 0.0) parts.push_back(lumens(s.totalFluxLm));
    if (!s.colour.empty()) parts.push_back(s.colour);
    if (!s.colourRendering.empty()) parts.push_back("colour rendering " + s.colourRendering);
    if (info.lampSets.size() > 1)
      parts.push_back("lamp set 1 of " + std::to_string(info.lampSets.size()));
  } else {
    for (const char* key : {"LAMP", "LAMPCAT"})
      if (std::string k = keyword(info, key); !k.empty()) parts.push_back(k);
    if (!web.isAbsolute() && info.lumensPerLamp > 0.0)
      parts.push_back(std::to_string(info.numLamps) + " × " + lumens(info.lumensPerLamp));
  }
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
  return out;
}

// The name and the file of the [[luminaire]] entry a placement comes from, as the case writes
// them (a case made in code without entries: the placement's own).
std::string entryName(const CaseFile& c, const LuminairePlacement& p) {
  const std::size_t i = static_cast<std::size_t>(p.entry);
  return i < c.luminaireEntries.size() ? c.luminaireEntries[i].name : p.name;
}
std::string entryFile(const CaseFile& c, const LuminairePlacement& p) {
  const std::size_t i = static_cast<std::size_t>(p.entry);
  return i < c.luminaireEntries.size() ? c.luminaireEntries[i].fileText : p.file.filename().string();
}

}  // namespace

std::optional<double> leastColourRendering(const std::string& field) {
  // A number of two or three digits, 0…100, that is not part of a group code ("1B" has one digit).
  for (std::size_t i = 0; i < field.size();) {
    if (!std::isdigit(static_cast<unsigned char>(field[i]))) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < field.size() && std::isdigit(static_cast<unsigned char>(field[j]))) ++j;
    const bool groupCode = j - i == 1;
    if (!groupCode && j - i <= 3) {
      const double v = std::stod(field.substr(i, j - i));
      if (v <= 100.0) return v;
    }
    i = j;
  }
  // CIE colour rendering groups: a digit 1–4 with A or B for 1 and 2.
  static constexpr struct {
    const char* code;
    double leastRa;
  } kGroups[] = {{"1A", 90}, {"1B", 80}, {"2A", 70}, {"2B", 60}};
  std::string upper = field;
  for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  for (const auto& g : kGroups)
    if (upper.find(g.code) != std::string::npos) return g.leastRa;
  const std::size_t b = upper.find_first_not_of(' '), e = upper.find_last_not_of(' ');
  if (b != std::string::npos && b == e) {
    if (upper[b] == '3') return 40.0;
    if (upper[b] == '4') return 20.0;
  }
  return std::nullopt;
}

namespace {

LuminaireTypeReport typeReport(const CaseFile& c, const LuminairePlacement& p, const PhotometricWeb& web) {
  const LuminaireSummary s = summarizeLuminaire(web);
  LuminaireTypeReport t;
  t.file = entryFile(c, p);
  t.manufacturer = keyword(web.info(), "MANUFAC");
  t.luminaire = keyword(web.info(), "LUMINAIRE");
  t.catalogueNumber = keyword(web.info(), "LUMCAT");
  t.lamp = lampText(web);
  if (!web.info().lampSets.empty()) {
    t.colourRendering = web.info().lampSets.front().colourRendering;
    t.leastRa = leastColourRendering(t.colourRendering);
  }
  t.multiplier = p.multiplier;
  t.maintenanceFactor = p.maintenanceFactor;
  t.fluxLm = s.totalLumens * p.multiplier;
  if (s.lampLumens > 0.0) {
    t.lampFluxLm = s.lampLumens * p.multiplier;
    t.lightOutputRatio = s.lightOutputRatio;
  }
  if (p.powerW) {
    t.powerW = *p.powerW;
    t.powerFromCase = true;
  } else if (s.inputWatts > 0.0) {
    t.powerW = s.inputWatts;
  }
  if (t.powerW) t.efficacyLmPerW = t.fluxLm / *t.powerW;
  for (const double cDeg : {0.0, 90.0}) {
    const PlaneCurve curve = planeCurve(web, cDeg, kPolarStepDeg);
    std::vector<double> cd = curve.intensityCd;
    for (double& v : cd) v *= p.multiplier;
    t.polar.push_back(PolarCurve{cDeg == 0.0 ? "C0-C180" : "C90-C270", curve.angleDeg, std::move(cd),
                                 cDeg == 0.0 ? "#c0392b" : "#1f5fa8", cDeg != 0.0});
  }
  return t;
}

}  // namespace

std::vector<LuminaireTypeReport> luminaireSchedule(const CaseFile& c, const Scene& scene) {
  using Key = std::tuple<std::filesystem::path, double, double, double>;  // file, multiplier, MF, power_w
  std::map<Key, std::size_t> index;
  std::vector<LuminaireTypeReport> types;
  for (std::size_t i = 0; i < c.luminaires.size() && i < scene.luminaires.size(); ++i) {
    const LuminairePlacement& p = c.luminaires[i];
    const PhotometricWeb* web = scene.luminaires[i].web.get();
    if (!web) continue;
    const Key key{p.file, p.multiplier, p.maintenanceFactor, p.powerW.value_or(-1.0)};
    auto [it, added] = index.try_emplace(key, types.size());
    if (added) types.push_back(typeReport(c, p, *web));
    LuminaireTypeReport& t = types[it->second];
    ++t.count;
    const std::string entry = entryName(c, p);
    if (std::find(t.entries.begin(), t.entries.end(), entry) == t.entries.end()) t.entries.push_back(entry);
  }
  return types;
}

std::vector<SurfaceMaterialReport> surfaceMaterials(const Scene& scene) {
  std::set<uint32_t> openings;
  for (const LuminaireSource& l : scene.luminaires)
    if (l.openingShape != std::numeric_limits<uint32_t>::max()) openings.insert(l.openingShape);
  std::vector<std::size_t> surfaces(scene.materials.size(), 0);
  auto use = [&](uint32_t material, std::size_t n) {
    if (material >= scene.materials.size()) return;
    const Material& m = scene.materials[material];
    const Material* seen = seenMaterial(scene.materials, m);
    if (!seen) return;
    material = static_cast<uint32_t>(seen - scene.materials.data());
    surfaces[material] += n;
  };
  for (uint32_t i = 0; i < scene.shapes.size(); ++i)
    if (!openings.count(i)) use(scene.shapes[i].material, 1);
  const TriangleMesh& mesh = scene.mesh;
  for (std::size_t r = 0; r < mesh.runs.size(); ++r) {
    const uint32_t end = r + 1 < mesh.runs.size() ? mesh.runs[r + 1].firstTriangle
                                                  : static_cast<uint32_t>(mesh.triangles.size());
    use(mesh.runs[r].material, end - mesh.runs[r].firstTriangle);
  }
  std::vector<SurfaceMaterialReport> out;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const MaterialFamily& family = familyOf(m);
    if (surfaces[i] == 0 || family.emits() || family.role() == HitRole::kAbsorb) continue;
    SurfaceMaterialReport r;
    r.material = m.name;
    r.type = family.name();
    r.surfaces = surfaces[i];
    const NormalIncidence n = family.normalIncidence(m);
    r.reflectance = n.reflectance;
    r.specularReflectance = n.specularReflectance;
    r.transmittance = n.transmittance;
    out.push_back(std::move(r));
  }
  return out;
}

ReferenceGrid referenceGrid(const CaseFile& c, const std::vector<PreparedGrid>& grids) {
  const auto horizontal = [](const PreparedGrid& g) {
    return !g.spec->daylightFactor && gridMeasures(g, GridQuantity::kHorizontal);
  };
  if (!c.referenceGrid.empty()) {
    for (std::size_t i = 0; i < grids.size(); ++i) {
      if (grids[i].spec->name != c.referenceGrid) continue;
      if (!horizontal(grids[i]))
        throw InputError(c.referenceGridLoc, "'reference_grid' names grid '" + c.referenceGrid +
                                                 "', whose points do not all measure horizontal illuminance "
                                                 "(sensors facing straight up): W/m²/100 lx needs it");
      return {static_cast<int>(i), "the case's reference grid"};
    }
    throw InputError(c.referenceGridLoc, "'reference_grid' names no grid of the case: '" + c.referenceGrid + "'");
  }
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].spec->taskArea.empty() && horizontal(grids[i]))
      return {static_cast<int>(i), "the case's first grid of horizontal illuminance"};
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].spec->area == GridSpec::Area::kTask && horizontal(grids[i]))
      return {static_cast<int>(i), "the task grid of the first task area"};
  return {};
}

EnergyReport energyReport(const CaseFile& c, const std::vector<LuminaireTypeReport>& schedule,
                          const Box& sceneBounds, const ReferenceGrid& reference,
                          const std::vector<GridReport>& grids) {
  EnergyReport e;
  for (const LuminaireTypeReport& t : schedule) {
    if (t.powerW) {
      e.installedPowerW += static_cast<double>(t.count) * *t.powerW;
    } else {
      for (const std::string& name : t.entries) e.luminairesWithoutPower.push_back(name);
    }
  }
  if (!sceneBounds.empty()) e.planExtentM = Vec2(sceneBounds.hi.x - sceneBounds.lo.x, sceneBounds.hi.y - sceneBounds.lo.y);
  if (c.floorAreaM2) {
    e.floorAreaM2 = *c.floorAreaM2;
    e.floorAreaFromCase = true;
  } else if (!sceneBounds.empty()) {
    e.floorAreaM2 = e.planExtentM.x * e.planExtentM.y;
  }
  if (e.floorAreaM2) e.powerDensityWm2 = powerDensityWm2(e.installedPowerW, *e.floorAreaM2);
  if (reference.index >= 0) {
    const GridReport& g = grids[static_cast<std::size_t>(reference.index)];
    e.referenceGrid = g.name;
    e.referenceGridReason = reference.reason;
    e.referenceAverageLux = g.stats.averageLux;
    if (e.powerDensityWm2) e.powerDensityWm2Per100Lux = normalisedPowerDensity(*e.powerDensityWm2, g.stats.averageLux);
  }
  return e;
}

}  // namespace candela
