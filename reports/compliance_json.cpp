// summary.json's compliance.<name> (docs/compliance.md lists every key).
#include "reports/compliance_report.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace candela {

namespace {

using nlohmann::json;

json number(double v) { return std::isfinite(v) ? json(v) : json(); }
json point(const Vec3& p) { return json::array({p.x, p.y, p.z}); }
std::string level(En17037Level l) { return std::string(levelName(l)); }

json criterion(const ProvisionCriterion& c) {
  return {{"threshold_lux", c.thresholdLux},
          {"plane_fraction", c.planeFraction},
          {"hour_first_time_fraction", c.hourFirstTimeFraction},
          {"hour_first_pass", c.hourFirstPass},
          {"sensor_first_plane_fraction", c.sensorFirstPlaneFraction},
          {"sensor_first_pass", c.sensorFirstPass}};
}

json provisionSpace(const ProvisionSpaceReport& s) {
  json levels = json::array();
  for (const ProvisionLevelResult& l : s.illuminance.levels)
    levels.push_back({{"level", level(l.level.level)},
                      {"target", criterion(l.target)},
                      {"minimum_target", criterion(l.minimumTarget)}});
  json j{{"space", s.space},
         {"sensors", s.illuminance.sensors},
         {"level_hour_first", level(s.illuminance.hourFirstLevel)},
         {"level_sensor_first", level(s.illuminance.sensorFirstLevel)},
         {"levels", levels}};
  if (s.daylightFactor) {
    json df = json::array();
    for (const DaylightFactorLevelResult& l : s.daylightFactor->levels)
      df.push_back({{"level", level(l.level.level)},
                    {"target_pct", l.targetPct},
                    {"minimum_target_pct", l.minimumTargetPct},
                    {"target_plane_fraction", l.targetPlaneFraction},
                    {"minimum_target_plane_fraction", l.minimumPlaneFraction},
                    {"pass", l.pass}});
    j["daylight_factor"] = {{"level", level(s.daylightFactor->level)},
                            {"mean_pct", s.meanDaylightFactorPct},
                            {"levels", df}};
  }
  return j;
}

void addEn17037(json& j, const En17037Report& r) {
  if (!r.spaces.empty()) {
    json spaces = json::array();
    for (const ProvisionSpaceReport& s : r.spaces) spaces.push_back(provisionSpace(s));
    j["daylight_provision"] = {{"level", level(r.provisionLevel)},
                               {"aggregation", r.sensorFirst ? "sensor-first" : "hour-first"},
                               {"level_other_aggregation", level(r.provisionLevelOther)},
                               {"aggregations_disagree", r.provisionLevel != r.provisionLevelOther},
                               {"daylight_hours", r.daylightHours},
                               {"median_diffuse_illuminance_lux", r.medianDiffuseLux},
                               {"daylight_factor_level", level(r.daylightFactorLevel)},
                               {"spaces", spaces}};
  }
  if (!r.sunlight.empty()) {
    json pts = json::array();
    for (const SunlightReportPoint& p : r.sunlight) {
      json iv = json::array();
      for (const auto& [a, b] : p.intervals) iv.push_back({a, b});
      pts.push_back({{"position", point(p.position)}, {"hours", p.hours}, {"intervals", iv}, {"level", level(p.level)}});
    }
    j["sunlight_exposure"] = pts;
    j["sunlight_date"] = r.sunlightDate;
    j["sunlight_min_altitude_deg"] = r.sunlightMinAltitudeDeg;
    j["sunlight_min_altitude_default"] = r.sunlightMinAltitudeDefault;
    j["sun_above_min_altitude_hours"] = r.sunAboveMinHours;
  }
  if (!r.viewOut.empty()) {
    json pts = json::array();
    for (const ViewOutReportPoint& v : r.viewOut)
      pts.push_back({{"position", point(v.eye)},
                     {"horizontal_sight_angle_deg", v.sightAngleDeg},
                     {"total_sight_angle_deg", v.totalSightAngleDeg},
                     {"outside_distance_m", number(v.outsideDistanceM)},
                     {"median_outside_distance_m", number(v.medianOutsideDistanceM)},
                     {"outside_unobstructed", std::isinf(v.outsideDistanceM)},
                     {"layers", v.layers},
                     {"level_sight_angle", level(v.sightLevel)},
                     {"level_distance", level(v.distanceLevel)},
                     {"level_layers", level(v.layersLevel)},
                     {"level", level(v.level)}});
    j["view_out"] = pts;
  }
  if (!r.glare.empty()) {
    json views = json::array();
    for (const GlareViewReport& g : r.glare) {
      json checks = json::array();
      for (const GlareViewReport::Check& c : g.checks)
        checks.push_back({{"time", c.time},
                          {"blinds_closed", c.blindsClosed},
                          {"dgp_imageless", c.imagelessDgp},
                          {"dgp_rendered", c.renderedDgp},
                          {"dgp_difference", c.imagelessDgp - c.renderedDgp},
                          {"ev_imageless_lux", c.imagelessEvLux},
                          {"ev_rendered_lux", c.renderedEvLux}});
      views.push_back({{"position", point(g.position)},
                       {"direction", point(g.direction)},
                       {"azimuth_deg", g.azimuthDeg},
                       {"share_above_dgp_0_35", g.shareAbove035},
                       {"share_above_dgp_0_40", g.shareAbove040},
                       {"share_above_dgp_0_45", g.shareAbove045},
                       {"glare_autonomy", g.glareAutonomy},
                       {"level", level(g.level)},
                       {"blinds", g.blinds},
                       {"blinds_space", g.blindsSpace.empty() ? json(nullptr) : json(g.blindsSpace)},
                       {"blinds_closed_hours", g.blindsClosedHours},
                       {"checks", checks}});
      if (!g.blindsNote.empty()) views.back()["blinds_note"] = g.blindsNote;
    }
    j["protection_from_glare"] = {{"exceedance", r.glareExceedance}, {"views", views}};
  }
}

void addLeed(json& j, const LeedReport& r) {
  json spaces = json::array();
  for (const LeedSpaceReport& s : r.spaces) {
    json e{{"space", s.space}, {"area_m2", s.areaM2}};
    if (r.times.empty()) {
      e["sDA300_50"] = s.sdaPct;
      e["ASE1000_250"] = s.asePct;
      e["ase_above_10_percent"] = s.aseAbove10;
    } else {
      e["in_range_pct"] = s.inRangePct;
      e["in_range_pct_by_time"] = s.inRangeByTimePct;
      e["in_range_pct_standard_error"] = s.inRangeStandardErrorPct;
      e["in_range_pct_standard_error_by_time"] = s.inRangeByTimeStandardErrorPct;
      e["mean_illuminance_lux_by_time"] = s.meanLuxByTime;
      e["mean_illuminance_lux_standard_error_by_time"] = s.meanLuxByTimeStandardError;
    }
    spaces.push_back(e);
  }
  j["spaces"] = spaces;
  j["points"] = r.points;
  j["each_space_above_55_percent"] = r.eachSpaceAbove55;
  if (r.times.empty()) {
    j["average_sDA300_50"] = r.averagePct;
    j["ase_exceeds_10_percent"] = r.aseExceeds10Percent;
  } else {
    j["average_in_range_pct"] = r.averagePct;
    j["average_in_range_pct_standard_error"] = r.averageStandardErrorPct;
    j["times"] = r.times;
    json skies = json::array();
    for (std::size_t t = 0; t < r.skyByTime.size(); ++t)
      skies.push_back({{"time", r.times.at(t)},
                       {"diffuse_horizontal_illuminance_lux", r.skyByTime[t].diffuseHorizontalLux},
                       {"direct_normal_illuminance_lux", r.skyByTime[t].directNormalLux},
                       {"days_averaged", r.skyByTime[t].days}});
    j["sky_by_time"] = skies;
  }
}

}  // namespace

nlohmann::json complianceJson(const ComplianceReport& r) {
  json j{{"standard", r.standard}, {"verdict", r.verdict}, {"verdict_lines", r.verdictLines}};
  if (r.en17037) addEn17037(j, *r.en17037);
  if (r.leed) addLeed(j, *r.leed);
  if (r.section) r.section->addJson(j);
  json times = json::object();
  for (const auto& [part, t] : r.timesS) times[part] = t;
  j["time_s"] = times;
  return j;
}

}  // namespace candela
