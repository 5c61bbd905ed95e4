// Imageless annual glare (docs/annual-glare.md): hourly daylight glare probability (DGP, Wienold &
// Christoffersen 2006) at a view — eye position and line of sight — over a year of Perez skies,
// without rendering, after Jones's imageless method (Accelerad's dcglare, Honeybee's imageless
// annual glare):
//
//   Ev(h)  vertical illuminance at the eye, from the daylight coefficients of a sensor at the
//          eye facing the line of sight (engine/daylight_coefficients.h: sky patches, direct
//          sun, interreflected sun), exactly as the annual study's sensors;
//   sources(h)  the sky and ground patches seen straight through the openings whose seen
//          luminance exceeds the glare-source threshold, each with its tally Σ τ² ω / P² over the
//          directions of the forward hemisphere that reach it (traced once per view), and the
//          sun's disc when it is in front of the eye, L = τ E_n / ω_sun;
//   DGP(h) metrics/glare.h daylightGlareProbability(Ev, sources), with the low-light correction.
//
// Every function takes a Tracer, so the same view can be computed with the blinds open and
// closed (study/blinds.h) and combined hour by hour (metrics/annual_glare.h combineByHour).
#pragma once

#include "engine/daylight_coefficients.h"
#include "engine/tracer.h"
#include "metrics/glare.h"
#include "photometry/annual_sky.h"
#include "photometry/sky_patches.h"
#include "engine/random_streams.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela {

// An observer for annual glare: eye position (m) and line of sight (unit, model frame); the
// view's "up" is +Z (+Y for a line of sight within 0.1° of vertical).
struct GlareView {
  std::string name;
  Vec3 eyeM{0.0};
  Vec3 direction{0.0, 1.0, 0.0};
};

// The view frame of metrics/glare.h and engine/camera.h: x right = forward × up, y up =
// right × forward, z forward.
struct ViewFrame {
  Vec3 right, up, forward;
  Vec3 toView(const Vec3& dirModel) const {
    return {glm::dot(dirModel, right), glm::dot(dirModel, up), glm::dot(dirModel, forward)};
  }
  Vec3 toModel(const Vec3& dirView) const { return dirView.x * right + dirView.y * up + dirView.z * forward; }
};
ViewFrame viewFrame(const Vec3& direction);

// Which patches and pixels are glare sources: seen luminance above `fixedCdM2` when it is
// positive (default 2000 cd/m², evalglare 2.x's default threshold), else above `factorOfMean` ×
// the mean luminance of the field of view (evalglare 1.x's 5 ×). The imageless method takes that
// mean as Ev/π, exact for a uniform field (as dcglare does).
struct GlareSourceThreshold {
  double fixedCdM2 = 2000.0;
  double factorOfMean = 5.0;
  double imagelessCdM2(double evLux) const;
};

// The sky and ground a view sees straight through its openings, per patch of SkyPatches (index 0
// the ground): a midpoint rule over the forward hemisphere in cells of equal angle, Δθ = Δφ =
// 90°/rowsPer90Deg, each cell's exact solid angle, one transmittance ray through its centre.
struct SkyViewTally {
  std::vector<double> solidAngleSr;   // Σ ω of the cells whose ray reaches the patch (τ > 0)
  std::vector<double> transmittedSr;  // Σ τ ω
  std::vector<double> glareWeightSr;  // Σ τ² ω / P², P the position index of the cell's centre
  int rowsPer90Deg = 0;
  // The patch as one glare source of luminance τ̄ L (τ̄ = transmittedSr / solidAngleSr) over
  // solidAngleSr, with the position index that gives L² · glareWeightSr exactly.
  GlareSource source(int patch, double patchLuminanceCdM2) const;
};
// Rows are traced in parallel and summed in row order: the tally does not depend on `threads`.
SkyViewTally skyViewTally(const Tracer& tracer, const GlareView& view, const SkyPatches& patches, double northDeg,
                          int rowsPer90Deg, int threads);

// The sun's disc seen from the eye for each sun direction (unit, model frame; the annual sun
// hours, sunDirectionsModel order): a grid of samples² directions at the centres of equal-area
// cells of the 0.533° disc, each with a transmittance ray. Zero for a sun behind the eye's
// forward hemisphere. Deterministic.
struct SunViewTally {
  std::vector<float> visibleFraction;       // share of the disc's samples with τ > 0
  std::vector<float> rmsTransmittance;      // √(mean τ²) over those samples
  std::vector<float> positionIndex;         // of the sun's centre in the view frame
  // The disc as a glare source for a direct normal illuminance (lux): L = τ_rms E_n / ω_sun
  // over visibleFraction · ω_sun, so L² ω = E_n² mean(τ²) / ω_sun.
  GlareSource source(std::size_t sun, double directNormalLux) const;
};
SunViewTally sunViewTally(const Tracer& tracer, const GlareView& view, const std::vector<Vec3>& sunDirsModel,
                          int samples, int threads);

// The solid angle of the 0.533° sun disc, sr (6.8·10⁻⁵).
double sunSolidAngleSr();

// What a year of a view needs besides the tracer and the view.
struct AnnualGlareJob {
  const AnnualSky* sky = nullptr;
  const SunSet* sunSet = nullptr;     // indirectSunSet(*sky)
  double northDeg = 0.0;
  TraceSettings settings;             // the case's (the method is forced to path, as the annual study)
  int sunSamples = 4;                 // rays over the disc for Ev's direct sun ([annual] sun_samples)
  int threads = 0;
};

struct ImagelessGlareOptions {
  GlareSourceThreshold threshold;
  int rowsPer90Deg = 180;     // 0.5° cells for the sky tally
  int sunDiscSamples = 4;     // 4 × 4 samples over the sun's disc
  // Hemisphere and sky samples of the eye's coefficients, × the case's: a view is one sensor, so
  // its Monte Carlo noise (the same draw for all its hours) is cheap to lower. On the office demo
  // at normal quality, 8 brings two streams' shares of hours above 0.40 from 40.7 / 38.1 % to
  // 37.4 / 37.3 % for 2 s a view instead of 0.3 s (docs/annual-glare.md).
  int evSampleFactor = 8;
  bool lowLightCorrection = true;
};

// A view's year, one value per hour of the sky.
struct ViewAnnualGlare {
  std::vector<float> dgp;          // 0 in hours without daylight (Ev = 0)
  std::vector<float> verticalLux;  // Ev, lux
  SkyViewTally sky;
  SunViewTally sun;
  double coefficientsS = 0.0, tallyS = 0.0, hoursS = 0.0;  // wall times
};

// The interreflected sun's settings of the annual study (each path carries every sun of the set,
// so fewer paths than for the sky).
TraceSettings interreflectedSunSettings(const TraceSettings& settings);

// Ev at the eye (random stream `stream` for its coefficients; pick one per view, apart from the
// grids' sensor indices, e.g. kAnnualGlareStreamBase + view index), the tallies, then every hour.
inline constexpr uint64_t kAnnualGlareStreamBase = streams::kAnnualGlare.first + 1;
ViewAnnualGlare imagelessAnnualGlare(const Tracer& tracer, const GlareView& view, uint64_t stream,
                                     const AnnualGlareJob& job, const ImagelessGlareOptions& options = {});

// The hourly step alone, for a given Ev (lux) per hour: the sources of each hour and its DGP.
// `sun` has one entry per sun hour of `sky` (sunHours order).
std::vector<float> imagelessHourlyDgp(std::span<const float> verticalLux, const AnnualSky& sky,
                                      const SkyViewTally& skyTally, const SunViewTally& sun,
                                      const ImagelessGlareOptions& options);

}  // namespace candela
