#include "study/output_names.h"

#include "base/error.h"
#include "reports/annual_results.h"
#include "reports/report_data.h"
#include "study/run_outputs.h"

#include <map>
#include <string>
#include <vector>

namespace candela {

namespace {

struct Owner {
  std::string kind;  // "grid", "view"
  std::string name;
  FileLoc loc;
};

// The files of a grid or view, by the writers' own naming rules.
std::vector<std::string> gridFiles(const GridSpec& g, bool annual) {
  const std::string stem = safeFileName(g.name);
  if (!annual) return {stem + ".csv"};
  return {stem + "_annual.csv", annualResultsFileName(g.name), annualResultsFileName(g.name + "_direct_sun")};
}

std::vector<std::string> viewFiles(const ViewSpec& v) {
  const std::string stem = safeFileName(v.name);
  return {stem + ".exr", stem + ".png", stem + "_preview.png"};
}

}  // namespace

void checkOutputNames(const CaseFile& c) {
  const bool annual = c.sky.type.kind == SkyKind::kAnnual;
  std::map<std::string, Owner> owners;
  const std::vector<std::string> reserved = {"summary.csv", "summary.json", "report.html", kResultMarker};
  auto claim = [&](const std::string& file, const Owner& o) {
    for (const std::string& r : reserved)
      if (file == r)
        throw InputError(o.loc, o.kind + " name '" + o.name + "' would overwrite " + r + "; choose another name");
    const auto [it, fresh] = owners.emplace(file, o);
    if (fresh) return;
    const Owner& first = it->second;
    const std::string who = first.kind == o.kind ? o.kind + "s '" + first.name + "' and '" + o.name + "'"
                                                 : first.kind + " '" + first.name + "' and " + o.kind + " '" + o.name + "'";
    throw InputError(o.loc, who + " would both write " + file + "; choose distinct names");
  };
  for (const GridSpec& g : c.grids)
    for (const std::string& f : gridFiles(g, annual)) claim(f, {"grid", g.name, g.loc});
  if (!annual)
    for (const ViewSpec& v : c.views)
      for (const std::string& f : viewFiles(v)) claim(f, {"view", v.name, v.loc});
}

}  // namespace candela
