// Fuzz target: an LBNL BSDF XML file (engine/radiance/bsdf_xml.h, parseBsdfXml), Klems or tensor
// tree; what it reads is queried in a few directions on both sides (evaluation, sampling, the
// integrals and the peak), so that a malformed file that passes the reader cannot break the
// queries either.
#include "engine/radiance/bsdf_xml.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto b = candela::parseBsdfXml(candela::fuzz::asText(data, size), "fuzz.xml");
    const candela::Vec3 dirs[] = {{0.0, 0.0, 1.0}, {0.0, 0.0, -1.0}, {0.6, 0.0, 0.8}, {-0.3, 0.4, -std::sqrt(0.75)},
                                  {0.999, 0.0, 0.0447}, {0.0, -0.5, -std::sqrt(0.75)}};
    for (const auto& out : dirs) {
      for (const auto& in : dirs) (void)b->eval(in, out, true);
      candela::Bsdf::Sample s;
      (void)b->sampleIn(out, candela::Vec2(0.3, 0.7), 0.5, s);
      (void)b->sampleIn(out, candela::Vec2(0.999, 0.0), 0.9999, s, true);
      (void)b->pdfIn(-out, out);
      (void)b->albedoToward(out, true, true);
      (void)b->hemispherical(out, false);
      (void)b->peakThrough(out);
    }
  } catch (const candela::InputError&) {
  }
  return 0;
}
