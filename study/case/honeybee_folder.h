// Honeybee's radiance folder (honeybee-radiance-folder's layout: model/scene, model/aperture,
// model/aperture_group with states.json) read into a case: `[[scene]] honeybee_folder = "..."`
// (docs/case-format.md). The static scene becomes [[scene]] files, each aperture group a
// [[window_group]] with its states (docs/annual.md "Window states").
#pragma once

#include "study/case/case_file.h"

#include <filesystem>

namespace candela {

// Appends the folder's scene files to out.scenes, in the order Radiance needs them (every .mat
// of model/scene then model/aperture, then their .rad files, each folder's files by name; .blk
// files, the black-out variants of other recipes, are left out), and each group of
// model/aperture_group/states.json to out.windowGroups, in the file's order: its name the
// group's key, each state's name its "identifier" and its scene its "default" file. `folder` is
// the radiance folder (holding model/) or its model folder. Throws InputError at `loc` when the
// folder has neither model/scene nor model/aperture, and at states.json (its line where known)
// for a file that is not such JSON, a state without identifier or default, a default file that
// does not exist, a group name twice, or dynamic scene or interior aperture groups (not read).
// The folder holding model/ becomes the scene's root folder (SceneReadOptions::rootFolder): the
// files Honeybee's scene files name from there (./model/bsdf/clear.xml) are found wherever
// candela runs.
void readHoneybeeFolder(const std::filesystem::path& folder, const FileLoc& loc, CaseFile& out);

}  // namespace candela
