// A luminaire's photometric file, whichever format it is in.
#pragma once

#include "photometry/photometric_web.h"

#include <filesystem>

namespace candela {

// Reads an .ies (IES LM-63) or .ldt (EULUMDAT) file, by extension, case-insensitive. Throws
// InputError.
PhotometricWeb readPhotometricFile(const std::filesystem::path& path);

}  // namespace candela
