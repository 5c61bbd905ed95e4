// EN 13201 road lighting: the lighting classes of EN 13201-2:2015 and their requirements, the
// point formulas of EN 13201-3:2015 (luminance from an r-table, veiling luminance, threshold
// increment) and the verdict of a road over its computed figures. Pure functions: the grids,
// observers and the light at each point come from study/compliance/en13201.h. docs/road.md gives
// the source of every number.
#pragma once

#include "base/math.h"
#include "metrics/targets.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// The families of EN 13201-2:2015: M (motorised traffic, luminance), C (conflict areas,
// illuminance and its uniformity), P (pedestrians and low speed, average and minimum illuminance),
// HS (pedestrians and low speed by the hemispherical illuminance, the P classes' alternative).
enum class RoadClassFamily { kM, kC, kP, kHS };

struct RoadClass {
  RoadClassFamily family = RoadClassFamily::kM;
  int index = 1;  // M1..M6, C0..C5, P1..P6, HS1..HS3
  std::string name() const;
};
// "M1".."M6", "C0".."C5", "P1".."P6", "HS1".."HS3" (upper or lower case); nullopt otherwise.
std::optional<RoadClass> parseRoadClass(std::string_view text);

// The additional classes of EN 13201-2:2015 a road may carry besides its class: SC (the least
// semi-cylindrical illuminance, for facial recognition) and EV (the least vertical illuminance,
// where vertical surfaces must be seen).
enum class AdditionalClassKind { kSC, kEV };
struct AdditionalRoadClass {
  AdditionalClassKind kind = AdditionalClassKind::kSC;
  int index = 1;  // SC1..SC9, EV1..EV6
  std::string name() const;
};
// "SC1".."SC9", "EV1".."EV6" (upper or lower case); nullopt otherwise.
std::optional<AdditionalRoadClass> parseAdditionalRoadClass(std::string_view text);

// EN 13201-2:2015 Table 1 (M classes): the least maintained average luminance L̄ (cd/m²), overall
// uniformity U0 = Lmin/L̄, longitudinal uniformity Ul, the edge illuminance ratio R_EI (least
// values) and the threshold increment f_TI (%, greatest).
struct MClassRequirement {
  double averageLuminanceCdM2 = 0.0, overallUniformity = 0.0, longitudinalUniformity = 0.0;
  double thresholdIncrementPct = 0.0, edgeIlluminanceRatio = 0.0;
};
// Table 2 (C classes): the least maintained average illuminance Ē (lx) and uniformity Emin/Ē.
struct CClassRequirement {
  double averageLux = 0.0, overallUniformity = 0.0;
};
// Table 3 (P classes): the least maintained average Ē and minimum Emin (lx); Ē must not exceed
// kPClassAverageCeiling times the class's value.
struct PClassRequirement {
  double averageLux = 0.0, minimumLux = 0.0;
};
inline constexpr double kPClassAverageCeiling = 1.5;
// HS classes: the least maintained average hemispherical illuminance Ē_hs (lx) and its uniformity
// E_hs,min/Ē_hs.
struct HsClassRequirement {
  double averageLux = 0.0, uniformity = 0.0;
};
MClassRequirement mClassRequirement(int index);    // 1..6
CClassRequirement cClassRequirement(int index);    // 0..5
PClassRequirement pClassRequirement(int index);    // 1..6
HsClassRequirement hsClassRequirement(int index);  // 1..3
// The least maintained semi-cylindrical (SC1..SC9) or vertical (EV1..EV6) illuminance, lx.
double additionalClassMinimumLux(const AdditionalRoadClass& c);

// Semi-cylindrical and vertical illuminances are computed 1.5 m above the road, on the
// illuminance grid's plan points, facing both ways along the road (candela's reading of
// EN 13201-3's pedestrians' height and main directions: docs/road.md).
inline constexpr double kFacialHeightM = 1.5;

// A standard road surface reflection table (an r-table): the reduced luminance coefficient
// r(β, tan γ) = q(β, γ) cos³γ in sr⁻¹ at the table's own average luminance coefficient q0
// (en13201_rtables.cpp gives the values and their source). β is the angle in plan between the
// vertical plane of observation and that of the light's incidence (0: the luminaire beyond the
// point as the observer looks, the forward, specular side), γ the light's angle of incidence from
// the vertical. Blank cells of the published table (geometries the table leaves out) are 0.
struct RTable {
  std::string_view name;  // "R1" … "R4", "C1", "C2"
  double q0 = 0.0;        // the table's average luminance coefficient Q0, sr⁻¹
  const double* values = nullptr;  // [tan γ row][β column], in 10⁻⁴ sr⁻¹
};
// The r-table named `name` ("R3"), or null when candela does not have it (docs/road.md).
const RTable* findRTable(std::string_view name);
// The names of the tables candela has, for messages ("R1, R2, R3, R4, C1, C2").
std::string supportedRTables();
// r(β, tan γ) in sr⁻¹ at the table's q0: bilinear in β (folded into 0..180°) and tan γ between the
// table's rows and columns; 0 beyond tan γ = 12 (the table's last row: such light is left out).
double reducedLuminanceCoefficient(const RTable& table, double betaDeg, double tanGamma);
// The table's tan γ rows and β columns (29 and 20 values).
const std::vector<double>& rTableTanGammas();
const std::vector<double>& rTableBetasDeg();

// EN 13201-3:2015 (and CIE 140): the luminance at a road point from one luminaire of intensity
// `intensityCd` towards it, mounted `heightM` above the road, `r` its reduced luminance coefficient
// (sr⁻¹, scaled to the surface's q0): L = r I / h² in cd/m².
inline double roadPointLuminanceCdM2(double intensityCd, double r, double heightM) {
  return r * intensityCd / (heightM * heightM);
}

// The veiling luminance one luminaire makes at the eye (EN 13201-3, CIE 140):
// Lv = 10 E / θ² in cd/m², E the illuminance it gives at the eye on a plane normal to the line of
// sight (lx) and θ the angle between the line of sight and the luminaire (degrees).
inline double veilingLuminanceCdM2(double eyeIlluminanceLux, double angleDeg) {
  return 10.0 * eyeIlluminanceLux / (angleDeg * angleDeg);
}
// Angles outside [1.5°, 60°] are outside the formula's range and contribute nothing.
inline constexpr double kVeilingMinAngleDeg = 1.5, kVeilingMaxAngleDeg = 60.0;
// Luminaires more than 20° above the line of sight are screened by the car's roof.
inline constexpr double kScreeningAngleDeg = 20.0;
// The observer's line of sight: 1° below the horizontal, eyes 1.5 m above the road.
inline constexpr double kLineOfSightDownDeg = 1.0, kObserverEyeHeightM = 1.5;
// Luminance observers stand 60 m before the field of calculation.
inline constexpr double kObserverDistanceM = 60.0;
// Luminaires up to 500 m ahead of the observer count in the veiling luminance.
inline constexpr double kVeilingReachM = 500.0;

// The threshold increment in % from the veiling luminance and the initial average road luminance
// (cd/m²): 65 Lv / L̄^0.8 for L̄ ≤ 5 cd/m², 95 Lv / L̄^1.05 above (EN 13201-3:2015). +inf when L̄ is 0
// and Lv is not.
double thresholdIncrementPct(double veilingCdM2, double averageLuminanceCdM2);

// One criterion of a class, as the report lists it.
struct RoadCriterion {
  std::string name;       // "average_luminance_cd_m2", ...
  double value = 0.0;     // computed
  double required = 0.0;  // the class's limit
  bool atLeast = true;    // value ≥ required passes (false: value ≤ required)
  Verdict verdict = Verdict::kNotChecked;
};

// The light of one luminance observer (one lane): its eye, the road's luminance seen from it and
// the threshold increment of its lane.
struct RoadObserverResult {
  Vec3 eyeM{0.0};
  double averageLuminanceCdM2 = 0.0, minLuminanceCdM2 = 0.0, overallUniformity = 0.0;
  double longitudinalUniformity = 0.0;      // Lmin/Lmax on its lane's centre line
  double initialAverageLuminanceCdM2 = 0.0;  // the same luminaires at a maintenance factor of 1
  double veilingLuminanceCdM2 = 0.0;         // the largest over the TI observer positions
  double thresholdIncrementPct = 0.0;
};

struct RoadResult {
  std::string name;
  RoadClass roadClass;
  std::string surface;  // "R3"
  double q0 = 0.0;
  // The road in plan: the field starts at `start` on its near edge and runs `lengthM` along
  // `along`; it spans `widthM` to the left of `along` (across), in `lanes` equal lanes.
  Vec2 start{0.0}, along{1.0, 0.0}, across{0.0, 1.0};
  double lengthM = 0.0, widthM = 0.0;
  int lanes = 1;
  // Illuminance over the field (horizontal, on the road surface), lx.
  std::vector<Vec2> illuminancePoints;
  std::vector<double> illuminanceLux;
  double averageLux = 0.0, minLux = 0.0, maxLux = 0.0, illuminanceUniformity = 0.0;  // Emin/Ē
  // M classes: the luminance grid (its points in plan) and each observer's luminance there.
  std::vector<Vec2> luminancePoints;
  std::vector<RoadObserverResult> observers;
  // The installation's figures: the least L̄, U0 and Ul and the greatest TI over the observers.
  double averageLuminanceCdM2 = 0.0, overallUniformity = 0.0, longitudinalUniformity = 0.0;
  double thresholdIncrementPct = 0.0;
  // Edge illuminance ratio: the lower side's Ē(outside strip)/Ē(inside strip), the strips `stripWidthM` wide.
  double edgeIlluminanceRatio = 0.0, stripWidthM = 0.0;
  double edgeRatioNearSide = 0.0, edgeRatioFarSide = 0.0;
  // HS classes: the hemispherical illuminance on the road at the illuminance points, lx.
  std::vector<double> hemisphericalLux;
  double averageHemisphericalLux = 0.0, minHemisphericalLux = 0.0, hemisphericalUniformity = 0.0;
  // Additional classes: at the illuminance points, 1.5 m up, the lesser of the two directions
  // along the road (SC: semi-cylindrical; EV: vertical), lx; their minima.
  std::vector<AdditionalRoadClass> additional;
  std::vector<double> semiCylindricalLux, verticalLux;
  double minSemiCylindricalLux = 0.0, minVerticalLux = 0.0;
  std::vector<RoadCriterion> criteria;
  Verdict verdict = Verdict::kNotChecked;
};

// Mean, minimum and maximum of `values` (all 0 for none).
struct RoadStats {
  double average = 0.0, min = 0.0, max = 0.0;
};
RoadStats roadStats(const std::vector<double>& values);

// Fills the installation's figures from the observers (least L̄, U0, Ul; greatest TI), then the
// criteria of the road's class and its verdict (pass when every criterion passes).
void judgeRoad(RoadResult& r);

}  // namespace candela
