// EN 13201 road lighting in summary.json (compliance.<name>.roads[i]; docs/road.md) and in the
// report: a plan of each road (its field, lanes, grid points, observers and the luminaires) and
// its figures against its EN 13201-2 class.
#pragma once

#include "metrics/en13201.h"
#include "reports/compliance_report.h"

#include <string>
#include <vector>

namespace candela {

struct En13201Report {
  std::vector<RoadResult> roads;
  struct Luminaire {
    std::string name;
    Vec3 positionM{0.0};
  };
  std::vector<Luminaire> luminaires;
};

class En13201Section final : public StandardSection {
 public:
  explicit En13201Section(En13201Report report) : report_(std::move(report)) {}
  std::string title() const override { return "EN 13201 road lighting"; }
  void addJson(nlohmann::json& entry) const override;
  // summary.json's `roads` (issue 39's name): the same road objects as compliance.<name>.roads,
  // appended when several entries hold roads.
  void addTopLevelJson(nlohmann::json& summary) const override;
  std::string html() const override;
  const En13201Report& report() const { return report_; }

 private:
  En13201Report report_;
};

// The plan of one road alone, `<svg ...>...</svg>`: the field of calculation and its lanes, the
// illuminance points shaded by their value, the luminance points, the observers (60 m before the
// field: drawn at the plan's edge with their distance when the plan would be too long) and the
// luminaires near the field.
std::string en13201PlanSvg(const RoadResult& road, const std::vector<En13201Report::Luminaire>& luminaires);

}  // namespace candela
