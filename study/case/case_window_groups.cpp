#include "study/case/case_window_groups.h"

namespace candela {

using namespace case_toml;

namespace {

// `states = [{ name, scene }, ...]` and the rule's keys `schedule` and `sun_grid`.
void readWindowStates(const Context& c, Table& tab, WindowGroupSpec& g) {
  if (const toml::node* n = tab.get("states")) {
    const std::vector<const toml::table*> states = asTableList(c, *n, "states", "{ name = \"...\", scene = \"file.rad\" }");
    if (states.size() > kMaxWindowStates)
      c.fail(*n, "'states' holds " + std::to_string(states.size()) + " states; at most " +
                     std::to_string(kMaxWindowStates));
    for (const toml::table* t : states) {
      const toml::node& e = *t;
      Table st(*t, c, "a state of window group '" + g.name + "'");
      WindowGroupSpec::State s;
      s.loc = c.at(e);
      s.name = asString(c, st.require("name"), "name");
      if (s.name.empty()) c.fail(*st.get("name"), "a state's 'name' must not be empty");
      for (const WindowGroupSpec::State& o : g.states)
        if (o.name == s.name) c.fail(*st.get("name"), "window group '" + g.name + "' has two states named '" + s.name + "'");
      s.scene = filePath(st, "scene", "state scene file");
      st.finish();
      g.states.push_back(std::move(s));
    }
  }
  const toml::node* schedule = tab.get("schedule");
  const toml::node* sunGrid = tab.get("sun_grid");
  if ((schedule || sunGrid) && g.states.empty())
    c.fail(schedule ? *schedule : *sunGrid, "'schedule' and 'sun_grid' choose among 'states'; this group has none");
  if (schedule && sunGrid) c.fail(*sunGrid, "give either 'schedule' or 'sun_grid', not both");
  if (schedule) {
    g.scheduleLoc = c.at(*schedule);
    g.schedule = filePath(tab, "schedule", "schedule file");
  }
  if (sunGrid) {
    g.sunGridLoc = c.at(*sunGrid);
    g.sunGrid = asString(c, *sunGrid, "sun_grid");
    if (g.sunGrid.empty()) c.fail(*sunGrid, "'sun_grid' must name a [[grid]]");
  }
}

}  // namespace

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
  // A group of a Honeybee folder ([[scene]] honeybee_folder): this entry sets its rule only.
  for (WindowGroupSpec& folderGroup : out.windowGroups) {
    if (folderGroup.name != g.name) continue;
    for (const char* key : {"states", "surfaces", "blinds_transmittance"})
      if (const toml::node* n = tab.get(key))
        c.fail(*n, "window group '" + g.name + "' comes from a Honeybee folder ([[scene]] honeybee_folder): this "
                   "entry may only set its rule ('schedule' or 'sun_grid'), not '" + key + "'");
    readWindowStates(c, tab, folderGroup);
    tab.finish();
    return;
  }
  readWindowStates(c, tab, g);
  // With states, `surfaces` is optional: the base scene's surfaces the states replace.
  const toml::node* pn = g.states.empty() ? &tab.require("surfaces") : tab.get("surfaces");
  if (pn) {
    g.patternsLoc = c.at(*pn);
    const toml::array& patterns = asArray(c, *pn, "surfaces", 0, "an array of surface identifiers or patterns");
    if (patterns.empty())
      c.fail(*pn, "'surfaces' must name at least one glazing surface (an identifier or a pattern such as \"south_*\")");
    for (const toml::node& n : patterns) {
      g.patterns.push_back(asString(c, n, "surfaces"));
      if (g.patterns.back().empty()) c.fail(n, "'surfaces' holds an empty identifier");
    }
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
