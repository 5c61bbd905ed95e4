// The guards against silent nonsense (study/warnings.h, docs/warnings.md): each case below ran
// with exit 0 and nothing unusual before; each now carries its warning (code, file, line), and
// the same case without the problem, and the demo cases, carry none.
#include "study/warnings.h"
#include "photometry/photometric_file.h"

#include "base/units.h"
#include "engine/radiance/reader.h"
#include "photometry/epw.h"
#include "photometry/ies_lm63.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/points_study.h"
#include "study/grids/prepared_grid.h"
#include "study/run_case.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(CANDELA_TEST_DATA) / "study" / "warnings";
const fs::path kRoot = fs::path(CANDELA_TEST_DATA).parent_path().parent_path();
const std::string kPanel = "../../../../cases/luminaires/led_panel_600.ies";
const std::string kEpw = "../../epw/synthetic_golden_2026.epw";  // LOCATION 39.74, -105.18, UTC-7

// A case written here, as if it were tests/data/study/warnings/case.toml.
CaseFile caseOf(const std::string& text) { return parseCaseFile(text, kDir / "case.toml"); }

// The point-in-time study's input checks, as runGridStudy runs them.
Warnings inputWarnings(const CaseFile& c) {
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  const Tracer tracer(*scene);
  return pointInTimeWarnings(c, tracer, grids);
}

std::vector<std::string> codes(const Warnings& w) {
  std::vector<std::string> out;
  for (const Warning& x : w) out.push_back(x.code);
  return out;
}

std::string dump(const Warnings& w) {
  std::string s;
  for (const Warning& x : w) s += warningLine(x) + "\n";
  return s;
}

const std::string kRoom = "[[scene]]\nfile = \"room.rad\"\n";
const std::string kGrid =
    "[[grid]]\nname = \"workplane\"\ncorners = [[0.0, 0.0], [4.0, 3.0]]\nheight = 0.8\nspacing = 0.5\nborder = 0.5\n";
const std::string kLuminaire = "[[luminaire]]\nfile = \"" + kPanel + "\"\nposition = [1.0, 1.5, 2.79]\n";

TEST(Warnings, DemoCasesHaveNone) {
  for (const char* name : {"small-room", "office", "office-daylight"}) {
    const Warnings w = inputWarnings(readCaseFile(kRoot / "cases" / name / "case.toml"));
    EXPECT_TRUE(w.empty()) << name << ":\n" << dump(w);
  }
  const CaseFile annual = readCaseFile(kRoot / "cases" / "office-annual" / "case.toml");
  const EpwFile epw = readEpw(annual.sky.weather.string());
  const std::unique_ptr<Scene> scene = loadAnnualScene(annual, 0.0);
  const Warnings w = annualInputWarnings(annual, epw.location, *scene, prepareGrids(annual, gridBounds(*scene)));
  EXPECT_TRUE(w.empty()) << dump(w);
}

TEST(Warnings, SceneWithoutAnyLightSource) {
  const Warnings w = inputWarnings(caseOf(kRoom + kGrid));
  ASSERT_EQ(codes(w), std::vector<std::string>{"no_light_source"});
  EXPECT_EQ(w[0].loc.file, (kDir / "case.toml").string());
  EXPECT_EQ(w[0].loc.line, 0);
  EXPECT_TRUE(inputWarnings(caseOf(kRoom + kLuminaire + kGrid)).empty());
  // A sky is a light source too.
  EXPECT_TRUE(inputWarnings(caseOf(kRoom + "[sky]\ntype = \"cie-overcast\"\n" + kGrid)).empty());
}

// An ies2rad luminaire is a light source unless its distribution is dark throughout.
TEST(Warnings, Ies2radLuminaireIsALightSourceUnlessItsDataAreZero) {
  const fs::path dir = fs::path(CANDELA_TEST_DATA) / "rad" / "ies2rad";
  for (const char* file : {"panel.rad", "dark.rad"}) {
    Scene sc;
    readRadianceFile(dir / file, sc);
    Warnings w;
    checkLightSources(sc, FileLoc{file, 0, 0}, w);
    EXPECT_EQ(codes(w), std::string(file) == "dark.rad" ? std::vector<std::string>{"no_light_source"}
                                                          : std::vector<std::string>{})
        << file;
  }
}

TEST(Warnings, LuminairesOutsideEnclosedOrInMillimetres) {
  // room.rad: the room 4 × 3 × 2.8 m, a plenum roof at 3.2 m, a closed 0.2 m box around (3, 2.5, 2).
  const std::string lum = "[[luminaire]]\nfile = \"" + kPanel + "\"\nposition = ";
  const std::string text = kRoom +                                  // lines 1–2
                           lum + "[1.0, 1.5, 2.79]\n" +             // line 3: fine
                           lum + "[1000.0, 1500.0, 2790.0]\n" +     // line 6: millimetres
                           lum + "[10.0, 1.5, 2.79]\n" +            // line 9: outside the scene
                           lum + "[1.0, 1.5, 3.0]\n" +              // line 12: in the plenum
                           lum + "[3.0, 2.5, 2.0]\n" +              // line 15: inside the box
                           kGrid;
  const Warnings w = inputWarnings(caseOf(text));
  ASSERT_EQ(codes(w), (std::vector<std::string>{"millimetre_positions", "luminaire_outside_scene",
                                                "luminaire_above_ceiling", "luminaire_in_closed_volume"}))
      << dump(w);
  EXPECT_EQ(w[0].loc.line, 6);
  EXPECT_EQ(w[1].loc.line, 9);
  EXPECT_EQ(w[2].loc.line, 12);
  EXPECT_EQ(w[3].loc.line, 15);
  for (const Warning& x : w) EXPECT_EQ(x.loc.file, (kDir / "case.toml").string());
}

// The case's other positions written in millimetres lay kilometres away and flipped verdicts with
// no warning (EN 17037 sunlight "below minimum" to "high", UGR "fail" to "pass").
TEST(Warnings, ObserversAndComplianceListsInMillimetres) {
  const std::string observer = "[[observer]]\nposition = ";
  const std::string text = kRoom + kLuminaire + kGrid +                                  // lines 1–11
                           observer + "[1.0, 1.5]\ndirection = [1.0, 0.0]\n" +          // line 12: fine
                           observer + "[1000.0, 1500.0]\ndirection = [1.0, 0.0]\n";     // line 15: millimetres
  const Warnings w = inputWarnings(caseOf(text));
  ASSERT_EQ(codes(w), std::vector<std::string>{"millimetre_positions"}) << dump(w);
  EXPECT_EQ(w[0].loc.line, 15);
  EXPECT_NE(w[0].message.find("observer 'observer2'"), std::string::npos) << w[0].message;

  // EN 17037's lists: one warning a list, at its key; metres give none.
  Box room;
  room.extend(Vec3(0.0));
  room.extend(Vec3(4.0, 3.0, 2.8));
  CaseFile c;
  ComplianceSpec s;
  s.name = "en17037";
  s.sunlightPoints = {{2000.0, 10.0, 1200.0}, {3000.0, 10.0, 1200.0}};
  s.sunlightLoc = FileLoc{"case.toml", 7, 0};
  s.viewPoints = {{2.0, 1.5, 1.2}};
  s.viewLoc = FileLoc{"case.toml", 8, 0};
  GlareViewSpec g;
  g.positionM = Vec3(2000.0, 1500.0, 1200.0);
  g.loc = FileLoc{"case.toml", 10, 0};
  s.glareViews = {g};
  c.compliance = {s};
  Warnings m;
  checkMillimetrePositions(c, room, m);
  ASSERT_EQ(codes(m), (std::vector<std::string>{"millimetre_positions", "millimetre_positions"})) << dump(m);
  EXPECT_EQ(m[0].loc.line, 7);
  EXPECT_NE(m[0].message.find("sunlight point 1"), std::string::npos) << m[0].message;
  EXPECT_EQ(m[1].loc.line, 10);
  c.compliance[0].viewPoints = {{2000.0, 1500.0, 1200.0}};
  m.clear();
  checkMillimetrePositions(c, room, m);
  EXPECT_EQ(m.size(), 3u) << dump(m);
  c.compliance[0].sunlightPoints = {{2.0, 0.01, 1.2}};
  c.compliance[0].viewPoints = {{2.0, 1.5, 1.2}};
  c.compliance[0].glareViews[0].positionM = Vec3(2.0, 1.5, 1.2);
  m.clear();
  checkMillimetrePositions(c, room, m);
  EXPECT_TRUE(m.empty()) << dump(m);
}

// A room 4 x 3 x 2.8 m closed but for a 1 m x 1.2 m opening in its south wall (y = 0), glazed
// with clear glass or not.
std::string roomWithOpening(bool glazed) {
  auto rect = [](const std::string& mod, const std::string& name, const std::vector<Vec3>& v) {
    std::ostringstream s;
    s << mod << " polygon " << name << " 0 0 12";
    for (const Vec3& p : v) s << " " << p.x << " " << p.y << " " << p.z;
    return s.str() + "\n";
  };
  auto south = [&](const std::string& mod, const std::string& name, double x0, double x1, double z0, double z1) {
    return rect(mod, name, {{x0, 0, z0}, {x1, 0, z0}, {x1, 0, z1}, {x0, 0, z1}});
  };
  std::string s = "void plastic grey 0 0 5 .5 .5 .5 0 0\nvoid glass clear 0 0 3 .9 .9 .9\n";
  s += rect("grey", "floor", {{0, 0, 0}, {0, 3, 0}, {4, 3, 0}, {4, 0, 0}});
  s += rect("grey", "ceiling", {{0, 0, 2.8}, {4, 0, 2.8}, {4, 3, 2.8}, {0, 3, 2.8}});
  s += rect("grey", "north", {{0, 3, 0}, {4, 3, 0}, {4, 3, 2.8}, {0, 3, 2.8}});
  s += rect("grey", "west", {{0, 0, 0}, {0, 3, 0}, {0, 3, 2.8}, {0, 0, 2.8}});
  s += rect("grey", "east", {{4, 0, 0}, {4, 3, 0}, {4, 3, 2.8}, {4, 0, 2.8}});
  s += south("grey", "s_left", 0, 1.5, 0, 2.8) + south("grey", "s_right", 2.5, 4, 0, 2.8) +
       south("grey", "s_below", 1.5, 2.5, 0, 0.9) + south("grey", "s_above", 1.5, 2.5, 2.1, 2.8);
  if (glazed) s += south("clear", "window", 1.5, 2.5, 0.9, 2.1);
  return s;
}

// An unglazed opening is no window for EN 17037's view out: the eye read 0 deg and "none" with
// no warning.
TEST(Warnings, ViewOutThroughAnUnglazedOpening) {
  CaseFile c;
  ComplianceSpec s;
  s.name = "en17037";
  s.viewPoints = {{2.0, 2.9, 1.2}, {2.0, 1.5, 1.2}};  // both see the opening at eye height
  s.viewLoc = FileLoc{"case.toml", 9, 0};
  c.compliance = {s};
  for (const bool glazed : {false, true}) {
    Scene scene;
    readRadianceText(roomWithOpening(glazed), "room.rad", scene);
    const Tracer tracer(scene);
    Warnings w;
    checkViewOutOpenings(tracer, c, w);
    if (glazed) {
      EXPECT_TRUE(w.empty()) << dump(w);
      continue;
    }
    ASSERT_EQ(codes(w), std::vector<std::string>{"view_out_unglazed_opening"});
    EXPECT_EQ(w[0].loc.line, 9);
    EXPECT_NE(w[0].message.find("2 of 2 view points see outside without glazing"), std::string::npos) << w[0].message;
  }
}

// luminaire_power_unknown: a photometric file with 0 input watts (a real one: the shared
// reference's defined.ies) and no `power_w`; once per [[luminaire]] entry, however many fittings
// its array has, at the entry's line. `power_w` or a file with its watts gives none.
TEST(Warnings, LuminaireOfUnknownPower) {
  const std::string noWatts = (fs::path(CANDELA_REFERENCE) / "photometry" / "renderpipeline" / "defined.ies").string();
  ASSERT_EQ(readPhotometricFile(noWatts).inputWatts(), 0.0);
  const std::string lum = "[[luminaire]]\nfile = \"" + noWatts + "\"\nposition = [1.0, 1.5, 2.79]\n";
  const std::string text = kRoom +                                                          // lines 1–2
                           kLuminaire +                                                     // lines 3–5: 36 W
                           lum + "array = { rows = 1, columns = 2, spacing = [1.0, 1.0] }\n" +  // line 6
                           lum + "power_w = 40\n" +                                        // line 10: given
                           kGrid;
  const Warnings w = inputWarnings(caseOf(text));
  ASSERT_EQ(codes(w), std::vector<std::string>{"luminaire_power_unknown"}) << dump(w);
  EXPECT_EQ(w[0].loc.line, 6);
  EXPECT_NE(w[0].message.find("luminaire 'luminaire2': its photometric file defined.ies gives no input power"),
            std::string::npos)
      << w[0].message;
}

TEST(Warnings, GridSpacingLargerThanItsArea) {
  const CaseFile c = readCaseFile(kDir / "spacing.toml");
  const Warnings w = inputWarnings(c);
  ASSERT_EQ(codes(w), std::vector<std::string>{"grid_spacing_exceeds_extent"}) << dump(w);
  EXPECT_EQ(w[0].loc.file, (kDir / "spacing.toml").string());
  EXPECT_EQ(w[0].loc.line, 12);
  EXPECT_NE(w[0].message.find("grid 'wide': spacing 5 m exceeds its calculation area of 3 × 2 m"), std::string::npos)
      << w[0].message;
  EXPECT_TRUE(inputWarnings(caseOf(kRoom + kLuminaire + kGrid)).empty());
}

TEST(Warnings, SensorsOnASurfaceOrOutsideTheRoom) {
  // sensors.pts: line 3 in the plenum above the ceiling, line 5 on the corner of two walls; a
  // sensor on the floor facing up (line 9) and one facing a wall 1.5 m away are fine.
  const CaseFile c = caseOf(kRoom + kLuminaire + "[[grid]]\nname = \"desk\"\nkind = \"points\"\nfile = \"sensors.pts\"\n");
  const Warnings w = inputWarnings(c);
  ASSERT_EQ(codes(w), (std::vector<std::string>{"sensor_near_surface", "sensor_outside_room"})) << dump(w);
  const std::string pts = (kDir / "sensors.pts").string();
  EXPECT_EQ(w[0].loc.file, pts);
  EXPECT_EQ(w[0].loc.line, 5);
  EXPECT_NE(w[0].message.find("1 of 10 sensor points lies on or within 5 mm"), std::string::npos) << w[0].message;
  EXPECT_EQ(w[1].loc.file, pts);
  EXPECT_EQ(w[1].loc.line, 3);
  // The plenum point and the corner point (open to the outside through the walls' plane).
  EXPECT_NE(w[1].message.find("2 of 10 sensor points lie outside the room"), std::string::npos) << w[1].message;
}

TEST(Warnings, ReadmeExamplePointLiesOnAWallCorner) {
  // `echo "0 0 0.8 0 0 1" | candela points room.rad --sky cie-overcast` read 7 495 lx inside a
  // closed room: the point is on the corner of two walls and sees the sky beyond them.
  PointsJob job;
  job.scenes = {kRoot / "cases" / "small-room" / "room.rad"};
  job.sky = [](DaylightSpec d) {
    d.skyType = SkyType{SkyKind::kCieOvercast};
    return d;
  };
  job.trace.quality = Quality::kDraft;
  const PointsScene scene = loadPointsScene(job);
  const std::vector<FileLoc> locs = {FileLoc{"<stdin>", 1, 0}};
  const PointsResult r = computePoints(scene, job.accelerator, {{Vec3(0.0, 0.0, 0.8), Vec3(0.0, 0.0, 1.0)}},
                                       silentObserver(), locs);
  ASSERT_EQ(codes(r.warnings), std::vector<std::string>{"sensor_near_surface"}) << dump(r.warnings);
  EXPECT_EQ(r.warnings[0].loc.str(), "<stdin>:1");
  EXPECT_GT(r.estimates[0].illuminanceLux(), 1000.0);  // the silent nonsense itself, unchanged
  // A point in the room: no warning (and 0 lx: the closed room lets no daylight in).
  const PointsResult inRoom = computePoints(scene, job.accelerator, {{Vec3(2.0, 1.5, 0.8), Vec3(0.0, 0.0, 1.0)}});
  EXPECT_TRUE(inRoom.warnings.empty()) << dump(inRoom.warnings);
  // Strict: the first warning is an error before anything is traced.
  PointsScene strict = loadPointsScene(job);
  strict.strict = true;
  EXPECT_THROW(computePoints(strict, job.accelerator, {{Vec3(0.0, 0.0, 0.8), Vec3(0.0, 0.0, 1.0)}}), InputError);
}

std::string siteCase(const std::string& site) {
  return kRoom + kLuminaire + site + "[sky]\ntype = \"cie-overcast\"\nweather = \"" + kEpw +
         "\"\ntime = \"2026-06-21T12:00\"\n" + kGrid;
}

TEST(Warnings, SiteThatContradictsTheWeatherFile) {
  // Line 6: [site]. Sydney's coordinates with Golden's weather.
  const Warnings w = inputWarnings(caseOf(siteCase("[site]\nlatitude = -33.9\nlongitude = 151.2\n")));
  ASSERT_EQ(codes(w), std::vector<std::string>{"site_contradicts_weather"}) << dump(w);
  EXPECT_EQ(w[0].loc.line, 6);
  EXPECT_NE(w[0].message.find("Golden SYNTHETIC: 39.74°, -105.2°"), std::string::npos) << w[0].message;
  // The right place, but a time zone other than the file's.
  const Warnings tz = inputWarnings(caseOf(siteCase("[site]\nlatitude = 39.7\nlongitude = -105.0\ntimezone = 1.0\n")));
  ASSERT_EQ(codes(tz), std::vector<std::string>{"site_contradicts_weather"}) << dump(tz);
  EXPECT_NE(tz[0].message.find("in its time zone"), std::string::npos) << tz[0].message;
  // Within 1° and the same time zone: fine.
  EXPECT_TRUE(inputWarnings(caseOf(siteCase("[site]\nlatitude = 39.5\nlongitude = -105.0\ntimezone = -7\n"))).empty());
  // Annual studies compare the same way.
  const CaseFile annual = caseOf(kRoom + "[site]\nlatitude = -33.9\nlongitude = 151.2\n[sky]\ntype = \"annual\"\nweather = \"" +
                                 kEpw + "\"\n" + kGrid);
  Warnings aw;
  checkSiteAgainstWeather(annual, readEpw(annual.sky.weather.string()).location, aw);
  EXPECT_EQ(codes(aw), std::vector<std::string>{"site_contradicts_weather"});
}

// A clear sky given a site and a time but no direct normal illuminance has a sun of 0 lx: warned
// at [sky] (line 7), with the default diffuse illuminance named. Not when the sun's illuminance is
// given, when a weather file gives it, when `sun = false` says no sun is meant, or at night.
TEST(Warnings, ClearSkyWhoseSunCarriesNoLight) {
  const std::string site = "[site]\nlatitude = 39.74\nlongitude = -105.18\ntimezone = -7\n";
  const auto clear = [&](const std::string& time, const std::string& extra) {
    return inputWarnings(caseOf(kRoom + site + "[sky]\ntype = \"cie-clear\"\ntime = \"" + time + "\"\n" + extra + kGrid));
  };
  const Warnings w = clear("2026-06-21T12:00", "");
  ASSERT_EQ(codes(w), std::vector<std::string>{"sky_without_sun"}) << dump(w);
  EXPECT_EQ(w[0].loc.line, 7);  // after [[scene]] (2 lines) and [site] (4)
  EXPECT_NE(w[0].message.find("default 10 000 lx"), std::string::npos) << w[0].message;
  EXPECT_TRUE(clear("2026-06-21T12:00", "direct_normal_illuminance = 60000\n").empty());
  EXPECT_TRUE(clear("2026-06-21T12:00", "sun = false\n").empty());
  EXPECT_TRUE(clear("2026-06-21T23:00", "").empty());  // the sun is down
  const Warnings given = clear("2026-06-21T12:00", "diffuse_horizontal_illuminance = 20000\n");
  ASSERT_EQ(codes(given), std::vector<std::string>{"sky_without_sun"}) << dump(given);
  EXPECT_EQ(given[0].message.find("default"), std::string::npos);
  // A weather file's hour gives the sun its light.
  EXPECT_TRUE(inputWarnings(caseOf(kRoom + "[sky]\ntype = \"cie-clear\"\nweather = \"" + kEpw +
                                   "\"\ntime = \"2026-06-21T12:00\"\n" + kGrid))
                  .empty());
}

TEST(Warnings, PointInTimeSkyFromWeatherTakesItsLocationWithoutSite) {
  // No [site]: the sun was placed at 0°, 0°, UTC+0 before; now at the weather file's LOCATION.
  const DaylightSpec d = daylightFromCase(caseOf(siteCase("")));
  ASSERT_TRUE(d.latitudeDeg && d.longitudeDeg);
  EXPECT_DOUBLE_EQ(*d.latitudeDeg, 39.74);
  EXPECT_DOUBLE_EQ(*d.longitudeDeg, -105.18);
  EXPECT_DOUBLE_EQ(d.timezoneHours, -7.0);
  // A [site] without a time zone takes the file's.
  const DaylightSpec s = daylightFromCase(caseOf(siteCase("[site]\nlatitude = 39.7\nlongitude = -105.0\n")));
  EXPECT_DOUBLE_EQ(s.timezoneHours, -7.0);
  EXPECT_DOUBLE_EQ(*s.latitudeDeg, 39.7);
}

TEST(Warnings, ZeroWithZeroErrorUnderAnUnfoundGlowBulb) {
  // glow.toml: a 2 cm glow bulb (L = 100 W/sr/m²) 1.2 m over the work plane, draft quality, no
  // interreflection. Before the small-emitter rule most points read 0 ± 0 lx; now the bulb is
  // sampled from every point (it is far smaller than a stratum), so every point reads its cap
  // formula E = π L (r/d)² cos θ, between the values straight under it (d = 1.2 m) and at the
  // grid's farthest corner (1.5 m and 1 m off: d² = 1.2² + 1.5² + 1²), and nothing warns.
  RunRequest request;
  request.outDir = fs::path(testing::TempDir()) / "warnings_glow";
  fs::remove_all(request.outDir);
  const RunResult r = runCase(kDir / "glow.toml", request);
  auto cap = [](double d2) { return kLumensPerWatt * kPi * 100.0 * 0.02 * 0.02 / d2 * (1.2 / std::sqrt(d2)); };
  const double hi = cap(1.2 * 1.2), lo = cap(1.2 * 1.2 + 1.5 * 1.5 + 1.0 * 1.0);
  ASSERT_EQ(r.data.grids[0].values.size(), 24u);
  for (double v : r.data.grids[0].values) {
    EXPECT_GE(v, lo * (1 - 1e-9));
    EXPECT_LE(v, hi * (1 + 1e-9));
  }
  EXPECT_TRUE(r.data.warnings.empty()) << dump(r.data.warnings);

  // The criterion alone (still wanted for glows not sampled from a point, e.g. a thin one whose
  // bounding sphere is large): a zero facing the bulb warns, a zero facing away (the bulb behind
  // its hemisphere) or a non-zero value does not.
  const CaseFile c = readCaseFile(kDir / "glow.toml");
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  const Tracer tracer(*scene);
  const std::vector<SensorPoint> pts = {{Vec3(2.0, 1.5, 0.8), Vec3(0.0, 0.0, 1.0)},
                                        {Vec3(2.0, 1.5, 0.8), Vec3(0.0, 0.0, -1.0)}};
  SensorSet set{"points", &pts, FileLoc{"p.pts", 0, 0}, {}};
  const double zero[2] = {0.0, 0.0};
  Warnings w;
  checkErrorBars(tracer, set, zero, zero, w);
  ASSERT_EQ(codes(w), std::vector<std::string>{"untrusted_error_bar"});
  EXPECT_NE(w[0].message.find("1 of 2 sensor points reads 0 ± 0 lx (first: point 1"), std::string::npos) << w[0].message;
  const double lit[2] = {1.79, 1.79};
  Warnings none;
  checkErrorBars(tracer, set, lit, zero, none);
  EXPECT_TRUE(none.empty());
}

TEST(Warnings, StrictRunWritesNothingAndARunCarriesItsWarnings) {
  RunRequest request;
  request.outDir = fs::path(testing::TempDir()) / "warnings_strict";
  fs::remove_all(request.outDir);
  request.strict = true;
  try {
    runCase(kDir / "spacing.toml", request);
    FAIL() << "a strict run with a warning must throw";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 12);
    EXPECT_NE(std::string(e.what()).find("spacing.toml:12: grid 'wide': spacing 5 m"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(request.outDir));

  request.strict = false;
  const RunResult r = runCase(kDir / "spacing.toml", request);
  ASSERT_EQ(codes(r.data.warnings), std::vector<std::string>{"grid_spacing_exceeds_extent"});
  std::ifstream in(request.outDir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0]["code"], "grid_spacing_exceeds_extent");
  EXPECT_EQ(j["warnings"][0]["line"], 12);
  EXPECT_EQ(j["warnings"][0]["file"], (kDir / "spacing.toml").string());
  std::ifstream html(request.outDir / "report.html");
  std::stringstream page;
  page << html.rdbuf();
  EXPECT_NE(page.str().find("class=\"warnings\""), std::string::npos);
}

// Points inside a closed cabinet read 0 ± 0 while the rest of their grid is lit: warned of, with
// their count (the points inside the cabinet's box, or behind it from the one luminaire of the
// black room: found here by a slab test of their own) and the first at its place.
TEST(Warnings, SensorsThatReadNothingInALitGrid) {
  RunRequest request;
  request.outDir = fs::path(testing::TempDir()) / "warnings_dark";
  fs::remove_all(request.outDir);
  const fs::path casePath = kDir / "cabinet.toml";
  const RunResult r = runCase(casePath, request);
  const CaseFile c = readCaseFile(casePath);
  const SensorGrid g = makePlaneGrid(c.grids[0].plane);
  const Vec3 lo(3.9, 2.0, 0.0), hi(4.0, 2.5, 0.5), lum = c.luminaires[0].positionM;
  auto hitsBox = [&](const Vec3& p) {
    double t0 = 0.0, t1 = 1.0;
    for (int a = 0; a < 3; ++a) {
      double ta = (lo[a] - p[a]) / (lum[a] - p[a]), tb = (hi[a] - p[a]) / (lum[a] - p[a]);
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    return t0 <= t1;
  };
  std::size_t dark = 0;
  for (const SensorPoint& p : g.points) dark += hitsBox(p.position);
  ASSERT_GE(dark, 5u);  // the 5 inside at least (x 3.95, y 2.05…2.45)
  ASSERT_EQ(codes(r.data.warnings), std::vector<std::string>{"sensor_reads_nothing"}) << dump(r.data.warnings);
  const Warning& w = r.data.warnings[0];
  EXPECT_NE(w.message.find(std::to_string(dark) + " of " + std::to_string(g.size()) + " sensor points read 0 ± 0 lx"),
            std::string::npos)
      << w.message;
  EXPECT_EQ(w.loc.line, 10);  // the [[grid]] entry
  // A grid that is dark everywhere (no light reaches it at all) is not this warning's.
  Warnings none;
  const std::vector<SensorPoint> pts = g.points;
  const std::vector<double> zero(pts.size(), 0.0);
  checkDarkSensors(SensorSet{"grid 'x'", &pts, {}, {}}, zero.data(), zero.data(), none);
  EXPECT_TRUE(none.empty());
}

// A rotationally symmetric distribution falling linearly from I0 at nadir to 0 at 90°: its flux is
// 2π I0 (1 − 2/π) = 2283 lm for I0 = 1000 cd, against 1000 lm of lamps, so LOR = 228 %.
std::string iesWith(double nadirCd) {
  return "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 2 1 1 2 0 0 0\n1 1 40\n0 90\n0\n" + std::to_string(nadirCd) + " 0\n";
}

TEST(Warnings, PhotometryThatGivesMoreLightThanItsLampsOrNone) {
  Scene scene;
  std::vector<LuminairePlacement> placed(3);
  const char* names[] = {"bright.ies", "dark.ies", "fine.ies"};
  const std::string texts[] = {iesWith(1000.0), iesWith(0.0), iesWith(300.0)};  // 228 %, none, 68 %
  for (int i = 0; i < 3; ++i) {
    placed[i].file = names[i];
    placed[i].loc = FileLoc{"case.toml", 10 * (i + 1), 0};
    LuminaireMounting m;
    scene.luminaires.push_back(placeLuminaire(std::make_shared<const PhotometricWeb>(parseIes(texts[i], names[i], ".")), m));
  }
  Warnings w;
  checkPhotometry(scene, placed, w);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].code, "luminaire_photometry");
  EXPECT_NE(w[0].message.find("light output ratio of 228."), std::string::npos) << w[0].message;
  EXPECT_EQ(w[0].loc.line, 10);
  EXPECT_NE(w[1].message.find("no intensity above 0 cd"), std::string::npos) << w[1].message;
  EXPECT_EQ(w[1].loc.line, 20);
}

TEST(Warnings, WeatherHoursWithMissingIrradiance) {
  // "120 of 8760 hours have missing irradiance" once passed without a word (72 hours marked 9999).
  const EpwFile marked = readEpw((fs::path(CANDELA_TEST_DATA) / "epw" / "missing_marks.epw").string());
  Warnings w;
  checkWeatherGaps(marked, "missing_marks.epw", w);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].code, "weather_missing_hours");
  EXPECT_EQ(w[0].message, "3 of 72 hours have missing irradiance; they are treated as dark");
  Warnings none;
  checkWeatherGaps(readEpw((fs::path(CANDELA_TEST_DATA) / "epw" / "synthetic_3day.epw").string()), "x.epw", none);
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace candela
