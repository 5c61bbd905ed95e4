#include "study/case/case_file.h"

#include "engine/scene.h"
#include "study/case/case_scene.h"
#include "study/grids/prepared_grid.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path casesDir() { return fs::path(CANDELA_TEST_DATA) / "cases"; }

// "LINE: file:LINE: message" of the InputError parsing `text` as the case `path` throws, or
// "accepted".
std::string parseError(const std::string& text, const fs::path& path) {
  try {
    parseCaseFile(text, path);
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

TEST(CaseFile, ReadsEveryKeyOfTheFullCase) {
  const fs::path path = casesDir() / "full" / "case.toml";
  const CaseFile c = readCaseFile(path);
  const fs::path dir = path.parent_path();
  EXPECT_EQ(c.name, "Test office");
  EXPECT_EQ(c.description, "All keys, for the reader's tests");

  ASSERT_EQ(c.scenes.size(), 1u);
  EXPECT_EQ(c.scenes[0].file, (dir / "geometry/room.rad").lexically_normal());
  EXPECT_EQ(c.scenes[0].loc.line, 7);

  // 2 × 3 array + one single fitting. Columns run along +X by 1.5 m, rows along +Y by 2 m.
  ASSERT_EQ(c.luminaires.size(), 7u);
  const LuminairePlacement& last = c.luminaires[5];
  EXPECT_EQ(last.row, 1);
  EXPECT_EQ(last.column, 2);
  EXPECT_EQ(last.positionM, Vec3(1.5 + 2 * 1.5, 1.0 + 2.0, 2.8));
  EXPECT_EQ(last.name, "DL[2,3]");
  EXPECT_DOUBLE_EQ(last.spinDeg, 90.0);
  EXPECT_DOUBLE_EQ(last.multiplier, 2.0);
  EXPECT_DOUBLE_EQ(last.maintenanceFactor, 0.8);
  EXPECT_EQ(last.aim, Vec3(0, 0, -1));  // default
  EXPECT_EQ(last.loc.line, 9);
  const LuminairePlacement& single = c.luminaires[6];
  EXPECT_EQ(single.entry, 1);
  EXPECT_EQ(single.name, "luminaire2");
  EXPECT_EQ(single.aim, Vec3(0, 0, -1));  // normalised from [0, 0, -2]
  EXPECT_EQ(single.file, (dir / "luminaires/downlight.ies").lexically_normal());
  ASSERT_TRUE(single.openingReflectance.has_value());
  EXPECT_DOUBLE_EQ(*single.openingReflectance, 0.5);
  EXPECT_FALSE(last.openingReflectance.has_value());  // absent: no opening surface

  EXPECT_TRUE(c.site.present);
  EXPECT_EQ(c.site.latitudeText, "37d52'N");  // kept as written
  EXPECT_FALSE(c.site.latitudeDeg.has_value());
  EXPECT_DOUBLE_EQ(c.site.longitudeDeg.value(), -122.27);
  EXPECT_DOUBLE_EQ(c.site.elevationM, 52.0);
  EXPECT_DOUBLE_EQ(c.site.timezoneHours.value(), -8.0);
  EXPECT_DOUBLE_EQ(c.site.northDeg, 10.0);
  EXPECT_EQ(c.site.grid, "local");

  EXPECT_EQ(c.sky.type.kind, SkyKind::kCieGeneral);
  EXPECT_EQ(c.sky.type.cieType, 12);
  EXPECT_EQ(skyTypeName(c.sky.type), "cie:12");
  EXPECT_EQ(c.sky.time, "2026-03-21T12:00:00");  // a TOML date-time, written out
  EXPECT_DOUBLE_EQ(c.sky.diffuseHorizontalIlluminanceLux.value(), 10000.0);
  EXPECT_DOUBLE_EQ(c.sky.groundReflectance, 0.25);
  EXPECT_FALSE(c.sky.sun);
  EXPECT_EQ(c.sky.weather, (dir / "weather/site.epw").lexically_normal());
  EXPECT_DOUBLE_EQ(c.sky.sunAltitudeDeg.value(), 45.0);
  EXPECT_DOUBLE_EQ(c.sky.sunAzimuthDeg.value(), 180.0);

  ASSERT_EQ(c.grids.size(), 4u);
  const GridSpec& wp = c.grids[0];
  EXPECT_EQ(wp.name, "workplane");
  EXPECT_EQ(wp.kind, GridKind::kPlane);
  EXPECT_TRUE(wp.plane.isRectangle);
  EXPECT_DOUBLE_EQ(wp.plane.origin.z, 0.8);
  EXPECT_DOUBLE_EQ(wp.plane.spacingM.value(), 0.5);
  EXPECT_DOUBLE_EQ(wp.plane.borderM, 0.5);
  EXPECT_DOUBLE_EQ(wp.targetAverageLux.value(), 500.0);
  EXPECT_DOUBLE_EQ(wp.targetUniformity.value(), 0.6);
  EXPECT_EQ(makePlaneGrid(wp.plane).size(), 60u);  // (5 m / 0.5) × (3 m / 0.5)
  EXPECT_FALSE(c.grids[1].plane.isRectangle);
  EXPECT_FALSE(c.grids[1].plane.spacingM.has_value());  // "auto"
  EXPECT_TRUE(c.grids[1].daylightFactor);
  const GridSpec& wall = c.grids[2];
  EXPECT_EQ(wall.plane.origin, Vec3(6, 0, 0));
  EXPECT_EQ(wall.plane.vAxis, Vec3(0, 0, 1));
  EXPECT_EQ(wall.plane.normal.value(), Vec3(-1, 0, 0));
  EXPECT_EQ(makePlaneGrid(wall.plane).size(), 12u);
  EXPECT_EQ(c.grids[3].kind, GridKind::kPoints);
  EXPECT_EQ(c.grids[3].pointsFile, (casesDir() / "points/desk.pts").lexically_normal());

  ASSERT_EQ(c.views.size(), 2u);
  EXPECT_EQ(c.views[0].name, "entrance");
  EXPECT_NEAR(c.views[0].direction.x, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(c.views[0].resolution, glm::ivec2(320, 240));
  EXPECT_EQ(c.views[0].fovDeg, Vec2(70, 50));
  EXPECT_EQ(c.views[1].name, "view2");
  EXPECT_EQ(c.views[1].type, ViewType::kFisheye);
  EXPECT_EQ(c.views[1].fovDeg, Vec2(180, 180));

  EXPECT_EQ(c.settings.quality, Quality::kHigh);
  EXPECT_EQ(c.settings.seed, 42u);
  EXPECT_EQ(c.settings.bounces.value(), 3);
  EXPECT_EQ(c.settings.samples.value(), 256);
  EXPECT_EQ(c.settings.method.value(), Method::kPath);
  EXPECT_DOUBLE_EQ(c.settings.targetRelativeError.value(), 0.005);
  EXPECT_EQ(c.settings.threads, 2);
  EXPECT_EQ(c.settings.scene.objMapping, (dir / "geometry" / "faces.map").lexically_normal());
  EXPECT_EQ(c.output.dir, (dir / "results").lexically_normal());
}

TEST(CaseFile, DefaultsOfAMinimalCase) {
  const CaseFile c = readCaseFile(casesDir() / "minimal.toml");
  EXPECT_EQ(c.name, "minimal");
  EXPECT_FALSE(c.site.present);
  EXPECT_FALSE(c.sky.present);
  EXPECT_EQ(c.sky.type.kind, SkyKind::kNone);
  ASSERT_EQ(c.grids.size(), 1u);
  EXPECT_EQ(c.grids[0].name, "grid1");
  EXPECT_FALSE(c.grids[0].plane.spacingM.has_value());
  // Auto on 5 m × 4 m: p = 0.6 m → 9 × 7 cells.
  EXPECT_EQ(makePlaneGrid(c.grids[0].plane).size(), 63u);
  EXPECT_EQ(c.settings.quality, Quality::kNormal);
  EXPECT_EQ(c.settings.seed, 1u);
  EXPECT_FALSE(c.settings.bounces.has_value());
  EXPECT_EQ(c.output.dir, (casesDir() / "out").lexically_normal());
}

// [[grid]] quantity, facing, modelling: read as written, facing normalised, and absent keys
// leave the grid as before (planar on its normal, no modelling).
TEST(CaseFile, GridQuantityKeys) {
  const fs::path path = casesDir() / "errors" / "quantity.toml";
  const std::string grid = "[[grid]]\ncorners = [[0, 0], [4, 3]]\nheight = 1.2\n";
  const CaseFile c = parseCaseFile(grid + "quantity = \"semi-cylindrical\"\nfacing = [0, -2]\nmodelling = true\n" + grid +
                                       "quantity = \"cylindrical\"\n" + grid,
                                   path);
  ASSERT_EQ(c.grids.size(), 3u);
  EXPECT_EQ(c.grids[0].quantity, GridQuantity::kSemiCylindrical);
  EXPECT_EQ(c.grids[0].quantityLoc.line, 4);
  EXPECT_EQ(c.grids[0].facing, Vec2(0.0, -1.0));
  EXPECT_TRUE(c.grids[0].modelling);
  EXPECT_EQ(c.grids[0].modellingLoc.line, 6);
  EXPECT_EQ(c.grids[1].quantity, GridQuantity::kCylindrical);
  EXPECT_FALSE(c.grids[1].modelling);
  EXPECT_FALSE(c.grids[2].quantity.has_value());
  EXPECT_FALSE(c.grids[2].modelling);
  // Every name reads back to its quantity.
  for (GridQuantity q : {GridQuantity::kHorizontal, GridQuantity::kVertical, GridQuantity::kCylindrical,
                         GridQuantity::kSemiCylindrical, GridQuantity::kHemispherical})
    EXPECT_EQ(parseGridQuantity(gridQuantityKey(q)), q);
  EXPECT_FALSE(parseGridQuantity("Cylindrical").has_value());
}

TEST(CaseFile, AnnualKeysAndTheirDefaults) {
  const fs::path path = casesDir() / "errors" / "annual.toml";  // relative paths resolve from here
  const std::string head = "[sky]\ntype = \"annual\"\nweather = \"../../epw/synthetic_golden_2026.epw\"\n";
  const CaseFile d = parseCaseFile(head, path);
  EXPECT_EQ(d.sky.type.kind, SkyKind::kAnnual);
  EXPECT_FALSE(d.annual.present);
  EXPECT_EQ(d.annual.occupancyStartHour, 8.0);
  EXPECT_EQ(d.annual.occupancyEndHour, 18.0);
  EXPECT_EQ(d.annual.daThresholdLux, 300.0);
  EXPECT_EQ(d.annual.udiLowLux, 100.0);
  EXPECT_EQ(d.annual.udiHighLux, 3000.0);
  EXPECT_EQ(d.annual.sdaFraction, 0.5);
  EXPECT_EQ(d.annual.aseThresholdLux, 1000.0);
  EXPECT_EQ(d.annual.aseHours, 250.0);
  EXPECT_EQ(d.annual.skySubdivision, 1);
  EXPECT_TRUE(d.annual.blinds);
  EXPECT_FALSE(d.annual.reportSensor.has_value());
  const CaseFile c = parseCaseFile(head + "[annual]\noccupancy_start = \"07:30\"\noccupancy_end = \"17:45\"\n"
                                          "da_threshold = 500\nudi_low = 200\nudi_high = 2500\nsda_fraction = 0.6\n"
                                          "ase_threshold = 1200\nase_hours = 100\nsky_subdivision = 2\nsun_samples = 9\n"
                                          "blinds = false\nreport_sensor = 17\n",
                                   path);
  EXPECT_TRUE(c.annual.present);
  EXPECT_EQ(c.annual.occupancyStartHour, 7.5);
  EXPECT_EQ(c.annual.occupancyEndHour, 17.75);
  EXPECT_EQ(c.annual.daThresholdLux, 500.0);
  EXPECT_EQ(c.annual.udiLowLux, 200.0);
  EXPECT_EQ(c.annual.udiHighLux, 2500.0);
  EXPECT_EQ(c.annual.sdaFraction, 0.6);
  EXPECT_EQ(c.annual.aseThresholdLux, 1200.0);
  EXPECT_EQ(c.annual.aseHours, 100.0);
  EXPECT_EQ(c.annual.skySubdivision, 2);
  EXPECT_EQ(c.annual.sunSamples, 9);
  EXPECT_FALSE(c.annual.blinds);
  EXPECT_EQ(c.annual.reportSensor.value_or(-1), 17);
  EXPECT_EQ(c.annual.reportSensorLoc.line, 16);  // the 16th line of the text
}

// [[observer]]: plan position, eye height (1.2 m seated by default), a horizontal line of sight
// (normalised), an optional UGR limit; errors at their key's line.
TEST(CaseFile, ObserverKeysDefaultsAndErrors) {
  const fs::path path = casesDir() / "errors" / "observer.toml";
  const CaseFile c = parseCaseFile(
      "[[observer]]\nname = \"desk\"\nposition = [2.0, 1.5]\ndirection = [0.0, 2.0]\nugr_limit = 19\n"
      "[[observer]]\nposition = [4.0, 1.0]\ndirection = [-1.0, 0.0]\neye_height = 1.6\n",
      path);
  ASSERT_EQ(c.observers.size(), 2u);
  EXPECT_EQ(c.observers[0].name, "desk");
  EXPECT_EQ(c.observers[0].eyeM(), Vec3(2.0, 1.5, 1.2));
  EXPECT_EQ(c.observers[0].direction, Vec2(0.0, 1.0));
  EXPECT_EQ(c.observers[0].ugrLimit.value(), 19.0);
  EXPECT_EQ(c.observers[0].loc.line, 1);
  EXPECT_EQ(c.observers[1].name, "observer2");
  EXPECT_EQ(c.observers[1].eyeM(), Vec3(4.0, 1.0, 1.6));
  EXPECT_FALSE(c.observers[1].ugrLimit.has_value());
  auto error = [&](const std::string& text) { return parseError(text, path); };
  EXPECT_EQ(error("[[observer]]\nposition = [0, 0]\n\ndirection = [0, 0]\n").rfind("4: ", 0), 0u);  // at its line
  EXPECT_NE(error("[[observer]]\nposition = [0, 0]\ndirection = [0, 0]\n").find("'direction' must not be zero"),
            std::string::npos);
  EXPECT_NE(error("[[observer]]\ndirection = [0, 1]\n").find("needs the key 'position'"), std::string::npos);
  EXPECT_NE(error("[[observer]]\nposition = [0, 0]\ndirection = [0, 1]\neye_height = 0\n")
                .find("'eye_height' must be greater than 0"),
            std::string::npos);
  EXPECT_NE(error("[[observer]]\nposition = [0, 0]\ndirection = [0, 1]\nugr_limit = 50\n")
                .find("'ugr_limit' must be between 0 and 40"),
            std::string::npos);
  EXPECT_NE(error("[[observer]]\nposition = [0, 0]\ndirection = [0, 1]\nheight = 1\n").find("unknown key 'height'"),
            std::string::npos);
  EXPECT_NE(error("[[observer]]\nname = \"a\"\nposition = [0, 0]\ndirection = [0, 1]\n"
                  "[[observer]]\nname = \"a\"\nposition = [1, 0]\ndirection = [0, 1]\n")
                .find("two observers are named 'a'"),
            std::string::npos);
}

struct ErrorCase {
  const char* file;
  int line;
  const char* words;  // a piece of the message
};

class CaseFileError : public testing::TestWithParam<ErrorCase> {};

TEST_P(CaseFileError, NamesFileAndLine) {
  const ErrorCase& e = GetParam();
  const fs::path path = casesDir() / "errors" / e.file;
  try {
    readCaseFile(path);
    FAIL() << e.file << " was accepted";
  } catch (const InputError& err) {
    EXPECT_EQ(err.loc().file, path.string());
    EXPECT_EQ(err.loc().line, e.line) << err.what();
    EXPECT_NE(std::string(err.what()).find(e.words), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find(std::string(e.file) + ":" + std::to_string(e.line) + ": "),
              std::string::npos)
        << err.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, CaseFileError,
    testing::Values(ErrorCase{"syntax_error.toml", 5, "TOML syntax error"},
                    ErrorCase{"unknown_top_key.toml", 4, "unknown key 'grids'"},
                    ErrorCase{"unknown_grid_key.toml", 8, "unknown key 'spacng' in [[grid]]"},
                    ErrorCase{"unknown_array_key.toml", 4, "unknown key 'gap'"},
                    ErrorCase{"wrong_type.toml", 4, "'height' must be a number, got a string"},
                    ErrorCase{"missing_scene.toml", 6, "scene file 'geometry/nowhere.rad' not found"},
                    ErrorCase{"missing_luminaire.toml", 3, "luminaire file 'no_such.ies' not found"},
                    ErrorCase{"missing_weather.toml", 3, "weather file 'no_such.epw' not found"},
                    ErrorCase{"missing_obj_map.toml", 3, "OBJ mapping file 'no_such.map' not found"},
                    ErrorCase{"missing_points.toml", 5, "sensor points file 'no_such.pts' not found"},
                    ErrorCase{"negative_spacing.toml", 4, "'spacing' must be greater than 0"},
                    ErrorCase{"zero_area.toml", 3, "zero area"},
                    ErrorCase{"bad_resolution.toml", 4, "'resolution' must be between 1 and 16384"},
                    ErrorCase{"contrast_half.toml", 5, "needs both 'task' and 'background'"},
                    ErrorCase{"unknown_sky.toml", 5, "unknown sky type 'cloudy'"},
                    ErrorCase{"unknown_quality.toml", 3, "unknown quality 'ultra'"},
                    ErrorCase{"bad_target_error.toml", 2, "'target_error' must be between 0 and 100 (percent)"},
                    ErrorCase{"duplicate_grid.toml", 6, "two grids are named 'a'"},
                    ErrorCase{"missing_position.toml", 2, "needs the key 'position'"},
                    ErrorCase{"bad_opening_reflectance.toml", 5,
                              "'opening_reflectance' must be between 0 and 1 (a diffuse reflectance), got 1.2"},
                    ErrorCase{"negative_opening_reflectance.toml", 4, "'opening_reflectance' must be between 0 and 1"},
                    ErrorCase{"bad_time.toml", 3, "'time' must read YYYY-MM-DDTHH:MM"},
                    ErrorCase{"border_eats_grid.toml", 3, "leaves no area"},
                    ErrorCase{"bad_latitude.toml", 2, "'latitude' must be between -90 and 90"},
                    ErrorCase{"bad_uniformity.toml", 4, "'target_uniformity' must be between 0 and 1"},
                    ErrorCase{"annual_bad_clock.toml", 6, "'occupancy_start' must be a time of day"},
                    ErrorCase{"annual_occupancy_order.toml", 5, "'occupancy_end' must be later than 'occupancy_start'"},
                    ErrorCase{"annual_threshold_order.toml", 5, "udi_low < da_threshold < udi_high"},
                    ErrorCase{"annual_subdivision.toml", 6, "'sky_subdivision' must be between 1 and 8"},
                    ErrorCase{"glare_check_resolution.toml", 10, "'check_resolution' must lie in 16 .. 4096 pixels"},
                    // A grid at 1e19 m under a sky once aborted the process inside Embree.
                    ErrorCase{"huge_height.toml", 4, "'height' must lie within ±1e7"},
                    // A NUL once silently cut the path short.
                    ErrorCase{"nul_path.toml", 2, "'file' must not contain a NUL character"},
                    // Illuminance quantities (docs/case-format.md#grid).
                    ErrorCase{"quantity_unknown.toml", 8, "unknown quantity 'cylinder' (expected horizontal, vertical"},
                    ErrorCase{"quantity_missing_facing.toml", 8, "quantity \"vertical\" needs 'facing' = [x, y]"},
                    ErrorCase{"quantity_semi_missing_facing.toml", 9,
                              "quantity \"semi-cylindrical\" needs 'facing' = [x, y]"},
                    ErrorCase{"quantity_zero_facing.toml", 9, "'facing' must not be the zero vector"},
                    ErrorCase{"quantity_facing_not_needed.toml", 9,
                              "'facing' applies to quantity = \"vertical\" or \"semi-cylindrical\" only"},
                    ErrorCase{"quantity_facing_3d.toml", 9, "'facing' must be a horizontal direction [x, y]"},
                    ErrorCase{"quantity_with_normal.toml", 8, "give either 'normal'"},
                    ErrorCase{"quantity_daylight_factor.toml", 9, "daylight_factor is defined on horizontal illuminance"},
                    ErrorCase{"modelling_not_bool.toml", 8, "'modelling' must be true or false, got a string"},
                    // Energy and the luminaire schedule (docs/en12464.md).
                    ErrorCase{"bad_power_w.toml", 5,
                              "'power_w' must be greater than 0 W (the luminaire's input power), got 0"},
                    ErrorCase{"power_w_text.toml", 5, "'power_w' must be a number, got a string"},
                    ErrorCase{"bad_floor_area.toml", 4, "'floor_area' must be greater than 0 m², got -12.5"},
                    ErrorCase{"unknown_reference_grid.toml", 3,
                              "'reference_grid' names no grid of the case: 'workplane' (the grids: 'desk')"},
                    ErrorCase{"reference_grid_daylight_factor.toml", 3, "a daylight-factor grid"},
                    ErrorCase{"reference_grid_vertical.toml", 3,
                              "grid 'wall' of cylindrical illuminance: W/m²/100 lx needs horizontal illuminance"}),
    [](const testing::TestParamInfo<ErrorCase>& info) {
      std::string n = info.param.file;
      return n.substr(0, n.find('.'));
    });

TEST(CaseFile, GridOutsideTheSceneNamesTheGridLine) {
  const fs::path path = casesDir() / "errors" / "grid_outside.toml";
  const CaseFile c = readCaseFile(path);  // valid on its own
  Box room;
  room.extend(Vec3(0, 0, 0));
  room.extend(Vec3(6, 4, 3));
  const std::optional<Warning> w = gridOutsideScene(c.grids[0], room);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->code, "grid_outside_scene");
  EXPECT_EQ(w->loc.line, 5) << w->message;
  EXPECT_NE(w->message.find("outside the scene"), std::string::npos) << w->message;
  // The full case's grids, the vertical wall grid and the points grid included, fit the room.
  const CaseFile full = readCaseFile(casesDir() / "full" / "case.toml");
  for (const GridSpec& g : full.grids) EXPECT_FALSE(gridOutsideScene(g, room)) << g.name;
  EXPECT_FALSE(gridOutsideScene(c.grids[0], Box{}));  // no geometry: nothing to check
}

TEST(CaseFile, GridOverAFlatGroundLitByLuminairesIsInsideTheScene) {
  // A car park: a ground polygon and luminaires on poles, no sky. The ground's box is flat, so a
  // grid 0.8 m above it was refused as "outside the scene"; the box of the scene and its
  // luminaires holds it, and a grid beyond that box is a warning, not a refusal.
  const fs::path dir = fs::path(testing::TempDir()) / "car_park_case";
  fs::create_directories(dir);
  std::ofstream(dir / "ground.rad") << "void plastic asphalt 0 0 5 .1 .1 .1 0 0\n"
                                       "asphalt polygon ground 0 0 12 0 0 0 20 0 0 20 20 0 0 20 0\n";
  std::ofstream(dir / "case.toml") << "[[scene]]\nfile = \"ground.rad\"\n\n"
                                      "[[luminaire]]\nfile = \"" + (casesDir() / "full" / "luminaires" / "downlight.ies").string() +
                                          "\"\nposition = [10.0, 10.0, 8.0]\n\n"
                                      "[[grid]]\nname = \"parking\"\ncorners = [[1.0, 1.0], [19.0, 19.0]]\nheight = 0.8\n\n"
                                      "[[grid]]\nname = \"road\"\ncorners = [[1.0, 1.0], [30.0, 19.0]]\nheight = 0.0\n";
  const CaseFile c = readCaseFile(dir / "case.toml");
  const std::unique_ptr<Scene> scene = loadCaseScene(c, false);
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  ASSERT_EQ(grids.size(), 2u);
  EXPECT_FALSE(grids[0].outside) << grids[0].outside->message;
  ASSERT_TRUE(grids[1].outside);
  EXPECT_EQ(grids[1].outside->code, "grid_outside_scene");
  EXPECT_EQ(grids[1].outside->loc.line, 13);
  EXPECT_NE(grids[1].outside->message.find("point (30, 1, 0) m"), std::string::npos) << grids[1].outside->message;
}

TEST(CaseFile, EveryDemoCaseReadsAndItsGridsFitItsScene) {
  // The cases/ folder the README runs: each reads, its scene loads and its grids lie inside it
  // (the demos are not all traced in CI, so a typo in one must fail here).
  const fs::path demos = fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases";
  int read = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(demos)) {
    const fs::path file = e.path() / "case.toml";
    if (!fs::exists(file)) continue;
    SCOPED_TRACE(file.string());
    const CaseFile c = readCaseFile(file);
    const std::unique_ptr<Scene> scene = loadCaseScene(c, false);  // geometry (an annual sky is no scene sky)
    for (const GridSpec& g : c.grids) EXPECT_FALSE(gridOutsideScene(g, scene->bounds())) << g.name;
    ++read;
  }
  EXPECT_GE(read, 6);  // small-room, office and its daylight, annual, window-group and compliance variants
}

TEST(CaseFile, MissingCaseFile) {
  EXPECT_THROW(readCaseFile(casesDir() / "no_such_case.toml"), InputError);
}

// A [[task_area]] makes three grids (the task area, its immediate surrounding and background)
// with EN 12464-1:2021's targets derived from the task's Ē_m.
TEST(CaseFile, TaskAreaMakesItsThreeGrids) {
  const fs::path path = casesDir() / "errors" / "task_area.toml";
  const CaseFile c = parseCaseFile(
      "[[task_area]]\nname = \"desk\"\ncorners = [[2.8, 1.8], [1.2, 1.0]]\nheight = 0.75\n"
      "maintained_illuminance = 750\nuniformity = 0.7\nugr_limit = 19\nra = 80\nroom = [[0, 0], [4, 3]]\n",
      path);
  ASSERT_EQ(c.taskAreas.size(), 1u);
  ASSERT_EQ(c.grids.size(), 3u);
  const TaskAreaSpec& a = c.taskAreas[0];
  EXPECT_EQ(a.outline.size(), 4u);
  EXPECT_EQ(a.ugrLimit.value(), 19.0);
  EXPECT_EQ(a.ra.value(), 80.0);
  EXPECT_EQ(c.grids[0].name, "desk");
  EXPECT_EQ(c.grids[0].area, GridSpec::Area::kTask);
  EXPECT_EQ(c.grids[0].targetAverageLux.value(), 750.0);
  EXPECT_EQ(c.grids[0].targetUniformity.value(), 0.7);
  EXPECT_EQ(c.grids[1].name, "desk surrounding");
  EXPECT_EQ(c.grids[1].targetAverageLux.value(), 500.0);
  EXPECT_EQ(c.grids[1].targetUniformity.value(), 0.40);
  EXPECT_EQ(c.grids[2].name, "desk background");
  EXPECT_DOUBLE_EQ(c.grids[2].targetAverageLux.value(), 500.0 / 3.0);
  EXPECT_EQ(c.grids[2].targetUniformity.value(), 0.10);
  // The background's lattice ends at the room's walls; the bands' widths are the standard's.
  EXPECT_EQ(c.grids[2].plane.outline[0], Vec2(0.0, 0.0));
  EXPECT_EQ(c.grids[2].plane.outline[1], Vec2(4.0, 3.0));
  EXPECT_EQ(c.grids[1].plane.band.toM, 0.5);
  EXPECT_EQ(c.grids[2].plane.band.fromM, 0.5);
  EXPECT_EQ(c.grids[2].plane.band.toM, 3.5);
  EXPECT_FALSE(c.grids[2].clipToRoom);
  // The bands' spacing is EN 12464-1's automatic one for their width: d = 0.5 m and 3 m.
  EXPECT_FALSE(c.grids[0].plane.spacingM.has_value());
  EXPECT_EQ(c.grids[1].plane.spacingM, autoGridSpacingM(0.5));
  EXPECT_EQ(c.grids[2].plane.spacingM, autoGridSpacingM(3.0));
  EXPECT_NEAR(*c.grids[1].plane.spacingM, 0.1, 1e-12);
  EXPECT_NEAR(*c.grids[2].plane.spacingM, 0.4, 1e-12);
  for (const GridSpec& g : c.grids) EXPECT_EQ(g.plane.origin.z, 0.75);
  auto error = [&](const std::string& text) { return parseError(text, path); };
  const std::string body = "height = 0.8\nmaintained_illuminance = 500\n";
  EXPECT_NE(error("[[task_area]]\n" + body).find("needs 'corners'"), std::string::npos);
  EXPECT_NE(error("[[task_area]]\ncorners = [[0, 0], [1, 1]]\npolygon = [[0, 0], [1, 0], [0, 1]]\n" + body)
                .find("either 'corners' or 'polygon'"),
            std::string::npos);
  EXPECT_NE(error("[[task_area]]\ncorners = [[0, 0], [1, 1]]\n" + body + "room = [[0.5, 0], [3, 3]]\n")
                .find("reaches outside its 'room'"),
            std::string::npos);
  EXPECT_EQ(error("[[task_area]]\ncorners = [[0, 0], [1, 1]]\n" + body + "ugr_limit = 50\n").rfind("5: ", 0), 0u);
  EXPECT_NE(error("[[grid]]\nname = \"desk\"\ncorners = [[0, 0], [1, 1]]\nheight = 0.8\n"
                  "[[task_area]]\nname = \"desk\"\ncorners = [[0, 0], [1, 1]]\n" + body)
                .find("two grids are named 'desk'"),
            std::string::npos);
}

// A task area's cylindrical illuminance and modelling make a fourth grid over it at eye height.
TEST(CaseFile, TaskAreaCylindricalAndModellingGrid) {
  const fs::path path = casesDir() / "errors" / "task_area.toml";
  const std::string area = "[[task_area]]\nname = \"desk\"\ncorners = [[1, 1], [2, 2]]\nheight = 0.75\n"
                           "maintained_illuminance = 500\n";
  const CaseFile c = parseCaseFile(area + "cylindrical_illuminance = 150\nmodelling = true\neye_height = 1.6\n", path);
  ASSERT_EQ(c.grids.size(), 4u);
  const GridSpec& z = c.grids[3];
  EXPECT_EQ(z.name, "desk cylindrical");
  EXPECT_EQ(z.area, GridSpec::Area::kCylindrical);
  EXPECT_EQ(z.taskArea, "desk");
  EXPECT_EQ(z.quantity, GridQuantity::kCylindrical);
  EXPECT_TRUE(z.modelling);
  EXPECT_EQ(z.plane.origin.z, 1.6);
  EXPECT_EQ(z.plane.outline, c.taskAreas[0].outline);
  EXPECT_EQ(z.targetAverageLux, 150.0);
  EXPECT_EQ(z.targetUniformity, 0.10);
  // Modelling alone: the grid without an Ē_z target, at the seated 1.2 m.
  const CaseFile m = parseCaseFile(area + "modelling = true\n", path);
  ASSERT_EQ(m.grids.size(), 4u);
  EXPECT_FALSE(m.grids[3].targetAverageLux.has_value());
  EXPECT_FALSE(m.grids[3].targetUniformity.has_value());
  EXPECT_EQ(m.grids[3].plane.origin.z, 1.2);
  EXPECT_EQ(parseCaseFile(area, path).grids.size(), 3u);
  EXPECT_THROW(parseCaseFile(area + "eye_height = 3\n", path), InputError);
  EXPECT_THROW(parseCaseFile(area + "cylindrical_illuminance = 0\n", path), InputError);
}

// A [[surface_grid]] is read as written; its grids are made with the scene (study/grids/surface_grids.h).
TEST(CaseFile, ReadsSurfaceGrids) {
  const fs::path path = casesDir() / "errors" / "surface_grid.toml";
  const CaseFile c = parseCaseFile(
      "[[surface_grid]]\nname = \"walls\"\nsurfaces = [\"wall_*\", \"door\"]\nroom_type = \"school\"\n"
      "side = \"back\"\nspacing = 0.4\noffset = 0.002\ntarget_uniformity = 0.2\n"
      "[[surface_grid]]\nsurfaces = [\"ceiling\"]\nspacing = \"auto\"\n",
      path);
  ASSERT_EQ(c.surfaceGrids.size(), 2u);
  EXPECT_TRUE(c.grids.empty());
  const SurfaceGridSpec& s = c.surfaceGrids[0];
  EXPECT_EQ(s.patterns, (std::vector<std::string>{"wall_*", "door"}));
  EXPECT_EQ(s.roomType, RoomType::kEducation);
  EXPECT_EQ(s.side, SurfaceGridSpec::Side::kBack);
  EXPECT_EQ(s.spacingM, 0.4);
  EXPECT_EQ(s.offsetM, 0.002);
  EXPECT_EQ(s.targetUniformity, 0.2);
  EXPECT_FALSE(s.targetAverageLux.has_value());
  EXPECT_EQ(s.patternsLoc.line, 3);
  const SurfaceGridSpec& d = c.surfaceGrids[1];
  EXPECT_EQ(d.name, "surfaces 2");
  EXPECT_FALSE(d.spacingM.has_value());
  EXPECT_FALSE(d.roomType.has_value());
  EXPECT_EQ(d.side, SurfaceGridSpec::Side::kAuto);
  EXPECT_EQ(d.offsetM, 0.001);
  auto error = [&](const std::string& text) { return parseError(text, path); };
  EXPECT_NE(error("[[surface_grid]]\nname = \"w\"\n").find("needs the key 'surfaces'"), std::string::npos);
  EXPECT_EQ(error("[[surface_grid]]\nsurfaces = []\n").rfind("2: ", 0), 0u);
  EXPECT_EQ(error("[[surface_grid]]\nsurfaces = [\"\"]\n").rfind("2: ", 0), 0u);
  EXPECT_EQ(error("[[surface_grid]]\nsurfaces = \"wall_*\"\n").rfind("2: ", 0), 0u);
  EXPECT_NE(error("[[surface_grid]]\nsurfaces = [\"w\"]\nroom_type = \"kitchen\"\n").find("3: unknown room_type"),
            std::string::npos);
  EXPECT_NE(error("[[surface_grid]]\nsurfaces = [\"w\"]\nside = \"inside\"\n").find("3: unknown side"),
            std::string::npos);
  EXPECT_EQ(error("[[surface_grid]]\nsurfaces = [\"w\"]\noffset = 0.5\n").rfind("3: ", 0), 0u);
  EXPECT_EQ(error("[[surface_grid]]\nsurfaces = [\"w\"]\nspacing = 0\n").rfind("3: ", 0), 0u);
  EXPECT_NE(error("[[surface_grid]]\nsurfaces = [\"w\"]\nheight = 1\n").find("3: unknown key 'height'"),
            std::string::npos);
  EXPECT_NE(error("[[grid]]\nname = \"w\"\ncorners = [[0, 0], [1, 1]]\nheight = 0.8\n"
                  "[[surface_grid]]\nname = \"w\"\nsurfaces = [\"w\"]\n")
                .find("two grids are named 'w'"),
            std::string::npos);
}

// Energy (docs/case-format.md): a luminaire's `power_w` applies to every fitting of its array,
// `[case] floor_area` and `reference_grid` are read as written; a task area's grid may be the
// reference.
TEST(CaseFile, ReadsPowerFloorAreaAndReferenceGrid) {
  const fs::path path = casesDir() / "errors" / "energy.toml";
  const CaseFile c = parseCaseFile(
      "[case]\nfloor_area = 42.5\nreference_grid = \"desk\"\n"
      "[[luminaire]]\nfile = \"../full/luminaires/downlight.ies\"\nposition = [1, 1, 2.8]\npower_w = 23.5\n"
      "array = { rows = 2, columns = 2, spacing = [1, 1] }\n"
      "[[luminaire]]\nfile = \"../full/luminaires/downlight.ies\"\nposition = [3, 1, 2.8]\n"
      "[[task_area]]\nname = \"desk\"\ncorners = [[1, 1], [2, 2]]\nheight = 0.8\nmaintained_illuminance = 500\n",
      path);
  EXPECT_EQ(c.floorAreaM2.value(), 42.5);
  EXPECT_EQ(c.referenceGrid, "desk");
  EXPECT_EQ(c.referenceGridLoc.line, 3);
  ASSERT_EQ(c.luminaires.size(), 5u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(c.luminaires[i].powerW.value(), 23.5);
  EXPECT_FALSE(c.luminaires[4].powerW.has_value());  // the file's input watts
  // The entries, once each for all their fittings: names without "[row,col]", files as written.
  ASSERT_EQ(c.luminaireEntries.size(), 2u);
  EXPECT_EQ(c.luminaireEntries[0].name, "luminaire1");
  EXPECT_EQ(c.luminaires[3].name, "luminaire1[2,2]");
  EXPECT_EQ(c.luminaires[3].entry, 0);
  EXPECT_EQ(c.luminaireEntries[1].fileText, "../full/luminaires/downlight.ies");
  EXPECT_EQ(c.luminaireEntries[1].loc.line, 9);
  const CaseFile plain = parseCaseFile("[case]\nname = \"x\"\n", path);
  EXPECT_FALSE(plain.floorAreaM2.has_value());
  EXPECT_TRUE(plain.referenceGrid.empty());
}

}  // namespace
}  // namespace candela
