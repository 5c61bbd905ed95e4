// The daylight-coefficient observer (docs/annual.md): while a sensor estimate runs with a
// SkyTally, every sky or ground contribution it makes is also added to its patch's bin, as lux per
// cd/m² of patch luminance, and every path vertex adds each sun's light. The tally is passed down
// explicitly (TraceContext::tally); a null pointer means no observer.
#pragma once

#include "base/math.h"
#include "base/units.h"
#include "photometry/site.h"
#include "photometry/sky_patches.h"

#include <vector>

namespace candela {

// `outer` is the product of the factors the enclosing calls will apply to the radiance being
// computed (1/k of a split, ρ/π of a diffuse vertex, ...), so a contribution's weight is known
// where it arises; TallyFactor scopes each such factor.
struct SkyTally {
  const SkyPatches* patches = nullptr;  // sky patches tallied (none: suns only)
  double northDeg = 0.0;
  double* direct = nullptr;    // seen from the sensor with no reflection on the way
  double* indirect = nullptr;  // everything else
  // The direct part is computed patch by patch apart (skyCoefficients), so the sensor's
  // own sky samples and unreflected escapes are not tallied.
  bool directApart = false;
  // Suns (unit, model frame) whose light is tallied at path vertices by a shadow ray each, per
  // unit normal illuminance (sunCoefficients).
  const std::vector<Vec3>* suns = nullptr;
  double* sunIndirect = nullptr;
  Rgb outer{1.0};
};

// Multiplies the tally's outer factor by f for the scope of the object (nothing without a tally).
class TallyFactor {
 public:
  TallyFactor(SkyTally* tally, const Rgb& f) : tally_(tally) {
    if (tally_) {
      saved_ = tally_->outer;
      tally_->outer *= f;
    }
  }
  TallyFactor(SkyTally* tally, double f) : TallyFactor(tally, Rgb(f)) {}
  ~TallyFactor() {
    if (tally_) tally_->outer = saved_;
  }
  TallyFactor(const TallyFactor&) = delete;
  TallyFactor& operator=(const TallyFactor&) = delete;

 private:
  SkyTally* tally_;
  Rgb saved_{1.0};
};

// Adds weight·outer (photopic: the sky's luminance is achromatic) to the bin of model direction d.
inline void tallySky(SkyTally& tally, const Vec3& d, const Rgb& weight, bool direct) {
  const int bin = tally.patches->indexOf(modelToTrue(d, tally.northDeg));
  (direct ? tally.direct : tally.indirect)[bin] += photopic(tally.outer * weight);
}

}  // namespace candela
