// The scene a case file describes: its Radiance files in order, then its luminaires. Shared by
// `candela points --case` and `candela run`.
#pragma once

#include "engine/case_file.h"
#include "engine/scene.h"

#include <memory>

namespace candela {

// Reads every [[scene]] file and places every [[luminaire]] (arrays already expanded by the
// case reader). Photometric files shared by several placements are read once. Throws
// InputError naming the bad file and line.
std::unique_ptr<Scene> loadCaseScene(const CaseFile& c);

// Places one luminaire from its photometric web.
LuminaireSource placeLuminaire(std::shared_ptr<const PhotometricWeb> web, const LuminairePlacement& p);

}  // namespace candela
