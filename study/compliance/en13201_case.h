// The case file's EN 13201 table (docs/case-format.md, docs/road.md): [[road]], read into
// CaseFile::roadLighting.
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

namespace candela {

// Reads every [[road]] of `root` (absent: none). Throws InputError at the line of a bad value: an
// unknown class or surface, a length, width or q0 ≤ 0, lanes < 1, a zero direction, a name used
// twice.
void readRoadTables(const case_toml::Context& c, const toml::table& root, CaseFile& out);

// After [[compliance]] is read: roads without a [[compliance]] standard = "en13201" are an error
// (nothing would check them), and so is such an entry without a road, or two of them.
void checkRoadCompliance(const CaseFile& c);

}  // namespace candela
