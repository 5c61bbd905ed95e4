// The case file's grids: [[grid]] entries and the grids a [[task_area]] makes (its task area,
// immediate surrounding and background, EN 12464-1:2021), read as study/case/case_file.cpp reads the
// rest of the file.
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

#include <set>
#include <string>

namespace candela {

// Appends the [[grid]] entry `t` (the index-th) to out.grids; `names` holds the grid names so far.
void readGrid(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
              CaseFile& out);
// Appends the [[task_area]] `t` to out.taskAreas and its three grids to out.grids.
void readTaskArea(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                  CaseFile& out);

// Appends the [[surface_grid]] `t` to out.surfaceGrids (its grids are made with the scene).
void readSurfaceGrid(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                     CaseFile& out);

}  // namespace candela
