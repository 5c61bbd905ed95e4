// Statistics of a sensor grid's illuminances, as a designer reads them off an EN 12464-1 report.
#pragma once

#include <cstddef>
#include <vector>

namespace candela {

// Summary of the illuminances of one grid. All illuminances in lux.
struct GridStats {
  std::size_t count = 0;    // number of points
  double averageLux = 0.0;  // Eavg (area-weighted when weights are given)
  double minimumLux = 0.0;  // Emin
  double maximumLux = 0.0;  // Emax
  double medianLux = 0.0;   // median (mean of the two middle values for an even count)
  double u0 = 0.0;          // overall uniformity Emin/Eavg (EN 12464-1:2021, 3.1.x "U0"); 0 if Eavg = 0
  double ud = 0.0;          // diversity Emin/Emax; 0 if Emax = 0
};

// Arithmetic mean of the illuminances in lux; 0 for an empty grid.
double averageIlluminance(const std::vector<double>& lux);

// Weighted mean sum(w·E)/sum(w); `weights` are the areas (m²) the points stand for and must have
// the same length as `lux`. Throws std::invalid_argument on a length mismatch or a non-positive
// total weight.
double weightedAverageIlluminance(const std::vector<double>& lux, const std::vector<double>& weights);

// Minimum / maximum in lux; 0 for an empty grid.
double minimumIlluminance(const std::vector<double>& lux);
double maximumIlluminance(const std::vector<double>& lux);

// All statistics at once. With `weights` empty the average is the plain mean (the usual case:
// EN 12464-1 grids have equal cells); otherwise it is area-weighted.
GridStats computeGridStats(const std::vector<double>& lux, const std::vector<double>& weights = {});

}  // namespace candela
