// EN 13201 road lighting as a study (docs/road.md): at the EN 13201-3 grids of each [[road]]
// (study/compliance/en13201_grids.h), the horizontal illuminance and, for M classes, the road
// luminance from the surface's r-table seen by each lane's observer, the threshold increment and
// the edge illuminance ratio; verdicts against the class (metrics/en13201.h).
//
// The light is computed directly from each luminaire's intensity towards the point, as
// EN 13201-3 does (the point law for illuminance, L = r I / h² for luminance), with the scene's
// geometry as a shadow test between the point and the luminaire's photometric centre. Light
// reflected by the scene is not counted (the standard counts direct light only, and the r-table
// stands for the road's own reflection).
#pragma once

#include "engine/scene.h"
#include "engine/tracer.h"
#include "metrics/en13201.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/compliance/en13201_grids.h"

#include <array>
#include <vector>

namespace candela {

// The case's en13201 entry, or null.
const ComplianceSpec* en13201Entry(const CaseFile& c);

// The light of a scene's luminaires on a road on the plane z = 0. Each luminaire's intensities are
// the scene's (multiplier, no maintenance factor: the initial values) times its maintenance factor
// for maintained values. `tracer` (may be null: nothing shadows) tests the line between a point
// and a luminaire's photometric centre.
class RoadLight {
 public:
  RoadLight(const Scene& scene, const Tracer* tracer, std::vector<double> maintenanceFactors);
  // Horizontal illuminance at plan point p of the road (z = 0), maintained, lx.
  double illuminanceLux(const Vec2& p) const;
  // Luminance at plan point p seen from `eye` (r-table `table` scaled by q0/Q0): maintained and
  // initial, cd/m².
  struct Luminance {
    double maintained = 0.0, initial = 0.0;
  };
  Luminance luminanceCdM2(const Vec2& p, const Vec3& eye, const RTable& table, double q0) const;
  // Veiling luminance at `eye` looking along the plan direction `along`, 1° down, from the
  // luminaires up to 500 m ahead and not above the 20° screening plane, initial values, cd/m².
  double veilingLuminanceCdM2(const Vec3& eye, const Vec2& along) const;
  // Hemispherical illuminance at plan point p of the road (z = 0), maintained, lx.
  double hemisphericalLux(const Vec2& p) const;
  // Semi-cylindrical and vertical illuminance at plan point p, 1.5 m above the road, facing the
  // plan direction `along` ([0]) and its opposite ([1]): maintained, lx.
  struct Facing {
    double semiCylindrical = 0.0, vertical = 0.0;
  };
  std::array<Facing, 2> facingLux(const Vec2& p, const Vec2& along) const;
  // Mean height of the luminaires above the road (z), m; 0 without luminaires.
  double meanMountingHeightM() const;

 private:
  // Fraction of light passing from `from` to luminaire k (1 without a tracer).
  double visibility(const Vec3& from, std::size_t k) const;
  // fn(k, s, d2, i) for each luminaire k whose maintained intensity i towards `point` is positive:
  // s the unit direction from the point to its photometric centre, d2 their squared distance.
  template <class Fn>
  void eachLuminaire(const Vec3& point, Fn&& fn) const;
  const Scene& scene_;
  const Tracer* tracer_;
  std::vector<double> maintenance_;
};

// One road's figures at its grids.
RoadResult computeRoad(const RoadSpec& road, const RoadLight& light);

// Every road of the case in `scene` (the case's geometry and luminaires at a maintenance factor
// of 1, loadRoadScene), their maintenance factors `maintenanceFactors` (one per scene luminaire).
std::vector<RoadResult> computeEn13201(const CaseFile& c, const Scene& scene, const std::vector<double>& maintenanceFactors);

// The scene of the road study: the case's geometry and luminaires without daylight, each luminaire
// at its initial intensities (multiplier only); the maintenance factors in `maintenanceFactors`.
std::unique_ptr<Scene> loadRoadScene(const CaseFile& c, std::vector<double>& maintenanceFactors);

// The run's step (study/grid_study.cpp): for the case's en13201 entry, its roads' results and the
// report's compliance entry. Nothing without an entry.
void addEn13201Compliance(const CaseFile& c, ReportData& data);

}  // namespace candela
