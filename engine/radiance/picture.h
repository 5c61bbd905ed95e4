// Radiance pictures (.hdr, .pic: RGBE, Radiance reference manual "Picture File Format" and
// src/common/color.c, resolu.c, header.c) read as the three data arrays colorpict and mixpict look
// up, as Radiance's getpict (src/rt/data.c) makes them: two dimensions, y (rows, bottom to top)
// then x, from 0 to 1 along the picture's shorter side and to its aspect along the longer one
// (PIXASPECT counted), the values the pixels' own (no EXPOSURE undone: Radiance does not either).
//
// Read here rather than with stb_image (Debian's libstb-dev): stb reads one orientation of the
// eight and decodes mantissas without Radiance's half step, (m + 0.5)·2^(e−136).
#pragma once

#include "engine/radiance/data_file.h"

#include <array>
#include <filesystem>
#include <string_view>

namespace candela {

// At most this many pixels (each channel one data array: 24 bytes a pixel once read).
inline constexpr size_t kMaxPicturePixels = kMaxDataValues;

// The picture's red, green and blue arrays; InputError at the file (its header line, or the
// scanline that is damaged) for a file that is not a Radiance RGBE picture.
std::array<RadDataArray, 3> parseRadiancePicture(std::string_view bytes, const std::string& fileName);

// Reads a picture file (a regular file: base/input_file.h); errors as parseRadiancePicture.
std::array<RadDataArray, 3> readRadiancePicture(const std::filesystem::path& path);

// Radiance 6's hyperspectral pictures (specpict; src/rt/data.c getspec, src/common/color.c):
// a header with NCOMP= (4 to 24 components) and WAVELENGTH_SPLITS= (nm, the longest first: the
// components are NCOMP equal bands from the first to the last), then scanlines of NCOMP mantissas
// and one common exponent a pixel, flat. Read as one data array of three dimensions, y and x as a
// picture's and then wavelength at the bands' centres (in the file's order, the longest first).
inline constexpr int kMaxSpectralComponents = 24;  // Radiance's MAXCSAMP
RadDataArray parseHyperspectralPicture(std::string_view bytes, const std::string& fileName);
RadDataArray readHyperspectralPicture(const std::filesystem::path& path);

}  // namespace candela
