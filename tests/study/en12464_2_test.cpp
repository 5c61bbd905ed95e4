// EN 12464-2 outdoor work places as a study (study/compliance/en12464_2.h): a ground-only scene
// lit by an isotropic point source (E = I h / d³ at every grid point), the glare rating of CIE 112
// at observers against the formula worked by hand from the geometry (E_eye, θ, L_ve from the
// area's mean), an obstruction, a measured IES file against its own table read here, the case's
// keys and errors, and the car park example.
#include "study/compliance/en12464_2.h"

#include "study/case/case_file.h"
#include "study/compliance/en12464_2_case.h"
#include "study/run_case.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = kPi / 180.0;
constexpr double kIntensityCd = 100.0;  // the isotropic source's
constexpr double kRho = 0.2;            // the ground's reflectance

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// A 60 m square of ground (reflectance 0.2) and, 8 m south of the origin, a black wall 2 m wide
// and 10 m high: it hides the source from an observer behind it and reflects nothing.
void writeGround(const fs::path& dir) {
  writeFile(dir / "ground.rad",
            "void plastic soil\n0\n0\n5 0.2 0.2 0.2 0 0\n\n"
            "soil polygon ground\n0\n0\n12\n-30 -30 0\n30 -30 0\n30 30 0\n-30 30 0\n\n"
            "void plastic black\n0\n0\n5 0 0 0 0 0\n\n"
            "black polygon wall\n0\n0\n12\n-1 -8 0\n1 -8 0\n1 -8 10\n-1 -8 10\n");
  writeFile(dir / "isotropic.ies",
            "IESNA:LM-63-2002\n[TEST] isotropic point source for the EN 12464-2 tests\nTILT=NONE\n"
            "1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 90 180\n0\n100 100 100\n");
}

struct OutdoorRun {
  nlohmann::json entry;  // summary.json's compliance["en12464-2"]
  std::vector<Vec3> points;  // the area's grid points, from its CSV
  std::vector<double> lux;   // their illuminance, as the run holds it (the CSV rounds to 8 digits)
};

// Runs the case `text` written into `dir` (draft quality: the point sources' direct light is exact
// at any quality, and nothing else reaches an upward sensor on the ground).
OutdoorRun runIn(const fs::path& dir, const std::string& text, const std::string& area) {
  writeFile(dir / "case.toml", text);
  RunRequest request;
  request.outDir = dir / "out";
  request.trace.quality = Quality::kDraft;
  const RunResult run = runCase(dir / "case.toml", request);
  OutdoorRun r;
  for (const GridReport& g : run.data.grids)
    if (g.name == area) r.lux = g.values;
  r.entry = nlohmann::json::parse(test_support::slurp(request.outDir / "summary.json"))["compliance"]["en12464-2"];
  std::istringstream csv(test_support::slurp(request.outDir / (area + ".csv")));
  std::string line;
  std::getline(csv, line);  // x,y,z,dx,dy,dz,illuminance_lux,...
  while (std::getline(csv, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<double> v;
    while (std::getline(row, cell, ',')) v.push_back(std::stod(cell));
    r.points.emplace_back(v[0], v[1], v[2]);
  }
  EXPECT_EQ(r.points.size(), r.lux.size());
  return r;
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// GR of one source seen from `eye` along azimuth +X (east) 2° below the horizontal, by hand.
double grByHand(const Vec3& eye, const Vec3& source, double intensityCd, double averageLux) {
  const Vec3 to = source - eye;
  const double d2 = glm::dot(to, to);
  const double thetaDeg = std::atan(to.z / to.x) / kDeg + 2.0;  // the source is in the sight's plane
  const double eyeLux = intensityCd * std::cos(thetaDeg * kDeg) / d2;
  const double lvl = 10.0 * eyeLux / (thetaDeg * thetaDeg);
  const double lve = 0.035 * kRho * averageLux / kPi;
  return 27.0 + 24.0 * std::log10(lvl / std::pow(lve, 0.9));
}

const std::string kHeader = "[[scene]]\nfile = \"ground.rad\"\n";
const std::string kCompliance = "[[compliance]]\nstandard = \"en12464-2\"\n";

TEST(En12464_2Study, IsotropicSourceOverTheGround) {
  const fs::path dir = test_support::scratchDir("en12464_2", "isotropic");
  writeGround(dir);
  const OutdoorRun r = runIn(dir,
                      kHeader +
                          "[[luminaire]]\nfile = \"isotropic.ies\"\nposition = [0.0, 0.0, 6.0]\n"
                          "[[task_area]]\nstandard = \"en12464-2\"\nname = \"yard\"\ncorners = [[-5.0, -5.0], [5.0, 5.0]]\n"
                          "maintained_illuminance = 1.0\nuniformity = 0.6\ngr_limit = 40\nground_reflectance = 0.2\n"
                          "spacing = 1.0\n"
                          "[[observer]]\nkind = \"gr\"\nname = \"east\"\nposition = [-10.0, 0.0]\ndirection = [1.0, 0.0]\n"
                          "[[observer]]\nkind = \"gr\"\nname = \"round\"\nposition = [-10.0, 0.0]\n"
                          "[[observer]]\nkind = \"gr\"\nname = \"walled\"\nposition = [0.0, -10.0]\n"
                          "direction = [0.0, 1.0]\n" + kCompliance,
                      "yard");
  // The grid: 10 × 10 cell centres, each E = I h / d³ (the point law of the ratio estimator).
  ASSERT_EQ(r.points.size(), 100u);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const Vec3 d = Vec3(0.0, 0.0, 6.0) - r.points[i];
    const double e = kIntensityCd * d.z / std::pow(glm::length(d), 3.0);
    EXPECT_NEAR(r.lux[i], e, 1e-9 * e) << r.points[i].x << ", " << r.points[i].y;
  }
  const double eHav = mean(r.lux);
  const nlohmann::json& area = r.entry["task_areas"][0];
  EXPECT_NEAR(area["average_lux"].get<double>(), eHav, 1e-9 * eHav);
  EXPECT_NEAR(area["uniformity"].get<double>(), area["min_lux"].get<double>() / eHav, 1e-12);
  // U0 = E_min/Ē: the corner points (±4.5, ±4.5) against the mean, 0.53: below 0.6.
  const double eCorner = kIntensityCd * 6.0 / std::pow(std::sqrt(4.5 * 4.5 * 2.0 + 36.0), 3.0);
  EXPECT_NEAR(area["min_lux"].get<double>(), eCorner, 1e-9 * eCorner);
  EXPECT_EQ(area["verdict_uniformity"], "fail");
  EXPECT_EQ(area["verdict_average"], "pass");

  const nlohmann::json& obs = r.entry["observers"];
  ASSERT_EQ(obs.size(), 3u);
  // One line of sight, east: the source 10 m ahead and 4.5 m above the eye.
  const double gr = grByHand(Vec3(-10.0, 0.0, 1.5), Vec3(0.0, 0.0, 6.0), kIntensityCd, eHav);
  EXPECT_EQ(obs[0]["task_area"], "yard");  // the only outdoor area
  EXPECT_NEAR(obs[0]["environment_veil_cd_m2"].get<double>(), 0.035 * kRho * eHav / kPi, 1e-12);
  ASSERT_EQ(obs[0]["views"].size(), 1u);
  EXPECT_NEAR(obs[0]["views"][0]["azimuth_deg"].get<double>(), 90.0, 1e-12);
  EXPECT_NEAR(obs[0]["gr_max"].get<double>(), gr, 1e-9);
  EXPECT_EQ(obs[0]["gr_limit"], 40.0);
  EXPECT_EQ(obs[0]["verdict"], gr <= 40.0 ? "pass" : "fail");
  // All around: eight lines of sight from north; the source is in front of the eye looking
  // north-east, east and south-east only.
  const nlohmann::json& views = obs[1]["views"];
  ASSERT_EQ(views.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(views[k]["azimuth_deg"].get<double>(), 45.0 * static_cast<double>(k), 1e-12);
    EXPECT_EQ(views[k]["gr"].is_null(), k < 1 || k > 3) << k;
  }
  EXPECT_NEAR(views[2]["gr"].get<double>(), gr, 1e-9);
  EXPECT_NEAR(obs[1]["gr_max"].get<double>(), gr, 1e-9);  // looking straight at it is the worst
  EXPECT_LT(views[1]["gr"].get<double>(), gr);
  // Behind the black wall the source is hidden: no veil, no rating, a pass.
  EXPECT_EQ(obs[2]["views"][0]["luminaires_in_view"], 0);
  EXPECT_TRUE(obs[2]["gr_max"].is_null());
  EXPECT_EQ(obs[2]["verdict"], "pass");
  EXPECT_EQ(area["gr_observers"].size(), 3u);
}

// The IES file's table as written: the candela value at (C, γ), and linear in γ between rows.
struct IesTable {
  std::vector<double> gamma, c, values;  // values[ci * gamma.size() + gi]
  double at(double cDeg, double gammaDeg) const {
    const std::size_t ci = static_cast<std::size_t>(std::find(c.begin(), c.end(), cDeg) - c.begin());
    const std::size_t g = static_cast<std::size_t>(std::upper_bound(gamma.begin(), gamma.end(), gammaDeg) - gamma.begin()) - 1;
    const double* row = &values[ci * gamma.size()];
    if (g + 1 >= gamma.size()) return row[g];
    const double t = (gammaDeg - gamma[g]) / (gamma[g + 1] - gamma[g]);
    return (1.0 - t) * row[g] + t * row[g + 1];
  }
};

IesTable readIesTable(const fs::path& p) {
  const std::string text = test_support::slurp(p);
  std::istringstream in(text.substr(text.find("TILT=NONE") + 9));
  double lamps, lumens, multiplier, nv, nh, type, units, w, l, h, ballast, future, watts;
  in >> lamps >> lumens >> multiplier >> nv >> nh >> type >> units >> w >> l >> h >> ballast >> future >> watts;
  IesTable t;
  t.gamma.resize(static_cast<std::size_t>(nv));
  t.c.resize(static_cast<std::size_t>(nh));
  t.values.resize(t.gamma.size() * t.c.size());
  for (double& g : t.gamma) in >> g;
  for (double& c : t.c) in >> c;
  for (double& v : t.values) in >> v, v *= multiplier * ballast;
  return t;
}

TEST(En12464_2Study, MeasuredIesFileAgainstItsTable) {
  const fs::path dir = test_support::scratchDir("en12464_2", "real_ies");
  writeGround(dir);
  const std::string file = "OutdoorRoadway IES OS 8988-2022 03 AM01 60W 4000K.ies";
  fs::copy_file(fs::path(CANDELA_REFERENCE) / "photometry" / "eulumdat-rs" / file, dir / file);
  const IesTable table = readIesTable(dir / file);
  ASSERT_EQ(table.gamma.size(), 361u);
  // The observer sees the pole's luminaire (8 m up, aimed down, C0 towards +X) at γ = 60° in the
  // C180 plane: 6.5 m above the eye, 6.5 tan 60° m away; d = 13 m, θ = 30° + 2°.
  const double x = 6.5 * std::tan(60.0 * kDeg);
  std::ostringstream observer;
  observer.precision(17);
  observer << "[[observer]]\nkind = \"gr\"\nname = \"o\"\nposition = [" << -x << ", 0.0]\ndirection = [1.0, 0.0]\n";
  const OutdoorRun r = runIn(dir,
                      kHeader + "[[luminaire]]\nfile = \"" + file + "\"\nposition = [0.0, 0.0, 8.0]\n"
                          "[[task_area]]\nstandard = \"en12464-2\"\nname = \"strip\"\ncorners = [[-0.5, -0.5], [8.5, 0.5]]\n"
                          "maintained_illuminance = 5.0\nground_reflectance = 0.2\nspacing = 1.0\n" + observer.str() +
                          kCompliance,
                      "strip");
  // The strip's points (k, 0, 0), k = 0…8: C0 plane, γ = atan(k/8), E = I(0, γ) cos γ / d².
  ASSERT_EQ(r.points.size(), 9u);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const double px = r.points[i].x;
    EXPECT_NEAR(px, static_cast<double>(i), 1e-12);
    const double gamma = std::atan(px / 8.0) / kDeg, d2 = px * px + 64.0;
    const double e = table.at(0.0, gamma) * std::cos(gamma * kDeg) / d2;
    EXPECT_NEAR(r.lux[i], e, 1e-9 * e) << "x = " << px;
  }
  const double eHav = mean(r.lux);
  const double intensity = table.at(180.0, 60.0);  // a tabulated value: no interpolation
  EXPECT_NEAR(r.entry["observers"][0]["gr_max"].get<double>(),
              grByHand(Vec3(-x, 0.0, 1.5), Vec3(0.0, 0.0, 8.0), intensity, eHav), 1e-9);
  // By the numbers: θ = 32°, E_eye = I cos 32° / 169.
  const double eyeLux = intensity * std::cos(32.0 * kDeg) / 169.0;
  const double lvl = 10.0 * eyeLux / (32.0 * 32.0);
  EXPECT_NEAR(r.entry["observers"][0]["views"][0]["luminaires_veil_cd_m2"].get<double>(), lvl, 1e-9 * lvl);
}

// Ra against the colour rendering the EULUMDAT file states (cases/luminaires/led_panel_600.ldt:
// group 1B, Ra ≥ 80): an area asking 80 passes, one asking 85 fails; no observer: GR not checked.
TEST(En12464_2Study, ColourRenderingFromTheEulumdatFile) {
  const fs::path dir = test_support::scratchDir("en12464_2", "ra");
  writeGround(dir);
  fs::copy_file(fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "luminaires" / "led_panel_600.ldt",
                dir / "panel.ldt");
  const std::string area = "[[task_area]]\nstandard = \"en12464-2\"\ncorners = [[-2.0, -2.0], [2.0, 2.0]]\n"
                           "maintained_illuminance = 1.0\n";
  const OutdoorRun r = runIn(dir,
                             kHeader + "[[luminaire]]\nfile = \"panel.ldt\"\nposition = [0.0, 0.0, 4.0]\n" + area +
                                 "name = \"a\"\nra = 80\n" + area + "name = \"b\"\nra = 85\n" + kCompliance,
                             "a");
  const nlohmann::json& areas = r.entry["task_areas"];
  ASSERT_EQ(areas.size(), 2u);
  for (const nlohmann::json& a : areas) {
    EXPECT_EQ(a["ra_least"], 80.0);
    EXPECT_EQ(a["verdict_gr"], "n/a");
  }
  EXPECT_EQ(areas[0]["verdict_ra"], "pass");
  EXPECT_EQ(areas[1]["verdict_ra"], "fail");
  EXPECT_EQ(areas[1]["verdict"], "fail");
  EXPECT_EQ(r.entry["verdict"], "fail");
}

// Without `ground_reflectance` ρ is the scene's: the ground's plastic of reflectance 0.2 under every
// point; an area over no surface at all is an error at its line.
TEST(En12464_2Study, GroundReflectanceFromTheScene) {
  const fs::path dir = test_support::scratchDir("en12464_2", "rho_scene");
  writeGround(dir);
  const std::string head = kHeader + "[[luminaire]]\nfile = \"isotropic.ies\"\nposition = [0.0, 0.0, 6.0]\n"
                                     "[[task_area]]\nstandard = \"en12464-2\"\nname = \"yard\"\n";
  const std::string tail = "maintained_illuminance = 1.0\nspacing = 1.0\n"
                           "[[observer]]\nkind = \"gr\"\nposition = [-10.0, 0.0]\ndirection = [1.0, 0.0]\n" +
                           kCompliance;
  const OutdoorRun r = runIn(dir, head + "corners = [[-5.0, -5.0], [5.0, 5.0]]\n" + tail, "yard");
  EXPECT_NEAR(r.entry["task_areas"][0]["ground_reflectance"].get<double>(), kRho, 1e-12);
  EXPECT_EQ(r.entry["task_areas"][0]["ground_reflectance_from"], "scene");
  EXPECT_NEAR(r.entry["observers"][0]["gr_max"].get<double>(),
              grByHand(Vec3(-10.0, 0.0, 1.5), Vec3(0.0, 0.0, 6.0), kIntensityCd, mean(r.lux)), 1e-9);
  try {
    runIn(dir, head + "corners = [[100.0, 100.0], [110.0, 110.0]]\n" + tail, "yard");
    FAIL() << "an area over no surface";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 6) << e.what();
    EXPECT_NE(std::string(e.what()).find("give 'ground_reflectance'"), std::string::npos) << e.what();
  }
}

// A luminaire on its pole lies above a ground-only scene's flat box: not outside the scene unless
// it stands beyond the ground's plan extent or below the ground (study/warnings.cpp).
TEST(En12464_2Study, PolesOverFlatGroundAreNotOutsideTheScene) {
  const fs::path dir = test_support::scratchDir("en12464_2", "flat_ground");
  writeGround(dir);  // the isotropic source (and a ground with a wall, replaced by the ground alone)
  writeFile(dir / "ground.rad", "void plastic soil\n0\n0\n5 0.2 0.2 0.2 0 0\n\n"
                                "soil polygon ground\n0\n0\n12\n-30 -30 0\n30 -30 0\n30 30 0\n-30 30 0\n");
  const std::string lum = "[[luminaire]]\nfile = \"isotropic.ies\"\nposition = ";
  writeFile(dir / "case.toml", kHeader + lum + "[0.0, 0.0, 8.0]\n" +  // lines 3-5: over the ground
                                   lum + "[50.0, 0.0, 8.0]\n" +      // lines 6-8: beyond its extent
                                   lum + "[0.0, 0.0, -1.0]\n" +      // lines 9-11: below it
                                   "[[grid]]\nname = \"g\"\ncorners = [[-5.0, -5.0], [5.0, 5.0]]\nheight = 0.0\n");
  RunRequest request;
  request.outDir = dir / "out";
  request.trace.quality = Quality::kDraft;
  const RunResult run = runCase(dir / "case.toml", request);
  std::vector<int> lines;
  for (const Warning& w : run.data.warnings)
    if (w.code == "luminaire_outside_scene") lines.push_back(w.loc.line);
  EXPECT_EQ(lines, (std::vector<int>{6, 9}));
}

// Obtrusive light against closed forms: the isotropic 100 cd source 6 m up; a window 20 m north
// facing it gets E_v = I cos ι / d² (cos ι = 20/d, d² = 416); one behind the black wall gets none
// and sees no luminaire; one facing away none. The upward light ratio of an isotropic source is
// one half (the midpoint rule is exact on a constant), against E2's 5 % (EN 12193 Table 5), or a
// limit of the case's.
TEST(En12464_2Study, ObtrusiveLightOfAnIsotropicSource) {
  const fs::path dir = test_support::scratchDir("en12464_2", "obtrusive");
  writeGround(dir);
  const std::string points =
      "property_points = [{ name = \"north\", position = [0.0, 20.0, 2.0], normal = [0.0, -1.0, 0.0] },\n"
      "  { name = \"walled\", position = [0.0, -20.0, 2.0], normal = [0.0, 1.0, 0.0] },\n"
      "  { name = \"away\", position = [0.0, 20.0, 2.0], normal = [0.0, 1.0, 0.0] }]\n";
  const std::string lum = "[[luminaire]]\nfile = \"isotropic.ies\"\nposition = [0.0, 0.0, 6.0]\n";
  const OutdoorRun r = runIn(dir, kHeader + lum + kCompliance + "environmental_zone = \"E2\"\n" + points, "");
  const nlohmann::json& o = r.entry["obtrusive_light"];
  EXPECT_EQ(o["environmental_zone"], "E2");
  EXPECT_EQ(o["limit_property_illuminance_lux"], 5.0);
  EXPECT_EQ(o["limit_intensity_cd"], 7500.0);
  EXPECT_EQ(o["limit_upward_light_ratio"], 0.05);
  const nlohmann::json& p = o["property_points"];
  ASSERT_EQ(p.size(), 3u);
  const double d2 = 416.0, ev = kIntensityCd * (20.0 / std::sqrt(d2)) / d2;
  EXPECT_NEAR(p[0]["illuminance_lux"].get<double>(), ev, 1e-9 * ev);
  EXPECT_NEAR(p[0]["max_intensity_cd"].get<double>(), kIntensityCd, 1e-9);
  EXPECT_EQ(p[0]["verdict_illuminance"], "pass");
  EXPECT_EQ(p[0]["verdict_intensity"], "pass");
  for (int i : {1, 2}) {
    EXPECT_EQ(p[i]["illuminance_lux"].get<double>(), 0.0) << i;
    EXPECT_EQ(p[i]["max_intensity_cd"].get<double>(), 0.0) << i;
    EXPECT_TRUE(p[i]["brightest_luminaire"].is_null()) << i;
  }
  EXPECT_NEAR(o["total_flux_lm"].get<double>(), 4.0 * kPi * kIntensityCd, 1e-9);
  EXPECT_NEAR(o["upward_light_ratio"].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(o["verdict_upward_light_ratio"], "fail");
  EXPECT_EQ(o["verdict"], "fail");
  EXPECT_EQ(r.entry["verdict"], "fail");
  // The case's limits replace the zone's: a ratio of 60 % allowed, and 0.2 lx at the windows.
  const OutdoorRun own = runIn(dir, kHeader + lum + kCompliance + "environmental_zone = \"E2\"\n" +
                                        "obtrusive_limits = { upward_light_ratio = 0.6, property_illuminance = 0.2 }\n" +
                                        points, "");
  const nlohmann::json& q = own.entry["obtrusive_light"];
  EXPECT_EQ(q["verdict_upward_light_ratio"], "pass");
  EXPECT_EQ(q["property_points"][0]["verdict_illuminance"], "fail");  // 0.236 lx > 0.2 lx
  EXPECT_EQ(q["limit_intensity_cd"], 7500.0);                          // the zone's, not replaced
}

// The upward light ratio of a Lambertian emitter (I = I0 cos γ below its plane) aimed 30° off the
// nadir: (1 − cos 30°)/2 of its flux goes above the horizontal (the part of its hemisphere beyond
// the horizontal plane), to the midpoint rule's and the file's 1° tabulation's error.
TEST(En12464_2Study, UpwardLightRatioOfATiltedLambertianEmitter) {
  const fs::path dir = test_support::scratchDir("en12464_2", "lambert_ulr");
  writeGround(dir);
  std::ostringstream ies;
  ies << "IESNA:LM-63-2002\n[TEST] Lambertian emitter, I = 1000 cos(gamma)\nTILT=NONE\n"
      << "1 -1 1 181 1 1 2 0 0 0\n1 1 0\n";
  for (int g = 0; g <= 180; ++g) ies << g << (g < 180 ? " " : "\n");
  ies << "0\n";
  for (int g = 0; g <= 180; ++g) ies << (g <= 90 ? 1000.0 * std::cos(g * kDeg) : 0.0) << (g < 180 ? " " : "\n");
  writeFile(dir / "lambert.ies", ies.str());
  const double alpha = 30.0 * kDeg;
  const OutdoorRun r = runIn(dir, kHeader + "[[luminaire]]\nfile = \"lambert.ies\"\nposition = [0.0, 0.0, 6.0]\n"
                                  "aim = [" + std::to_string(std::sin(alpha)) + ", 0.0, " + std::to_string(-std::cos(alpha)) +
                                  "]\n" + kCompliance + "environmental_zone = \"E4\"\n", "");
  const nlohmann::json& o = r.entry["obtrusive_light"];
  EXPECT_NEAR(o["total_flux_lm"].get<double>(), kPi * 1000.0, 2e-3 * kPi * 1000.0);
  EXPECT_NEAR(o["upward_light_ratio"].get<double>(), (1.0 - std::cos(alpha)) / 2.0, 1e-3);
  EXPECT_EQ(o["verdict_upward_light_ratio"], "pass");  // 6.7 % ≤ E4's 25 %
  EXPECT_TRUE(o["property_points"].empty());
}

TEST(En12464_2Case, GrLatticeOverTheArea) {
  OutdoorTaskAreaSpec a;
  a.name = "yard";
  a.outline = {{0.0, 0.0}, {25.0, 0.0}, {25.0, 10.0}, {0.0, 10.0}};
  a.grSpacingM = 10.0;
  const std::vector<GrObserverSpec> o = gridGrObservers(a);
  // ⌈25/10⌉ = 3 cells along x (8.33 m), 1 along y: their centres.
  ASSERT_EQ(o.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(o[k].positionM.x, 25.0 / 3.0 * (static_cast<double>(k) + 0.5), 1e-12);
    EXPECT_NEAR(o[k].positionM.y, 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(o[k].eyeHeightM, 1.5);
    EXPECT_FALSE(o[k].direction);  // all around
    EXPECT_DOUBLE_EQ(o[k].stepDeg, 45.0);
    EXPECT_DOUBLE_EQ(o[k].inclinationDeg, -2.0);
  }
}

// Bad input: InputError at the offending line.
void expectError(const std::string& body, int line, const std::string& words) {
  const fs::path dir = test_support::scratchDir("en12464_2", "errors");
  writeGround(dir);
  writeFile(dir / "case.toml", kHeader + body);  // the header takes lines 1-2
  try {
    readCaseFile(dir / "case.toml");
    FAIL() << "no error for: " << body;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(En12464_2Case, BadInputNamesTheLine) {
  const std::string area = "[[task_area]]\nstandard = \"en12464-2\"\ncorners = [[0.0, 0.0], [10.0, 10.0]]\n"
                           "maintained_illuminance = 10\nground_reflectance = 0.2\n";  // lines 3-7
  const std::string gr = "[[observer]]\nkind = \"gr\"\nposition = [5.0, 5.0]\n";
  expectError("[[task_area]]\nstandard = \"en12464-3\"\n", 4, "'standard'");
  expectError(area + "gr_limit = 5\n" + kCompliance, 8, "'gr_limit'");
  expectError(area + "ugr_limit = 19\n" + kCompliance, 8, "unknown key 'ugr_limit'");
  expectError("[[task_area]]\nstandard = \"en12464-2\"\ncorners = [[0.0, 0.0], [10.0, 10.0]]\n"
              "maintained_illuminance = 10\nground_reflectance = 1.5\n" + kCompliance,
              7, "ground_reflectance");
  expectError(area + "[[observer]]\nkind = \"gr2\"\nposition = [1.0, 1.0]\n" + kCompliance, 9, "'kind'");
  expectError(area + gr + "direction = [1.0, 0.0]\ndirection_step = 30\n" + kCompliance, 12, "direction_step");
  expectError(area + gr + "task_area = \"lot\"\n" + kCompliance, 8, "'lot'");
  expectError(area + gr + "inclination = -60\n" + kCompliance, 11, "'inclination'");
  expectError(area, 3, "needs a [[compliance]] entry");
  expectError(kCompliance, 3, "nothing to check");
  expectError(kCompliance + "spaces = [\"a\"]\n", 5, "'spaces'");
  expectError(area + "gr_spacing = 10\n[[task_area]]\nstandard = \"en12464-2\"\nname = \"b\"\n"
              "corners = [[20.0, 0.0], [30.0, 10.0]]\nmaintained_illuminance = 10\n" +
              "[[observer]]\nkind = \"gr\"\nposition = [15.0, 5.0]\n" + kCompliance,
              14, "stands in no outdoor task area");
  // A GR lattice is bounded before it is made: 10 m at 1 mm is 10⁸ observers (limit 10⁵).
  expectError(area + "gr_spacing = 0.001\n" + kCompliance, 8,
              "makes a lattice of 100000000 observers over the task area 'task area 1', more than the 100000");
  // Obtrusive light: a zone without built-in limits, a ratio beyond 1, points without limits, a
  // point without its normal, the keys on another standard's entry.
  expectError(area + kCompliance + "environmental_zone = \"E0\"\n", 10, "'environmental_zone' must be");
  expectError(area + kCompliance + "obtrusive_limits = { upward_light_ratio = 1.5 }\n", 10, "upward_light_ratio");
  expectError(area + kCompliance + "property_points = [{ position = [0.0, 20.0, 2.0], normal = [0.0, -1.0, 0.0] }]\n",
              10, "need the limits");
  expectError(area + kCompliance + "environmental_zone = \"E3\"\nproperty_points = [{ position = [0.0, 20.0, 2.0] }]\n",
              11, "normal");
  // The list's form (asTableList, shared with glare_views and window states): empty, or an entry
  // that is no table, each at its line.
  expectError(area + kCompliance + "environmental_zone = \"E3\"\nproperty_points = []\n", 11,
              "'property_points' needs at least one entry { name, position");
  expectError(area + kCompliance + "environmental_zone = \"E3\"\nproperty_points = [\n  [0.0, 20.0, 2.0]\n]\n", 12,
              "each of 'property_points' must be { name, position");
  expectError("[[compliance]]\nstandard = \"en1838\"\nenvironmental_zone = \"E3\"\n", 5,
              "'environmental_zone' belongs to standard = \"en12464-2\"");
}

// The example: every part in summary.json, each GR consistent with its own L_vl and L_ve, and the
// report's section.
TEST(En12464_2Study, CarParkExample) {
  RunRequest request;
  request.outDir = test_support::scratchDir("en12464_2", "car_park") / "out";
  request.trace.quality = Quality::kDraft;
  const fs::path casePath = fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "car-park" / "case.toml";
  runCase(casePath, request);
  const nlohmann::json j = nlohmann::json::parse(test_support::slurp(request.outDir / "summary.json"));
  const nlohmann::json& e = j["compliance"]["en12464-2"];
  EXPECT_EQ(e["standard"], "en12464-2");
  ASSERT_EQ(e["task_areas"].size(), 1u);
  const nlohmann::json& a = e["task_areas"][0];
  for (const char* key : {"name", "average_lux", "min_lux", "uniformity", "maintained_illuminance_lux", "gr_limit",
                          "gr_max", "verdict_average", "verdict_uniformity", "verdict_gr", "verdict_ra", "verdict"})
    EXPECT_TRUE(a.contains(key)) << key;
  EXPECT_EQ(a["verdict_ra"], "n/a");  // an IES file states no colour rendering
  // 2 observers of the case and the 10 m lattice over 40 m × 24 m: 4 × 3.
  ASSERT_EQ(e["observers"].size(), 14u);
  for (const nlohmann::json& o : e["observers"]) {
    const double lve = o["environment_veil_cd_m2"].get<double>();
    EXPECT_NEAR(lve, 0.035 * 0.15 * a["average_lux"].get<double>() / kPi, 1e-12);
    for (const nlohmann::json& v : o["views"]) {
      if (v["gr"].is_null()) continue;
      EXPECT_NEAR(v["gr"].get<double>(),
                  27.0 + 24.0 * std::log10(v["luminaires_veil_cd_m2"].get<double>() / std::pow(lve, 0.9)), 1e-9);
    }
  }
  const std::string html = test_support::slurp(request.outDir / "report.html");
  EXPECT_NE(html.find("EN 12464-2:2014 outdoor work places"), std::string::npos);
  EXPECT_NE(html.find("class=\"en12464-2-plan\""), std::string::npos);
}

}  // namespace
}  // namespace candela
