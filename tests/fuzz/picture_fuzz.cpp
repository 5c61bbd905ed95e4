// Fuzz target: a Radiance picture's bytes (engine/radiance/picture.h, parseRadiancePicture and
// parseHyperspectralPicture): the header, the resolution line in its eight orientations, flat and
// run-length scanlines, spectral pixels; each array looked up at a few points as colorpict and
// specpict would.
#include "engine/radiance/picture.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto rgb = candela::parseRadiancePicture(candela::fuzz::asText(data, size), "fuzz.hdr");
    for (const candela::RadDataArray& a : rgb)
      for (double u : {-1.0, 0.0, 0.3, 1.0, 7.0}) {
        const double pt[] = {u, 0.5 * u};
        (void)a.value(pt);
      }
  } catch (const candela::InputError&) {
  }
  try {
    const candela::RadDataArray s = candela::parseHyperspectralPicture(candela::fuzz::asText(data, size), "fuzz.hsr");
    for (double u : {-1.0, 0.0, 0.3, 1.0, 7.0}) {
      const double pt[] = {u, 0.5 * u, 550.0 + 100.0 * u};
      (void)s.value(pt);
    }
  } catch (const candela::InputError&) {
  }
  return 0;
}
