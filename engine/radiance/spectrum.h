// Spectra reduced to Radiance's three channels: a reflectance or transmittance spectrum s(λ)
// (Radiance 6's `spectrum` and `specfile` patterns) becomes the RGB colour whose CIE XYZ is that
// of s under an equal-energy light, in Radiance's RGB primaries (R 0.640 0.330, G 0.290 0.600,
// B 0.150 0.060, white at 1/3 1/3: src/common/color.h), so that a flat spectrum of value v is
// (v, v, v). The CIE 1931 2° colour-matching functions are the multi-lobe Gaussian fit of
// Wyman, Sloan and Shirley (2013), "Simple analytic approximations to the CIE XYZ color matching
// functions", JCGT 2(2), within about 1 % of the tables; each is normalised to its own integral
// over 380–780 nm, which fixes the white exactly.
#pragma once

#include "base/math.h"
#include "base/units.h"

#include <functional>
#include <vector>

namespace candela {

// CIE XYZ to Radiance's RGB (the primaries and white above; Radiance's xyz2rgbmat,
// src/common/spec_rgb.c): Y is kept, photopic(rgb) = Y.
Rgb xyzToRadianceRgb(const Vec3& xyz);

// x̄, ȳ, z̄ at `nm` (the fit; 0 far outside the visible).
Vec3 cieColourMatching(double nm);

// The RGB of the spectrum s(λ) given from nmA to nmB (0 outside), integrated in 1 nm steps over
// 380–780 nm.
Rgb spectrumToRgb(const std::function<double(double nm)>& s, double nmA, double nmB);

// The RGB per unit value at each node of a spectrum given at increasing wavelengths nodesNm (≥ 2)
// and linearly interpolated between them (0 outside), reduced as spectrumToRgb: a spectrum of
// values s_k there has the RGB Σ s_k W_k (the W_k are spectrumToRgb of the nodes' hat functions).
// The spectral patterns evaluated at each hit (specfunc, specdata) reduce their values with them.
std::vector<Rgb> spectrumNodeWeights(const std::vector<double>& nodesNm);

}  // namespace candela
