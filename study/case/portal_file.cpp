#include "study/case/portal_file.h"

#include "base/input_file.h"
#include "engine/portals.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace candela {

std::vector<Portal> parsePortals(std::string_view text, const std::string& source) {
  std::vector<Portal> out;
  std::istringstream in{std::string(text)};
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<double> v;
    const FileLoc loc{source, lineNo, 0};
    for (std::string w; words >> w;) {
      char* end = nullptr;
      const double x = std::strtod(w.c_str(), &end);
      if (end == w.c_str() || *end != '\0' || !std::isfinite(x))
        throw InputError(loc, "'" + w + "' is not a number (a portal is x y z of each vertex, in m)");
      v.push_back(x);
    }
    if (v.empty()) continue;
    if (v.size() % 3 != 0)
      throw InputError(loc, "a portal is x y z of each vertex: " + std::to_string(v.size()) +
                                " numbers are not a whole number of vertices");
    Portal p;
    p.loc = loc;
    p.name = source + ":" + std::to_string(lineNo);
    for (size_t i = 0; i < v.size(); i += 3) p.outline.emplace_back(v[i], v[i + 1], v[i + 2]);
    const std::string why = portalOutlineProblem(p.outline);
    if (!why.empty()) throw InputError(loc, why);
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<Portal> readPortalFile(const std::filesystem::path& path) {
  return parsePortals(readInputFile(path, "portal file"), path.string());
}

}  // namespace candela
