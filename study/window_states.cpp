#include "study/window_states.h"

#include "base/error.h"
#include "base/input_file.h"
#include "engine/obj_reader.h"
#include "engine/radiance/reader.h"
#include "metrics/window_groups.h"
#include "study/case/case_scene.h"
#include "study/grids/surface_grids.h"

#include <sstream>

namespace candela {

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

bool hasWindowStates(const CaseFile& c) {
  for (const WindowGroupSpec& g : c.windowGroups)
    if (!g.states.empty()) return true;
  return false;
}

std::vector<uint8_t> readStateSchedule(const std::filesystem::path& path, const std::vector<std::string>& states,
                                       std::size_t hours) {
  const std::string text = readInputFile(path, "schedule file");
  std::istringstream in(text);
  std::vector<uint8_t> out;
  out.reserve(hours);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const FileLoc at{path.string(), number, 0};
    if (out.size() == hours)
      throw InputError(at, "the schedule has more than " + std::to_string(hours) +
                               " lines: one state per hour of the weather file's year");
    const std::string name = trimmed(line);
    if (name.empty()) throw InputError(at, "empty line: every line names the state of one hour");
    std::size_t k = 0;
    while (k < states.size() && states[k] != name) ++k;
    if (k == states.size()) {
      std::string known;
      for (const std::string& s : states) known += (known.empty() ? "'" : ", '") + s + "'";
      throw InputError(at, "unknown state '" + name + "' (the group's states: " + known + ")");
    }
    out.push_back(static_cast<uint8_t>(k));
  }
  if (out.size() != hours)
    throw InputError(FileLoc{path.string(), number, 0},
                     "the schedule ends after " + std::to_string(out.size()) + " lines; the weather file's year has " +
                         std::to_string(hours) + " hours");
  return out;
}

WindowStates resolveWindowStates(const CaseFile& c, std::size_t hours) {
  WindowStates ws;
  if (!hasWindowStates(c)) return ws;
  for (const WindowGroupSpec& spec : c.windowGroups) {
    if (spec.states.empty())
      throw InputError(spec.loc, "window group '" + spec.name + "' has no 'states' while others have: give every "
                                 "group its states (LM-83's blinds and window states do not mix)");
    WindowStateGroup g;
    g.name = spec.name;
    for (const WindowGroupSpec::State& s : spec.states) {
      g.states.push_back(s.name);
      g.files.push_back(s.scene);
    }
    if (!spec.schedule.empty()) {
      g.scheduled = readStateSchedule(spec.schedule, g.states, hours);
    } else {
      if (spec.states.size() < 2)
        throw InputError(spec.loc, "window group '" + spec.name + "': the direct-sun rule chooses among at least two "
                                   "states; give another state or a 'schedule' file");
      if (!spec.sunGrid.empty()) {
        for (std::size_t i = 0; i < c.grids.size(); ++i)
          if (c.grids[i].name == spec.sunGrid) g.sunGrid = static_cast<int>(i);
        if (g.sunGrid < 0) throw InputError(spec.sunGridLoc, "'sun_grid': no [[grid]] is named '" + spec.sunGrid + "'");
      }
      g.sunIndex = ws.sunGroups++;
    }
    ws.groups.push_back(std::move(g));
  }
  if (ws.groups.size() > kMaxStateGroups)
    throw InputError(c.windowGroups.front().loc, "at most " + std::to_string(kMaxStateGroups) +
                                                     " window groups with states, got " + std::to_string(ws.groups.size()));
  if (ws.sunGroups > kMaxWindowGroups)
    throw InputError(c.windowGroups.front().loc, "at most " + std::to_string(kMaxWindowGroups) +
                                                     " window groups under the direct-sun rule, got " +
                                                     std::to_string(ws.sunGroups));
  return ws;
}

void readStateScene(const CaseFile& c, const std::vector<int>& choice, Scene& scene, SurfaceLabels* labels,
                    const WindowStates* ws) {
  SceneReader reader(scene, c.settings.scene);
  // The case's files as readSceneFiles reads them: Radiance files, then OBJ files.
  for (const ScenePath& s : c.scenes)
    if (!isObjPath(s.file)) reader.readFile(s.file);
  for (const ScenePath& s : c.scenes)
    if (isObjPath(s.file)) reader.readFile(s.file);
  for (const WindowGroupSpec& spec : c.windowGroups) {
    if (spec.patterns.empty()) continue;
    std::vector<bool> used(spec.patterns.size(), false);
    removeSurfaces(scene, spec.patterns, used);
    for (std::size_t k = 0; k < used.size(); ++k)
      if (!used[k])
        throw InputError(spec.patternsLoc, "window group '" + spec.name + "': no surface of the scene is named '" +
                                               spec.patterns[k] + "' (the states replace the surfaces it names)");
  }
  // Each group's state file; the surfaces it adds: shapes [s0, s1), mesh triangles [t0, t1).
  struct Added {
    std::size_t s0, s1, t0, t1;
  };
  std::vector<Added> added;
  for (std::size_t g = 0; g < c.windowGroups.size(); ++g) {
    const std::vector<WindowGroupSpec::State>& states = c.windowGroups[g].states;
    if (states.empty()) continue;
    Added a{scene.shapes.size(), 0, scene.mesh.triangles.size(), 0};
    reader.readFile(states.at(static_cast<std::size_t>(g < choice.size() ? choice[g] : 0)).scene);
    a.s1 = scene.shapes.size();
    a.t1 = scene.mesh.triangles.size();
    added.push_back(a);
  }
  if (labels && ws) {
    labels->ofSurface.assign(scene.surfaceCount(), -1);
    labels->count = ws->sunGroups;
    const std::size_t shapes = scene.shapes.size();
    for (std::size_t g = 0; g < ws->groups.size() && g < added.size(); ++g) {
      const int label = ws->groups[g].sunIndex;
      if (label < 0) continue;
      for (std::size_t i = added[g].s0; i < added[g].s1; ++i) labels->ofSurface[i] = label;
      for (std::size_t i = added[g].t0; i < added[g].t1; ++i) labels->ofSurface[shapes + i] = label;
    }
  }
}

std::unique_ptr<Scene> loadStateScene(const CaseFile& c, double northDeg, const WindowStates& ws,
                                      const std::vector<int>& choice, SurfaceLabels* labels) {
  auto scene = std::make_unique<Scene>();
  readStateScene(c, choice, *scene, labels, &ws);
  finishAnnualScene(c, northDeg, *scene);
  return scene;
}

void foldWindowState(const float* stateYear, const float* reference, const std::vector<uint8_t>& state, int k,
                     const std::vector<uint8_t>& switched, std::size_t sensors, float* combined) {
  const std::size_t nh = state.size();
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t h = 0; h < nh; ++h) {
      if (state[h] != k) continue;
      const std::size_t i = s * nh + h;
      combined[i] = switched[h] == 1 ? stateYear[i] : combined[i] + (stateYear[i] - reference[i]);
    }
}

}  // namespace candela
