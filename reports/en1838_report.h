// EN 1838 emergency lighting in summary.json (compliance.<name>: escape_routes, open_areas,
// high_risk_areas, safety_points; docs/emergency.md) and in the report: its tables and a plan of
// the routes and areas with the luminaires and the verdicts.
#pragma once

#include "metrics/en1838.h"
#include "reports/compliance_report.h"
#include "reports/report_data.h"

#include <optional>

namespace candela {

class En1838Section final : public StandardSection {
 public:
  // `section`: the scene cut above the floor, drawn under the plan (optional).
  En1838Section(En1838Result result, std::optional<PlanSection> section)
      : result_(std::move(result)), section_(std::move(section)) {}
  std::string title() const override { return "EN 1838:2013 emergency lighting"; }
  void addJson(nlohmann::json& entry) const override;
  std::string html() const override;
  // en1838_points.csv: part,name,x,y,z,dx,dy,dz,illuminance_lux, one row a calculation point.
  void writeFiles(const std::filesystem::path& dir) const override;
  const En1838Result& result() const { return result_; }

 private:
  En1838Result result_;
  std::optional<PlanSection> section_;
};

// The per-point CSV's text (en1838_points.csv).
std::string en1838PointsCsv(const En1838Result& r);

// The plan alone, `<svg ...>...</svg>`: walls, routes (their width, centre line), open areas
// (outline and dashed core), high-risk areas, safety points and luminaires (emergency ones
// filled), each area labelled with its name and verdict.
std::string en1838PlanSvg(const En1838Result& r, const PlanSection* section);

}  // namespace candela
