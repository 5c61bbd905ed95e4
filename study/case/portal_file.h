// Portal files (`candela points --portal FILE`, docs/daylight.md#portals): openings without
// glazing, one planar polygon per line as its vertices' coordinates in metres,
//   x1 y1 z1  x2 y2 z2  x3 y3 z3  [...]
// '#' starts a comment; blank lines are skipped.
#pragma once

#include "engine/scene.h"

#include <filesystem>
#include <string_view>
#include <vector>

namespace candela {

// Throws InputError("FILE:LINE: ...") for a word that is not a number, a count not a multiple of
// three, fewer than three vertices or a polygon that is not planar (engine/portals.h).
std::vector<Portal> parsePortals(std::string_view text, const std::string& source);
std::vector<Portal> readPortalFile(const std::filesystem::path& path);

}  // namespace candela
