#include "metrics/grid_stats.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace candela {

double averageIlluminance(const std::vector<double>& lux) {
  if (lux.empty()) return 0.0;
  double sum = 0.0;
  for (double e : lux) sum += e;
  return sum / static_cast<double>(lux.size());
}

double weightedAverageIlluminance(const std::vector<double>& lux, const std::vector<double>& weights) {
  if (weights.size() != lux.size())
    throw std::invalid_argument("weightedAverageIlluminance: " + std::to_string(lux.size()) +
                                " values but " + std::to_string(weights.size()) + " weights");
  double sum = 0.0, total = 0.0;
  for (std::size_t i = 0; i < lux.size(); ++i) {
    sum += weights[i] * lux[i];
    total += weights[i];
  }
  if (!(total > 0.0)) throw std::invalid_argument("weightedAverageIlluminance: total weight must be positive");
  return sum / total;
}

double minimumIlluminance(const std::vector<double>& lux) {
  return lux.empty() ? 0.0 : *std::min_element(lux.begin(), lux.end());
}

double maximumIlluminance(const std::vector<double>& lux) {
  return lux.empty() ? 0.0 : *std::max_element(lux.begin(), lux.end());
}

GridStats computeGridStats(const std::vector<double>& lux, const std::vector<double>& weights) {
  GridStats s;
  s.count = lux.size();
  if (lux.empty()) return s;
  s.averageLux = weights.empty() ? averageIlluminance(lux) : weightedAverageIlluminance(lux, weights);
  s.minimumLux = minimumIlluminance(lux);
  s.maximumLux = maximumIlluminance(lux);
  std::vector<double> sorted(lux);
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  s.medianLux = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  s.u0 = s.averageLux > 0.0 ? s.minimumLux / s.averageLux : 0.0;
  s.ud = s.maximumLux > 0.0 ? s.minimumLux / s.maximumLux : 0.0;
  return s;
}

}  // namespace candela
