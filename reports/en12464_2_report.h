// EN 12464-2 outdoor work places in summary.json (compliance.<name>: task_areas, observers;
// docs/outdoor.md) and in the report: a plan of the areas, luminaires and GR observers, and one
// table of the areas' lines (Ē_m, U0, GR_L, Ra) and one of the observers' glare ratings.
#pragma once

#include "metrics/en12464_2.h"
#include "reports/compliance_report.h"
#include "reports/report_data.h"

namespace candela {

class En12464_2Section final : public StandardSection {
 public:
  explicit En12464_2Section(En12464_2Result result) : result_(std::move(result)) {}
  std::string title() const override { return "EN 12464-2:2014 outdoor work places"; }
  void addJson(nlohmann::json& entry) const override;
  std::string html() const override;
  const En12464_2Result& result() const { return result_; }

 private:
  En12464_2Result result_;
};

// The plan alone, `<svg ...>...</svg>`: the task areas (coloured by verdict, labelled), the
// luminaires, and each GR observer with its worst line of sight.
std::string en12464_2PlanSvg(const En12464_2Result& r);

}  // namespace candela
