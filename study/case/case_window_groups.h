// The case file's [[window_group]] entries (docs/case-format.md), read as study/case/case_file.cpp
// reads the rest of the file. Whether the patterns name glazing of the scene is checked when the
// scene is read (study/window_groups.h).
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

#include <set>
#include <string>

namespace candela {

// At most this many states per window group.
inline constexpr std::size_t kMaxWindowStates = 64;

// Appends the [[window_group]] `t` (the index-th) to out.windowGroups; `names` holds the group
// names so far (a name twice, an empty pattern list or a transmittance outside (0, 1] is an
// InputError at its line).
void readWindowGroup(const case_toml::Context& c, const toml::table& t, int index, std::set<std::string>& names,
                     CaseFile& out);

}  // namespace candela
