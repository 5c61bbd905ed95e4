// summary.json: the content of summary.csv as structured data (nlohmann-json), for scripts.
#pragma once

#include <filesystem>
#include <string>

#include "reports/report_data.h"

namespace candela {

// {
//   "case": {"name", "description", "file"}, "version", "started_at", "seed", "run_time_s",
//   "settings": {key: value, ...},
//   "grids": [{"name", "description", "quantity", "unit", "points", "average", "minimum",
//              "maximum", "u0", "ud", "target_average", "target_uniformity" (null if unset),
//              "verdict_average", "verdict_uniformity", "verdict",
//              grids with a `quantity` only: "quantity_key" ("cylindrical", ...),
//              modelling grids only: "modelling": {"cylindrical_average_lux",
//              "horizontal_average_lux", "ratio" (Ē_z/Ē_h), "range" ([0.3, 0.6]), "verdict"},
//              annual grids only: "DA300", "cDA300", "UDI_fell_short", "UDI_supplementary",
//              "UDI_autonomous", "UDI_exceeded" (grid means, % of occupied hours), "sDA300_50",
//              "ASE1000_250" (% of sensors), "sun_hours_mean" (h), "sensors", "occupied_hours",
//              "coefficients_time_s", "product_time_s" (s, null if unset)}],
//   annual runs only: "coefficients_time_s", "product_time_s",
//   "views": [{"name", "mean_luminance_cd_m2" (solid-angle weighted mean over the image),
//              "mean_luminance_relative_standard_error", "glare_source_luminance_cd_m2" (the
//              image's DGP glare sources pooled), "glare_source_luminance_relative_standard_error"
//              (fractions; null when unknown, or the view has no image glare source)}],
//   point-in-time runs only (docs/reports.md, "Luminaire schedule, energy and surfaces"):
//   "luminaires": [{"file", "entries", "manufacturer", "luminaire", "catalogue_number", "lamp",
//                   "count", "flux_lm", "lamp_flux_lm" (null: absolute photometry), "power_w"
//                   (null: unknown), "power_source" ("file", "case"), "light_output_ratio"
//                   (null: absolute), "multiplier", "maintenance_factor", "efficacy_lm_per_w"}],
//   "surfaces": [{"material", "type", "reflectance", "specular_reflectance", "transmittance"
//                 (null where the material passes no light), "surfaces"}],
//   "energy": {"installed_power_w", "installed_power_is_lower_bound", "floor_area_m2",
//              "floor_area_source" ("case", "scene plan extent"), "power_density_w_m2",
//              "power_density_w_m2_per_100lx", "reference_grid", "reference_grid_average_lux",
//              "luminaires_without_power"}
// }
// Values are in each grid's unit (lux, or % for daylight-factor grids); verdicts "pass",
// "fail" or "n/a".
std::string summaryJson(const ReportData& data);

// Writes <dir>/summary.json and returns its path.
std::filesystem::path writeSummaryJson(const std::filesystem::path& dir, const ReportData& data);

// summary.csv and summary.json together.
void writeSummary(const std::filesystem::path& dir, const ReportData& data);

}  // namespace candela
