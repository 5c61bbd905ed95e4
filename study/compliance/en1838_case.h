// The case file's EN 1838 tables (docs/case-format.md, docs/emergency.md): [[escape_route]],
// [[open_area]] and [[safety_point]], read into CaseFile::emergency.
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

namespace candela {

// Reads the three tables of `root` (absent: none). Throws InputError at the line of a route with
// fewer than 2 points or a width ≤ 0, an open area with fewer than 3 corners, not convex or whose
// core (the area without its 0.5 m border) is empty, a name used twice.
void readEmergencyTables(const case_toml::Context& c, const toml::table& root, CaseFile& out);

// After [[compliance]] is read: routes, open areas, safety points or high-risk task areas without
// a [[compliance]] standard = "en1838" are an error (nothing would check them), and so is such an
// entry with none of them.
void checkEmergencyCompliance(const CaseFile& c);

}  // namespace candela
