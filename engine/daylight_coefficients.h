// Annual daylight by daylight coefficients (docs/annual.md): trace once, then every hour of a
// year is a matrix product.
//
//   E(s, h) = Σ_p DC(s, p) L(p, h)                    sky and ground patches
//           + S(s, h) E_sun,n(h)                      direct sun at its actual position
//           + Σ_j w_j(h) I(s, j) E_sun,n(h)           the sun's interreflected light
//
// DC(s, p) is the illuminance at sensor s from a luminance of 1 cd/m² over patch p (lux per
// cd/m²), traced with the point-study estimator (skyCoefficients). The sun is not
// spread over a patch: S(s, h) is the cosine-weighted visible fraction of the 0.533° disc at the
// hour's actual position, so sun patches and ASE have sharp edges; I(s, j) is the interreflected
// illuminance per lux of direct normal illuminance from sun position j of a set that covers the
// year's sun path (the mean position of the hours whose sun lies in each patch of Reinhart's MF:2),
// interpolated between the positions nearest to the hour's sun, traced
// with a shadow ray to every sun at every diffuse vertex (sunCoefficients).
#pragma once

#include "base/distribution.h"
#include "engine/tracer.h"
#include "photometry/annual_sky.h"
#include "photometry/sky_patches.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace candela {

struct DaylightCoefficients {
  int sensors = 0, patches = 0;
  // Sensor-major, [s * patches + p], lux per cd/m² of patch luminance.
  std::vector<float> total;
};

// Sun positions standing for the year's suns in the interreflected term: the normalised mean
// direction of the sun-up hours (with direct light) in each patch of SkyPatches(subdivision).
// An hour's interreflected sun is interpolated between the set's positions nearest to its sun,
// weighted by inverse squared angular distance (a stand-in alone moved the sun patch on a floor
// enough for 3–5 % errors at a March morning sun in a side-lit room; tests).
struct SunSet {
  static constexpr int kNearest = 3;
  std::vector<Vec3> dirsTrue;  // unit, true frame
  // Per hour of the sky: indices into dirsTrue (-1: none; all -1 without direct sun) and weights
  // summing to 1.
  std::vector<std::array<int, kNearest>> nearest;
  std::vector<std::array<float, kNearest>> weight;
};
// Reinhart MF:2 (6° rows): with Tregenza's 12° patches the stand-in sun moved the sun patch on
// a floor enough for errors of 5–13 % in a side-lit room at a low sun (tests).
SunSet indirectSunSet(const AnnualSky& sky, int subdivision = 2);

// Daylight coefficients at a sensor (docs/annual.md): the illuminance in lux that a luminance
// of 1 cd/m² over each patch of `patches` (index 0 the ground) gives at p, added to direct[]
// (seen from p with no reflection between: straight through thin glass and trans) and
// indirect[] (after any reflection), each patches.count() long. The same estimator as
// estimateIrradiance — sky sampled by s.lightSamples importance samples (MIS) and by the stratified
// hemisphere, interreflection path traced — with the method forced to path and no adaptive
// supersampling. The scene needs a sky (its model only guides sampling; a uniform sky suits
// every patch); its other sources add nothing to the tallies.
// directByPatch: the direct part is sampled patch by patch (s.lightSamples stratified shadow
// rays in each, 4× for the ground), so that every patch's share is known alike; false tallies
// the point estimator's own sky samples instead (the same random numbers as estimateIrradiance, for
// tests).
// 9 parameters: the public daylight-coefficient entry point, each one a separate input.
void skyCoefficients(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                   const SkyPatches& patches, double* direct, double* indirect, bool directByPatch = true);

// Interreflected illuminance in lux at p from each sun direction (unit, model frame) per lux
// of direct normal illuminance, added to indirect[] (one per sun): the light of the suns
// reaching every diffuse vertex of the paths, one shadow ray per sun per vertex. The sun's
// direct light at p is not included.
void sunCoefficients(const Tracer& tracer, const Vec3& p, const Vec3& n, uint64_t pointIndex, const TraceSettings& s,
                   const std::vector<Vec3>& sunDirsModel, double* indirect);

// A sky whose luminance is constant over each patch of `patches` (cd/m², one per patch; index 0,
// the ground, is not part of a sky). As the scene's sky of a coefficient run it guides the
// sampling of the sky (skyCoefficients); as a point run's sky it is what the
// coefficients assume.
class PatchSky : public SkyModel {
 public:
  PatchSky(const SkyPatches& patches, std::vector<double> luminanceCdM2);
  double relativeLuminance(const Vec3& dirTrue) const override;
  std::string name() const override { return "patches"; }

 private:
  SkyPatches patches_;
  std::vector<double> luminance_;
};

// The sampling guide of a year's coefficients: each sky patch's mean luminance over the hours,
// plus a floor of a tenth of the mean (so that no patch goes unsampled).
std::shared_ptr<const SkyModel> yearSamplingGuide(const AnnualSky& sky);

// Coefficients of every sensor (point i uses random stream i: results do not depend on the
// thread count). The tracer's scene must have a sky (see skyCoefficients).
// progress(done) as for computeIrradiance (thread-safe, cheap), may be empty.
// With a distribution, the sensors are shared between its processes (base/distribution.h) and
// every process gets every row; progress counts this process's sensors.
// 8 parameters: the public batch entry point (geometry, sky, settings, threads, progress, processes).
DaylightCoefficients computeDaylightCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                                 const std::vector<Vec3>& normals, const SkyPatches& patches,
                                                 const TraceSettings& settings, int threads,
                                                 const std::function<void(size_t)>& progress = {},
                                                 const Distribution& distribution = localDistribution());

// S(s, j) for sun directions j (unit, model frame): mean over `samples` stratified directions
// in the sun's disc of max(0, cos incidence) × transmittance, sensor-major [s * suns + j].
// Illuminance from the sun is S × its direct normal illuminance.
// 8 parameters: the public batch entry point (geometry, suns, sampling, threads, processes).
std::vector<float> directSunCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                         const std::vector<Vec3>& normals, const std::vector<Vec3>& sunDirsModel,
                                         int samples, uint64_t seed, int threads,
                                         const Distribution& distribution = localDistribution());

// I(s, j) for the suns of a set (unit, model frame), sensor-major [s * suns + j], lux per lux of
// direct normal illuminance. Point i uses random stream i.
// 8 parameters: the public batch entry point (geometry, suns, settings, threads, progress, processes).
std::vector<float> indirectSunCoefficients(const Tracer& tracer, const std::vector<Vec3>& positions,
                                           const std::vector<Vec3>& normals, const std::vector<Vec3>& sunDirsModel,
                                           const TraceSettings& settings, int threads,
                                           const std::function<void(size_t)>& progress = {},
                                           const Distribution& distribution = localDistribution());

// Sensor blocks: the three functions above over `positions.size()` consecutive sensors of a
// study, the first of which is the study's sensor `firstIndex`. Point k of the block uses random
// stream firstIndex + k, so a study traced block by block gets, float for float, the values of
// the same study traced whole (study/annual_study.cpp keeps one block in memory at a time).
struct SensorBlock {
  std::span<const Vec3> positions, normals;  // the block's own, equal in size
  std::size_t firstIndex = 0;
};
DaylightCoefficients computeDaylightCoefficients(const Tracer& tracer, const SensorBlock& block,
                                                 const SkyPatches& patches, const TraceSettings& settings,
                                                 int threads, const std::function<void(size_t)>& progress = {},
                                                 const Distribution& distribution = localDistribution());
std::vector<float> directSunCoefficients(const Tracer& tracer, const SensorBlock& block,
                                         const std::vector<Vec3>& sunDirsModel, int samples, uint64_t seed,
                                         int threads, const Distribution& distribution = localDistribution());
std::vector<float> indirectSunCoefficients(const Tracer& tracer, const SensorBlock& block,
                                           const std::vector<Vec3>& sunDirsModel, const TraceSettings& settings,
                                           int threads, const std::function<void(size_t)>& progress = {},
                                           const Distribution& distribution = localDistribution());

// Labels of scene surfaces, e.g. the window group of each glazing surface (study/window_groups.h):
// ofSurface[surface id] in [0, count), or -1 for none; one entry per Scene::surfaceCount().
struct SurfaceLabels {
  std::vector<int> ofSurface;
  int count = 0;
};

// directSunCoefficients for a block, with each disc sample's light also attributed to the label
// of the first `glass` surface its ray crosses leaving the sensor (Tracer::transmittance's
// firstGlass; a ray through no labelled glass is attributed to none). Returns labels.count + 1
// arrays, sensor-major [s * suns + j]: [0] the total, float for float directSunCoefficients',
// [1 + g] the part through label g. The parts sum to the total but for the unlabelled part.
// Throws std::invalid_argument when labels.ofSurface has not one entry per surface.
// 8 parameters: directSunCoefficients' own and the labels.
std::vector<std::vector<float>> directSunCoefficientsByLabel(const Tracer& tracer, const SensorBlock& block,
                                                             const std::vector<Vec3>& sunDirsModel, int samples,
                                                             uint64_t seed, int threads, const SurfaceLabels& labels,
                                                             const Distribution& distribution = localDistribution());

// annualIlluminance sums sensors in groups of this many (Eigen products of a fixed shape, so
// that no value depends on the thread count); a block of sensors that starts at a multiple of it
// gets the same floats as the whole study.
inline constexpr int kAnnualProductBlock = 64;

// A year of hourly illuminance at the sensors, sensor-major [s * hours + h], lux.
struct AnnualIlluminance {
  int sensors = 0, hours = 0;
  std::vector<float> total;      // sky + ground + sun, direct and interreflected
  std::vector<float> directSun;  // the sun's direct part alone (ASE, hours of sun, blinds rule)
  double productTimeS = 0.0;     // wall time of the hourly products
};

// The products above for every hour of `sky`. sunCoefficients has one column per hour with the
// sun up and a direct normal illuminance > 0, in hour order (as sunDirectionsModel returns
// them); sunIndirect one per sun of `sunSet`. Throws std::invalid_argument when sizes disagree.
AnnualIlluminance annualIlluminance(const DaylightCoefficients& dc, const std::vector<float>& sunCoefficients,
                                    const std::vector<float>& sunIndirect, const SunSet& sunSet,
                                    const AnnualSky& sky, int threads);

// The direct sun of every hour from coefficients S (sensor-major [s * suns + j], the suns of
// sunHours(sky)), sensor-major [s * hours + h], lux: the floats annualIlluminance's directSun
// holds for the same coefficients. Throws std::invalid_argument when sizes disagree.
std::vector<float> hourlyDirectSun(const std::vector<float>& sunCoefficients, int sensors, const AnnualSky& sky);

// The hours that have direct sun (sun up, direct normal illuminance > 0) and their directions
// in the model frame (site north `northDeg`).
std::vector<int> sunHours(const AnnualSky& sky);
std::vector<Vec3> sunDirectionsModel(const AnnualSky& sky, double northDeg);

}  // namespace candela
