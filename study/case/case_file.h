// The TOML case file (docs/case-format.md is the full reference): plain structs out, every path
// resolved relative to the case file, every bad key an InputError naming the file and line.
#pragma once

#include "base/warning.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "engine/radiance/reader.h"
#include "engine/trace_settings.h"
#include "base/math.h"
#include "engine/camera.h"
#include "engine/luminaire_source.h"
#include "photometry/sky_type.h"
#include "metrics/targets.h"
#include "study/compliance/compliance_spec.h"
#include "study/compliance/en13201_spec.h"
#include "study/compliance/en12464_2_spec.h"
#include "study/compliance/en1838_spec.h"
#include "study/grids/grid_quantity.h"
#include "study/grids/sensor_grid.h"

namespace candela {

struct ScenePath {
  std::filesystem::path file;  // Radiance scene, absolute or relative to the working directory
  FileLoc loc;                 // the `file` key
};

// One luminaire placed in the scene; `[[luminaire]]` entries with an `array` expand into one
// placement per fitting.
struct LuminairePlacement {
  std::filesystem::path file;           // IES LM-63 or EULUMDAT
  std::string name;                     // `name` or "luminaire<N>"; arrays append "[row,col]"
  Vec3 positionM{0.0};                  // photometric centre, m
  Vec3 aim{0.0, 0.0, -1.0};             // unit direction of the photometric nadir
  double spinDeg = 0.0;                 // rotation about the aim; 0: C0 plane towards +X
  double multiplier = 1.0;              // scales intensities
  double maintenanceFactor = 1.0;       // MF in (0, 1]; intensities scale by multiplier × MF
  // `opening_reflectance` in [0, 1]: the luminous opening becomes an opaque diffuse surface of
  // this reflectance (engine/luminaire_opening.h); absent: no surface (light passes the opening).
  std::optional<double> openingReflectance;
  // `power_w`: the luminaire's input power in W (> 0), in place of the file's input watts (the
  // luminaire schedule and the installed power, study/luminaire_schedule.h); unset: the file's.
  std::optional<double> powerW;
  // `emergency`: an emergency luminaire (EN 1838, docs/emergency.md); `emergency_factor` in (0, 1]:
  // the share of the file's flux it gives in emergency mode.
  bool emergency = false;
  double emergencyFactor = 1.0;
  int entry = 0;                        // index of the [[luminaire]] entry (0-based): CaseFile::luminaireEntries
  int row = 0, column = 0;              // position in the entry's array (0, 0 without array)
  FileLoc loc;                          // the [[luminaire]] entry
  LuminaireMounting mounting() const { return {name, positionM, aim, spinDeg, multiplier * maintenanceFactor}; }
};

// What a [[luminaire]] entry says once for all its placements (kept apart from them: a 10⁶
// fitting array would hold each string 10⁶ times).
struct LuminaireEntry {
  std::string name;                     // `name` or "luminaire<N>", without an array's "[row,col]"
  std::string fileText;                 // the `file` key as written (reports name the file so)
  FileLoc loc;                          // the [[luminaire]] entry
};

struct SiteSpec {
  bool present = false;
  // Latitude/longitude as written: a number in degrees (north/east positive) or a text such
  // as "37d52'N" that photometry's site helper parses. At most one of each pair is set.
  std::optional<double> latitudeDeg, longitudeDeg;
  std::string latitudeText, longitudeText;
  FileLoc latitudeLoc, longitudeLoc;
  double elevationM = 0.0;
  std::optional<double> timezoneHours;  // hours from UTC, standard time (east positive)
  double northDeg = 0.0;                // true north, degrees clockwise from model +Y
  std::string grid;                     // free text: the survey grid / CRS of the model (report only)
  FileLoc loc;
};



struct SkySpec {
  bool present = false;
  SkyType type;                         // photometry/sky_type.h
  std::string time;                     // local standard time "YYYY-MM-DDTHH:MM[:SS]", as written
  FileLoc timeLoc;
  std::optional<double> diffuseHorizontalIlluminanceLux;
  std::optional<double> directNormalIlluminanceLux;
  std::optional<double> directNormalIrradianceWm2;
  std::optional<double> diffuseHorizontalIrradianceWm2;
  double groundReflectance = 0.2;
  bool sun = true;                      // include the solar disc (where the sky type has one)
  std::filesystem::path weather;        // EPW file, empty if none
  std::optional<double> sunAltitudeDeg; // overrides the solar position computed from time/site
  std::optional<double> sunAzimuthDeg;  // degrees clockwise from north
  FileLoc loc;
};

enum class GridKind { kPlane, kPoints };

struct GridSpec {
  std::string name;
  GridKind kind = GridKind::kPlane;
  PlaneGridSpec plane;                  // kind = plane: geometry, spacing, border, normal
  std::filesystem::path pointsFile;     // kind = points
  std::optional<double> targetAverageLux;
  std::optional<double> targetUniformity;  // U0 = Emin/Eavg
  bool daylightFactor = false;          // report the grid as a daylight factor in %
  // `quantity` (study/grids/grid_quantity.h): unset, planar illuminance on the grid's normal (the
  // points file's normals), as before the key existed.
  std::optional<GridQuantity> quantity;
  FileLoc quantityLoc;
  Vec2 facing{1.0, 0.0};                // `facing`: plan direction, vertical and semi-cylindrical
  // `modelling`: cylindrical and horizontal illuminance at every point too, and their ratio
  // (EN 12464-1:2021 modelling).
  bool modelling = false;
  FileLoc modellingLoc;
  FileLoc loc;                          // the [[grid]] entry
  // Grids a [[task_area]] makes: its name and which of its areas this is; a background without
  // a `room` is clipped to the scene's plan extent when it is made (study/grids/prepared_grid.cpp).
  std::string taskArea;
  enum class Area { kNone, kTask, kSurrounding, kBackground, kCylindrical } area = Area::kNone;
  bool clipToRoom = false;
  // Grids a [[surface_grid]] makes (study/grids/surface_grids.h): its name, the scene surfaces this
  // grid lies on (their identifiers) and which surface of the room they are.
  std::string surfaceGrid;
  std::vector<std::string> onSurfaces;
  RoomSurface roomSurface = RoomSurface::kNone;
};

// A [[surface_grid]] (EN 12464-1:2021 walls and ceilings): a grid on every flat scene surface
// whose identifier matches one of `patterns` (globs, * and ?), one grid for each plane they lie
// in, sensors on the surface's side facing the room. The targets are the case's or, with a
// `room_type`, the standard's for walls and ceilings (metrics/targets.h).
struct SurfaceGridSpec {
  std::string name;
  std::vector<std::string> patterns;
  std::optional<RoomType> roomType;
  enum class Side { kAuto, kFront, kBack } side = Side::kAuto;
  std::optional<double> spacingM;       // unset: EN 12464-1 automatic for each surface
  double offsetM = 0.001;               // sensors this far off the surface, into the room
  std::optional<double> targetAverageLux, targetUniformity;  // override the room type's
  FileLoc loc, patternsLoc;
};

// A [[task_area]] (EN 12464-1:2021): the task area with its required maintained illuminance and
// uniformity, which makes three grids: the task area, its immediate surrounding (a 0.5 m band)
// and the background (a 3 m band beyond, within the room), each with the standard's targets
// (metrics/targets.h). The UGR limit is checked at the observers standing in the three areas.
struct TaskAreaSpec {
  std::string name;
  std::vector<Vec2> outline;            // plan polygon (a rectangle's four corners)
  double heightM = 0.8;
  double maintainedLux = 500.0;         // Ē_m of the task area
  std::optional<double> uniformity;     // U0 of the task area
  std::optional<double> ugrLimit;       // UGR_L
  std::optional<double> ra;             // required Ra (against the luminaires' colour rendering)
  // `cylindrical_illuminance` (Ē_z,m required, lx) and `modelling`: a fourth grid over the task
  // area at `eye_height` (1.2 m seated, 1.6 m standing) of cylindrical illuminance, U0 ≥ 0.10,
  // with the modelling ratio when asked (EN 12464-1:2021, "Cylindrical illuminance and modelling").
  std::optional<double> cylindricalLux;
  bool modelling = false;
  double eyeHeightM = 1.2;
  // `emergency = "high-risk"`: a high-risk task area of EN 1838:2013 4.4 (docs/emergency.md).
  bool emergencyHighRisk = false;
  std::optional<double> spacingM;      // `spacing`, m
  FileLoc loc;
};

// A [[view]]: the camera (engine/camera.h) with its name and contrast points.
struct ViewSpec : View {
  std::string name;
  // Contrast: a task point and a background point (m) seen from the view position; both or
  // neither. The run reports C = (Lt − Lb)/Lb and CRF = C / C_ref (docs/views.md).
  std::optional<Vec3> taskM, backgroundM;
  FileLoc loc;
};

// An [[observer]]: a glare rating (UGR, CIE 117) at an eye position without rendering, from every
// luminaire's luminous opening seen along a horizontal line of sight (docs/glare.md).
struct ObserverSpec {
  std::string name;
  Vec2 positionM{0.0};          // plan position of the observer
  double eyeHeightM = 1.2;      // above the floor plane z = 0: 1.2 m seated, 1.6 m standing
  Vec2 direction{0.0, 1.0};     // line of sight in plan (horizontal, as CIE 117's), unit
  std::optional<double> ugrLimit;  // UGR_L of EN 12464-1: pass when UGR ≤ the limit
  FileLoc loc;
  Vec3 eyeM() const { return {positionM.x, positionM.y, eyeHeightM}; }
};

// A [[window_group]] of an annual study (docs/annual.md "Window groups"): the glazing surfaces
// (identifiers or globs, * and ?) whose LM-83 blinds open and close together. Checked against the
// scene when it is read (study/window_groups.h).
struct WindowGroupSpec {
  std::string name;
  std::vector<std::string> patterns;
  // The closed blinds' diffuse transmittance, a factor on the glass's normal transmittance
  // (0, 1]; unset: LM-83-12 2.2.7's 20 % (study/blinds.h kBlindsTransmittance).
  std::optional<double> blindsTransmittance;
  FileLoc loc, patternsLoc;
  // Window states (docs/annual.md "Window states"): the group's geometry and materials in each
  // state, one Radiance file each; `patterns` (optional then) name base-scene surfaces the states
  // replace. The rule: `schedule`, a file of one state name per hour, or else LM-83's direct-sun
  // threshold on the grid `sunGrid` (empty: each grid for itself), first state below it, second above.
  struct State {
    std::string name;
    std::filesystem::path scene;
    FileLoc loc;
  };
  std::vector<State> states;
  std::filesystem::path schedule;
  std::string sunGrid;
  FileLoc scheduleLoc, sunGridLoc;
};

// Unset optionals take the quality preset's value (chosen by the engine).
struct Settings {
  Quality quality = Quality::kNormal;
  uint64_t seed = 1;
  std::optional<int> bounces;
  std::optional<int> samples;
  std::optional<Method> method;
  std::optional<double> targetRelativeError;  // target_error (percent in the file): per-point target
  int threads = 0;                      // 0 = all cores
  SceneReadOptions scene;               // patterns, nonplanar: how the scene files are read
};

// [annual]: settings of a climate-based annual study ([sky] type = "annual"). Defaults are those
// of the metrics' definitions (docs/annual.md).
struct AnnualSpec {
  bool present = false;
  double occupancyStartHour = 8.0;      // local standard time, "HH:MM" in the file
  double occupancyEndHour = 18.0;
  double daThresholdLux = 300.0;        // DA, cDA, sDA
  double udiLowLux = 100.0;             // UDI: fell short below, supplementary from here
  double udiHighLux = 3000.0;           // UDI: exceeded above
  double sdaFraction = 0.5;             // sDA: share of occupied hours at daThresholdLux
  double aseThresholdLux = 1000.0;      // ASE: direct sun
  double aseHours = 250.0;              // ASE: hours above aseThresholdLux
  int skySubdivision = 1;               // Reinhart MF: 1 = Tregenza's 145 patches
  int sunSamples = 4;                   // rays over the sun's disc per sensor and hour
  bool blinds = true;                   // LM-83's operable blinds for sDA
  std::optional<int> reportSensor;      // the sensor whose hours are plotted (index, 0-based)
  FileLoc reportSensorLoc;
  FileLoc loc;
};

struct OutputSpec {
  std::filesystem::path dir;            // default: "out" beside the case file
};

struct CaseFile {
  std::filesystem::path path;           // the case file itself
  std::string name;                     // [case] name, default: the file's stem
  std::string description;
  // [case] floor_area (m², > 0): the area the power density is over; unset: the plan (x-y)
  // extent of the scene's bounding box (study/luminaire_schedule.h).
  std::optional<double> floorAreaM2;
  // [case] reference_grid: the grid whose average illuminance W/m²/100 lx is taken on (a grid
  // of the case, horizontal illuminance, not a daylight factor); empty: the first such [[grid]],
  // else the first task area's task grid.
  std::string referenceGrid;
  FileLoc referenceGridLoc;
  std::vector<ScenePath> scenes;
  std::vector<LuminairePlacement> luminaires;
  std::vector<LuminaireEntry> luminaireEntries;  // one per [[luminaire]] entry, in case order
  std::vector<Portal> portals;          // [[portal]]: openings that guide sky sampling
  SiteSpec site;
  SkySpec sky;
  std::vector<GridSpec> grids;
  std::vector<ViewSpec> views;
  std::vector<ObserverSpec> observers;  // [[observer]]
  std::vector<TaskAreaSpec> taskAreas;  // [[task_area]]; their grids are in `grids`
  // [[surface_grid]]: their grids need the scene, and are added to `grids` when it is read
  // (withSurfaceGrids, study/grids/surface_grids.h).
  std::vector<SurfaceGridSpec> surfaceGrids;
  // [[compliance]]: the standards the case is checked against (study/compliance/compliance_spec.h); annual
  // cases only.
  std::vector<ComplianceSpec> compliance;
  // [[window_group]]: none, one group of all the glazing per grid (as before the key existed).
  std::vector<WindowGroupSpec> windowGroups;
  // [[escape_route]], [[open_area]], [[safety_point]]: EN 1838 (study/compliance/en1838_spec.h).
  EmergencySpec emergency;
  // [[road]]: EN 13201 (study/compliance/en13201_spec.h).
  RoadLightingSpec roadLighting;
  // [[task_area]] standard = "en12464-2", [[observer]] kind = "gr": EN 12464-2 (study/compliance/en12464_2_spec.h).
  OutdoorSpec outdoor;
  Settings settings;
  AnnualSpec annual;
  OutputSpec output;
};

// Reads and checks a case file. Throws InputError("case.toml:LINE: ...") for TOML syntax
// errors, unknown keys, wrong types, impossible values and missing referenced files.
CaseFile readCaseFile(const std::filesystem::path& path);

// Same from text; `path` names the file in errors and anchors relative paths.
CaseFile parseCaseFile(std::string_view text, const std::filesystem::path& path);

// grid_outside_scene (docs/warnings.md) at the grid's line when a point of the grid (the
// outline's corners for plane grids, every point of a points file) lies outside `bounds` grown by
// `toleranceM`; nothing otherwise. An empty box (no geometry) accepts every grid. `bounds` is the
// box of the scene and its luminaires (gridBounds): a grid over a flat ground lit by luminaires
// (a car park) lies inside it.
std::optional<Warning> gridOutsideScene(const GridSpec& grid, const Box& bounds, double toleranceM = 1e-3);

}  // namespace candela
