// Reader for Radiance's scene description language (Radiance reference manual, "Scene
// Description"): primitives `modifier type identifier`, then string, integer and real arguments,
// each preceded by its count; `#` comments; several files in order, modifiers defined before use.
#pragma once

#include "engine/scene.h"

#include <filesystem>
#include <string_view>

namespace candela {

// Tolerances of the polygon checks: a vertex farther than kPlanarTolerance × the polygon's
// diameter from its best plane makes it non-planar; an area below kDegenerateTolerance ×
// diameter² makes it degenerate.
inline constexpr double kPlanarTolerance = 1e-3;
inline constexpr double kDegenerateTolerance = 1e-10;

// Appends the primitives of one file to the scene. Throws InputError("file:line: ...") on any
// error; a line starting with '!' (an inline command) is refused, never run.
void readRadianceFile(const std::filesystem::path& path, Scene& scene);

// Same for text already in memory; `fileName` is used in error messages.
void readRadianceText(std::string_view text, const std::string& fileName, Scene& scene);

}  // namespace candela
