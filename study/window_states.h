// Window states of an annual study (docs/annual.md "Window states"): [[window_group]]s whose
// geometry and materials come from one Radiance file per state, a rule choosing a state per
// hour, and the scenes of each state (the group's state file added to the base scene, the base
// scene's surfaces the group names removed).
#pragma once

#include "engine/daylight_coefficients.h"
#include "engine/scene.h"
#include "study/case/case_file.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace candela {

// At most this many groups with states (each extra state is a coefficient pass).
inline constexpr std::size_t kMaxStateGroups = 64;

struct WindowStateGroup {
  std::string name;
  std::vector<std::string> states;               // state names, in the entry's order
  std::vector<std::filesystem::path> files;      // each state's scene file
  std::vector<uint8_t> scheduled;                // schedule rule: the state of every hour; empty: sun rule
  int sunGrid = -1;                              // sun rule: the grid (case order) that decides; -1: each grid
  int sunIndex = -1;                             // sun rule: the group's bit among the sun-rule groups
};

struct WindowStates {
  std::vector<WindowStateGroup> groups;
  int sunGroups = 0;  // groups under the direct-sun rule (bits 0 .. sunGroups − 1)
  bool empty() const { return groups.empty(); }
};

// Whether any [[window_group]] has `states`.
bool hasWindowStates(const CaseFile& c);

// The case's window states with their schedules read for a year of `hours` hours. Throws
// InputError at the entry when some groups have states and others not, when `sun_grid` names no
// grid, when there are more than kMaxStateGroups groups or more than kMaxWindowGroups use the
// direct-sun rule; readStateSchedule's errors.
WindowStates resolveWindowStates(const CaseFile& c, std::size_t hours);

// A schedule file: one state name per line (surrounding blanks ignored), exactly `hours` lines
// (an empty last line ends the file). Returns each hour's state index. Throws InputError at
// file:line for an unknown name, an empty line, or a count other than `hours` (the first line
// too many, or the end of a short file).
std::vector<uint8_t> readStateSchedule(const std::filesystem::path& path, const std::vector<std::string>& states,
                                       std::size_t hours);

// The scene files of a case with window states read into `scene`, group g in state choice[g]
// (0 where choice is shorter): the case's scene files, less every surface a group's `surfaces`
// patterns match, then each group's state file in group order. With labels and ws: each
// sun-rule group's surfaces labelled with its sunIndex (others -1), count ws->sunGroups. Throws
// InputError at the group when a pattern matches no surface.
void readStateScene(const CaseFile& c, const std::vector<int>& choice, Scene& scene, SurfaceLabels* labels = nullptr,
                    const WindowStates* ws = nullptr);

// The annual scene (sky as loadAnnualScene) of readStateScene.
std::unique_ptr<Scene> loadStateScene(const CaseFile& c, double northDeg, const WindowStates& ws,
                                      const std::vector<int>& choice, SurfaceLabels* labels = nullptr);

// Group q's state year folded into the switched year: in every hour h with state[h] == k,
// combined = stateYear itself when q is the only group off its first state at h (switched[h],
// the number of groups off their first state, is 1), else combined += stateYear − reference
// (light is linear in each window's transmission: exact when no path crosses two groups).
// Arrays sensor-major [s * hours + h], hours = state.size().
void foldWindowState(const float* stateYear, const float* reference, const std::vector<uint8_t>& state, int k,
                     const std::vector<uint8_t>& switched, std::size_t sensors, float* combined);

}  // namespace candela
