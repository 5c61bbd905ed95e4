#include "reports/en1838_report.h"

#include "base/atomic_file.h"
#include "reports/csv_writer.h"
#include "reports/plan_svg.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace candela {

namespace {

using nlohmann::json;

// JSON has no infinity: a ratio over a minimum of 0 is null.
json number(double v) { return std::isfinite(v) ? json(v) : json(); }

json position(const Vec3& p) { return json::array({p.x, p.y, p.z}); }

json stats(const En1838Stats& s) {
  return {{"points", s.points}, {"min_lux", s.minLux}, {"max_lux", s.maxLux}, {"average_lux", s.averageLux}};
}

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "∞";
  return formatFixed(v, decimals);
}

std::string verdictCell(Verdict v) {
  const bool ok = v == Verdict::kPass;
  return std::string("<td class=\"") + (ok ? "ok" : "no") + "\">" + verdictName(v) + "</td>";
}

}  // namespace

void En1838Section::addJson(json& j) const {
  const En1838Result& r = result_;
  j["emergency_luminaires"] = r.emergencyLuminaires;
  j["maintenance_factor"] = r.maintenanceFactor;
  j["light"] = "direct";  // EN 1838 disregards reflected light
  j["leave_out"] = r.leftOut;
  json routes = json::array();
  for (const EscapeRouteResult& e : r.routes) {
    json strips = json::array();
    for (const RouteStripResult& s : e.strips)
      strips.push_back({{"offset_m", s.offsetM},
                        {"width_m", s.widthM},
                        {"centre_line", stats(s.centreLine)},
                        {"central_band", stats(s.band)},
                        {"uniformity_ratio", number(s.centreLine.maxToMin())}});
    routes.push_back({{"name", e.name},
                      {"width_m", e.widthM},
                      {"height_m", e.heightM},
                      {"min_centre_line_lux", e.minCentreLineLux},
                      {"max_centre_line_lux", e.maxCentreLineLux},
                      {"uniformity_ratio", number(e.uniformityRatio)},
                      {"central_band_min_lux", e.centralBandMinLux},
                      {"min_centre_line_position", position(e.minCentreLineAtM)},
                      {"strips", strips},
                      {"verdict", verdictName(e.verdict)}});
  }
  j["escape_routes"] = routes;
  json areas = json::array();
  for (const OpenAreaResult& a : r.openAreas)
    areas.push_back({{"name", a.name},
                     {"height_m", a.heightM},
                     {"points", a.stats.points},
                     {"min_lux", a.stats.minLux},
                     {"min_position", position(a.minAtM)},
                     {"max_lux", a.stats.maxLux},
                     {"average_lux", a.stats.averageLux},
                     {"uniformity_ratio", number(a.uniformityRatio)},
                     {"verdict", verdictName(a.verdict)}});
  j["open_areas"] = areas;
  json risky = json::array();
  for (const HighRiskAreaResult& a : r.highRiskAreas)
    risky.push_back({{"name", a.name},
                     {"height_m", a.heightM},
                     {"points", a.stats.points},
                     {"maintained_illuminance_lux", a.maintainedLux},
                     {"required_lux", a.requiredLux},
                     {"min_lux", a.stats.minLux},
                     {"min_position", position(a.minAtM)},
                     {"max_lux", a.stats.maxLux},
                     {"average_lux", a.stats.averageLux},
                     {"uniformity", a.uniformity},
                     {"verdict", verdictName(a.verdict)}});
  j["high_risk_areas"] = risky;
  json points = json::array();
  for (const SafetyPointResult& p : r.safetyPoints)
    points.push_back({{"name", p.name},
                      {"position", {p.positionM.x, p.positionM.y, p.positionM.z}},
                      {"facing", {p.facing.x, p.facing.y}},
                      {"vertical_lux", p.verticalLux},
                      {"required_lux", kEn1838SafetyPointLux},
                      {"nearest_emergency_luminaire_m",
                       std::isfinite(p.nearestLuminaireM) ? json(p.nearestLuminaireM) : json(nullptr)},
                      {"near_m", kEn1838NearM},
                      {"verdict", verdictName(p.verdict)}});
  j["safety_points"] = points;
}

std::string En1838Section::html() const {
  const En1838Result& r = result_;
  std::ostringstream h;
  h << "<p>Emergency mode: " << r.emergencyLuminaires
    << " emergency luminaire(s) at their emergency flux, maintenance factor " << formatFixed(r.maintenanceFactor, 2)
    << ", direct light only (EN 1838 disregards reflected light; docs/emergency.md).";
  if (!r.leftOut.empty()) {
    h << " Left out of the scene (the empty floor): ";
    for (std::size_t k = 0; k < r.leftOut.size(); ++k) h << (k ? ", " : "") << "<code>" << xmlEscape(r.leftOut[k]) << "</code>";
    h << ".";
  }
  h << "</p>\n";
  h << en1838PlanSvg(r, section_ ? &*section_ : nullptr) << "\n";
  h << "<p class=\"legend\">Plan: filled circles emergency luminaires, open circles the others; routes with their "
       "width and dashed centre line; open areas with their dashed core (0.5 m inside); squares safety points with "
       "their facing; a cross marks each minimum; green passes, red fails. Walls cut 1 m above the floor.</p>\n";
  if (!r.routes.empty()) {
    h << "<h3>Escape routes (4.2: centre line ≥ 1 lx, central band ≥ 0.5 lx, max/min ≤ 40)</h3>\n"
         "<table class=\"compliance\"><tr><th>route</th><th>width m</th><th>strips</th><th>E<sub>min</sub> centre "
         "line lx</th><th>E<sub>max</sub> centre line lx</th><th>max/min</th><th>E<sub>min</sub> central band "
         "lx</th><th>verdict</th></tr>\n";
    for (const EscapeRouteResult& e : r.routes)
      h << "<tr><td>" << xmlEscape(e.name) << "</td><td class=\"num\">" << fixed(e.widthM, 2)
        << "</td><td class=\"num\">" << e.strips.size() << "</td><td class=\"num\">" << fixed(e.minCentreLineLux, 2)
        << "</td><td class=\"num\">" << fixed(e.maxCentreLineLux, 2) << "</td><td class=\"num\">"
        << fixed(e.uniformityRatio, 1) << "</td><td class=\"num\">" << fixed(e.centralBandMinLux, 2) << "</td>"
        << verdictCell(e.verdict) << "</tr>\n";
    h << "</table>\n";
  }
  if (!r.openAreas.empty()) {
    h << "<h3>Anti-panic open areas (4.3: core area ≥ 0.5 lx, max/min ≤ 40)</h3>\n"
         "<table class=\"compliance\"><tr><th>area</th><th>points</th><th>E<sub>min</sub> lx</th><th>at m</th>"
         "<th>E<sub>max</sub> lx</th><th>max/min</th><th>verdict</th></tr>\n";
    for (const OpenAreaResult& a : r.openAreas)
      h << "<tr><td>" << xmlEscape(a.name) << "</td><td class=\"num\">" << a.stats.points << "</td><td class=\"num\">"
        << fixed(a.stats.minLux, 2) << "</td><td class=\"pos\">(" << fixed(a.minAtM.x, 2) << ", " << fixed(a.minAtM.y, 2)
        << ")</td><td class=\"num\">" << fixed(a.stats.maxLux, 2) << "</td><td class=\"num\">"
        << fixed(a.uniformityRatio, 1) << "</td>" << verdictCell(a.verdict) << "</tr>\n";
    h << "</table>\n";
  }
  if (!r.highRiskAreas.empty()) {
    h << "<h3>High-risk task areas (4.4: ≥ 10 % of Ē<sub>m</sub> and ≥ 15 lx, min/max ≥ 0.1)</h3>\n"
         "<table class=\"compliance\"><tr><th>area</th><th>Ē<sub>m</sub> lx</th><th>required lx</th><th>E<sub>min</sub> "
         "lx</th><th>E<sub>max</sub> lx</th><th>min/max</th><th>verdict</th></tr>\n";
    for (const HighRiskAreaResult& a : r.highRiskAreas)
      h << "<tr><td>" << xmlEscape(a.name) << "</td><td class=\"num\">" << fixed(a.maintainedLux, 0)
        << "</td><td class=\"num\">" << fixed(a.requiredLux, 1) << "</td><td class=\"num\">" << fixed(a.stats.minLux, 2)
        << "</td><td class=\"num\">" << fixed(a.stats.maxLux, 2) << "</td><td class=\"num\">"
        << fixed(a.uniformity, 3) << "</td>" << verdictCell(a.verdict) << "</tr>\n";
    h << "</table>\n";
  }
  if (!r.safetyPoints.empty()) {
    h << "<h3>Safety equipment and first aid (4.1: 5 lx vertical at the equipment, an emergency luminaire "
         "within 2 m horizontally)</h3>\n"
         "<table class=\"compliance\"><tr><th>point</th><th>position m</th><th>facing</th><th>E<sub>v</sub> "
         "lx</th><th>nearest emergency luminaire m</th><th>verdict</th></tr>\n";
    for (const SafetyPointResult& p : r.safetyPoints)
      h << "<tr><td>" << xmlEscape(p.name) << "</td><td class=\"pos\">(" << fixed(p.positionM.x, 2) << ", "
        << fixed(p.positionM.y, 2) << ", " << fixed(p.positionM.z, 2) << ")</td><td class=\"pos\">("
        << fixed(p.facing.x, 2) << ", " << fixed(p.facing.y, 2) << ")</td><td class=\"num\">"
        << fixed(p.verticalLux, 2) << "</td><td class=\"num\">"
        << (std::isfinite(p.nearestLuminaireM) ? fixed(p.nearestLuminaireM, 2) : std::string("none")) << "</td>"
        << verdictCell(p.verdict) << "</tr>\n";
    h << "</table>\n";
  }
  return h.str();
}

std::string en1838PlanSvg(const En1838Result& r, const PlanSection* section) {
  // The plan's extent: everything it draws, with a margin.
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto grow = [&](const Vec2& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); };
  for (const auto& e : r.routes)
    for (const Vec2& p : e.path) grow(p - Vec2(0.5 * e.widthM)), grow(p + Vec2(0.5 * e.widthM));
  for (const auto& a : r.openAreas)
    for (const Vec2& p : a.outline) grow(p);
  for (const auto& a : r.highRiskAreas)
    for (const Vec2& p : a.outline) grow(p);
  for (const auto& p : r.safetyPoints) grow(Vec2(p.positionM));
  for (const auto& l : r.luminaires) grow(l.positionM);
  if (section)
    for (const PlanSegment& s : section->walls) grow(s.a), grow(s.b);
  if (!(hi.x >= lo.x)) return "";
  lo -= Vec2(0.5), hi += Vec2(0.5);
  const double widthPx = 760.0, scale = widthPx / std::max(hi.x - lo.x, 1e-6);
  const double heightPx = (hi.y - lo.y) * scale;
  // Plan y up: SVG y down.
  auto X = [&](double x) { return svgNumber((x - lo.x) * scale); };
  auto Y = [&](double y) { return svgNumber((hi.y - y) * scale); };
  auto pts = [&](const std::vector<Vec2>& v) {
    std::string s;
    for (const Vec2& p : v) s += X(p.x) + "," + Y(p.y) + " ";
    return s;
  };
  auto colour = [](Verdict v) { return v == Verdict::kPass ? "#1e7b34" : "#b3261e"; };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"en1838-plan\" width=\"" << svgNumber(widthPx)
    << "\" height=\"" << svgNumber(heightPx) << "\" viewBox=\"0 0 " << svgNumber(widthPx) << " "
    << svgNumber(heightPx) << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  if (section) {
    for (const PlanFootprint& f : section->furniture)
      s << "<polygon points=\"" << pts(f.outline) << "\" fill=\"#eee\" stroke=\"" << (f.outlined ? "#bbb" : "none")
        << "\" stroke-width=\"0.5\"/>\n";
    for (const PlanSegment& w : section->walls)
      s << "<line x1=\"" << X(w.a.x) << "\" y1=\"" << Y(w.a.y) << "\" x2=\"" << X(w.b.x) << "\" y2=\"" << Y(w.b.y)
        << "\" stroke=\"#333\" stroke-width=\"2\"/>\n";
    for (const PlanSegment& w : section->openings)
      s << "<line x1=\"" << X(w.a.x) << "\" y1=\"" << Y(w.a.y) << "\" x2=\"" << X(w.b.x) << "\" y2=\"" << Y(w.b.y)
        << "\" stroke=\"#4a90c2\" stroke-width=\"2\"/>\n";
  }
  for (const OpenAreaResult& a : r.openAreas) {
    s << "<polygon points=\"" << pts(a.outline) << "\" fill=\"" << colour(a.verdict)
      << "\" fill-opacity=\"0.08\" stroke=\"" << colour(a.verdict) << "\" stroke-width=\"1\"/>\n";
    s << "<polygon points=\"" << pts(a.core) << "\" fill=\"none\" stroke=\"" << colour(a.verdict)
      << "\" stroke-width=\"1\" stroke-dasharray=\"4 3\"/>\n";
  }
  for (const HighRiskAreaResult& a : r.highRiskAreas)
    s << "<polygon points=\"" << pts(a.outline) << "\" fill=\"" << colour(a.verdict)
      << "\" fill-opacity=\"0.15\" stroke=\"" << colour(a.verdict) << "\" stroke-width=\"1.5\"/>\n";
  for (const EscapeRouteResult& e : r.routes) {
    // The route's width as a wide translucent stroke, its centre line on top.
    s << "<polyline points=\"" << pts(e.path) << "\" fill=\"none\" stroke=\"" << colour(e.verdict)
      << "\" stroke-opacity=\"0.18\" stroke-linejoin=\"miter\" stroke-width=\"" << svgNumber(e.widthM * scale)
      << "\"/>\n<polyline points=\"" << pts(e.path) << "\" fill=\"none\" stroke=\"" << colour(e.verdict)
      << "\" stroke-width=\"1.5\" stroke-dasharray=\"8 4\"/>\n";
  }
  for (const En1838Luminaire& l : r.luminaires)
    s << "<circle cx=\"" << X(l.positionM.x) << "\" cy=\"" << Y(l.positionM.y) << "\" r=\""
      << (l.emergency ? "6" : "3") << "\" fill=\"" << (l.emergency ? "#f2a900" : "none") << "\" stroke=\""
      << (l.emergency ? "#7a5500" : "#999") << "\" stroke-width=\"1\"><title>" << xmlEscape(l.name)
      << (l.emergency ? " (emergency)" : "") << "</title></circle>\n";
  for (const SafetyPointResult& p : r.safetyPoints) {
    const double x = p.positionM.x, y = p.positionM.y;
    s << "<rect x=\"" << svgNumber((x - lo.x) * scale - 5) << "\" y=\"" << svgNumber((hi.y - y) * scale - 5)
      << "\" width=\"10\" height=\"10\" fill=\"" << colour(p.verdict) << "\"/>\n"
      << "<line x1=\"" << X(x) << "\" y1=\"" << Y(y) << "\" x2=\"" << X(x + 0.6 * p.facing.x) << "\" y2=\""
      << Y(y + 0.6 * p.facing.y) << "\" stroke=\"" << colour(p.verdict) << "\" stroke-width=\"2\"/>\n";
  }
  // Each area's and route's minimum: a small cross.
  auto cross = [&](const Vec3& p, Verdict v) {
    s << "<path d=\"M" << svgNumber((p.x - lo.x) * scale - 4) << "," << svgNumber((hi.y - p.y) * scale - 4) << "l8,8m0,-8l-8,8\" stroke=\""
      << colour(v) << "\" stroke-width=\"2\"><title>minimum</title></path>\n";
  };
  for (const EscapeRouteResult& e : r.routes) cross(e.minCentreLineAtM, e.verdict);
  for (const OpenAreaResult& a : r.openAreas) cross(a.minAtM, a.verdict);
  for (const HighRiskAreaResult& a : r.highRiskAreas) cross(a.minAtM, a.verdict);
  // Labels last, over everything.
  // Right of the plan's middle a label ends at its point, so that it stays inside the plan.
  const double middleX = 0.5 * (lo.x + hi.x);
  auto label = [&](const Vec2& at, const std::string& text, Verdict v) {
    s << "<text x=\"" << X(at.x) << "\" y=\"" << Y(at.y) << "\"" << (at.x > middleX ? " text-anchor=\"end\"" : "")
      << " fill=\"" << colour(v)
      << "\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\" font-weight=\"700\">" << xmlEscape(text) << " "
      << verdictName(v) << "</text>\n";
  };
  for (const EscapeRouteResult& e : r.routes) label(e.path.front() + Vec2(0.1, 0.1), e.name, e.verdict);
  for (const OpenAreaResult& a : r.openAreas) label(a.core.empty() ? a.outline.front() : a.core.back(), a.name, a.verdict);
  for (const HighRiskAreaResult& a : r.highRiskAreas) label(a.outline.back(), a.name, a.verdict);
  for (const SafetyPointResult& p : r.safetyPoints)
    label(Vec2(p.positionM) + Vec2(p.positionM.x > middleX ? -0.2 : 0.2, -0.3), p.name, p.verdict);
  s << "</svg>";
  return s.str();
}

std::string en1838PointsCsv(const En1838Result& r) {
  std::string out = "part,name,x,y,z,dx,dy,dz,illuminance_lux\n";
  char row[200];
  for (const En1838PointValue& p : r.points) {
    std::snprintf(row, sizeof row, ",%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", p.positionM.x, p.positionM.y, p.positionM.z,
                  p.normal.x, p.normal.y, p.normal.z, p.lux);
    out += csvField(p.part) + "," + csvField(p.name) + row;
  }
  return out;
}

void En1838Section::writeFiles(const std::filesystem::path& dir) const {
  writeFileAtomic(dir / "en1838_points.csv", en1838PointsCsv(result_));
}

}  // namespace candela
