#include "validation/case_registry.h"

#include <chrono>
#include <cmath>

namespace candela::validation {

std::vector<Case> engineCases();
std::vector<Case> daylightCases();
std::vector<Case> luminaireCases();
std::vector<Case> stabilityCases();
std::vector<Case> indirectCases();
std::vector<Case> annualCases();

double CaseResult::maxRelativeError() const {
  double m = 0.0;
  for (const PointResult& p : points) m = std::max(m, std::abs(p.relativeError()));
  return m;
}

double CaseResult::rmsRelativeError() const {
  if (points.empty()) return 0.0;
  double s = 0.0;
  for (const PointResult& p : points) s += p.relativeError() * p.relativeError();
  return std::sqrt(s / points.size());
}

std::vector<Case> allCases() {
  std::vector<Case> all = engineCases();
  for (Case& c : luminaireCases()) all.push_back(std::move(c));
  for (Case& c : daylightCases()) all.push_back(std::move(c));
  for (Case& c : annualCases()) all.push_back(std::move(c));
  for (Case& c : stabilityCases()) all.push_back(std::move(c));
  for (Case& c : indirectCases()) all.push_back(std::move(c));
  return all;
}

std::vector<CaseResult> runCases(bool quickOnly, const RunConfig& config) {
  std::vector<CaseResult> out;
  for (const Case& c : allCases()) {
    if (quickOnly && !c.quick) continue;
    // Cases time the engine themselves (building the scene and computing references excluded).
    CaseResult r = c.run(config);
    r.name = c.name;
    r.group = c.group;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace candela::validation
