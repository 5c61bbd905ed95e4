#include "reports/json_writer.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

#include "base/atomic_file.h"
#include "reports/csv_writer.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

// JSON has no NaN/Inf; write null instead of invalid JSON.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

// The luminaire schedule, the surfaces and the energy figures of a point-in-time run.
void addInstallation(nlohmann::json& j, const InstallationReport& in) {
  using nlohmann::json;
  json luminaires = json::array();
  for (const LuminaireTypeReport& t : in.luminaires)
    luminaires.push_back({{"file", t.file},
                          {"entries", t.entries},
                          {"manufacturer", t.manufacturer},
                          {"luminaire", t.luminaire},
                          {"catalogue_number", t.catalogueNumber},
                          {"lamp", t.lamp},
                          {"colour_rendering", t.colourRendering},
                          {"ra_least", optionalNumber(t.leastRa)},
                          {"count", t.count},
                          {"flux_lm", number(t.fluxLm)},
                          {"lamp_flux_lm", optionalNumber(t.lampFluxLm)},
                          {"power_w", optionalNumber(t.powerW)},
                          {"power_source", t.powerW ? json(t.powerFromCase ? "case" : "file") : json()},
                          {"light_output_ratio", optionalNumber(t.lightOutputRatio)},
                          {"multiplier", number(t.multiplier)},
                          {"maintenance_factor", number(t.maintenanceFactor)},
                          {"efficacy_lm_per_w", optionalNumber(t.efficacyLmPerW)}});
  j["luminaires"] = luminaires;
  json surfaces = json::array();
  for (const SurfaceMaterialReport& s : in.surfaces)
    surfaces.push_back({{"material", s.material},
                        {"type", s.type},
                        {"reflectance", number(s.reflectance)},
                        {"specular_reflectance", number(s.specularReflectance)},
                        {"transmittance", optionalNumber(s.transmittance)},
                        {"surfaces", s.surfaces}});
  j["surfaces"] = surfaces;
  const EnergyReport& e = in.energy;
  j["energy"] = {{"installed_power_w", number(e.installedPowerW)},
                 {"installed_power_is_lower_bound", !e.luminairesWithoutPower.empty()},
                 {"floor_area_m2", optionalNumber(e.floorAreaM2)},
                 {"floor_area_source", e.floorAreaM2 ? json(e.floorAreaFromCase ? "case" : "scene plan extent") : json()},
                 {"power_density_w_m2", optionalNumber(e.powerDensityWm2)},
                 {"power_density_w_m2_per_100lx", optionalNumber(e.powerDensityWm2Per100Lux)},
                 {"reference_grid", e.referenceGrid.empty() ? json() : json(e.referenceGrid)},
                 {"reference_grid_average_lux", e.referenceGrid.empty() ? json() : number(e.referenceAverageLux)},
                 {"luminaires_without_power", e.luminairesWithoutPower}};
}

}  // namespace

std::string summaryJson(const ReportData& data) {
  using nlohmann::json;
  json j;
  j["case"] = {{"name", data.run.caseName}, {"description", data.run.description}, {"file", data.run.caseFile}};
  j["version"] = data.run.version;
  j["started_at"] = data.run.startedAt;
  j["seed"] = data.run.seed;
  j["run_time_s"] = number(data.run.runTimeS);
  json settings = json::object();
  for (const auto& [k, v] : data.run.settings) settings[k] = v;
  j["settings"] = settings;
  if (!data.run.functionFiles.empty()) j["function_files"] = data.run.functionFiles;
  if (data.run.coefficientsTimeS) j["coefficients_time_s"] = number(*data.run.coefficientsTimeS);
  if (data.run.productTimeS) j["product_time_s"] = number(*data.run.productTimeS);
  json grids = json::array();
  for (const GridReport& g : data.grids) {
    json o = {{"name", g.name},
             {"description", g.description},
             {"quantity", g.quantity},
             {"unit", g.unit},
             {"points", g.stats.count},
             {"average", number(g.stats.averageLux)},
             {"minimum", number(g.stats.minimumLux)},
             {"maximum", number(g.stats.maximumLux)},
             {"median", number(g.stats.medianLux)},
             {"u0", number(g.stats.u0)},
             {"ud", number(g.stats.ud)},
             {"target_average", optionalNumber(g.targets.averageLux)},
             {"target_uniformity", optionalNumber(g.targets.uniformity)},
             {"verdict_average", verdictName(g.check.average)},
             {"verdict_uniformity", verdictName(g.check.uniformity)},
             {"verdict", verdictName(g.check.overall)}};
    if (!g.taskArea.empty()) {
      o["task_area"] = g.taskArea;
      o["area"] = g.area;
    }
    if (!g.surfaceGrid.empty()) {
      o["surface_grid"] = g.surfaceGrid;
      o["room_surface"] = g.roomSurface;
    }
    if (!g.quantityKey.empty()) o["quantity_key"] = g.quantityKey;
    if (g.modelling) {
      const ModellingResult& m = *g.modelling;
      o["modelling"] = {{"cylindrical_average_lux", number(m.cylindricalAverageLux)},
                        {"horizontal_average_lux", number(m.horizontalAverageLux)},
                        {"ratio", number(m.ratio)},
                        {"range", {kModellingRatioMin, kModellingRatioMax}},
                        {"verdict", verdictName(m.verdict)}};
    }
    // The plan's section (study/grids/plan_section.h): where it is cut and what it holds, as counts.
    if (g.planSection >= 0 && static_cast<std::size_t>(g.planSection) < data.planSections.size()) {
      const PlanSection& p = data.planSections[static_cast<std::size_t>(g.planSection)];
      o["plan_section"] = {{"cut_height_m", number(p.cutHeightM)},
                           {"floor_level_m", number(p.floorLevelM)},
                           {"raised_above_floor", p.raisedAboveFloor},
                           {"walls", p.walls.size()},
                           {"openings", p.openings.size()},
                           {"openings_above", p.openingsAbove.size()},
                           {"furniture", p.furniture.size()},
                           {"dropped_segments", p.droppedSegments},
                           {"dropped_footprints", p.droppedFootprints},
                           {"skipped_curved", p.skippedCurved}};
    }
    if (g.annual) {
      const GridAnnualSummary& a = g.annual->summary;
      o["DA300"] = number(a.DA300);
      o["cDA300"] = number(a.cDA300);
      o["UDI_fell_short"] = number(a.UDI_fell_short);
      o["UDI_supplementary"] = number(a.UDI_supplementary);
      o["UDI_autonomous"] = number(a.UDI_autonomous);
      o["UDI_exceeded"] = number(a.UDI_exceeded);
      o["sDA300_50"] = number(a.sDA300_50);
      o["ASE1000_250"] = number(a.ASE1000_250);
      o["sun_hours_mean"] = number(a.sunHoursMean);
      o["sensors"] = a.sensors;
      o["occupied_hours"] = a.occupiedHours;
      o["coefficients_time_s"] = optionalNumber(data.run.coefficientsTimeS);
      o["product_time_s"] = optionalNumber(data.run.productTimeS);
      if (!g.annual->windowGroups.empty()) {
        json groups = json::array();
        for (const AnnualGridReport::WindowGroupHours& w : g.annual->windowGroups)
          groups.push_back({{"name", w.name}, {"surfaces", w.surfaces}, {"blinds_closed_hours", w.blindsClosedHours}});
        o["window_groups"] = groups;
      }
      if (!g.annual->windowStates.empty()) {
        json states = json::array();
        for (const AnnualGridReport::WindowStateResult& w : g.annual->windowStates)
          states.push_back({{"group", w.group},
                            {"state", w.state},
                            {"occupied_hours", w.occupiedHours},
                            {"DA300", number(w.summary.DA300)},
                            {"sDA300_50", number(w.summary.sDA300_50)},
                            {"ASE1000_250", number(w.summary.ASE1000_250)},
                            {"UDI_autonomous", number(w.summary.UDI_autonomous)},
                            {"UDI_exceeded", number(w.summary.UDI_exceeded)}});
        o["window_states"] = states;
      }
    }
    grids.push_back(o);
  }
  j["grids"] = grids;
  json views = json::array();
  for (const ViewReport& v : data.views)
    views.push_back({{"name", v.name},
                     {"mean_luminance_cd_m2", number(v.meanLuminanceCdM2)},
                     {"mean_luminance_relative_standard_error", number(v.meanLuminanceRelativeStandardError)},
                     {"glare_source_luminance_cd_m2", optionalNumber(v.glareSourceLuminanceCdM2)},
                     {"glare_source_luminance_relative_standard_error",
                      v.glareSourceLuminanceRelativeStandardError ? number(*v.glareSourceLuminanceRelativeStandardError)
                                                                  : json()}});
  j["views"] = views;
  json observers = json::array();
  for (const ObserverReport& o : data.observers) {
    const std::optional<bool> pass = o.pass();
    observers.push_back({{"name", o.name},
                         {"position_m", {o.eyeM.x, o.eyeM.y}},
                         {"eye_height_m", o.eyeM.z},
                         {"direction", {o.direction.x, o.direction.y}},
                         {"ugr", optionalNumber(o.ugr)},
                         {"ugr_limit", optionalNumber(o.ugrLimit)},
                         {"verdict", pass ? json(*pass ? "pass" : "fail") : json()},
                         {"luminaires_in_view", o.luminairesInView},
                         {"vertical_illuminance_lux", number(o.verticalLux)},
                         {"background_luminance_cd_m2", number(o.backgroundCdM2)}});
  }
  j["observers"] = observers;
  json taskAreas = json::array();
  for (const TaskAreaReport& a : data.taskAreas) {
    auto gridName = [&](int i) { return i >= 0 ? json(data.grids[static_cast<std::size_t>(i)].name) : json(); };
    taskAreas.push_back({{"name", a.name},
                         {"task_grid", gridName(a.task)},
                         {"surrounding_grid", gridName(a.surrounding)},
                         {"background_grid", gridName(a.background)},
                         {"cylindrical_grid", gridName(a.cylindrical)},
                         {"ugr_limit", optionalNumber(a.ugrLimit)},
                         {"ugr", optionalNumber(a.ugr)},
                         {"ugr_observers", a.observers},
                         {"verdict_ugr", verdictName(a.ugrVerdict)},
                         {"ra_required", optionalNumber(a.ra)},
                         {"ra_least", optionalNumber(a.leastRa)},
                         {"ra_unknown", a.raUnknown},
                         {"verdict_ra", verdictName(a.raVerdict)},
                         {"verdict", verdictName(a.verdict)}});
  }
  j["task_areas"] = taskAreas;
  json surfaceGrids = json::array();
  for (const SurfaceGridReport& s : data.surfaceGrids) {
    json grids = json::array();
    for (int i : s.grids) grids.push_back(data.grids[static_cast<std::size_t>(i)].name);
    surfaceGrids.push_back({{"name", s.name},
                            {"room_type", s.roomType.empty() ? json() : json(s.roomType)},
                            {"grids", grids},
                            {"verdict", verdictName(s.verdict)}});
  }
  j["surface_grids"] = surfaceGrids;
  int checked = 0, failed = 0;
  j["verdict"] = verdictName(overallVerdict(data, &checked, &failed));
  j["verdict_lines"] = {{"checked", checked}, {"failed", failed}};
  if (data.installation) addInstallation(j, *data.installation);
  if (!data.compliance.empty()) {
    json compliance = json::object();
    for (const ComplianceReport& r : data.compliance) compliance[r.name] = complianceJson(r);
    j["compliance"] = compliance;
    for (const ComplianceReport& r : data.compliance)
      if (r.section) r.section->addTopLevelJson(j);
  }
  // Always present (empty when none), so a pipeline can test it without a key check.
  json warnings = json::array();
  for (const Warning& w : data.warnings)
    warnings.push_back({{"code", w.code},
                        {"message", w.message},
                        {"file", w.loc.file},
                        {"line", w.loc.line > 0 ? json(w.loc.line) : json()}});
  j["warnings"] = warnings;
  return j.dump(2) + "\n";
}

fs::path writeSummaryJson(const fs::path& dir, const ReportData& data) {
  fs::create_directories(dir);
  const fs::path path = dir / "summary.json";
  writeFileAtomic(path, summaryJson(data));
  return path;
}

void writeSummary(const fs::path& dir, const ReportData& data) {
  writeSummaryCsv(dir, data);
  writeSummaryJson(dir, data);
}

}  // namespace candela
