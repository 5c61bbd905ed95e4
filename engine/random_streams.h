// Every family of random streams a trace draws from, in one place. Rng(seed, stream) gives
// independent numbers for distinct streams (base/rng.h), so two families must never share a
// stream number: each family is a range [first, first + size) and the check at the end of this
// file proves at compile time that no two ranges overlap. A new family is one line here.
//
// Top-level streams (a sensor point, a pixel, an observer: what estimateIrradiance and the
// integrators get as `pointIndex`) lie below 2^60; the streams derived from one of them (its sky
// patches, its sun, its hemisphere directions) add 2^60 and above to it, so each derived family
// is as large as the top-level space it is derived from.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace candela::streams {

struct Range {
  uint64_t first = 0, size = 0;
  constexpr uint64_t end() const { return first + size; }
};

inline constexpr uint64_t kTopLevelEnd = uint64_t{1} << 57;  // every top-level stream is below

// Top-level streams.
// A sensor point's own stream is its index (< 2^39); its path-method batches without the cache
// add 2^39, and batch b > 0 adds b·2^40 (b < 2^8).
inline constexpr Range kSensorPoints{0, uint64_t{1} << 48};
inline constexpr uint64_t kWithoutCacheOffset = uint64_t{1} << 39;
inline constexpr uint64_t kBatchStride = uint64_t{1} << 40;
// The grids' target's pilot estimates (engine/sensors.cpp), one a sensor point (index < 2^39).
inline constexpr Range kGridPilot{uint64_t{1} << 50, uint64_t{1} << 39};
// The time estimate's pilot estimates of points that see a scattering window
// (study/resource_estimate.h hemispherePilot), one a pilot point (< 2^39); nothing a run reports
// draws from them.
inline constexpr Range kEstimatePilot{uint64_t{1} << 53, uint64_t{1} << 39};
// A camera pixel's rays (pixel index < 2^32).
inline constexpr Range kCameraPixels{uint64_t{1} << 48, uint64_t{1} << 32};
// The observers of a grid study's luminaire glare (study/view_glare.h), one each.
inline constexpr Range kObservers{uint64_t{1} << 52, uint64_t{1} << 32};
// Annual glare views (study/annual_glare.h): one stream a view, and the eye's coefficients one
// below the first.
inline constexpr Range kAnnualGlare{(uint64_t{3} << 52) - 1, (uint64_t{1} << 32) + 1};
// The irradiance estimates of a camera ray (engine/render.cpp), kMaxEstimates consecutive ones a
// ray.
inline constexpr Range kCameraIrradiance{uint64_t{1} << 56, uint64_t{1} << 56};

// Derived from a top-level stream s: s + first.
// Sky patches sampled patch by patch (skyCoefficients).
inline constexpr Range kSkyPatches{uint64_t{1} << 60, kTopLevelEnd};
// The suns of the annual study's direct sun (engine/daylight_coefficients.cpp), by sensor.
inline constexpr Range kSuns{uint64_t{2} << 60, kTopLevelEnd};
// A point's stratified hemisphere directions (engine/irradiance_estimator.h).
inline constexpr Range kDirections{uint64_t{4} << 60, kTopLevelEnd};

// The irradiance cache's builder (engine/cache_builder.cpp), record i < 2^56: the radii of
// phase A, the values of phase B, and each record's directions its value stream + 2^56; the
// second level's alike.
inline constexpr uint64_t kRecordDirectionOffset = uint64_t{1} << 56;
inline constexpr Range kRecordRadii{uint64_t{0x50} << 56, uint64_t{1} << 56};
inline constexpr Range kRecordRadii2{uint64_t{0x58} << 56, uint64_t{1} << 56};
inline constexpr Range kRecords{uint64_t{0x60} << 56, uint64_t{2} << 56};
inline constexpr Range kRecords2{uint64_t{0x70} << 56, uint64_t{2} << 56};

inline constexpr std::array<Range, 14> kAll = {kSensorPoints, kGridPilot,    kEstimatePilot, kCameraPixels, kObservers,
                                               kAnnualGlare,  kCameraIrradiance, kSkyPatches, kSuns,       kDirections,
                                               kRecordRadii,  kRecordRadii2, kRecords,       kRecords2};

constexpr bool disjoint(const std::array<Range, 14>& all) {
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (all[i].first < all[j].end() && all[j].first < all[i].end()) return false;
  return true;
}
static_assert(disjoint(kAll), "two families of random streams overlap");
static_assert(kSensorPoints.end() <= kTopLevelEnd && kGridPilot.end() <= kTopLevelEnd &&
                  kEstimatePilot.end() <= kTopLevelEnd && kCameraPixels.end() <= kTopLevelEnd &&
                  kObservers.end() <= kTopLevelEnd && kAnnualGlare.end() <= kTopLevelEnd &&
                  kCameraIrradiance.end() <= kTopLevelEnd,
              "a top-level stream reaches the derived ones");
static_assert(kAll.back().end() > kAll.back().first, "no range wraps past 2^64");

}  // namespace candela::streams
