// The UGR table of a photometric file (`candela luminaire FILE --ugr-table`): the file's
// intensities and luminous opening as metrics/ugr_table.h takes them, at CIE 117's reference
// lamp flux, and the correction to the file's own flux.
#pragma once

#include "metrics/ugr_table.h"
#include "photometry/photometric_web.h"

namespace candela {

// CIE 117-1995's tables are "uncorrected": for luminaires whose lamps give Φ0 = 1000 lm in all.
// For lamps of Φ lm, UGR rises by 8 log10(Φ / Φ0) (CIE 190 eq. 2): L² and Lb both scale with Φ.
inline constexpr double kUgrReferenceLampLumens = 1000.0;

struct LuminaireUgrTable {
  UgrTable table;             // at kUgrReferenceLampLumens
  double lampLumens = 0.0;    // the file's rated lamp flux, lm; its luminaire flux when absolute
  bool absolutePhotometry = false;
  // 8 log10(lampLumens / Φ0): add it to every cell for the file's own lamps.
  double fluxCorrection() const;
};

// The web's intensities times `scale`, its opening, and its cone fluxes (exact integrals of the
// interpolated web, photometric_web.h) times `scale`. Keeps a reference to `web`.
UgrLuminaire ugrLuminaireOf(const PhotometricWeb& web, double scale = 1.0);

// Throws InputError at the file's opening line when the opening has no area (a point): a UGR
// needs the luminance of the luminous parts.
LuminaireUgrTable luminaireUgrTable(const PhotometricWeb& web, const UgrTableSettings& settings = {});

}  // namespace candela
