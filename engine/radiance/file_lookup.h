// Where a file that a scene file names is looked for, as Radiance finds its files (getpath with
// RAYPATH): the name relative to the working directory, then to each folder of RAYPATH
// (':'-separated), then to the folder of the file that names it. An absolute name, one with a
// '..', or an empty one is refused: nothing outside those places is opened, whatever the scene
// says. Used for every file a scene file names: function files (.cal), data files (.dat),
// pictures, the text patterns' fonts (.fnt) and text files, the
// files and argument files of !xform, genprism's vertex files, the OBJ files of `mesh`.
#pragma once

#include "base/error.h"

#include <filesystem>
#include <string>

namespace candela {

// The path of `name` (a `role` such as "function file", named by `who` at loc; `folder` the
// naming file's folder). `root`, when given, is looked in last: the root of a model whose files
// name others from it, as a working directory of its own (a Honeybee radiance folder's: Honeybee
// runs Radiance there, and its files name ./model/bsdf/…). InputError at loc when the name is not
// allowed or found nowhere (the message names the places, never a file's content).
std::filesystem::path findSceneFile(const std::string& name, const std::filesystem::path& folder, const FileLoc& loc,
                                    const std::string& who, const std::string& role,
                                    const std::filesystem::path& root = {});

}  // namespace candela
