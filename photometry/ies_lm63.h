// Reader of IES LM-63 photometric files (1986, 1991, 1995, 2002 and 2019 editions) into a
// PhotometricWeb. Types C and B are read; type A is refused. See docs/luminaires.md.
#pragma once

#include "photometry/photometric_web.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace candela {

struct IesOptions {
  // Installed lamp tilt in degrees at which the TILT multiplier table is read (0: the test
  // orientation). The multiplier is applied to every intensity as a constant.
  double tiltAngleDeg = 0.0;
};

// Reads `path`; TILT=<file> is looked up relative to the file's folder. Throws InputError
// "file:line: message" for a missing or malformed file.
PhotometricWeb readIes(const std::filesystem::path& path, const IesOptions& options = {});

// Parses IES text; `fileName` names the text in errors, `folder` resolves TILT=<file>.
PhotometricWeb parseIes(std::string_view text, const std::string& fileName,
                        const std::filesystem::path& folder, const IesOptions& options = {});

// The opening shape for LM-63 signed luminous dimensions (LM-63-2019 table 1; the older
// editions' "negative width = round" is the circular case with length 0).
OpeningShape iesOpeningShape(double width, double length, double height);

}  // namespace candela
