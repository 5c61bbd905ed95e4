// OpenEXR output of luminance images: 32-bit FLOAT channels (half floats stop at 65504, below
// the luminance of the sun, of bare lamps and of sunlit sky), written atomically.
#pragma once

#include "base/atomic_file.h"
#include "base/units.h"

#include <filesystem>
#include <string>
#include <vector>

namespace candela {

// The string attribute naming the unit of the Y channel (and of R, G, B).
inline constexpr const char* kExrUnitAttribute = "luminanceUnit";
inline constexpr const char* kExrLuminanceUnit = "cd/m2";

// Writes a width × height image (rows top to bottom) with channel Y = luminance in cd/m² and,
// when `rgb` is not empty, channels R, G, B = rgbScale × rgb in the same unit (for Radiance RGB
// radiance, rgbScale = 179 lm/W, so that 0.265 R + 0.670 G + 0.065 B = Y). Header: the string
// attribute "luminanceUnit" = "cd/m2", OpenEXR's standard whiteLuminance = 1 (cd/m² of RGB
// (1, 1, 1)) and an optional comment. Streamed a block of rows at a time into a temporary file
// beside `path`, then renamed. Throws std::runtime_error (OpenEXR's message) on failure,
// leaving `path` untouched.
void writeLuminanceExr(const std::filesystem::path& path, int width, int height,
                       const std::vector<float>& luminanceCdM2, const std::vector<glm::vec3>& rgb = {},
                       double rgbScale = 1.0, const std::string& comment = {});
// The same into `out`, left uncommitted (its caller commits it); `name` for messages.
void writeLuminanceExr(AtomicFile& out, const std::string& name, int width, int height,
                       const std::vector<float>& luminanceCdM2, const std::vector<glm::vec3>& rgb, double rgbScale,
                       const std::string& comment);

}  // namespace candela
