// Reader of EULUMDAT (.ldt) files into a PhotometricWeb. Layout after Stockmar, "EULUMDAT - ein
// Leuchtendatenformat fuer den europaeischen Beleuchtungsplaner", Licht '90, pp. 641-644: one
// value per line, intensities in cd/klm. See docs/luminaires.md.
#pragma once

#include "photometry/photometric_web.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace candela {

// Reads `path`. Throws InputError "file:line: message" for a missing or malformed file.
PhotometricWeb readEulumdat(const std::filesystem::path& path);

// Parses EULUMDAT text; `fileName` names it in errors.
PhotometricWeb parseEulumdat(std::string_view text, const std::string& fileName);

}  // namespace candela
