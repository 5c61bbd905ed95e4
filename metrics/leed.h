// LEED v4.1 EQ credit Daylight, option 1 ("Simulation: Spatial Daylight Autonomy and Annual
// Sunlight Exposure"), BD+C and ID+C: points from the floor-area-weighted average sDA300/50% of
// the regularly occupied spaces, the spaces whose ASE1000,250 exceeds 10 %, and the "each space
// at least 55 %" line. docs/leed.md has the credit language this follows and its sources.
//
// Pure functions: the caller supplies each space's sDA and ASE (IES LM-83-12, metrics/annual.h,
// with the blinds of study/annual_study.cpp) and its floor area.
#pragma once

#include <string>
#include <vector>

namespace candela {

// Table 1 of the credit has two columns.
enum class LeedProjectType {
  kGeneral,     // New Construction, Core and Shell, Schools, Retail, Data Centers, Warehouses and
                // Distribution Centers, Hospitality; and ID+C (Commercial Interiors, Retail, Hospitality)
  kHealthcare,  // the spaces are those in the perimeter area of EQ credit Quality Views (the caller's)
};

// One regularly occupied space.
struct LeedSpace {
  std::string name;
  double floorAreaM2 = 0.0;  // > 0; for a plane grid, sensors × the lattice's cell area (docs/leed.md)
  double sdaPercent = 0.0;   // sDA300/50%, % of the space's sensors (0..100)
  double asePercent = 0.0;   // ASE1000,250, % of the space's sensors (0..100)
};

struct LeedSpaceResult {
  std::string name;
  double floorAreaM2 = 0.0, sdaPercent = 0.0, asePercent = 0.0;
  // ASE1000,250 > 10 %: not a failure, but the project must "identify how the space is designed
  // to address glare" (credit language, option 1).
  bool aseAbove10 = false;
  bool sdaAtLeast55 = false;  // this space's share of the "each space at least 55 %" line
};

struct LeedOption1Result {
  double averageSdaPercent = 0.0;  // floor-area-weighted over the spaces
  double totalFloorAreaM2 = 0.0;
  int averagePoints = 0;           // Table 1 from the average alone: 0..3 (0..2 healthcare)
  bool eachSpaceAtLeast55 = false;
  int points = 0;                  // with the "each space" line: 0..3 (0..2 healthcare)
  bool exemplaryPerformance = false;
  std::vector<LeedSpaceResult> spaces;
  std::vector<std::string> glareToAddress;  // names of the spaces with ASE above 10 %
  // One line: the points, the average and what remains for the project to document.
  std::string verdict;
};

// Option 1's points (LEED v4.1 BD+C / ID+C, EQ credit Daylight, Table 1):
//   average sDA >= 40 %: 1 point, >= 55 %: 2 points, >= 75 %: 3 points (healthcare: exemplary
//   performance instead of a third point);
//   each space sDA >= 55 %: 1 additional point when the average gave 2 (general), exemplary
//   performance otherwise (healthcare; or general with 3 points already).
// "At least" in the credit: a value exactly at a boundary earns it. Throws std::invalid_argument
// for no spaces, an area not > 0 or a percentage outside [0, 100].
LeedOption1Result leedV41Option1(const std::vector<LeedSpace>& spaces,
                                 LeedProjectType type = LeedProjectType::kGeneral);

// The floor area a regular plane grid stands for: its sensors times the lattice's cell area (m²),
// each sensor the centre of one cell (study/grids/sensor_grid.h). Throws std::invalid_argument for a
// negative count or cell area.
double gridFloorAreaM2(int sensors, double cellAreaM2);

// Option 2's share of sensors in [loLux, hiLux] with its sampling uncertainty. Each sensor's
// estimate E ± σ (its Monte Carlo standard error, normal) is in range with probability
// p = Φ((hi − E)/σ) − Φ((lo − E)/σ) (the indicator when σ = 0); the count in range is then a sum of
// independent Bernoulli variables, whose standard deviation is √Σ p(1 − p). `sharePct` is the
// share of estimates in range as counted (what the points are read from), `standardErrorPct` that
// deviation over the sensors, in percent. Throws std::invalid_argument when the sizes differ,
// a σ is negative or lo > hi.
struct InRangeShare {
  double sharePct = 0.0;
  double standardErrorPct = 0.0;
};
InRangeShare inRangeShare(const std::vector<double>& lux, const std::vector<double>& sigmaLux, double loLux,
                          double hiLux);

}  // namespace candela
