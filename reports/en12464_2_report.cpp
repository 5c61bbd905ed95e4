#include "reports/en12464_2_report.h"

#include "reports/plan_svg.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace candela {

namespace {

using nlohmann::json;

json orNull(const std::optional<double>& v) { return v ? json(*v) : json(); }

std::string cell(const std::optional<double>& v, int decimals) { return v ? formatFixed(*v, decimals) : "–"; }

std::string verdictCell(Verdict v) {
  const char* cls = v == Verdict::kPass ? "ok" : v == Verdict::kFail ? "no" : "na";
  return std::string("<td class=\"") + cls + "\">" + (v == Verdict::kNotChecked ? "not checked" : verdictName(v)) +
         "</td>";
}

// The view with the largest GR (the first when none has one).
const GrViewResult* worstView(const GrObserverResult& o) {
  const GrViewResult* worst = o.views.empty() ? nullptr : &o.views.front();
  for (const GrViewResult& v : o.views)
    if (v.gr && (!worst->gr || *v.gr > *worst->gr)) worst = &v;
  return worst;
}

}  // namespace

void En12464_2Section::addJson(json& j) const {
  const En12464_2Result& r = result_;
  json areas = json::array();
  for (const OutdoorAreaResult& a : r.areas)
    areas.push_back({{"name", a.name},
                     {"height_m", a.heightM},
                     {"points", a.points},
                     {"maintained_illuminance_lux", a.maintainedLux},
                     {"average_lux", a.averageLux},
                     {"min_lux", a.minLux},
                     {"max_lux", a.maxLux},
                     {"uniformity", a.u0},
                     {"uniformity_required", orNull(a.uniformityRequired)},
                     {"verdict_average", verdictName(a.averageVerdict)},
                     {"verdict_uniformity", verdictName(a.uniformityVerdict)},
                     {"gr_limit", orNull(a.grLimit)},
                     {"gr_max", orNull(a.grMax)},
                     {"gr_observers", a.grObservers},
                     {"ground_reflectance", orNull(a.groundReflectance)},
                     {"ground_reflectance_from", a.groundReflectance ? (a.groundReflectanceFromScene ? "scene" : "case") : "none"},
                     {"verdict_gr", verdictName(a.grVerdict)},
                     {"ra_required", orNull(a.ra)},
                     {"ra_least", orNull(a.raLeast)},
                     {"ra_unknown", a.raUnknown},
                     {"verdict_ra", verdictName(a.raVerdict)},
                     {"verdict", verdictName(a.verdict)}});
  j["task_areas"] = areas;
  json observers = json::array();
  for (const GrObserverResult& o : r.observers) {
    json views = json::array();
    for (const GrViewResult& v : o.views)
      views.push_back({{"azimuth_deg", v.azimuthDeg},
                       {"direction", json::array({v.sight.x, v.sight.y, v.sight.z})},
                       {"luminaires_veil_cd_m2", v.luminairesVeilCdM2},
                       {"luminaires_in_view", v.luminairesInView},
                       {"gr", orNull(v.gr)}});
    observers.push_back({{"name", o.name},
                         {"task_area", o.taskArea},
                         {"eye", json::array({o.eyeM.x, o.eyeM.y, o.eyeM.z})},
                         {"from_grid", o.fromGrid},
                         {"inclination_deg", o.inclinationDeg},
                         {"ground_reflectance", o.groundReflectance},
                         {"average_horizontal_lux", o.averageHorizontalLux},
                         {"environment_veil_cd_m2", o.environmentVeilCdM2},
                         {"views", views},
                         {"gr_max", orNull(o.grMax)},
                         {"gr_limit", orNull(o.grLimit)},
                         {"verdict", verdictName(o.verdict)}});
  }
  j["observers"] = observers;
  if (r.obtrusive) {
    const ObtrusiveLightResult& o = *r.obtrusive;
    json points = json::array();
    for (const PropertyPointResult& p : o.points)
      points.push_back({{"name", p.name},
                        {"position", json::array({p.positionM.x, p.positionM.y, p.positionM.z})},
                        {"normal", json::array({p.normal.x, p.normal.y, p.normal.z})},
                        {"illuminance_lux", p.illuminanceLux},
                        {"max_intensity_cd", p.maxIntensityCd},
                        {"brightest_luminaire", p.brightestLuminaire.empty() ? json() : json(p.brightestLuminaire)},
                        {"verdict_illuminance", verdictName(p.illuminanceVerdict)},
                        {"verdict_intensity", verdictName(p.intensityVerdict)}});
    j["obtrusive_light"] = {{"environmental_zone", o.zone.empty() ? json() : json(o.zone)},
                            {"limit_property_illuminance_lux", orNull(o.limits.propertyLux)},
                            {"limit_intensity_cd", orNull(o.limits.intensityCd)},
                            {"limit_upward_light_ratio", orNull(o.limits.upwardLightRatio)},
                            {"property_points", points},
                            {"upward_flux_lm", o.upwardFluxLm},
                            {"total_flux_lm", o.totalFluxLm},
                            {"upward_light_ratio", o.upwardLightRatio},
                            {"verdict_upward_light_ratio", verdictName(o.upwardVerdict)},
                            {"verdict", verdictName(o.verdict)}};
  }
}

std::string En12464_2Section::html() const {
  const En12464_2Result& r = result_;
  std::ostringstream h;
  h << "<p>Outdoor task areas: maintained illuminance Ē<sub>m</sub> and uniformity U<sub>0</sub> = "
       "E<sub>min</sub>/Ē on each area's grid; glare rating GR (CIE 112) = 27 + 24 log<sub>10</sub>(L<sub>vl</sub> / "
       "L<sub>ve</sub><sup>0.9</sup>) at the observers, L<sub>vl</sub> from the luminaires in front of the eye, "
       "L<sub>ve</sub> = 0.035 ρ E<sub>hav</sub>/π from the area (docs/outdoor.md).</p>\n";
  h << en12464_2PlanSvg(r) << "\n";
  h << "<p class=\"legend\">Plan: task areas coloured by verdict (green passes, red fails, grey not checked); "
       "circles luminaires; dots GR observers, the line their worst line of sight, labelled with its GR"
    << (r.obtrusive && !r.obtrusive->points.empty()
            ? "; squares property points (obtrusive light), the tick the way the window faces, with E<sub>v</sub>"
            : "")
    << ".</p>\n";
  h << "<h3>Task areas</h3>\n<table class=\"compliance\"><tr><th>area</th><th>points</th><th>Ē lx</th>"
       "<th>Ē<sub>m</sub> lx</th><th>Ē ≥ Ē<sub>m</sub></th><th>U<sub>0</sub></th><th>U<sub>0</sub> required</th>"
       "<th>U<sub>0</sub> ≥</th><th>GR<sub>max</sub></th><th>GR<sub>L</sub></th><th>GR ≤ GR<sub>L</sub></th>"
       "<th>Ra least</th><th>Ra required</th><th>Ra ≥</th><th>verdict</th></tr>\n";
  for (const OutdoorAreaResult& a : r.areas) {
    std::string raLeast = cell(a.raLeast, 0);
    if (!a.raUnknown.empty()) raLeast = "unknown";
    h << "<tr><td>" << xmlEscape(a.name) << "</td><td class=\"num\">" << a.points << "</td><td class=\"num\">"
      << formatFixed(a.averageLux, 1) << "</td><td class=\"num\">" << formatFixed(a.maintainedLux, 0) << "</td>"
      << verdictCell(a.averageVerdict) << "<td class=\"num\">" << formatFixed(a.u0, 2) << "</td><td class=\"num\">"
      << cell(a.uniformityRequired, 2) << "</td>" << verdictCell(a.uniformityVerdict) << "<td class=\"num\">"
      << cell(a.grMax, 1) << "</td><td class=\"num\">" << cell(a.grLimit, 0) << "</td>" << verdictCell(a.grVerdict)
      << "<td class=\"num\">" << raLeast << "</td><td class=\"num\">" << cell(a.ra, 0) << "</td>"
      << verdictCell(a.raVerdict) << verdictCell(a.verdict) << "</tr>\n";
  }
  h << "</table>\n";
  for (const OutdoorAreaResult& a : r.areas)
    if (a.groundReflectance && a.groundReflectanceFromScene)
      h << "<p class=\"sub\">" << xmlEscape(a.name) << ": ρ = " << formatFixed(*a.groundReflectance, 3)
        << " for L<sub>ve</sub>, the mean reflectance of the scene's surface under its points.</p>\n";
  for (const OutdoorAreaResult& a : r.areas)
    if (!a.raUnknown.empty())
      h << "<p class=\"sub\">" << xmlEscape(a.name) << ": Ra not checked, the file(s) state no colour rendering ("
        << xmlEscape(a.raUnknown.front()) << (a.raUnknown.size() > 1 ? ", …" : "")
        << "): the lamps' data sheet decides.</p>\n";
  if (!r.observers.empty()) {
    h << "<h3>Glare rating at the observers (CIE 112)</h3>\n<table class=\"compliance\"><tr><th>observer</th>"
         "<th>area</th><th>eye m</th><th>lines of sight</th><th>ρ</th><th>E<sub>hav</sub> lx</th><th>L<sub>ve</sub> "
         "cd/m²</th><th>worst azimuth °</th><th>L<sub>vl</sub> cd/m²</th><th>GR<sub>max</sub></th><th>GR<sub>L</sub>"
         "</th><th>verdict</th></tr>\n";
    for (const GrObserverResult& o : r.observers) {
      const GrViewResult* w = worstView(o);
      h << "<tr><td>" << xmlEscape(o.name) << "</td><td>" << xmlEscape(o.taskArea) << "</td><td class=\"pos\">("
        << formatFixed(o.eyeM.x, 1) << ", " << formatFixed(o.eyeM.y, 1) << ", " << formatFixed(o.eyeM.z, 2)
        << ")</td><td class=\"num\">" << o.views.size() << "</td><td class=\"num\">"
        << formatFixed(o.groundReflectance, 2) << "</td><td class=\"num\">" << formatFixed(o.averageHorizontalLux, 1)
        << "</td><td class=\"num\">" << formatFixed(o.environmentVeilCdM2, 4) << "</td><td class=\"num\">"
        << (w ? formatFixed(w->azimuthDeg, 0) : "–") << "</td><td class=\"num\">"
        << (w ? formatFixed(w->luminairesVeilCdM2, 3) : "–") << "</td><td class=\"num\">" << cell(o.grMax, 1)
        << "</td><td class=\"num\">" << cell(o.grLimit, 0) << "</td>" << verdictCell(o.verdict) << "</tr>\n";
    }
    h << "</table>\n";
  }
  if (r.obtrusive) {
    const ObtrusiveLightResult& o = *r.obtrusive;
    h << "<h3>Obtrusive light" << (o.zone.empty() ? "" : " (environmental zone " + xmlEscape(o.zone) + ")")
      << "</h3>\n<p class=\"sub\">Limits: vertical illuminance at properties " << cell(o.limits.propertyLux, 1)
      << " lx, luminous intensity towards them " << cell(o.limits.intensityCd, 0) << " cd, upward light ratio "
      << (o.limits.upwardLightRatio ? formatFixed(100.0 * *o.limits.upwardLightRatio, 0) + " %" : "–")
      << (o.zone.empty() ? " (the case's)" : " (the zone's before curfew, EN 12193 Table 5, unless the case gives its own)")
      << ". Direct light of the luminaires, obstructions included (docs/outdoor.md).</p>\n";
    if (!o.points.empty()) {
      h << "<table class=\"compliance\"><tr><th>property point</th><th>position m</th><th>facing</th>"
           "<th>E<sub>v</sub> lx</th><th>E<sub>v</sub> ≤ limit</th><th>I<sub>max</sub> cd</th><th>from</th>"
           "<th>I ≤ limit</th></tr>\n";
      for (const PropertyPointResult& p : o.points)
        h << "<tr><td>" << xmlEscape(p.name) << "</td><td class=\"pos\">(" << formatFixed(p.positionM.x, 1) << ", "
          << formatFixed(p.positionM.y, 1) << ", " << formatFixed(p.positionM.z, 1) << ")</td><td class=\"pos\">("
          << formatFixed(p.normal.x, 2) << ", " << formatFixed(p.normal.y, 2) << ", " << formatFixed(p.normal.z, 2)
          << ")</td><td class=\"num\">" << formatFixed(p.illuminanceLux, 2) << "</td>" << verdictCell(p.illuminanceVerdict)
          << "<td class=\"num\">" << formatFixed(p.maxIntensityCd, 0) << "</td><td>"
          << (p.brightestLuminaire.empty() ? "–" : xmlEscape(p.brightestLuminaire)) << "</td>"
          << verdictCell(p.intensityVerdict) << "</tr>\n";
      h << "</table>\n";
    }
    h << "<table class=\"compliance\"><tr><th>upward flux lm</th><th>total flux lm</th><th>upward light ratio</th>"
         "<th>≤ limit</th><th>obtrusive light</th></tr>\n<tr><td class=\"num\">"
      << formatFixed(o.upwardFluxLm, 0) << "</td><td class=\"num\">" << formatFixed(o.totalFluxLm, 0)
      << "</td><td class=\"num\">" << formatFixed(100.0 * o.upwardLightRatio, 2) << " %</td>"
      << verdictCell(o.upwardVerdict) << verdictCell(o.verdict) << "</tr>\n</table>\n";
  }
  return h.str();
}

std::string en12464_2PlanSvg(const En12464_2Result& r) {
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto grow = [&](const Vec2& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
  for (const OutdoorAreaResult& a : r.areas)
    for (const Vec2& p : a.outline) grow(p);
  for (const OutdoorLuminaire& l : r.luminaires) grow(Vec2(l.positionM));
  for (const GrObserverResult& o : r.observers) grow(Vec2(o.eyeM));
  if (r.obtrusive)
    for (const PropertyPointResult& p : r.obtrusive->points) grow(Vec2(p.positionM));
  if (!(hi.x >= lo.x)) return "";
  const double margin = 0.05 * std::max({hi.x - lo.x, hi.y - lo.y, 1.0});
  lo -= Vec2(margin), hi += Vec2(margin);
  const double widthPx = 760.0, scale = widthPx / std::max(hi.x - lo.x, 1e-6);
  const double heightPx = (hi.y - lo.y) * scale;
  auto X = [&](double x) { return svgNumber((x - lo.x) * scale); };
  auto Y = [&](double y) { return svgNumber((hi.y - y) * scale); };  // plan y up, SVG y down
  using Colour = const char*;
  auto colour = [](Verdict v) -> Colour { return v == Verdict::kPass ? "#1e7b34" : v == Verdict::kFail ? "#b3261e" : "#777"; };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"en12464-2-plan\" width=\"" << svgNumber(widthPx)
    << "\" height=\"" << svgNumber(heightPx) << "\" viewBox=\"0 0 " << svgNumber(widthPx) << " "
    << svgNumber(heightPx) << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  for (const OutdoorAreaResult& a : r.areas) {
    s << "<polygon points=\"";
    for (const Vec2& p : a.outline) s << X(p.x) << "," << Y(p.y) << " ";
    s << "\" fill=\"" << colour(a.verdict) << "\" fill-opacity=\"0.08\" stroke=\"" << colour(a.verdict)
      << "\" stroke-width=\"1.5\"/>\n";
  }
  for (const OutdoorLuminaire& l : r.luminaires)
    s << "<circle cx=\"" << X(l.positionM.x) << "\" cy=\"" << Y(l.positionM.y)
      << "\" r=\"5\" fill=\"#f2a900\" stroke=\"#7a5500\" stroke-width=\"1\"><title>" << xmlEscape(l.name) << ", "
      << formatFixed(l.positionM.z, 1) << " m</title></circle>\n";
  for (const GrObserverResult& o : r.observers) {
    const double x = o.eyeM.x, y = o.eyeM.y;
    s << "<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"3\" fill=\"" << colour(o.verdict) << "\"><title>"
      << xmlEscape(o.name) << "</title></circle>\n";
    if (const GrViewResult* w = worstView(o)) {
      const Vec2 d = glm::normalize(Vec2(w->sight.x, w->sight.y)) * (14.0 / scale);
      s << "<line x1=\"" << X(x) << "\" y1=\"" << Y(y) << "\" x2=\"" << X(x + d.x) << "\" y2=\"" << Y(y + d.y)
        << "\" stroke=\"" << colour(o.verdict) << "\" stroke-width=\"2\"/>\n";
      if (w->gr && !o.fromGrid)
        s << "<text x=\"" << svgNumber((x - lo.x) * scale + 5) << "\" y=\"" << svgNumber((hi.y - y) * scale - 5)
          << "\" fill=\"" << colour(o.verdict) << "\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">"
          << xmlEscape(o.name) << " GR " << formatFixed(*w->gr, 1) << "</text>\n";
    }
  }
  // Property points (obtrusive light): a square, a tick along the window's facing, the name and E_v.
  if (r.obtrusive)
    for (const PropertyPointResult& p : r.obtrusive->points) {
      const Colour c = colour(p.illuminanceVerdict == Verdict::kFail || p.intensityVerdict == Verdict::kFail
                                  ? Verdict::kFail
                                  : p.illuminanceVerdict == Verdict::kPass || p.intensityVerdict == Verdict::kPass
                                        ? Verdict::kPass
                                        : Verdict::kNotChecked);
      const double x = p.positionM.x, y = p.positionM.y;
      s << "<rect x=\"" << svgNumber((x - lo.x) * scale - 4) << "\" y=\"" << svgNumber((hi.y - y) * scale - 4)
        << "\" width=\"8\" height=\"8\" fill=\"#fff\" stroke=\"" << c << "\" stroke-width=\"2\"><title>"
        << xmlEscape(p.name) << "</title></rect>\n";
      if (glm::length(Vec2(p.normal)) > 1e-6) {
        const Vec2 d = glm::normalize(Vec2(p.normal)) * (12.0 / scale);
        s << "<line x1=\"" << X(x) << "\" y1=\"" << Y(y) << "\" x2=\"" << X(x + d.x) << "\" y2=\"" << Y(y + d.y)
          << "\" stroke=\"" << c << "\" stroke-width=\"2\"/>\n";
      }
      s << "<text x=\"" << svgNumber((x - lo.x) * scale + 7) << "\" y=\"" << svgNumber((hi.y - y) * scale + 14) << "\" fill=\""
        << c << "\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">" << xmlEscape(p.name) << " "
        << formatFixed(p.illuminanceLux, 2) << " lx</text>\n";
    }
  for (const OutdoorAreaResult& a : r.areas) {
    Vec2 top = a.outline.front();
    for (const Vec2& p : a.outline)
      if (p.y > top.y || (p.y == top.y && p.x < top.x)) top = p;
    s << "<text x=\"" << svgNumber((top.x - lo.x) * scale + 4) << "\" y=\"" << svgNumber((hi.y - top.y) * scale + 14)
      << "\" fill=\"" << colour(a.verdict) << "\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\" "
                                              "font-weight=\"700\">"
      << xmlEscape(a.name) << " " << (a.verdict == Verdict::kNotChecked ? "not checked" : verdictName(a.verdict))
      << "</text>\n";
  }
  s << "</svg>";
  return s.str();
}

}  // namespace candela
