// Reading the [[compliance]] entries of a case file (study/compliance/compliance_spec.h holds what they say;
// docs/compliance.md every key).
#pragma once

#include "study/case/case_file.h"
#include "study/case/case_toml.h"

#include <set>
#include <string>

namespace candela {

// One [[compliance]] table, after the case's grids (its `spaces` must name them): appended to
// out.compliance. `names` holds the entries' names so far (two alike are an error).
void readCompliance(const case_toml::Context& c, const toml::table& t, std::set<std::string>& names, CaseFile& out);

// 1 January = 1 (photometry/site.h's calendar).
int dayOfYear(const CivilDate& d);

}  // namespace candela
