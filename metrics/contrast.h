// Luminance contrast of a task against its background and the contrast rendition factor
// (Ward, Rubinstein & Clear 1988, after the IES's CRF: the contrast under the actual lighting
// relative to that under the reference, a uniform luminous sphere).
#pragma once

namespace candela {

// C = (Lt − Lb) / Lb, luminances in cd/m² (Lb > 0). Negative for a task darker than its
// background (dark print on paper).
double luminanceContrast(double taskCdM2, double backgroundCdM2);

// CRF = C / C_ref (C_ref ≠ 0).
double contrastRenditionFactor(double contrast, double referenceContrast);

// Reference contrast of matte (Lambertian) task and background of reflectances ρt and ρb: under a
// uniform sphere of luminance Ls both reflect L = ρ Ls, so C_ref = (ρt − ρb)/ρb. Matte surfaces
// under any lighting that gives them the same illuminance have this same contrast: CRF = 1.
double matteReferenceContrast(double taskReflectance, double backgroundReflectance);

}  // namespace candela
