// Fuzz target: a Radiance data file's text (engine/radiance/data_file.h, parseRadData), as
// brightdata, colordata, texdata and ies2rad's source.cal read them; the array looked up at a few
// points inside and outside its grid.
#include "engine/radiance/data_file.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const candela::RadDataArray a = candela::parseRadData(candela::fuzz::asText(data, size), "fuzz.dat");
    double pt[candela::kMaxDataDimensions];
    for (double u : {-1e9, -1.0, 0.0, 0.5, 1.0, 1e9}) {
      for (double& p : pt) p = u;
      (void)a.value(pt);
    }
  } catch (const candela::InputError&) {
  }
  return 0;
}
