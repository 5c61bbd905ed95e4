// EN 1838 as a study (study/compliance/en1838.h): direct illuminance from the emergency
// luminaires at the routes', areas' and points' sensors against closed forms (an isotropic point
// source of I cd at height h gives E = I h / d³ on the floor), direct light only (reflecting
// surfaces change nothing), the grids' shape, the case's keys and errors, and the example case.
#include "study/compliance/en1838.h"

#include "reports/en1838_report.h"

#include "engine/tracer.h"
#include "photometry/photometric_file.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/compliance/en1838_grids.h"
#include "study/run_case.h"
#include "study/resource_estimate.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr double kIntensityCd = 100.0;  // the isotropic source's
constexpr double kHeightM = 3.0;        // its height above the floor (z = 0)

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// An isotropic point source: 100 cd in every direction, no luminous opening (a point).
void writeIsotropicIes(const fs::path& p) {
  writeFile(p,
            "IESNA:LM-63-2002\n[TEST] isotropic point source for the EN 1838 tests\nTILT=NONE\n"
            "1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 90 180\n0\n100 100 100\n");
}

// A closed box 12 × 6 × 3.5 m of reflectance 0.5 plastic around the origin: floor at z = 0.
const char* kReflectingRoom = R"(void plastic grey
0
0
5 0.5 0.5 0.5 0 0
!genbox grey room 12 6 3.5 -i | xform -t -6 -3 0
)";

// A flat mirror 2 m beside the route facing it, a specular metal wall on the other side and a
// glossy floor: each would send the source's image (a virtual source) or a highlight onto the route.
const char* kMirrors = R"(void mirror silver
0
0
3 0.9 0.9 0.9

void metal steel
0
0
5 0.8 0.8 0.8 0.9 0

void plastic gloss
0
0
5 0.5 0.5 0.5 0.05 0

silver polygon mirror_wall
0
0
12
  -6 2 0
   6 2 0
   6 2 3.5
  -6 2 3.5

steel polygon metal_wall
0
0
12
  -6 -2 0
  -6 -2 3.5
   6 -2 3.5
   6 -2 0

gloss polygon floor
0
0
12
  -6 -2 -0.001
   6 -2 -0.001
   6  2 -0.001
  -6  2 -0.001
)";

// A case in `dir` with the source at (0, 0, 3) and `body` after it.
CaseFile writeCase(const fs::path& dir, const std::string& body, const std::string& luminaire = "isotropic.ies",
                   const std::string& extraLuminaireKeys = "emergency = true\n") {
  writeIsotropicIes(dir / "isotropic.ies");
  const std::string text = "[[luminaire]]\nfile = \"" + luminaire + "\"\nposition = [0.0, 0.0, " +
                           std::to_string(kHeightM) + "]\n" + extraLuminaireKeys + body;
  writeFile(dir / "case.toml", text);
  return readCaseFile(dir / "case.toml");
}

const char* kRoute =
    "[[escape_route]]\nname = \"r\"\npath = [[-4.0, 0.0], [4.0, 0.0]]\nwidth = 1.0\nspacing = 0.5\n"
    "[[compliance]]\nstandard = \"en1838\"\n";

double pointLaw(const Vec3& p) {
  const Vec3 d = Vec3(0.0, 0.0, kHeightM) - p;
  const double dist = glm::length(d);
  return kIntensityCd * d.z / (dist * dist * dist);
}

// The sensors' illuminance in the emergency scene, or (asRead) in the case's scene as read: its
// materials as they are, all its luminaires, no daylight.
std::vector<double> traceDirect(const CaseFile& c, const En1838Points& pts, const TraceSettings& s, bool asRead = false) {
  const std::unique_ptr<Scene> scene = asRead ? loadCaseScene(c, false) : loadEmergencyScene(c, 1.0);
  const Tracer tracer(*scene);
  std::vector<double> lux;
  for (const IrradianceEstimate& e : computeIrradiance(tracer, pts.sensors, s, 1)) lux.push_back(e.illuminanceLux());
  return lux;
}

TEST(En1838Study, CentreLineFollowsThePointLawExactly) {
  const fs::path dir = test_support::scratchDir("en1838", "point_law");
  const CaseFile c = writeCase(dir, kRoute);
  const En1838Points pts = en1838Points(c);
  ASSERT_EQ(pts.routeCentre.size(), 1u);
  ASSERT_EQ(pts.routeCentre[0].size(), 1u);  // 1 m wide: one strip
  const En1838Points::Span centre = pts.routeCentre[0][0];
  EXPECT_EQ(centre.count, 17u);  // 8 m at 0.5 m: both ends included
  const std::vector<double> lux = traceDirect(c, pts, directOnlySettings(TraceSettings{}));
  for (std::size_t i = centre.first; i < centre.first + centre.count; ++i) {
    const Vec3 p = pts.sensors[i].position;
    EXPECT_NEAR(lux[i], pointLaw(p), 1e-9 * pointLaw(p)) << "at x = " << p.x;
  }
  // The route's figures: minimum at the ends (d = 5 m), maximum under the source.
  const En1838Result r = computeEn1838(c, *en1838Entry(c), *loadEmergencyScene(c, 1.0), TraceSettings{}, 1);
  ASSERT_EQ(r.routes.size(), 1u);
  const double endLux = kIntensityCd * kHeightM / 125.0, topLux = kIntensityCd / (kHeightM * kHeightM);
  EXPECT_NEAR(r.routes[0].minCentreLineLux, endLux, 1e-9 * endLux);
  EXPECT_NEAR(r.routes[0].maxCentreLineLux, topLux, 1e-9 * topLux);
  EXPECT_NEAR(r.routes[0].uniformityRatio, topLux / endLux, 1e-9 * topLux / endLux);
  // The central band: half the width (±0.25 m), its minimum at the ends' edges.
  const double bandLux = pointLaw(Vec3(4.0, 0.25, 0.0));
  EXPECT_NEAR(r.routes[0].centralBandMinLux, bandLux, 1e-9 * bandLux);
  EXPECT_EQ(r.routes[0].verdict, Verdict::kPass);  // 2.4 lx, ratio 4.6
}

TEST(En1838Study, ReflectingRoomChangesNothing) {
  const fs::path dir = test_support::scratchDir("en1838", "reflecting");
  writeFile(dir / "room.rad", kReflectingRoom);
  const CaseFile c = writeCase(dir, std::string("[[scene]]\nfile = \"room.rad\"\n") + kRoute);
  const En1838Points pts = en1838Points(c);
  const std::vector<double> lux = traceDirect(c, pts, directOnlySettings(TraceSettings{}));
  for (std::size_t i = 0; i < pts.sensors.size(); ++i) {
    const double e = pointLaw(pts.sensors[i].position);
    EXPECT_NEAR(lux[i], e, 1e-9 * e) << "sensor " << i;
  }
  // The room as read, with interreflection, adds light (the test above could fail); the
  // emergency scene's surfaces are black: bounces find nothing to reflect there either.
  TraceSettings bounced;
  bounced.hemisphereSamples = 256;
  const std::size_t mid = pts.routeCentre[0][0].first + 8;  // x = 0, under the source
  const double underSource = pointLaw(pts.sensors[mid].position);
  EXPECT_GT(traceDirect(c, pts, bounced, true)[mid], 1.2 * underSource);
  EXPECT_NEAR(traceDirect(c, pts, bounced)[mid], underSource, 1e-9 * underSource);
}

TEST(En1838Study, MirrorsAndGlossChangeNothing) {
  const fs::path dir = test_support::scratchDir("en1838", "mirrors");
  writeFile(dir / "mirrors.rad", kMirrors);
  const CaseFile c = writeCase(dir, std::string("[[scene]]\nfile = \"mirrors.rad\"\n") + kRoute);
  const En1838Points pts = en1838Points(c);
  const std::vector<double> lux = traceDirect(c, pts, directOnlySettings(TraceSettings{}));
  for (std::size_t i = 0; i < pts.sensors.size(); ++i) {
    const double e = pointLaw(pts.sensors[i].position);
    EXPECT_NEAR(lux[i], e, 1e-9 * e) << "sensor " << i << " at " << pts.sensors[i].position.x << ", "
                                     << pts.sensors[i].position.y;
  }
  // Zero bounces alone are not enough: the mirror's virtual source and the metal's lobe add light
  // to the scene as read (about 20 % near x = 0), which the black-out removes.
  const std::vector<double> asRead = traceDirect(c, pts, directOnlySettings(TraceSettings{}), true);
  const std::size_t mid = pts.routeCentre[0][0].first + 8;
  EXPECT_GT(asRead[mid], 1.1 * pointLaw(pts.sensors[mid].position));
}

TEST(En1838Study, EmergencyFactorAndMaintenanceFactorScale) {
  const fs::path dir = test_support::scratchDir("en1838", "factors");
  const CaseFile c = writeCase(dir,
                               "[[safety_point]]\nname = \"box\"\nposition = [2.0, 0.0, 1.0]\nfacing = [-1.0, 0.0]\n"
                               "[[compliance]]\nstandard = \"en1838\"\nmaintenance_factor = 0.8\n",
                               "isotropic.ies", "emergency = true\nemergency_factor = 0.5\nmultiplier = 2.0\n");
  const ComplianceSpec& entry = *en1838Entry(c);
  EXPECT_DOUBLE_EQ(entry.emergencyMaintenanceFactor, 0.8);
  const En1838Result r = computeEn1838(c, entry, *loadEmergencyScene(c, 0.8), TraceSettings{}, 1);
  ASSERT_EQ(r.safetyPoints.size(), 1u);
  // Vertical illuminance facing −x at (2, 0, 1): E = I cos ι / d², cos ι = 2/d, d² = 4 + 4.
  const double d2 = 8.0, expected = 0.5 * 2.0 * 0.8 * kIntensityCd * (2.0 / std::sqrt(d2)) / d2;
  EXPECT_NEAR(r.safetyPoints[0].verticalLux, expected, 1e-9 * expected);
  EXPECT_DOUBLE_EQ(r.safetyPoints[0].nearestLuminaireM, 2.0);  // the luminaire over (0, 0): "near", 2 m
  EXPECT_EQ(r.safetyPoints[0].verdict, Verdict::kPass);  // 5.66 lx
}

// EN 1838 4.1's "near": an emergency luminaire within 2 m horizontally of the equipment. The
// point of the test above moved to (2.5, 0, 1) keeps more than 5 lx vertical (4.6 / (2.5² + 4)^1.5
// · 2.5 … computed below) but has its luminaire 2.5 m away: it fails.
TEST(En1838Study, SafetyPointNeedsAnEmergencyLuminaireWithinTwoMetres) {
  const fs::path dir = test_support::scratchDir("en1838", "near");
  const CaseFile c = writeCase(dir,
                               "[[safety_point]]\nname = \"box\"\nposition = [2.5, 0.0, 1.0]\nfacing = [-1.0, 0.0]\n"
                               "[[compliance]]\nstandard = \"en1838\"\n",
                               "isotropic.ies", "emergency = true\nmultiplier = 2.0\n");
  const En1838Result r = computeEn1838(c, *en1838Entry(c), *loadEmergencyScene(c, 1.0), TraceSettings{}, 1);
  ASSERT_EQ(r.safetyPoints.size(), 1u);
  const double d2 = 2.5 * 2.5 + 4.0, vertical = 2.0 * kIntensityCd * (2.5 / std::sqrt(d2)) / d2;
  ASSERT_GE(vertical, 5.0);
  EXPECT_NEAR(r.safetyPoints[0].verticalLux, vertical, 1e-9 * vertical);
  EXPECT_DOUBLE_EQ(r.safetyPoints[0].nearestLuminaireM, 2.5);
  EXPECT_EQ(r.safetyPoints[0].verdict, Verdict::kFail);
}

TEST(En1838Study, NonEmergencyLuminairesAreLeftOut) {
  const fs::path dir = test_support::scratchDir("en1838", "normal_only");
  const CaseFile c = writeCase(dir, kRoute, "isotropic.ies", "");
  ASSERT_TRUE(noEmergencyLuminaireWarning(c).has_value());
  EXPECT_EQ(noEmergencyLuminaireWarning(c)->code, "no_emergency_luminaire");
  EXPECT_EQ(noEmergencyLuminaireWarning(c)->loc.line, 9);  // the [[compliance]] entry
  const En1838Result r = computeEn1838(c, *en1838Entry(c), *loadEmergencyScene(c, 1.0), TraceSettings{}, 1);
  EXPECT_EQ(r.routes[0].maxCentreLineLux, 0.0);
  EXPECT_EQ(r.routes[0].verdict, Verdict::kFail);
}

TEST(En1838Study, RealIesFileAgainstItsOwnIntensity) {
  const fs::path dir = test_support::scratchDir("en1838", "real_ies");
  fs::copy_file(fs::path(CANDELA_TEST_DATA) / "ies" / "asym_c.ies", dir / "asym_c.ies");
  const CaseFile c = writeCase(dir, kRoute, "asym_c.ies");
  const PhotometricWeb web = readPhotometricFile(dir / "asym_c.ies");
  ASSERT_EQ(web.openingWidthM(), 0.0);  // a point source: the point law is exact
  const En1838Points pts = en1838Points(c);
  const std::vector<double> lux = traceDirect(c, pts, directOnlySettings(TraceSettings{}));
  for (std::size_t i = 0; i < pts.sensors.size(); ++i) {
    const Vec3 p = pts.sensors[i].position;
    const Vec3 toPoint = p - Vec3(0.0, 0.0, kHeightM);  // from the source; aim down, spin 0: local = world
    const double d = glm::length(toPoint);
    const double e = web.intensityCd(toPoint / d) * kHeightM / (d * d * d);
    EXPECT_NEAR(lux[i], e, 1e-9 * e) << "at (" << p.x << ", " << p.y << ")";
  }
}

TEST(En1838Study, OpenAreaCoreLeavesOutTheBorder) {
  const fs::path dir = test_support::scratchDir("en1838", "open_area");
  const CaseFile c = writeCase(dir,
                               "[[open_area]]\nname = \"hall\"\ncorners = [[-2.0, -1.5], [2.0, 1.5]]\nspacing = 0.25\n"
                               "[[compliance]]\nstandard = \"en1838\"\n");
  const En1838Points pts = en1838Points(c);
  ASSERT_EQ(pts.openAreas.size(), 1u);
  bool corner = false;
  double maxLux = 0.0;  // the lattice is centred in the core: the largest value of its points
  for (std::size_t i = pts.openAreas[0].first; i < pts.openAreas[0].first + pts.openAreas[0].count; ++i) {
    const Vec3 p = pts.sensors[i].position;
    maxLux = std::max(maxLux, pointLaw(p));
    EXPECT_LE(std::abs(p.x), 1.5 + 1e-12);
    EXPECT_LE(std::abs(p.y), 1.0 + 1e-12);
    corner = corner || (std::abs(std::abs(p.x) - 1.5) < 1e-12 && std::abs(std::abs(p.y) - 1.0) < 1e-12);
  }
  EXPECT_TRUE(corner);  // the core's boundary is sampled, corners included
  const En1838Result r = computeEn1838(c, *en1838Entry(c), *loadEmergencyScene(c, 1.0), TraceSettings{}, 1);
  // Minimum at the core's corners (1.5, 1.0), not the area's (2, 1.5).
  const double minLux = pointLaw(Vec3(1.5, 1.0, 0.0));
  EXPECT_NEAR(r.openAreas[0].stats.minLux, minLux, 1e-9 * minLux);
  EXPECT_NEAR(r.openAreas[0].stats.maxLux, maxLux, 1e-9 * maxLux);
  EXPECT_NEAR(r.openAreas[0].uniformityRatio, maxLux / minLux, 1e-9 * maxLux / minLux);
  EXPECT_EQ(r.openAreas[0].verdict, Verdict::kPass);
}

// `leave_out`: the empty floor the standard means. A desk (1 m × 1 m at 0.7 m) over the middle of
// the hall's core shadows the floor under it (0 lx: the area fails); left out by its identifier
// pattern, the core's minimum is the point law's at its corner again, as without furniture.
TEST(En1838Study, LeftOutFurnitureGivesTheEmptyFloor) {
  const fs::path dir = test_support::scratchDir("en1838", "leave_out");
  writeFile(dir / "desk.rad", "void plastic grey 0 0 5 .5 .5 .5 0 0\n!genbox grey desk 1 1 0.05 | xform -t -0.5 -0.5 0.7\n");
  const std::string area = "[[scene]]\nfile = \"desk.rad\"\n[[open_area]]\nname = \"hall\"\n"
                           "corners = [[-2.0, -1.5], [2.0, 1.5]]\nspacing = 0.25\n[[compliance]]\nstandard = \"en1838\"\n";
  const CaseFile furnished = writeCase(dir, area);
  const En1838Result withDesk =
      computeEn1838(furnished, *en1838Entry(furnished), *loadEmergencyScene(furnished, 1.0), TraceSettings{}, 1);
  EXPECT_EQ(withDesk.openAreas[0].stats.minLux, 0.0);
  EXPECT_EQ(withDesk.openAreas[0].verdict, Verdict::kFail);
  const CaseFile empty = writeCase(dir, area + "leave_out = [\"desk*\"]\n");
  const ComplianceSpec& entry = *en1838Entry(empty);
  ASSERT_EQ(entry.emergencyLeaveOut, (std::vector<std::string>{"desk*"}));
  const En1838Result r = computeEn1838(
      empty, entry, *loadEmergencyScene(empty, 1.0, entry.emergencyLeaveOut, entry.emergencyLeaveOutLoc), TraceSettings{}, 1);
  const double minLux = pointLaw(Vec3(1.5, 1.0, 0.0));
  EXPECT_NEAR(r.openAreas[0].stats.minLux, minLux, 1e-9 * minLux);
  EXPECT_EQ(r.openAreas[0].verdict, Verdict::kPass);
  // The report says what was left out.
  EXPECT_NE(En1838Section(r, std::nullopt).html().find("Left out of the scene (the empty floor): <code>desk*</code>."),
            std::string::npos);
  // A pattern that names no surface is an error at the key's line (the luminaire's 4 lines, the
  // scene's 2, the area's 4, the entry's 2: line 13).
  const CaseFile wrong = writeCase(dir, area + "leave_out = [\"table*\"]\n");
  try {
    loadEmergencyScene(wrong, 1.0, en1838Entry(wrong)->emergencyLeaveOut, en1838Entry(wrong)->emergencyLeaveOutLoc);
    FAIL() << "no error for a pattern naming no surface";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 13) << e.what();
    EXPECT_NE(std::string(e.what()).find("no surface of the scene is named 'table*'"), std::string::npos) << e.what();
  }
}

TEST(En1838Study, HighRiskTaskArea) {
  const fs::path dir = test_support::scratchDir("en1838", "high_risk");
  // 100 cd at 3 m over a 1 m square at the floor: 11.1 lx at most, below 15 lx: fails.
  const CaseFile c = writeCase(dir,
                               "[[task_area]]\nname = \"lathe\"\ncorners = [[-0.5, -0.5], [0.5, 0.5]]\nheight = 0.0\n"
                               "maintained_illuminance = 300\nemergency = \"high-risk\"\n"
                               "[[compliance]]\nstandard = \"en1838\"\n");
  const En1838Result r = computeEn1838(c, *en1838Entry(c), *loadEmergencyScene(c, 1.0), TraceSettings{}, 1);
  ASSERT_EQ(r.highRiskAreas.size(), 1u);
  EXPECT_DOUBLE_EQ(r.highRiskAreas[0].requiredLux, 30.0);
  const double minLux = pointLaw(Vec3(0.5, 0.5, 0.0));
  EXPECT_NEAR(r.highRiskAreas[0].stats.minLux, minLux, 1e-9 * minLux);
  EXPECT_EQ(r.highRiskAreas[0].verdict, Verdict::kFail);
}

TEST(En1838Grids, WideRouteIsStripsOfAtMostTwoMetres) {
  EscapeRouteSpec r;
  r.path = {{0.0, 0.0}, {10.0, 0.0}};
  r.widthM = 5.0;
  r.spacingM = 0.5;
  const std::vector<RouteStripPoints> s = routeStrips(r);
  ASSERT_EQ(s.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(s[k].widthM, 5.0 / 3.0, 1e-12);
    EXPECT_NEAR(s[k].offsetM, -2.5 + 5.0 / 3.0 * (k + 0.5), 1e-12);
    // Its centre line: from end to end at its offset (left of the path: +y).
    EXPECT_NEAR(s[k].centreLine.front().y, s[k].offsetM, 1e-12);
    EXPECT_NEAR(s[k].centreLine.front().x, 0.0, 1e-12);
    EXPECT_NEAR(s[k].centreLine.back().x, 10.0, 1e-12);
    // Its band: ± a quarter of its width about its centre line, edges included.
    double lo = 1e9, hi = -1e9;
    for (const Vec2& p : s[k].band) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    EXPECT_NEAR(lo, s[k].offsetM - 0.25 * s[k].widthM, 1e-12);
    EXPECT_NEAR(hi, s[k].offsetM + 0.25 * s[k].widthM, 1e-12);
  }
  r.widthM = 2.0;
  EXPECT_EQ(routeStrips(r).size(), 1u);  // exactly 2 m: one strip
}

TEST(En1838Grids, InsetOfAConvexPolygon) {
  const std::vector<Vec2> tri = {{0.0, 0.0}, {4.0, 0.0}, {0.0, 3.0}};
  const std::vector<Vec2> core = insetConvexPolygon(tri, 0.5);
  ASSERT_EQ(core.size(), 3u);
  // The 3-4-5 triangle's inradius is 1: the core is similar with inradius 0.5, half the size.
  double area = 0.0;
  for (std::size_t k = 0; k < core.size(); ++k)
    area += core[k].x * core[(k + 1) % 3].y - core[(k + 1) % 3].x * core[k].y;
  EXPECT_NEAR(0.5 * area, 6.0 * 0.25, 1e-12);
  EXPECT_TRUE(insetConvexPolygon(tri, 1.0).empty());
  EXPECT_FALSE(isConvexPolygon({{0, 0}, {4, 0}, {1, 1}, {0, 4}}));
}

// An L-shaped hall, 10 m × 10 m with a 6 m × 6 m corner cut away: its core is the L moved in
// 0.5 m on every side, mitred at the convex corners, and about the reflex corner (4, 4) the arc of
// radius 0.5 m: area 9 × 3 + 3 × 6 + (0.25 − π 0.5²/4) (the part of the square [3.5, 4]² outside
// the arc's disc), plus the nine 10° chords' segments the sampled arc adds, r²/2 (δ − sin δ) each.
// Every vertex of the core lies 0.5 m from the hall's walls or more; the lattice inside it at
// least 0.5 m less the chords' sagitta.
TEST(En1838Grids, InsetOfAConcavePolygonRoundsItsReflexCorner) {
  const std::vector<Vec2> hall = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
  const std::vector<Vec2> core = insetPolygon(hall, 0.5, 0.25);
  ASSERT_GE(core.size(), 6u);
  double area = 0.0;
  for (std::size_t k = 0; k < core.size(); ++k)
    area += core[k].x * core[(k + 1) % core.size()].y - core[(k + 1) % core.size()].x * core[k].y;
  const double delta = kPi / 18.0;
  EXPECT_NEAR(0.5 * area, 45.0 + 0.25 - kPi / 16.0 + 9.0 * 0.125 * (delta - std::sin(delta)), 1e-9);
  auto wallDistance = [&](const Vec2& p) {
    double d = 1e9;
    for (std::size_t i = 0; i < hall.size(); ++i) {
      const Vec2 a = hall[i], e = hall[(i + 1) % hall.size()] - a;
      const double t = std::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0, 1.0);
      d = std::min(d, glm::length(p - (a + t * e)));
    }
    return d;
  };
  for (const Vec2& p : core) EXPECT_GE(wallDistance(p), 0.5 - 1e-9);
  const std::vector<Vec2> pts = polygonPoints(core, 0.25);
  const double sagitta = 0.5 * (1.0 - std::cos(delta / 2.0));
  for (const Vec2& p : pts) EXPECT_GE(wallDistance(p), 0.5 - sagitta - 1e-9);
  // Read from a case, the hall's core points are those of its core.
  const fs::path dir = test_support::scratchDir("en1838", "concave_hall");
  const CaseFile c = writeCase(dir, "[[open_area]]\nname = \"hall\"\npolygon = [[0, 0], [10, 0], [10, 4], [4, 4], "
                                    "[4, 10], [0, 10]]\nspacing = 0.25\n[[compliance]]\nstandard = \"en1838\"\n");
  const En1838Points fromCase = en1838Points(c);
  ASSERT_EQ(fromCase.openAreas.size(), 1u);
  EXPECT_EQ(fromCase.openAreas[0].count, pts.size());
  // A convex polygon takes the convex inset.
  const std::vector<Vec2> square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_EQ(insetPolygon(square, 0.5, 0.25), insetConvexPolygon(square, 0.5));
}

// The run's memory check counts EN 1838's points before they are made: the bound holds the
// points made (the example's, and a wide route's strips), and a hall of 1000 m × 1000 m at 1 cm
// (10¹⁰ points) is refused at the entry's line, as an oversized grid is.
TEST(En1838Case, PointsAreBoundedBeforeTheyAreMade) {
  const CaseFile example = readCaseFile(fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "office-emergency" / "case.toml");
  const double made = static_cast<double>(en1838Points(example).sensors.size());
  EXPECT_GE(en1838PointBound(example), made);
  EXPECT_LE(en1838PointBound(example), 2.0 * made);
  const fs::path dir = test_support::scratchDir("en1838", "bound");
  const CaseFile wide = writeCase(dir, "[[escape_route]]\nname = \"r\"\npath = [[0.0, 0.0], [5.0, 0.0], [5.0, 3.0]]\n"
                                       "width = 4.5\nspacing = 0.3\n[[compliance]]\nstandard = \"en1838\"\n");
  EXPECT_GE(en1838PointBound(wide), static_cast<double>(en1838Points(wide).sensors.size()));
  const CaseFile huge = writeCase(dir, "[[open_area]]\nname = \"hall\"\ncorners = [[0.0, 0.0], [1000.0, 1000.0]]\n"
                                       "spacing = 0.01\n[[compliance]]\nstandard = \"en1838\"\n");
  const Scene empty;
  const ResourceEstimate e = estimateGridStudy(huge, gridPointCounts(huge), empty, TraceSettings{}, 1);
  ResourceLimits limits;
  limits.maxMemoryBytes = 64ull << 30;
  try {
    checkResources(e, limits, FileLoc{"case.toml", 0, 0});
    FAIL() << "10^10 points were not refused";
  } catch (const InputError& err) {
    EXPECT_EQ(err.loc().line, 9) << err.what();  // [[compliance]] (the luminaire's 4 lines, the area's 4)
    EXPECT_NE(std::string(err.what()).find("the EN 1838 study needs about"), std::string::npos) << err.what();
  }
}

// Bad input: InputError at the offending line.
void expectError(const std::string& body, int line, const std::string& words) {
  const fs::path dir = test_support::scratchDir("en1838", "errors");
  try {
    writeCase(dir, body);
    FAIL() << "no error for: " << body;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(En1838Case, BadInputNamesTheLine) {
  const std::string compliance = "[[compliance]]\nstandard = \"en1838\"\n";
  // The luminaire takes lines 1-4; the body starts on line 5.
  expectError("[[escape_route]]\npath = [[0.0, 0.0]]\nwidth = 1.0\n" + compliance, 6, "at least 2 points");
  expectError("[[escape_route]]\npath = [[0.0, 0.0], [1.0, 0.0]]\nwidth = 0.0\n" + compliance, 7, "'width'");
  expectError("[[escape_route]]\npath = [[0.0, 0.0], [1.0, 0.0]]\nwidth = -1.0\n" + compliance, 7, "'width'");
  expectError("[[open_area]]\npolygon = [[0.0, 0.0], [4.0, 0.0]]\n" + compliance, 6, "at least 3 corners");
  expectError("[[open_area]]\npolygon = [[0.0, 0.0], [6.0, 0.0], [0.0, 4.0], [2.0, 5.0]]\n" + compliance, 6,
              "crosses itself");
  // Two rooms joined by a 0.8 m passage: a core in two pieces.
  expectError("[[open_area]]\npolygon = [[0, 0], [4, 0], [4, 1.6], [6, 1.6], [6, 0], [10, 0], [10, 4], [6, 4], "
              "[6, 2.4], [4, 2.4], [4, 4], [0, 4]]\n" + compliance,
              6, "not one piece");
  expectError("[[open_area]]\ncorners = [[0.0, 0.0], [0.8, 4.0]]\n" + compliance, 6, "no core");
  expectError("[[safety_point]]\nposition = [0.0, 0.0, 1.0]\nfacing = [0.0, 0.0]\n" + compliance, 7, "'facing'");
  expectError("[[escape_route]]\npath = [[0.0, 0.0], [1.0, 0.0]]\nwidth = 1.0\n", 5, "en1838");
  expectError(compliance, 5, "nothing to check");
  expectError(compliance + "spaces = [\"hall\"]\n", 7, "'spaces' is for the daylight standards");
  expectError("[[task_area]]\ncorners = [[0.0, 0.0], [1.0, 1.0]]\nheight = 0.8\nmaintained_illuminance = 300\n"
              "emergency = \"low-risk\"\n" + compliance,
              9, "high-risk");
}

TEST(En1838Case, EmergencyFactorNeedsAnEmergencyLuminaire) {
  const fs::path dir = test_support::scratchDir("en1838", "factor_error");
  try {
    writeCase(dir, kRoute, "isotropic.ies", "emergency_factor = 0.5\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 4);
    EXPECT_NE(std::string(e.what()).find("emergency = true"), std::string::npos);
  }
  try {
    writeCase(dir, kRoute, "isotropic.ies", "emergency = true\nemergency_factor = 1.5\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 5);
  }
}

// The example case, run in-process at draft quality: every part is reported in summary.json.
TEST(En1838Study, OfficeEmergencyExample) {
  RunRequest request;
  request.outDir = test_support::scratchDir("en1838", "office_emergency") / "out";
  request.trace.quality = Quality::kDraft;
  const fs::path casePath = fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "office-emergency" / "case.toml";
  const RunResult r = runCase(casePath, request);
  const nlohmann::json j = nlohmann::json::parse(test_support::slurp(request.outDir / "summary.json"));
  const nlohmann::json& e = j["compliance"]["en1838"];
  EXPECT_EQ(e["standard"], "en1838");
  ASSERT_EQ(e["escape_routes"].size(), 1u);
  const nlohmann::json& route = e["escape_routes"][0];
  for (const char* key : {"name", "min_centre_line_lux", "max_centre_line_lux", "uniformity_ratio",
                          "central_band_min_lux", "verdict"})
    EXPECT_TRUE(route.contains(key)) << key;
  EXPECT_EQ(route["verdict"], "pass");
  EXPECT_GE(route["min_centre_line_lux"].get<double>(), 1.0);
  ASSERT_EQ(e["open_areas"].size(), 1u);
  for (const char* key : {"name", "min_lux", "max_lux", "uniformity_ratio", "verdict"})
    EXPECT_TRUE(e["open_areas"][0].contains(key)) << key;
  EXPECT_EQ(e["high_risk_areas"].size(), 1u);
  EXPECT_EQ(e["safety_points"].size(), 2u);
  // Each with an emergency downlight within 2 m (the first aid post fails on its 4.7 lx, not on this).
  for (const auto& point : e["safety_points"]) EXPECT_LE(point["nearest_emergency_luminaire_m"].get<double>(), 2.0);
  EXPECT_EQ(e["emergency_luminaires"], 5);
  const std::string html = test_support::slurp(request.outDir / "report.html");
  EXPECT_NE(html.find("EN 1838:2013 emergency lighting"), std::string::npos);
  EXPECT_NE(html.find("class=\"en1838-plan\""), std::string::npos);
  // en1838_points.csv: every point once, its minima those of summary.json (to the CSV's 4 decimals).
  std::istringstream csv(test_support::slurp(request.outDir / "en1838_points.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "part,name,x,y,z,dx,dy,dz,illuminance_lux");
  std::map<std::string, double> least;
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const std::string part = line.substr(0, line.find(','));
    const double lux = std::stod(line.substr(line.rfind(',') + 1));
    least.try_emplace(part, lux);
    least[part] = std::min(least[part], lux);
  }
  const auto& result = dynamic_cast<const En1838Section&>(*r.data.compliance.at(0).section).result();
  EXPECT_EQ(rows, result.points.size());
  EXPECT_GT(rows, 100u);
  EXPECT_NEAR(least.at("centre line"), route["min_centre_line_lux"].get<double>(), 5e-5);
  EXPECT_NEAR(least.at("open area core"), e["open_areas"][0]["min_lux"].get<double>(), 5e-5);
  EXPECT_EQ(least.count("safety point"), 1u);
}

}  // namespace
}  // namespace candela
