#include "study/window_groups.h"

#include "base/error.h"
#include "engine/materials/family.h"
#include "metrics/window_groups.h"
#include "study/blinds.h"
#include "study/grids/surface_grids.h"

#include <map>

namespace candela {

namespace {

bool isGlazing(const Scene& scene, uint32_t id) {
  return familyOf(scene.materials[scene.surfaceMaterial(id)]).isGlazing();
}

// Adds surface `id`'s name to the group's list unless it is the last one added (mesh runs share
// a name; a name repeats when several shapes carry it).
void addSurfaceName(WindowGroup& g, const std::string& name) {
  for (const std::string& s : g.surfaces)
    if (s == name) return;
  g.surfaces.push_back(name);
}

}  // namespace

WindowGroups resolveWindowGroups(const CaseFile& c, const Scene& scene) {
  WindowGroups out;
  if (c.windowGroups.empty()) return out;
  const uint32_t n = scene.surfaceCount();
  out.labels.ofSurface.assign(n, -1);
  std::vector<bool> leftOver(n, false);
  for (std::size_t gi = 0; gi < c.windowGroups.size(); ++gi) {
    const WindowGroupSpec& spec = c.windowGroups[gi];
    WindowGroup g;
    g.name = spec.name;
    g.blindsTransmittance = spec.blindsTransmittance.value_or(kBlindsTransmittance);
    std::vector<bool> used(spec.patterns.size(), false);
    for (uint32_t id = 0; id < n; ++id) {
      if (!isGlazing(scene, id)) continue;
      const std::string& name = scene.surfaceName(id);
      bool hit = false;
      for (std::size_t k = 0; k < spec.patterns.size(); ++k)
        if (globMatch(spec.patterns[k], name)) hit = used[k] = true;
      if (!hit) continue;
      const int other = out.labels.ofSurface[id];
      if (other >= 0 && other != static_cast<int>(gi))
        throw InputError(spec.patternsLoc, "glazing surface '" + name + "' is in window groups '" +
                                               out.groups[other].name + "' and '" + spec.name + "'");
      out.labels.ofSurface[id] = static_cast<int>(gi);
      addSurfaceName(g, name);
    }
    for (std::size_t k = 0; k < spec.patterns.size(); ++k)
      if (!used[k])
        throw InputError(spec.patternsLoc, "window group '" + spec.name + "': no glazing surface (material glass) "
                                           "of the scene is named '" + spec.patterns[k] + "'");
    out.groups.push_back(std::move(g));
  }
  WindowGroup other;
  other.name = kOtherWindowGroup;
  for (uint32_t id = 0; id < n; ++id)
    if (isGlazing(scene, id) && out.labels.ofSurface[id] < 0) {
      out.labels.ofSurface[id] = static_cast<int>(out.groups.size());
      addSurfaceName(other, scene.surfaceName(id));
    }
  if (!other.surfaces.empty()) {
    for (const WindowGroupSpec& s : c.windowGroups)
      if (s.name == kOtherWindowGroup)
        throw InputError(s.loc, "window group 'other' is the name of the glazing no group names ('" +
                                    other.surfaces.front() + "' ...): name the group otherwise or include them");
    out.groups.push_back(std::move(other));
  }
  if (out.groups.size() > static_cast<std::size_t>(kMaxWindowGroups))
    throw InputError(c.windowGroups.front().loc, "at most " + std::to_string(kMaxWindowGroups) +
                                                     " window groups (the implicit 'other' included), got " +
                                                     std::to_string(out.groups.size()));
  out.labels.count = static_cast<int>(out.groups.size());
  return out;
}

int closeWindowGroup(Scene& scene, const WindowGroups& groups, int g) {
  // One closed material per glass material the group uses, appended to the scene.
  std::map<uint32_t, uint32_t> closedOf;
  auto closed = [&](uint32_t glass) {
    auto it = closedOf.find(glass);
    if (it != closedOf.end()) return it->second;
    Material m = scene.materials[glass];
    m.name += "_blinds_closed";
    closeGlass(m, groups.groups[g].blindsTransmittance);
    const uint32_t index = static_cast<uint32_t>(scene.materials.size());
    scene.materials.push_back(std::move(m));
    return closedOf[glass] = index;
  };
  int changed = 0;
  for (uint32_t id = 0; id < scene.shapes.size(); ++id)
    if (groups.labels.ofSurface[id] == g) {
      scene.shapes[id].material = closed(scene.shapes[id].material);
      ++changed;
    }
  for (TriangleMesh::Run& run : scene.mesh.runs) {
    const uint32_t id = static_cast<uint32_t>(scene.shapes.size()) + run.firstTriangle;
    if (id < scene.surfaceCount() && groups.labels.ofSurface[id] == g) {
      run.material = closed(run.material);
      ++changed;
    }
  }
  return changed;
}

}  // namespace candela
