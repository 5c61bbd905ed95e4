#include "metrics/modelling.h"

#include "metrics/grid_stats.h"

#include <stdexcept>
#include <string>

namespace candela {

ModellingResult modellingRatio(const std::vector<double>& cylindricalLux, const std::vector<double>& horizontalLux) {
  if (cylindricalLux.size() != horizontalLux.size())
    throw std::invalid_argument("modellingRatio: " + std::to_string(cylindricalLux.size()) +
                                " cylindrical values but " + std::to_string(horizontalLux.size()) + " horizontal");
  ModellingResult m;
  m.cylindricalAverageLux = averageIlluminance(cylindricalLux);
  m.horizontalAverageLux = averageIlluminance(horizontalLux);
  m.ratio = pointModellingRatio(m.cylindricalAverageLux, m.horizontalAverageLux);
  const bool within = m.horizontalAverageLux > 0.0 && m.ratio >= kModellingRatioMin && m.ratio <= kModellingRatioMax;
  m.verdict = within ? Verdict::kPass : Verdict::kFail;
  return m;
}

}  // namespace candela
