// The case file's grids: [[grid]] entries and the grids a [[task_area]] makes (its task area,
// immediate surrounding and background, EN 12464-1:2021), read as study/case/case_file.cpp reads the
// rest of the file.
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

#include <set>
#include <string>
#include <vector>

namespace candela {

// Appends the [[grid]] entry `t` (the index-th) to out.grids; `names` holds the grid names so far.
void readGrid(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
              CaseFile& out);
// Appends the [[task_area]] `t` to out.taskAreas and its three grids to out.grids.
void readTaskArea(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                  CaseFile& out);

// An entry's 'name', not empty; `dflt` when it has none.
std::string entryName(case_toml::Table& tab, std::string dflt);
// A task area's plan outline (EN 12464-1's and EN 12464-2's [[task_area]]): 'corners' (two opposite
// corners, a rectangle) or a 'polygon' of at least 3 points, non-zero in area, exactly one of the
// two; errors at their lines, at `loc` when neither is given.
std::vector<Vec2> readTaskAreaOutline(case_toml::Table& tab, const FileLoc& loc);

// Appends the [[surface_grid]] `t` to out.surfaceGrids (its grids are made with the scene).
void readSurfaceGrid(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                     CaseFile& out);

}  // namespace candela
