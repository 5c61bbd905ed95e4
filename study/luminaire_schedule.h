// What a point-in-time report states about the installation (docs/en12464.md, "Energy and the
// luminaire schedule"): the luminaire schedule (one row per type of luminaire, with the data of
// its photometric file and the count placed), the reflectances of the materials the scene's
// surfaces use, and the installed power over the floor area (W/m², W/m²/100 lx).
#pragma once

#include "engine/scene.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/grids/prepared_grid.h"

#include <optional>
#include <string>
#include <vector>

namespace candela {

// The types of luminaire among the case's placements: the same photometric file, multiplier,
// maintenance factor and `power_w` make one type; types in the order of their first placement.
// `scene` is the case's (loadCaseScene): its luminaires[i] is placement i, with the file's web.
std::vector<LuminaireTypeReport> luminaireSchedule(const CaseFile& c, const Scene& scene);

// The least Ra an EULUMDAT colour rendering field promises: its number where it gives one
// ("80", "Ra 80", "1B/86": 80, 86), else the least of its CIE colour rendering group (1A: 90,
// 1B: 80, 2A: 70, 2B: 60, 3: 40, 4: 20; CIE 29.2 as EN 12464-1:2002 tabulated them); unset when
// it says neither (empty, free text).
std::optional<double> leastColourRendering(const std::string& field);

// The materials the scene's surfaces use, in the scene's order of the materials, with their
// photopic reflectance (diffuse + specular, at normal incidence) and, for trans and glass, their
// transmittance. An `illum` surface counts as its alternate material (what it looks like);
// emitters (light, glow), void and the luminaires' own openings (`opening_reflectance`, stated
// in the case) are not listed.
std::vector<SurfaceMaterialReport> surfaceMaterials(const Scene& scene);

// The grid W/m²/100 lx is taken on: its index among `grids` (-1: none) and why, in words.
struct ReferenceGrid {
  int index = -1;
  std::string reason;
};

// [case] reference_grid when given (an InputError at its line when that grid does not measure
// horizontal illuminance), else the first [[grid]] of horizontal illuminance that is not a
// daylight-factor grid, else the first task area's task grid.
ReferenceGrid referenceGrid(const CaseFile& c, const std::vector<PreparedGrid>& grids);

// The energy figures: the installed power Σ count × power over the schedule's types (a lower
// bound when a type's power is unknown: those types' entries are listed), the floor area
// ([case] floor_area, else the plan extent of `sceneBounds`), W/m² and W/m²/100 lx over the
// average of grids[reference.index].
EnergyReport energyReport(const CaseFile& c, const std::vector<LuminaireTypeReport>& schedule,
                          const Box& sceneBounds, const ReferenceGrid& reference,
                          const std::vector<GridReport>& grids);

}  // namespace candela
