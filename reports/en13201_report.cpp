#include "reports/en13201_report.h"

#include "reports/plan_svg.h"
#include "reports/report_data.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace candela {

namespace {

using nlohmann::json;

// JSON has no infinity.
json number(double v) { return std::isfinite(v) ? json(v) : json(); }

std::string fixed(double v, int decimals) { return std::isfinite(v) ? formatFixed(v, decimals) : "∞"; }

std::string verdictCell(Verdict v) {
  return std::string("<td class=\"") + (v == Verdict::kPass ? "ok" : "no") + "\">" + verdictName(v) + "</td>";
}

// The report's words and decimals for a criterion.
struct CriterionText {
  const char* key;
  const char* label;
  int decimals;
};
constexpr CriterionText kCriteria[] = {
    {"average_luminance_cd_m2", "average luminance L̄, cd/m²", 2},
    {"overall_uniformity", "overall uniformity U<sub>0</sub> = L<sub>min</sub>/L̄", 2},
    {"longitudinal_uniformity", "longitudinal uniformity U<sub>l</sub> (least over lanes)", 2},
    {"threshold_increment_percent", "threshold increment f<sub>TI</sub>, %", 1},
    {"edge_illuminance_ratio", "edge illuminance ratio R<sub>EI</sub>", 2},
    {"average_illuminance_lux", "average illuminance Ē, lx", 2},
    {"illuminance_uniformity", "uniformity E<sub>min</sub>/Ē", 2},
    {"minimum_illuminance_lux", "minimum illuminance E<sub>min</sub>, lx", 2},
    {"average_illuminance_ceiling_lux", "Ē at most 1.5 × the class's, lx", 2},
    {"average_hemispherical_illuminance_lux", "average hemispherical illuminance Ē<sub>hs</sub>, lx", 2},
    {"hemispherical_uniformity", "uniformity E<sub>hs,min</sub>/Ē<sub>hs</sub>", 2},
    {"minimum_semi_cylindrical_illuminance_lux", "minimum semi-cylindrical illuminance E<sub>sc,min</sub> (1.5 m, both ways along), lx", 2},
    {"minimum_vertical_illuminance_lux", "minimum vertical illuminance E<sub>v,min</sub> (1.5 m, both ways along), lx", 2},
};
const CriterionText& textOf(const std::string& key) {
  for (const CriterionText& t : kCriteria)
    if (key == t.key) return t;
  return kCriteria[0];
}

// "P3 + SC5 + EV4": the class and its additional classes.
std::string classNames(const RoadResult& r) {
  std::string s = r.roadClass.name();
  for (const AdditionalRoadClass& a : r.additional) s += " + " + a.name();
  return s;
}

json roadJson(const RoadResult& r) {
  json j = {{"name", r.name},
            {"class", r.roadClass.name()},
            {"points", r.illuminancePoints.size()},
            {"length_m", r.lengthM},
            {"width_m", r.widthM},
            {"lanes", r.lanes},
            {"average_illuminance_lux", r.averageLux},
            {"minimum_illuminance_lux", r.minLux},
            {"maximum_illuminance_lux", r.maxLux},
            {"illuminance_uniformity", r.illuminanceUniformity}};
  if (r.roadClass.family == RoadClassFamily::kHS) {
    j["average_hemispherical_illuminance_lux"] = r.averageHemisphericalLux;
    j["minimum_hemispherical_illuminance_lux"] = r.minHemisphericalLux;
    j["hemispherical_uniformity"] = r.hemisphericalUniformity;
  }
  if (!r.additional.empty()) {
    json names = json::array();
    for (const AdditionalRoadClass& a : r.additional) {
      names.push_back(a.name());
      if (a.kind == AdditionalClassKind::kSC) j["minimum_semi_cylindrical_illuminance_lux"] = r.minSemiCylindricalLux;
      else j["minimum_vertical_illuminance_lux"] = r.minVerticalLux;
    }
    j["additional_classes"] = names;
  }
  if (r.roadClass.family == RoadClassFamily::kM) {
    j["surface"] = r.surface;
    j["q0"] = r.q0;
    j["luminance_points"] = r.luminancePoints.size();
    j["average_luminance_cd_m2"] = r.averageLuminanceCdM2;
    j["overall_uniformity"] = r.overallUniformity;
    j["longitudinal_uniformity"] = r.longitudinalUniformity;
    j["threshold_increment_percent"] = number(r.thresholdIncrementPct);
    j["edge_illuminance_ratio"] = r.edgeIlluminanceRatio;
    j["edge_strip_width_m"] = r.stripWidthM;
    json observers = json::array();
    for (const RoadObserverResult& o : r.observers)
      observers.push_back({{"eye", {o.eyeM.x, o.eyeM.y, o.eyeM.z}},
                           {"average_luminance_cd_m2", o.averageLuminanceCdM2},
                           {"minimum_luminance_cd_m2", o.minLuminanceCdM2},
                           {"overall_uniformity", o.overallUniformity},
                           {"longitudinal_uniformity", o.longitudinalUniformity},
                           {"initial_average_luminance_cd_m2", o.initialAverageLuminanceCdM2},
                           {"veiling_luminance_cd_m2", o.veilingLuminanceCdM2},
                           {"threshold_increment_percent", number(o.thresholdIncrementPct)}});
    j["observers"] = observers;
  }
  json criteria = json::array();
  for (const RoadCriterion& c : r.criteria)
    criteria.push_back({{"name", c.name},
                        {"value", number(c.value)},
                        {"required", c.required},
                        {"limit", c.atLeast ? "minimum" : "maximum"},
                        {"verdict", verdictName(c.verdict)}});
  j["criteria"] = criteria;
  j["verdict"] = verdictName(r.verdict);
  return j;
}

}  // namespace

void En13201Section::addJson(json& entry) const {
  json roads = json::array();
  for (const RoadResult& r : report_.roads) roads.push_back(roadJson(r));
  entry["roads"] = roads;
  entry["light"] = "direct";
}

void En13201Section::addTopLevelJson(json& summary) const {
  json& roads = summary["roads"];
  if (!roads.is_array()) roads = json::array();
  for (const RoadResult& r : report_.roads) roads.push_back(roadJson(r));
}

std::string En13201Section::html() const {
  std::ostringstream h;
  h << "<p>Each road's field of calculation with the EN 13201-3 grids and observers; direct light of every "
       "luminaire of the case, the scene's geometry as shadows; luminance from the surface's r-table; maintained "
       "values (each luminaire's maintenance factor), the threshold increment from initial values (docs/road.md).</p>\n";
  for (const RoadResult& r : report_.roads) {
    h << "<h3>" << xmlEscape(r.name) << ": class " << classNames(r) << ", " << fixed(r.lengthM, 1) << " m × "
      << fixed(r.widthM, 2) << " m, " << r.lanes << (r.lanes == 1 ? " lane" : " lanes");
    if (r.roadClass.family == RoadClassFamily::kM) h << ", surface " << xmlEscape(r.surface) << " (q0 " << fixed(r.q0, 3) << ")";
    h << "</h3>\n" << en13201PlanSvg(r, report_.luminaires) << "\n";
    h << "<p class=\"legend\">Plan: the field of calculation (grey) and its lanes (dashed white); squares the "
         "illuminance points shaded from black (0 lx) to yellow (the maximum), dots the luminance points, circles the "
         "luminaires, triangles the observers (60 m before the field); for M classes the edge strips of R<sub>EI</sub> "
         "dashed, inside and outside each edge.</p>\n";
    h << "<table class=\"compliance\"><tr><th>criterion (EN 13201-2, class " << classNames(r)
      << ")</th><th>computed</th><th>required</th><th>verdict</th></tr>\n";
    for (const RoadCriterion& c : r.criteria) {
      const CriterionText& t = textOf(c.name);
      h << "<tr><td>" << t.label << "</td><td class=\"num\">" << fixed(c.value, t.decimals) << "</td><td class=\"num\">"
        << (c.atLeast ? "≥ " : "≤ ") << fixed(c.required, t.decimals) << "</td>" << verdictCell(c.verdict) << "</tr>\n";
    }
    h << "</table>\n";
    h << "<p>Illuminance on the road: Ē " << fixed(r.averageLux, 2) << " lx, E<sub>min</sub> " << fixed(r.minLux, 2)
      << " lx, E<sub>max</sub> " << fixed(r.maxLux, 2) << " lx over " << r.illuminancePoints.size() << " points.";
    if (r.roadClass.family == RoadClassFamily::kHS)
      h << " Hemispherical: Ē<sub>hs</sub> " << fixed(r.averageHemisphericalLux, 2) << " lx, E<sub>hs,min</sub> "
        << fixed(r.minHemisphericalLux, 2) << " lx.";
    if (!r.additional.empty())
      h << " At the same points 1.5 m up, the lesser of the two directions along the road: E<sub>sc,min</sub> "
        << fixed(r.minSemiCylindricalLux, 2) << " lx, E<sub>v,min</sub> " << fixed(r.minVerticalLux, 2) << " lx.";
    if (r.roadClass.family == RoadClassFamily::kM)
      h << " Edge strips " << fixed(r.stripWidthM, 2) << " m wide: R<sub>EI</sub> near side "
        << fixed(r.edgeRatioNearSide, 2) << ", far side " << fixed(r.edgeRatioFarSide, 2) << ".";
    h << "</p>\n";
    if (!r.observers.empty()) {
      h << "<table class=\"compliance\"><tr><th>observer (lane)</th><th>eye m</th><th>L̄ cd/m²</th><th>U<sub>0</sub>"
           "</th><th>U<sub>l</sub></th><th>L<sub>v</sub> cd/m²</th><th>f<sub>TI</sub> %</th></tr>\n";
      for (std::size_t k = 0; k < r.observers.size(); ++k) {
        const RoadObserverResult& o = r.observers[k];
        h << "<tr><td>" << k + 1 << "</td><td class=\"pos\">(" << fixed(o.eyeM.x, 1) << ", " << fixed(o.eyeM.y, 2)
          << ", " << fixed(o.eyeM.z, 1) << ")</td><td class=\"num\">" << fixed(o.averageLuminanceCdM2, 3)
          << "</td><td class=\"num\">" << fixed(o.overallUniformity, 2) << "</td><td class=\"num\">"
          << fixed(o.longitudinalUniformity, 2) << "</td><td class=\"num\">" << fixed(o.veilingLuminanceCdM2, 4)
          << "</td><td class=\"num\">" << fixed(o.thresholdIncrementPct, 1) << "</td></tr>\n";
      }
      h << "</table>\n";
    }
  }
  return h.str();
}

std::string en13201PlanSvg(const RoadResult& r, const std::vector<En13201Report::Luminaire>& luminaires) {
  // Road coordinates (u along, v across) drawn left to right; the plan shows the field with a margin
  // of one field length before and after it, and the observers at its left edge.
  auto toRoad = [&](const Vec2& p) { return Vec2(glm::dot(p - r.start, r.along), glm::dot(p - r.start, r.across)); };
  const double margin = std::max(0.5 * r.lengthM, 5.0);
  const double u0 = -margin, u1 = r.lengthM + margin;
  const double v0 = -std::max(r.stripWidthM, 2.0) - 1.0, v1 = r.widthM + std::max(r.stripWidthM, 2.0) + 1.0;
  const double widthPx = 760.0, scale = widthPx / (u1 - u0), heightPx = (v1 - v0) * scale;
  auto X = [&](double u) { return svgNumber((u - u0) * scale); };
  auto Y = [&](double v) { return svgNumber((v1 - v) * scale); };
  const double maxLux = std::max(r.maxLux, 1e-12);
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"en13201-plan\" width=\"" << svgNumber(widthPx)
    << "\" height=\"" << svgNumber(heightPx) << "\" viewBox=\"0 0 " << svgNumber(widthPx) << " " << svgNumber(heightPx)
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  // The carriageway beyond the field, the field, its lanes.
  s << "<rect x=\"" << X(u0) << "\" y=\"" << Y(r.widthM) << "\" width=\"" << svgNumber(widthPx) << "\" height=\""
    << svgNumber(r.widthM * scale) << "\" fill=\"#e4e4e4\"/>\n";
  s << "<rect x=\"" << X(0.0) << "\" y=\"" << Y(r.widthM) << "\" width=\"" << svgNumber(r.lengthM * scale)
    << "\" height=\"" << svgNumber(r.widthM * scale) << "\" fill=\"#c8c8c8\" stroke=\"#333\" stroke-width=\"1\"/>\n";
  for (int lane = 1; lane < r.lanes; ++lane) {
    const double v = lane * r.widthM / r.lanes;
    s << "<line x1=\"" << X(u0) << "\" y1=\"" << Y(v) << "\" x2=\"" << X(u1) << "\" y2=\"" << Y(v)
      << "\" stroke=\"#fff\" stroke-width=\"2\" stroke-dasharray=\"12 8\"/>\n";
  }
  // The edge illuminance ratio's strips beside the field (M classes), dashed: outside and inside each edge.
  if (r.stripWidthM > 0.0)
    for (double v : {-r.stripWidthM, 0.0, r.widthM - r.stripWidthM, r.widthM})
      s << "<rect x=\"" << X(0.0) << "\" y=\"" << Y(v + r.stripWidthM) << "\" width=\"" << svgNumber(r.lengthM * scale)
        << "\" height=\"" << svgNumber(r.stripWidthM * scale)
        << "\" fill=\"none\" stroke=\"#8a6d00\" stroke-width=\"1\" stroke-dasharray=\"3 3\"/>\n";
  // Illuminance points shaded from black (0) to yellow (the maximum).
  for (std::size_t k = 0; k < r.illuminancePoints.size(); ++k) {
    const Vec2 q = toRoad(r.illuminancePoints[k]);
    const int level = static_cast<int>(std::lround(255.0 * std::clamp(r.illuminanceLux[k] / maxLux, 0.0, 1.0)));
    s << "<rect x=\"" << svgNumber((q.x - u0) * scale - 4) << "\" y=\"" << svgNumber((v1 - q.y) * scale - 4)
      << "\" width=\"8\" height=\"8\" fill=\"rgb(" << level << "," << level << "," << level / 4 << ")\"><title>"
      << fixed(r.illuminanceLux[k], 2) << " lx</title></rect>\n";
  }
  for (const Vec2& p : r.luminancePoints) {
    const Vec2 q = toRoad(p);
    s << "<circle cx=\"" << X(q.x) << "\" cy=\"" << Y(q.y) << "\" r=\"1.8\" fill=\"#1f5fa8\"/>\n";
  }
  for (const En13201Report::Luminaire& l : luminaires) {
    const Vec2 q = toRoad(Vec2(l.positionM));
    if (q.x < u0 || q.x > u1 || q.y < v0 || q.y > v1) continue;
    s << "<circle cx=\"" << X(q.x) << "\" cy=\"" << Y(q.y) << "\" r=\"6\" fill=\"#f2a900\" stroke=\"#7a5500\"><title>"
      << xmlEscape(l.name) << " (h " << fixed(l.positionM.z, 1) << " m)</title></circle>\n";
  }
  // Observers: at the plan's left edge, labelled with their distance before the field.
  for (std::size_t k = 0; k < r.observers.size(); ++k) {
    const Vec2 q = toRoad(Vec2(r.observers[k].eyeM));
    const double u = std::max(q.x, u0) + 2.0 / scale;
    s << "<path d=\"M" << X(u) << "," << svgNumber((v1 - q.y) * scale - 6) << "l10,6l-10,6z\" fill=\"#7a1fa8\"/>\n"
      << "<text x=\"" << svgNumber((u - u0) * scale + 14) << "\" y=\"" << svgNumber((v1 - q.y) * scale + 4)
      << "\" fill=\"#7a1fa8\">observer " << k + 1 << " (" << fixed(-q.x, 0) << " m before)</text>\n";
  }
  const char* colour = r.verdict == Verdict::kPass ? "#1e7b34" : "#b3261e";
  s << "<text x=\"" << X(0.0) << "\" y=\"" << svgNumber((v1 - r.widthM) * scale - 6) << "\" fill=\"" << colour
    << "\" font-weight=\"700\">" << xmlEscape(r.name) << " " << classNames(r) << " " << verdictName(r.verdict)
    << "</text>\n</svg>";
  return s.str();
}

}  // namespace candela
