// EN 12464-2:2014 outdoor work places: what a task area and a GR observer found, and their
// verdicts (docs/outdoor.md). Filled by study/compliance/en12464_2.cpp, written by
// reports/en12464_2_report.h. The glare rating itself is metrics/glare_rating.h.
#pragma once

#include "base/math.h"
#include "metrics/targets.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// One line of sight of a GR observer.
struct GrViewResult {
  double azimuthDeg = 0.0;          // plan azimuth, degrees clockwise from plan +Y
  Vec3 sight{0.0, 1.0, 0.0};        // unit line of sight (inclined)
  double luminairesVeilCdM2 = 0.0;  // L_vl
  int luminairesInView = 0;         // luminaires in front of the eye that reach it
  std::optional<double> gr;         // unset: no luminaire in front of the eye
};

struct GrObserverResult {
  std::string name, taskArea;
  Vec3 eyeM{0.0};
  bool fromGrid = false;                 // one of a task area's gr_spacing lattice
  double inclinationDeg = 0.0;
  double groundReflectance = 0.0;        // ρ of its task area
  double averageHorizontalLux = 0.0;     // E_hav of its task area
  double environmentVeilCdM2 = 0.0;      // L_ve
  std::vector<GrViewResult> views;
  std::optional<double> grMax;           // the largest over the views; unset: no luminaire in view
  std::optional<double> grLimit;         // its own, else its task area's
  Verdict verdict = Verdict::kNotChecked;
};

struct OutdoorAreaResult {
  std::string name;
  std::vector<Vec2> outline;
  double heightM = 0.0;
  std::size_t points = 0;
  double averageLux = 0.0, minLux = 0.0, maxLux = 0.0, u0 = 0.0;  // the area's grid (U0 = E_min/Ē)
  double maintainedLux = 0.0;                                     // Ē_m required
  std::optional<double> uniformityRequired;
  Verdict averageVerdict = Verdict::kNotChecked, uniformityVerdict = Verdict::kNotChecked;
  std::optional<double> grLimit, grMax;  // GR_L; the largest GR of its observers
  // ρ of its surface for L_ve: the case's `ground_reflectance`, else measured in the scene
  // (`groundReflectanceFromScene`); unset when neither (then no observer rates it).
  std::optional<double> groundReflectance;
  bool groundReflectanceFromScene = false;
  std::vector<std::string> grObservers;
  Verdict grVerdict = Verdict::kNotChecked;
  // Ra: the least the luminaires' files state (EULUMDAT) where every one states it; the files that
  // do not (IES): then not checked.
  std::optional<double> ra, raLeast;
  std::vector<std::string> raUnknown;
  Verdict raVerdict = Verdict::kNotChecked;
  Verdict verdict = Verdict::kNotChecked;
};

struct OutdoorLuminaire {
  std::string name;
  Vec3 positionM{0.0};
};

// Obtrusive light's limits (EN 12464-2:2014 clause 4, CIE 150): the vertical illuminance at a
// property, the intensity of each luminaire towards it, the installation's upward light ratio.
struct ObtrusiveLimits {
  std::optional<double> propertyLux, intensityCd, upwardLightRatio;
};

// An environmental zone's limits before curfew: EN 12193:2008 Table 5 as the ITF Facilities
// Guide reproduces it (itf.uberflip.com/i/1255985-facilities-guide/56: E1 2 lx, 2 500 cd, 0 %;
// E2 5 lx, 7 500 cd, 5 %; E3 10 lx, 10 000 cd, 15 %; E4 25 lx, 25 000 cd, 25 %). Empty for any
// other name (E0 and the post-curfew values were not found in a source that could be cited).
std::optional<ObtrusiveLimits> obtrusiveZoneLimits(const std::string& zone);

struct PropertyPointResult {
  std::string name;
  Vec3 positionM{0.0}, normal{0.0, 1.0, 0.0};
  double illuminanceLux = 0.0;     // E_v on the plane of `normal`, direct from the luminaires
  double maxIntensityCd = 0.0;     // the largest intensity towards the point of a luminaire it sees
  std::string brightestLuminaire;  // that luminaire ("" when none is seen)
  Verdict illuminanceVerdict = Verdict::kNotChecked, intensityVerdict = Verdict::kNotChecked;
};

struct ObtrusiveLightResult {
  std::string zone;            // "" when the case gives its limits only
  ObtrusiveLimits limits;      // the zone's, each replaced by the case's where given
  std::vector<PropertyPointResult> points;
  double upwardFluxLm = 0.0, totalFluxLm = 0.0;  // the installation as placed
  double upwardLightRatio = 0.0;                 // upward / total (0 without flux)
  Verdict upwardVerdict = Verdict::kNotChecked;
  Verdict verdict = Verdict::kNotChecked;
};

// The points' and the ULR's verdicts against the limits ("not above": equal passes; not checked
// without the limit), and the whole: fail when any fails, pass when any is checked.
void judgeObtrusiveLight(ObtrusiveLightResult& r);

struct En12464_2Result {
  std::vector<OutdoorAreaResult> areas;
  std::vector<GrObserverResult> observers;
  std::vector<OutdoorLuminaire> luminaires;
  std::optional<ObtrusiveLightResult> obtrusive;
  Verdict verdict = Verdict::kNotChecked;
};

// grMax over the views, and the verdict: not checked without a limit; pass when no luminaire is in
// view or GR_max ≤ GR_L ("not above", as UGR_L).
void judgeGrObserver(GrObserverResult& o);

// The area's lines: Ē ≥ Ē_m and U0 ≥ its requirement ("not below": equal passes), GR of the
// observers rating it (each against its limit; not checked without a limit or without
// observers), and the whole: fail when any checked line fails, pass when all checked ones pass.
// Its Ra verdict is set before (the luminaires' data is the study's).
void judgeOutdoorArea(OutdoorAreaResult& a, const std::vector<GrObserverResult>& observers);

// The entry: fail when any area or observer or the obtrusive light fails, else pass.
void judgeEn12464_2(En12464_2Result& r);

}  // namespace candela
