// The case file's EN 12464-2 keys (docs/case-format.md, docs/outdoor.md): [[task_area]] with
// standard = "en12464-2" and [[observer]] with kind = "gr", read into CaseFile::outdoor.
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

#include <set>
#include <string>

namespace candela {

// Whether the [[task_area]] `t` is an outdoor one (`standard = "en12464-2"`); `standard` absent or
// "en12464-1": an indoor one. Throws InputError at any other value.
bool isOutdoorTaskArea(const case_toml::Context& c, const toml::table& t);

// Appends the outdoor task area `t` (the index-th [[task_area]]) to out.outdoor.areas and its
// illuminance grid, named as the area, to out.grids; `gridNames` holds the grid names so far.
void readOutdoorTaskArea(const case_toml::Context& c, const toml::table& t, int index,
                         std::set<std::string>& gridNames, CaseFile& out);

// Whether the [[observer]] `t` rates GR (`kind = "gr"`); `kind` absent or "ugr": UGR. Throws
// InputError at any other value.
bool isGrObserver(const case_toml::Context& c, const toml::table& t);

// Appends the GR observer `t` (the index-th [[observer]]) to out.outdoor.observers; `names` holds
// the observers' names so far.
void readGrObserver(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                    CaseFile& out);

// After [[compliance]] is read: each GR observer's task area (named, or the one it stands in, or
// the only one), the observers of the areas' gr_spacing lattices, and the entry: outdoor areas or
// GR observers without a [[compliance]] standard = "en12464-2" are an error (nothing would check
// them), as is such an entry with none of them, or two such entries.
void resolveOutdoor(CaseFile& out);

// The obtrusive light's keys of a [[compliance]] entry (`environmental_zone`, `obtrusive_limits`,
// `property_points`) into s.obtrusive: an error at the key for another standard, an unknown
// zone, a negative limit, a ratio outside [0, 1], points without limits.
void readObtrusiveLight(case_toml::Table& tab, ComplianceSpec& s);

// The observers a task area's `gr_spacing` asks for: the centres of a lattice of cells at most
// `spacingM` wide over the area's box, those inside the area, eye 1.5 m, looking all around.
std::vector<GrObserverSpec> gridGrObservers(const OutdoorTaskAreaSpec& a);

}  // namespace candela
