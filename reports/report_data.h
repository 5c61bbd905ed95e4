// Plain data the report writers take: no engine types, so reports/ depends on base and metrics
// only; metrics' result types are held as they are. study/ fills these from the case file and the
// computed grids.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/math.h"
#include "base/warning.h"
#include "metrics/annual.h"
#include "metrics/grid_stats.h"
#include "metrics/modelling.h"
#include "metrics/targets.h"
#include "reports/compliance_report.h"
#include "reports/polar_plot_svg.h"

namespace candela {

// A sensor as written to the grid CSV: position in m, unit normal.
struct ReportPoint {
  Vec3 position{0.0};
  Vec3 normal{0.0, 0.0, 1.0};
};

// An extra CSV column after illuminance_lux, e.g. {"error_lux", ...} or {"daylight_factor_pct", ...}.
struct ExtraColumn {
  std::string name;
  std::vector<double> values;  // one per point
};

// Where the points of a grid lie in its plane, for plans. A regular grid is a lattice of
// `columns` × `rows` cells of `spacingM`, cell (0, 0) starting at `originM`; each point sits at
// the centre of cells[i]. Irregular grids (points files) are drawn as dots at planPositions.
struct PlanLayout {
  bool regular = false;
  int columns = 0, rows = 0;
  Vec2 originM{0.0};
  Vec2 spacingM{0.0};
  std::vector<glm::ivec2> cells;     // per point (regular grids)
  std::vector<Vec2> planPositions;   // per point, plan coordinates in m
  std::vector<Vec2> outline;         // calculation area outline (m), optional
};

// One time step of an annual run, as the weather file (EPW) labels it: month 1–12, day of month
// 1–31, and the hour *ending* 1–24 (EPW convention: hour 1 covers 00:00–01:00 local standard time).
struct HourStamp {
  uint8_t month = 1;
  uint8_t day = 1;
  uint8_t hourEnding = 1;
  bool operator==(const HourStamp&) const = default;
};

// The annual results of one grid, for the annual CSV, the summary and the HTML section. The
// per-sensor vectors have one entry per point of the grid, in the grid's point order.
struct AnnualGridReport {
  std::vector<SensorAnnualMetrics> sensors;  // per sensor (metrics/annual.h)
  GridAnnualSummary summary;                 // grid means and shares, as summary.json names them
  // Temporal map of one sensor: its index in the grid, and its illuminance in lux for every
  // time step of the year (`hours` labels them; both have the same length, 8760 or 8784).
  int chosenSensor = -1;                     // < 0: no temporal map
  std::vector<double> chosenSensorLux;
  std::vector<HourStamp> hours;
  // The case's [[window_group]]s (docs/annual.md "Window groups"), each with the occupied hours
  // its LM-83 blinds were closed for this grid; empty without window groups.
  struct WindowGroupHours {
    std::string name;
    std::vector<std::string> surfaces;
    int blindsClosedHours = 0;
  };
  std::vector<WindowGroupHours> windowGroups;
  // Window states (docs/annual.md "Window states"): per group and state, the occupied hours the
  // grid's switched year spends in it and the metrics of the year with the group in that state
  // all year (the other groups in their first state); empty without states.
  struct WindowStateResult {
    std::string group, state;
    int occupiedHours = 0;
    GridAnnualSummary summary;
  };
  std::vector<WindowStateResult> windowStates;
};

// What a plan shows besides its grid (report.html): a luminaire's position or an observer's, in
// plan coordinates x, y (m), with its name; an observer's line of sight.
struct PlanMarker {
  enum class Kind { kLuminaire, kObserver } kind = Kind::kLuminaire;
  Vec2 positionM{0.0};
  Vec2 direction{0.0, 1.0};  // observers
  std::string name;
};

// The scene cut horizontally for the plans of horizontal grids (study/grids/plan_section.h), in plan
// coordinates x, y (m): what the plan draws over the grid's colours and under its markers.
struct PlanSegment {
  Vec2 a{0.0}, b{0.0};
};

struct PlanFootprint {
  std::vector<Vec2> outline;  // ≥ 3 vertices
  bool outlined = true;       // false for mesh triangles: their shared edges are not the object's
};

struct PlanSection {
  double cutHeightM = 0.0;      // z of the cut plane, m
  double floorLevelM = 0.0;     // z of the floor under it, m
  bool raisedAboveFloor = false;  // the grids lie at floor level: the cut is 1 m above the floor
  std::vector<PlanSegment> walls;          // opaque surfaces crossing the cut plane
  std::vector<PlanSegment> openings;       // glazing crossing it
  std::vector<PlanSegment> openingsAbove;  // vertical glazing above it (a sill higher than the cut)
  std::vector<PlanFootprint> furniture;    // horizontal surfaces between the floor and the cut
  std::size_t droppedSegments = 0;         // past the cap on segments (study/grids/plan_section.h)
  std::size_t droppedFootprints = 0;       // past the cap on footprint vertices
  std::size_t skippedCurved = 0;           // spheres, cones and rings crossing the cut: not drawn
};

// One grid's results and verdicts.
struct GridReport {
  std::string name;
  bool planIsXY = false;             // the plan's coordinates are x, y (a horizontal grid): markers fit it
  std::string taskArea;              // the [[task_area]] that made the grid, else empty
  std::string area;                  // then "task area", "immediate surrounding" or "background"
  std::string surfaceGrid;           // the [[surface_grid]] that made the grid, else empty
  std::string roomSurface;           // then "wall", "ceiling", "floor" or "surface"
  std::string description;           // e.g. "horizontal, 0.80 m above floor"
  std::string quantity = "Illuminance";  // or e.g. "Cylindrical illuminance Ē_z", "Daylight factor"
  // The case's `quantity` as written ("cylindrical", ...): empty when the grid gives none.
  std::string quantityKey;
  std::string unit = "lx";           // "lx", or "%" for daylight factor grids
  std::vector<double> values;        // per point, in `unit`
  GridStats stats;                   // in `unit`
  GridTargets targets;
  TargetCheck check;
  PlanLayout layout;
  std::optional<AnnualGridReport> annual;  // set for grids of an annual run ([sky] type = "annual")
  std::optional<ModellingResult> modelling;  // set for grids with `modelling = true`
  int planSection = -1;              // index into ReportData::planSections; -1: none drawn
};

// The run as a whole.
struct RunInfo {
  std::string caseName;
  std::string description;
  std::string caseFile;
  std::string version;               // candela version
  std::string startedAt;             // ISO 8601 local time of the run
  uint64_t seed = 0;
  double runTimeS = 0.0;             // wall-clock time of the computation, s
  // Annual runs: wall-clock time of the daylight-coefficient step and of the 8760-hour product
  // (coefficients × sky vectors), s. Unset for other runs.
  std::optional<double> coefficientsTimeS;
  std::optional<double> productTimeS;
  // Settings as shown to the reader, in order: {"quality", "normal"}, {"bounces", "2"}, ...
  std::vector<std::pair<std::string, std::string>> settings;
  // The function files the scene's patterns read (where they were found: docs/engine.md).
  std::vector<std::string> functionFiles;
};

// A rendered view: its pictures (PNG bytes, embedded in the HTML) and visual metrics as rows.
struct ViewReport {
  std::string name;
  std::string description;           // e.g. "perspective 60° × 45°, 480 × 320 px"
  std::vector<uint8_t> falseColorPng;  // luminance in false colour with its legend
  std::vector<uint8_t> previewPng;     // tone-mapped
  std::vector<std::pair<std::string, std::string>> metrics;  // {"UGR", "18.5"}, ...
  // The picture's noise (docs/views.md): the solid-angle weighted mean luminance in cd/m² and its
  // relative standard error (a fraction; NaN when the image has no error estimate), and the same
  // for the image's glare sources pooled (unset when the view has none: not a fisheye, or no
  // pixel above the DGP threshold).
  double meanLuminanceCdM2 = 0.0;
  double meanLuminanceRelativeStandardError = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> glareSourceLuminanceCdM2;
  std::optional<double> glareSourceLuminanceRelativeStandardError;
};

// An [[observer]]'s glare rating (study/view_glare.h luminaireGlare): UGR (CIE 117) from the
// luminaires in view along a horizontal line of sight, against EN 12464-1's limit UGR_L.
struct ObserverReport {
  std::string name;
  Vec3 eyeM{0.0};
  Vec2 direction{0.0, 1.0};
  std::optional<double> ugr;       // unset: no luminaire in view
  std::optional<double> ugrLimit;
  std::size_t luminairesInView = 0;
  double verticalLux = 0.0;        // at the eye, facing the line of sight
  double backgroundCdM2 = 0.0;     // UGR's Lb: the indirect part of that over π
  // pass when UGR ≤ UGR_L (or no luminaire in view); unset without a limit.
  std::optional<bool> pass() const {
    if (!ugrLimit) return std::nullopt;
    return !ugr || *ugr <= *ugrLimit;
  }
};

// A [[task_area]] checked as EN 12464-1:2021 asks (docs/en12464.md): its grids (indices into
// ReportData::grids; -1 for a band left empty by the room), the highest UGR of the observers
// standing in its areas against its limit, and the overall verdict (fail when any checked line
// fails, pass when every checked line passes).
struct TaskAreaReport {
  std::string name;
  int task = -1, surrounding = -1, background = -1;
  int cylindrical = -1;  // the Ē_z (and modelling) grid at eye height, when asked for
  std::optional<double> ugrLimit, ugr;
  std::vector<std::string> observers;  // those standing in the task area or its bands
  std::optional<double> ra;            // required Ra
  // The least Ra of the luminaires over the task area and its bands (else of all the case's) where
  // every one's file states it (EULUMDAT's colour rendering); the files that do not (IES); the
  // verdict: checked only when every one states it (study/task_area_report.cpp).
  std::optional<double> leastRa;
  std::vector<std::string> raUnknown;
  Verdict raVerdict = Verdict::kNotChecked;
  Verdict ugrVerdict = Verdict::kNotChecked;
  Verdict verdict = Verdict::kNotChecked;
};

// A [[surface_grid]] (walls and ceilings, EN 12464-1:2021): its grids (indices into
// ReportData::grids), the room type whose requirements it is checked against (empty: the case's
// own targets or none) and the overall verdict.
struct SurfaceGridReport {
  std::string name;
  std::string roomType;
  std::vector<int> grids;
  Verdict verdict = Verdict::kNotChecked;
};

// One type of luminaire of the case (the luminaire schedule, docs/en12464.md): the placements
// with the same photometric file, multiplier, maintenance factor and power. Texts as the file
// gives them (empty when it does not); flux per luminaire with the multiplier, before the
// maintenance factor.
struct LuminaireTypeReport {
  std::string file;                       // the photometric file, as the case names it
  std::vector<std::string> entries;       // the [[luminaire]] entries' names, in case order
  std::string manufacturer, luminaire, catalogueNumber, lamp;
  std::string colourRendering;            // EULUMDAT lamp set 1's field as written; empty for IES
  std::optional<double> leastRa;          // the least Ra it promises (study/luminaire_schedule.h)
  std::size_t count = 0;                  // luminaires placed (every fitting of an array)
  double fluxLm = 0.0;                    // luminaire flux, lm
  std::optional<double> lampFluxLm;       // rated lamp flux, lm; unset for absolute photometry
  std::optional<double> powerW;           // input power per luminaire, W; unset when unknown
  bool powerFromCase = false;             // `power_w` given in place of the file's
  std::optional<double> lightOutputRatio; // fraction; unset for absolute photometry
  double multiplier = 1.0;
  double maintenanceFactor = 1.0;
  std::optional<double> efficacyLmPerW;   // fluxLm / powerW; unset when the power is unknown
  std::vector<PolarCurve> polar;          // C0-C180 and C90-C270 intensity curves, cd
};

// A material a surface of the scene uses, with its photopic reflectance (and transmittance for
// the materials that pass light): the engine's derived values (Radiance's definitions).
struct SurfaceMaterialReport {
  std::string material;                   // the scene's name of it
  std::string type;                       // Radiance type: "plastic", "metal", "trans", "glass", ...
  double reflectance = 0.0;               // photopic, diffuse and specular, at normal incidence
  double specularReflectance = 0.0;       // the specular part of it
  std::optional<double> transmittance;    // photopic, at normal incidence; trans and glass only
  std::size_t surfaces = 0;               // surfaces (primitives, mesh triangles) of it
};

// The installed power of the luminaires over the floor area, and normalised by the reference
// grid's average illuminance (W/m²/100 lx).
struct EnergyReport {
  double installedPowerW = 0.0;           // Σ count × power over the types with known power
  std::optional<double> floorAreaM2;      // unset: no geometry and no [case] floor_area
  bool floorAreaFromCase = false;         // [case] floor_area; else the scene's plan extent
  Vec2 planExtentM{0.0};                  // the scene's bounding box in x and y, m
  std::optional<double> powerDensityWm2;
  std::optional<double> powerDensityWm2Per100Lux;
  std::string referenceGrid;              // empty: no horizontal illuminance grid
  std::string referenceGridReason;        // why it is that grid, for the reader
  double referenceAverageLux = 0.0;
  std::vector<std::string> luminairesWithoutPower;  // [[luminaire]] entries of unknown power
};

// What the point-in-time study adds about the installation: the luminaire schedule, the surfaces'
// reflectances and the energy figures.
struct InstallationReport {
  std::vector<LuminaireTypeReport> luminaires;
  std::vector<SurfaceMaterialReport> surfaces;
  EnergyReport energy;
};

struct ReportData {
  RunInfo run;
  std::vector<GridReport> grids;
  std::vector<ViewReport> views;
  std::vector<ObserverReport> observers;
  std::vector<TaskAreaReport> taskAreas;
  std::vector<SurfaceGridReport> surfaceGrids;
  std::vector<PlanMarker> planMarkers;  // luminaires and observers, drawn on horizontal grids' plans
  std::vector<PlanSection> planSections;  // one per distinct cut height (GridReport::planSection)
  std::optional<InstallationReport> installation;  // point-in-time runs
  std::vector<ComplianceReport> compliance;        // [[compliance]] entries (annual runs)
  double northDeg = 0.0;             // true north, degrees clockwise from plan +Y (north arrow)
  std::vector<Warning> warnings;     // what the run found suspicious (docs/warnings.md), in order
};

// The run's verdict as a whole (summary.json's "verdict", the report's summary): fail when any
// checked line fails (a grid's targets, a wall's or ceiling's and a task area's grids included, a
// modelling ratio, a task area's Ra, an observer's UGR, a [[compliance]] entry), pass when at least one is checked and all pass, else not checked. `checked`
// and `failed`, when given, count the lines.
Verdict overallVerdict(const ReportData& data, int* checked = nullptr, int* failed = nullptr);

// What the checked lines of overallVerdict are, in the report's words and order, only those the
// run has: "grids", "walls and ceiling", "modelling", "colour rendering", "observers' UGR",
// "daylight compliance", "standards" (a standard written by its own unit: EN 1838).
std::vector<std::string> checkedCategories(const ReportData& data);

// "2026-03-21" → "21 March 2026"; "2026-03-21T09:00" → "21 March 2026, 09:00" (the time as
// written: the reports' times are local standard time). Other text is returned as it is.
std::string dateInWords(const std::string& isoDate);

// "1 point", "3 points": a count with its noun in the right number.
std::string countOf(long long n, const std::string& singular, const std::string& plural);

// Shortest text that reads back to `v` within `significant` digits ("%.*g"); "nan"/"inf" kept.
std::string formatNumber(double v, int significant = 8);

// Fixed decimals for tables: formatFixed(523.456, 1) = "523.5".
std::string formatFixed(double v, int decimals);

// A grid name made safe as a file name: [A-Za-z0-9_-] kept, anything else becomes '_'.
std::string safeFileName(const std::string& name);

// One field of every sensor's annual metrics, e.g. annualColumn(a, &SensorAnnualMetrics::da).
template <class T>
std::vector<double> annualColumn(const AnnualGridReport& a, T SensorAnnualMetrics::*field) {
  std::vector<double> out;
  out.reserve(a.sensors.size());
  for (const SensorAnnualMetrics& s : a.sensors) out.push_back(static_cast<double>(s.*field));
  return out;
}

}  // namespace candela
