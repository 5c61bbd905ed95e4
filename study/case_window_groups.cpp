#include "study/case_window_groups.h"

namespace candela {

using namespace case_toml;

void readWindowGroup(const Context& c, const toml::table& t, int index, std::set<std::string>& names,
                     CaseFile& out) {
  Table tab(t, c, "[[window_group]]");
  WindowGroupSpec g;
  g.loc = tab.loc();
  g.name = "group " + std::to_string(index + 1);
  if (const toml::node* n = tab.get("name")) {
    g.name = asString(c, *n, "name");
    if (g.name.empty()) c.fail(*n, "'name' must not be empty");
  }
  if (!names.insert(g.name).second) throw InputError(g.loc, "two window groups are named '" + g.name + "'");
  const toml::node& pn = tab.require("surfaces");
  g.patternsLoc = c.at(pn);
  const toml::array& patterns = asArray(c, pn, "surfaces", 0, "an array of surface identifiers or patterns");
  if (patterns.empty())
    c.fail(pn, "'surfaces' must name at least one glazing surface (an identifier or a pattern such as \"south_*\")");
  for (const toml::node& n : patterns) {
    g.patterns.push_back(asString(c, n, "surfaces"));
    if (g.patterns.back().empty()) c.fail(n, "'surfaces' holds an empty identifier");
  }
  if (const toml::node* n = tab.get("blinds_transmittance")) {
    const double tau = asNumber(c, *n, "blinds_transmittance");
    if (!(tau > 0.0 && tau <= 1.0))
      c.fail(*n, "'blinds_transmittance' must be greater than 0 and at most 1, got " + compactNumber(tau));
    g.blindsTransmittance = tau;
  }
  tab.finish();
  out.windowGroups.push_back(std::move(g));
}

}  // namespace candela
