// Pictures of luminance images: a tone-mapped preview (what a photograph would show) and a
// false-colour map of luminance with its legend.
#pragma once

#include "base/atomic_file.h"
#include "base/units.h"
#include "reports/png_writer.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

// Reinhard, Stark, Shirley & Ferwerda 2002, "Photographic tone reproduction for digital images",
// global operator (eqs. 1, 2, 4): the log-average luminance maps to the key `key`, Ld =
// Ls (1 + Ls / Lwhite²) / (1 + Ls) with Lwhite the largest scaled luminance (at least 1), colour kept by
// scaling each pixel's RGB by Ld / L; then the sRGB transfer function (IEC 61966-2-1).
// `rgb` (any scale: only its ratios count) may be empty (grey picture); pixels with mask 0 are
// black. Rows top to bottom.
Image8 toneMap(int width, int height, const std::vector<float>& luminanceCdM2, const std::vector<glm::vec3>& rgb = {},
               const std::vector<uint8_t>& mask = {}, double key = 0.18);

// The same picture row by row, for pictures too large to hold; the arrays must outlive it.
RowPicture toneMapRows(int width, int height, const std::vector<float>& luminanceCdM2,
                       const std::vector<glm::vec3>& rgb = {}, const std::vector<uint8_t>& mask = {},
                       double key = 0.18);
// A false-colour scale for luminances: linear from 0 to a round number at or above the largest
// value, or logarithmic over whole decades from max/10⁴ (or the smallest positive value, if
// larger) to the largest; `minCdM2`/`maxCdM2` fix the range instead (log scales need min > 0).
ColorScale luminanceScale(const std::vector<float>& luminanceCdM2, bool logarithmic,
                          std::optional<double> minCdM2 = {}, std::optional<double> maxCdM2 = {});

// The false-colour picture of a luminance image with its legend in cd/m² ("cd/m2").
Image8 luminanceFalseColor(int width, int height, const std::vector<float>& luminanceCdM2, const ColorScale& scale);

// The three files of a rendered view in `dir`: <stem>.exr (Y and, when `rgb` is given, R, G, B =
// rgbScale × rgb in cd/m²; reports/exr_writer.h), <stem>.png (false colour on `scale`) and
// <stem>_preview.png (tone mapped; pixels with mask 0 black). Creates `dir`; each file is
// written atomically, streamed a row at a time.
// Throws std::runtime_error or std::filesystem::filesystem_error on failure.
struct ViewImagePaths {
  std::filesystem::path exr, falseColor, preview;
};
ViewImagePaths viewImagePaths(const std::filesystem::path& dir, const std::string& stem);
// The same three pictures written but not yet in place: temporaries in `dir`'s file system (unnamed
// where it has them: a process killed before commitInto leaves nothing), one picture in memory
// at a time. commitInto puts them into a folder of that file system (made later, say).
struct ViewImageFiles {
  std::string stem;
  std::unique_ptr<AtomicFile> exr, falseColor, preview;
  ViewImagePaths commitInto(const std::filesystem::path& dir);
};
ViewImageFiles writeViewImageFiles(const std::filesystem::path& dir, const std::string& stem, int width, int height,
                                   const std::vector<float>& luminanceCdM2, const std::vector<glm::vec3>& rgb,
                                   double rgbScale, const std::vector<uint8_t>& mask, const ColorScale& scale,
                                   const std::string& comment = {});
ViewImagePaths writeViewImages(const std::filesystem::path& dir, const std::string& stem, int width, int height,
                               const std::vector<float>& luminanceCdM2, const std::vector<glm::vec3>& rgb,
                               double rgbScale, const std::vector<uint8_t>& mask, const ColorScale& scale,
                               const std::string& comment = {});

}  // namespace candela
