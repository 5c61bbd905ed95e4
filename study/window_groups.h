// The [[window_group]]s of an annual study resolved against its scene (docs/annual.md "Window
// groups"): which glazing surface belongs to which group, and each group's closed blinds as a
// scene edit.
#pragma once

#include "engine/daylight_coefficients.h"
#include "engine/scene.h"
#include "study/case/case_file.h"

#include <string>
#include <vector>

namespace candela {

struct WindowGroup {
  std::string name;
  std::vector<std::string> surfaces;  // identifiers of its glazing surfaces, in scene order, once each
  double blindsTransmittance = 0.2;   // factor on the glass's normal transmittance when closed
};

struct WindowGroups {
  // The case's groups in case order, then "other" with the glazing no group names (if any).
  std::vector<WindowGroup> groups;
  SurfaceLabels labels;  // the group of every surface of the scene (-1: not glazing)
};

// The implicit group of the glazing that no [[window_group]] names.
inline constexpr const char* kOtherWindowGroup = "other";

// Glazing is every surface of material `glass` (what study/blinds.h closes). Throws InputError at
// the entry when a pattern matches no glazing surface, a glazing surface falls in two groups, a
// group is named "other" while glazing is left over, or there are more than kMaxWindowGroups
// groups (metrics/window_groups.h), the implicit one included. Without [[window_group]] entries:
// no groups (the study's one group per grid, as before).
WindowGroups resolveWindowGroups(const CaseFile& c, const Scene& scene);

// The scene with group g's glazing closed (LM-83-12 2.2.7: a Lambertian transmitter of the
// group's blindsTransmittance times the glass's normal transmittance, no beam, no reflection);
// the rest of the glazing stays glass. Returns the number of surfaces changed.
int closeWindowGroup(Scene& scene, const WindowGroups& groups, int g);

}  // namespace candela
