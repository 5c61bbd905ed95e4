// Fuzz target: a Radiance font file's text (engine/radiance/font.h, parseRadianceFont), as the
// text patterns read it; every glyph tested at a few points and a line laid out the three ways.
#include "engine/radiance/font.h"
#include "engine/radiance/text_pattern.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const candela::RadFont f = candela::parseRadianceFont(candela::fuzz::asText(data, size), "fuzz.fnt");
    for (const candela::RadGlyph& g : f.glyphs)
      for (double u : {0.0, 0.5, 127.5, 200.25, 254.99}) (void)candela::insideGlyph(&g, u, 255.0 - u);
    const std::string line = "A quick  brown\tfox    jumps";
    (void)candela::uniformLine(line, f);
    (void)candela::squeezedLine(line, f, 51);
    (void)candela::proportionalLine(line, f, 51);
  } catch (const candela::InputError&) {
  }
  return 0;
}
