// EN 13201 road lighting as a study (study/compliance/en13201.h): the EN 13201-3 grids and
// observers, and the light at them against closed forms: an isotropic point source of I cd at
// height h gives E = I h / d³ on the road and L = r(β, tan γ) (q0/Q0) I / h² with r read at the
// table's own nodes; the veiling luminance of one luminaire by hand; the edge illuminance ratio and
// the uniformities from the point law; a real IES file against its own intensities; the case's
// keys and errors; the example case.
#include "study/compliance/en13201.h"

#include "photometry/photometric_file.h"
#include "study/case/case_file.h"
#include "study/compliance/en13201_grids.h"
#include "study/run_case.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr double kIntensityCd = 1000.0;  // the isotropic source's
constexpr double kDeg = kPi / 180.0;

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

void writeIsotropicIes(const fs::path& p) {
  writeFile(p,
            "IESNA:LM-63-2002\n[TEST] isotropic point source for the EN 13201 tests\nTILT=NONE\n"
            "1 -1 1 3 1 1 2 0 0 0\n1 1 0\n0 90 180\n0\n1000 1000 1000\n");
}

// A two-lane road 30 m × 7 m along +x from the origin, class `cls`.
std::string road(const std::string& cls = "M3", const std::string& extra = "") {
  return "[[road]]\nname = \"main\"\nstart = [0.0, 0.0]\ndirection = [1.0, 0.0]\nlength = 30.0\nwidth = 7.0\n"
         "lanes = 2\nclass = \"" + cls + "\"\nsurface = \"R3\"\n" + extra +
         "[[compliance]]\nstandard = \"en13201\"\n";
}

// A case in `dir`: isotropic sources at `positions`, then `body`.
CaseFile writeCase(const fs::path& dir, const std::string& body, const std::vector<Vec3>& positions,
                   const std::string& luminaire = "isotropic.ies", const std::string& extraKeys = "") {
  writeIsotropicIes(dir / "isotropic.ies");
  std::string text;
  for (const Vec3& p : positions)
    text += "[[luminaire]]\nfile = \"" + luminaire + "\"\nposition = [" + std::to_string(p.x) + ", " +
            std::to_string(p.y) + ", " + std::to_string(p.z) + "]\n" + extraKeys;
  writeFile(dir / "case.toml", text + body);
  return readCaseFile(dir / "case.toml");
}

// E = I h / d³ at plan point p on z = 0 from isotropic sources.
double pointLaw(const std::vector<Vec3>& sources, const Vec2& p, double intensity = kIntensityCd) {
  double e = 0.0;
  for (const Vec3& s : sources) {
    const double d = glm::length(s - Vec3(p, 0.0));
    e += intensity * s.z / (d * d * d);
  }
  return e;
}

std::unique_ptr<Scene> sceneOf(const CaseFile& c, std::vector<double>& factors) { return loadRoadScene(c, factors); }

TEST(En13201Grids, TheStandardsSpacingsAndObservers) {
  RoadSpec r;
  r.start = Vec2(10.0, 0.0);
  r.direction = Vec2(0.0, 1.0);  // along +y: across is −x
  r.lengthM = 30.0;
  r.widthM = 7.0;
  r.lanes = 2;
  const RoadGrids g = roadGrids(r);
  // S ≤ 30 m: N = 10, D = 3 m, the first point at D/2.
  ASSERT_EQ(g.alongM.size(), 10u);
  EXPECT_DOUBLE_EQ(g.spacingAlongM, 3.0);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_NEAR(g.alongM[i], 1.5 + 3.0 * i, 1e-12);
  // Luminance: 3 points a lane, d = 3.5/3, the outer ones d/2 from the lane's edges.
  ASSERT_EQ(g.luminanceAcrossM.size(), 6u);
  const double d = 3.5 / 3.0;
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(g.luminanceAcrossM[j], (j / 3) * 3.5 + (j % 3 + 0.5) * d, 1e-12);
  // Illuminance: n ≥ 3 with d ≤ 1.5 m over 7 m: n = 5, d = 1.4.
  ASSERT_EQ(g.illuminanceAcrossM.size(), 5u);
  for (std::size_t j = 0; j < 5; ++j) EXPECT_NEAR(g.illuminanceAcrossM[j], 0.7 + 1.4 * j, 1e-12);
  // Observers: 60 m before the field, in each lane's middle, eyes 1.5 m up (across = −x here).
  ASSERT_EQ(g.observers.size(), 2u);
  EXPECT_NEAR(glm::length(g.observers[0] - Vec3(10.0 - 1.75, -60.0, 1.5)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(g.observers[1] - Vec3(10.0 - 5.25, -60.0, 1.5)), 0.0, 1e-12);
  const Vec2 p = g.plan(g.alongM[0], g.luminanceAcrossM[0]);
  EXPECT_NEAR(glm::length(p - Vec2(10.0 - 0.5 * d, 1.5)), 0.0, 1e-12);
  // Longer fields: the least N with D ≤ 3 m; narrow ones keep 3 points across.
  EXPECT_EQ(longitudinalPointCount(30.0), 10);
  EXPECT_EQ(longitudinalPointCount(31.0), 11);  // D = 2.82 m
  EXPECT_EQ(longitudinalPointCount(45.0), 15);  // D = 3 m exactly
  EXPECT_EQ(longitudinalPointCount(46.0), 16);
  EXPECT_EQ(longitudinalPointCount(12.0), 10);  // D = 1.2 m
  EXPECT_EQ(illuminanceTransverseCount(3.0), 3);
  EXPECT_EQ(illuminanceTransverseCount(4.6), 4);
  // Edge strips: min(5 m, half the width), inside and outside each edge.
  EXPECT_DOUBLE_EQ(g.stripWidthM, 3.5);
  EXPECT_NEAR(g.nearOutsideM.front(), -3.5 + 3.5 / 6.0, 1e-12);
  EXPECT_NEAR(g.farOutsideM.back(), 7.0 + 3.5 - 3.5 / 6.0, 1e-12);
}

TEST(En13201Study, IlluminanceFollowsThePointLaw) {
  const fs::path dir = test_support::scratchDir("en13201", "point_law");
  const std::vector<Vec3> sources = {{0.0, -0.5, 8.0}, {30.0, -0.5, 8.0}, {60.0, -0.5, 8.0}};
  const CaseFile c = writeCase(dir, road("C3"), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const std::vector<RoadResult> r = computeEn13201(c, *scene, factors);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0].illuminancePoints.size(), 50u);  // 10 along × 5 across
  std::vector<double> expected;
  for (std::size_t k = 0; k < r[0].illuminancePoints.size(); ++k) {
    expected.push_back(pointLaw(sources, r[0].illuminancePoints[k]));
    EXPECT_NEAR(r[0].illuminanceLux[k], expected.back(), 1e-12 * expected.back()) << "point " << k;
  }
  const RoadStats s = roadStats(expected);
  EXPECT_NEAR(r[0].averageLux, s.average, 1e-12 * s.average);
  EXPECT_NEAR(r[0].minLux, s.min, 1e-12 * s.min);
  EXPECT_NEAR(r[0].illuminanceUniformity, s.min / s.average, 1e-12);
  // C3: Ē ≥ 15 lx and Emin/Ē ≥ 0.4, judged on these numbers.
  const bool pass = s.average >= 15.0 && s.min / s.average >= 0.4;
  EXPECT_EQ(r[0].verdict, pass ? Verdict::kPass : Verdict::kFail);
}

TEST(En13201Study, MaintenanceFactorScalesMaintainedValuesOnly) {
  const fs::path dir = test_support::scratchDir("en13201", "maintenance");
  const std::vector<Vec3> sources = {{15.0, -0.5, 8.0}};
  const CaseFile c = writeCase(dir, road(), sources, "isotropic.ies", "maintenance_factor = 0.8\n");
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  ASSERT_EQ(factors, std::vector<double>{0.8});
  const RoadLight light(*scene, nullptr, factors);
  const Vec2 p(15.0, 2.0);
  EXPECT_NEAR(light.illuminanceLux(p), 0.8 * pointLaw(sources, p), 1e-12);
  const RoadLight::Luminance l = light.luminanceCdM2(p, Vec3(-45.0, 1.75, 1.5), *findRTable("R3"), 0.07);
  EXPECT_NEAR(l.maintained, 0.8 * l.initial, 1e-15);
}

// The luminance at points whose geometry falls on the r-table's nodes, against the table's printed
// values: L = r·10⁻⁴ (q0/0.07) I / h².
TEST(En13201Study, LuminanceFromTheRTableAtItsNodes) {
  const fs::path dir = test_support::scratchDir("en13201", "luminance");
  const double h = 10.0;
  const std::vector<Vec3> sources = {{50.0, 3.0, h}};
  const CaseFile c = writeCase(dir, road(), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadLight light(*scene, nullptr, factors);
  const RTable& r3 = *findRTable("R3");
  // Each point is seen from x = −10 m (or −100 m) looking along +x on the point's own line.
  const double q0 = 0.1;            // a lighter surface: every r scales by 0.1/0.07
  struct Case {
    Vec2 point;
    double rTable;  // the printed value, 10⁻⁴ sr⁻¹
    const char* what;
  };
  const Case cases[] = {
      {{50.0, 3.0}, 294, "under the luminaire: tan γ = 0"},
      {{30.0, 3.0}, 326, "luminaire 2h beyond the point: β = 0, tan γ = 2"},
      {{40.0, 3.0}, 362, "luminaire h beyond: β = 0, tan γ = 1"},
      {{50.0, -7.0}, 100, "luminaire h to the side: β = 90°, tan γ = 1"},
      {{55.0, 3.0}, 194, "luminaire h/2 behind: β = 180°, tan γ = 0.5"},
      {{20.0, 3.0}, 253, "3h beyond: β = 0, tan γ = 3"},
  };
  for (const Case& k : cases) {
    const double expected = k.rTable * 1e-4 * (q0 / 0.07) * kIntensityCd / (h * h);
    const Vec3 eye(-10.0, k.point.y, 1.5);
    const RoadLight::Luminance l = light.luminanceCdM2(k.point, eye, r3, q0);
    EXPECT_NEAR(l.maintained, expected, 1e-12 * expected) << k.what;
  }
  // Beyond tan γ = 12 the table ends: no luminance.
  EXPECT_EQ(light.luminanceCdM2(Vec2(-75.0, 3.0), Vec3(-100.0, 3.0, 1.5), r3, q0).maintained, 0.0);
}

// The hemispherical and semi-cylindrical illuminances against an independent quadrature of their
// definitions (the flux on a small hemisphere's / half-cylinder's curved surface over its area):
// E_hs = (1/2π) ∫ E_n max(0, n·s) dΩ over the upper hemisphere, E_sc = (1/π) ∫ E_n max(0, n(φ)·s) dφ
// over the half-cylinder's face, E_n = I/d² the illuminance normal to the light. The vertical
// illuminance against I (n·s)/d². The midpoint rule's error, for integrands of unit size with second
// derivatives at most 1 and one kink of slope jump at most 2 (the terminator), is at most
// h²(1/4 + (b−a)/24) over an interval of length b − a in steps h, and below (Δθ + Δφ)² for the
// hemisphere's two-dimensional rule: those bounds, times E_n, are the tolerances.
TEST(En13201Study, HemisphericalAndSemiCylindricalAgainstQuadrature) {
  const fs::path dir = test_support::scratchDir("en13201", "hemispherical");
  const std::vector<Vec3> sources = {{12.0, -0.5, 6.0}};
  const CaseFile c = writeCase(dir, road(), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadLight light(*scene, nullptr, factors);
  const Vec2 along(1.0, 0.0);
  auto hemisphere = [](const Vec3& s, int n) {  // (1/2π) ∫ max(0, n·s) dΩ, s unit
    double sum = 0.0;
    const double dt = 0.5 * kPi / n, dp = 2.0 * kPi / (4 * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 4 * n; ++j) {
        const double t = (i + 0.5) * dt, p = (j + 0.5) * dp;
        const Vec3 nrm(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
        sum += std::max(0.0, glm::dot(nrm, s)) * std::sin(t) * dt * dp;
      }
    return sum / (2.0 * kPi);
  };
  auto halfCylinder = [](const Vec3& s, const Vec2& facing, int n) {  // (1/π) ∫ max(0, n(φ)·s) dφ
    const Vec2 side(-facing.y, facing.x);
    double sum = 0.0;
    const double dp = kPi / n;
    for (int j = 0; j < n; ++j) {
      const double p = -0.5 * kPi + (j + 0.5) * dp;
      const Vec3 nrm(facing * std::cos(p) + side * std::sin(p), 0.0);
      sum += std::max(0.0, glm::dot(nrm, s)) * dp;
    }
    return sum / kPi;
  };
  for (const Vec2 p : {Vec2(3.0, 1.0), Vec2(12.0, 3.5), Vec2(20.0, 6.3), Vec2(12.0, -0.5)}) {
    // On the road: hemispherical.
    const Vec3 toSource = sources[0] - Vec3(p, 0.0);
    const double d2 = glm::dot(toSource, toSource);
    const Vec3 s = toSource / std::sqrt(d2);
    const int n = 400;
    const double step = 0.5 * kPi / n;  // Δθ = Δφ
    EXPECT_NEAR(light.hemisphericalLux(p), kIntensityCd / d2 * hemisphere(s, n), kIntensityCd / d2 * 4.0 * step * step)
        << p.x << ", " << p.y;
    // 1.5 m up: semi-cylindrical and vertical, facing +x and −x.
    const Vec3 up = sources[0] - Vec3(p, kFacialHeightM);
    const double u2 = glm::dot(up, up);
    const Vec3 su = up / std::sqrt(u2);
    const std::array<RoadLight::Facing, 2> f = light.facingLux(p, along);
    for (int side = 0; side < 2; ++side) {
      const Vec2 facing = side == 0 ? along : -along;
      const int n = 4000;
      const double h = kPi / n, bound = h * h * (0.25 + kPi / 24.0) / kPi;
      EXPECT_NEAR(f[side].semiCylindrical, kIntensityCd / u2 * halfCylinder(su, facing, n), kIntensityCd / u2 * bound)
          << p.x << ", " << p.y << " side " << side;
      const double ev = kIntensityCd / u2 * std::max(0.0, glm::dot(Vec3(facing, 0.0), su));
      EXPECT_NEAR(f[side].vertical, ev, 1e-12 * (ev + 1.0)) << p.x << ", " << p.y << " side " << side;
    }
  }
  // Straight under the luminaire (at 1.5 m): no light on vertical faces; on the road E_hs = E_h/2.
  EXPECT_EQ(light.facingLux(Vec2(12.0, -0.5), along)[0].semiCylindrical, 0.0);
  EXPECT_NEAR(light.hemisphericalLux(Vec2(12.0, -0.5)), 0.5 * light.illuminanceLux(Vec2(12.0, -0.5)), 1e-12);
}

// An HS2 footway with additional classes SC5 and EV6: its figures are the closed forms' at the
// illuminance grid (E_hs = I (1 + cos ε)/4d², E_sc = I sin ε (1 + cos α)/πd² and E_v = I (n·s)/d²,
// 1.5 m up, the lesser of the two directions along), and the verdicts follow from them.
TEST(En13201Study, HsClassAndAdditionalClassesFromTheClosedForms) {
  const fs::path dir = test_support::scratchDir("en13201", "hs_sc_ev");
  const std::vector<Vec3> sources = {{0.0, -0.5, 5.0}, {20.0, -0.5, 5.0}};
  const CaseFile c = writeCase(dir,
                               "[[road]]\nname = \"footway\"\nstart = [0.0, 0.0]\ndirection = [1.0, 0.0]\nlength = 20.0\n"
                               "width = 3.0\nclass = \"HS2\"\nadditional_classes = [\"SC5\", \"ev6\"]\n"
                               "[[compliance]]\nstandard = \"en13201\"\n",
                               sources);
  ASSERT_EQ(c.roadLighting.roads.size(), 1u);
  ASSERT_EQ(c.roadLighting.roads[0].additional.size(), 2u);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const std::vector<RoadResult> r = computeEn13201(c, *scene, factors);
  ASSERT_EQ(r.size(), 1u);
  std::vector<double> hs, sc, ev;
  for (const Vec2& p : r[0].illuminancePoints) {
    double h = 0.0, scPlus = 0.0, scMinus = 0.0, evPlus = 0.0, evMinus = 0.0;
    for (const Vec3& s : sources) {
      const Vec3 v = s - Vec3(p, 0.0);
      const double d2 = glm::dot(v, v);
      h += kIntensityCd * (1.0 + s.z / std::sqrt(d2)) / (4.0 * d2);
      const Vec3 u = s - Vec3(p, 1.5);
      const double u2 = glm::dot(u, u), horizontal = std::hypot(u.x, u.y);
      const double sinE = horizontal / std::sqrt(u2), cosA = u.x / horizontal;
      scPlus += kIntensityCd * sinE * (1.0 + cosA) / (kPi * u2);
      scMinus += kIntensityCd * sinE * (1.0 - cosA) / (kPi * u2);
      evPlus += kIntensityCd * std::max(0.0, u.x) / (u2 * std::sqrt(u2));
      evMinus += kIntensityCd * std::max(0.0, -u.x) / (u2 * std::sqrt(u2));
    }
    hs.push_back(h);
    sc.push_back(std::min(scPlus, scMinus));
    ev.push_back(std::min(evPlus, evMinus));
  }
  const RoadStats h = roadStats(hs);
  EXPECT_NEAR(r[0].averageHemisphericalLux, h.average, 1e-12 * h.average);
  EXPECT_NEAR(r[0].hemisphericalUniformity, h.min / h.average, 1e-12);
  EXPECT_NEAR(r[0].minSemiCylindricalLux, roadStats(sc).min, 1e-12);
  EXPECT_NEAR(r[0].minVerticalLux, roadStats(ev).min, 1e-12);
  ASSERT_EQ(r[0].criteria.size(), 4u);
  const bool pass = h.average >= 2.5 && h.min / h.average >= 0.15 && roadStats(sc).min >= 2.0 && roadStats(ev).min >= 0.5;
  EXPECT_EQ(r[0].verdict, pass ? Verdict::kPass : Verdict::kFail);
}

// One luminaire ahead of the observer: Lv = 10 E/θ², E = I cos θ / d², by hand.
TEST(En13201Study, VeilingLuminanceOfOneLuminaireByHand) {
  const fs::path dir = test_support::scratchDir("en13201", "veiling");
  const double h = 10.0;
  const std::vector<Vec3> sources = {{40.0, 0.0, h}};
  const CaseFile c = writeCase(dir, road(), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadLight light(*scene, nullptr, factors);
  // Eye at the origin, 1.5 m up, looking along +x 1° down. The luminaire 40 m ahead, 8.5 m above
  // the eye: 12.02° above the horizontal, θ = 13.02° from the line of sight, below the 20° screen.
  const double elevation = std::atan(8.5 / 40.0) / kDeg;
  const double theta = elevation + 1.0;
  const double d2 = 40.0 * 40.0 + 8.5 * 8.5;
  const double e = kIntensityCd * std::cos(theta * kDeg) / d2;
  const double lv = 10.0 * e / (theta * theta);
  EXPECT_NEAR(light.veilingLuminanceCdM2(Vec3(0.0, 0.0, 1.5), Vec2(1.0, 0.0)), lv, 1e-12 * lv);
  // TI with an average luminance of 1 cd/m²: 65 Lv; of 2 cd/m²: 65 Lv / 2^0.8.
  EXPECT_NEAR(thresholdIncrementPct(lv, 1.0), 65.0 * lv, 1e-12);
  EXPECT_NEAR(thresholdIncrementPct(lv, 2.0), 65.0 * lv / std::pow(2.0, 0.8), 1e-12);
  // 20 m ahead it is 23° above the horizontal (24° above the line of sight): screened by the roof.
  EXPECT_EQ(light.veilingLuminanceCdM2(Vec3(20.0, 0.0, 1.5), Vec2(1.0, 0.0)), 0.0);
  // Behind the eye: nothing.
  EXPECT_EQ(light.veilingLuminanceCdM2(Vec3(0.0, 0.0, 1.5), Vec2(-1.0, 0.0)), 0.0);
}

// The road's M-class figures from the point law and the r-table, recomputed here from the grid's
// points: U0 = Lmin/L̄ over the field, Ul = Lmin/Lmax on the lane's centre line, the edge
// illuminance ratio from I h / d³ in the strips.
TEST(En13201Study, UniformitiesAndEdgeRatioRecomputed) {
  const fs::path dir = test_support::scratchDir("en13201", "uniformity");
  const std::vector<Vec3> sources = {{0.0, -0.5, 8.0}, {30.0, -0.5, 8.0}, {60.0, -0.5, 8.0}, {-30.0, -0.5, 8.0}};
  const CaseFile c = writeCase(dir, road("M4"), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadResult r = computeEn13201(c, *scene, factors)[0];
  const RoadGrids g = roadGrids(c.roadLighting.roads[0]);
  const RTable& r3 = *findRTable("R3");
  ASSERT_EQ(r.observers.size(), 2u);
  for (int lane = 0; lane < 2; ++lane) {
    const Vec3 eye = g.observers[static_cast<std::size_t>(lane)];
    std::vector<double> all, centre;
    for (double a : g.alongM)
      for (std::size_t j = 0; j < g.luminanceAcrossM.size(); ++j) {
        const Vec2 p = g.plan(a, g.luminanceAcrossM[j]);
        double l = 0.0;
        for (const Vec3& s : sources) {
          const Vec2 foot = Vec2(s) - p, view = p - Vec2(eye);
          const double beta = std::acos(glm::dot(foot, view) / (glm::length(foot) * glm::length(view))) / kDeg;
          l += reducedLuminanceCoefficient(r3, beta, glm::length(foot) / s.z) * kIntensityCd / (s.z * s.z);
        }
        all.push_back(l);
        if (j == static_cast<std::size_t>(3 * lane + 1)) centre.push_back(l);
      }
    const RoadStats sa = roadStats(all), sc = roadStats(centre);
    const RoadObserverResult& o = r.observers[static_cast<std::size_t>(lane)];
    EXPECT_NEAR(o.averageLuminanceCdM2, sa.average, 1e-12 * sa.average);
    EXPECT_NEAR(o.overallUniformity, sa.min / sa.average, 1e-12);
    EXPECT_NEAR(o.longitudinalUniformity, sc.min / sc.max, 1e-12);
  }
  EXPECT_DOUBLE_EQ(r.overallUniformity, std::min(r.observers[0].overallUniformity, r.observers[1].overallUniformity));
  EXPECT_DOUBLE_EQ(r.longitudinalUniformity,
                   std::min(r.observers[0].longitudinalUniformity, r.observers[1].longitudinalUniformity));
  // Edge illuminance ratio: 3.5 m strips (half the width), 3 points across each.
  auto mean = [&](const std::vector<double>& across) {
    double sum = 0.0;
    for (const Vec2& p : g.points(across)) sum += pointLaw(sources, p);
    return sum / static_cast<double>(g.alongM.size() * across.size());
  };
  const double nearSide = mean(g.nearOutsideM) / mean(g.nearInsideM), farSide = mean(g.farOutsideM) / mean(g.farInsideM);
  EXPECT_NEAR(r.edgeRatioNearSide, nearSide, 1e-12);
  EXPECT_NEAR(r.edgeRatioFarSide, farSide, 1e-12);
  EXPECT_DOUBLE_EQ(r.edgeIlluminanceRatio, std::min(nearSide, farSide));
  // Poles on the near side: the far side's outer strip is darker than the near side's.
  EXPECT_LT(farSide, nearSide);
}

// Geometry of the scene shadows the road: a wall between a luminaire and part of the field.
TEST(En13201Study, SceneGeometryShadowsTheRoad) {
  const fs::path dir = test_support::scratchDir("en13201", "shadow");
  writeFile(dir / "wall.rad",
            "void plastic grey\n0\n0\n5 0.5 0.5 0.5 0 0\n"
            "grey polygon wall\n0\n0\n12\n 20 -5 0\n 20 12 0\n 20 12 6\n 20 -5 6\n");
  const std::vector<Vec3> sources = {{10.0, 3.0, 5.0}};
  const CaseFile c = writeCase(dir, "[[scene]]\nfile = \"wall.rad\"\n" + road("P2"), sources);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadResult r = computeEn13201(c, *scene, factors)[0];
  for (std::size_t k = 0; k < r.illuminancePoints.size(); ++k) {
    const Vec2 p = r.illuminancePoints[k];
    // Beyond the wall (x > 20) and below the line from the source over its top (z = 6 > 5: none).
    const double expected = p.x > 20.0 ? 0.0 : pointLaw(sources, p);
    EXPECT_NEAR(r.illuminanceLux[k], expected, 1e-12 * std::max(expected, 1.0)) << "at x = " << p.x;
  }
}

// A real road luminaire (LM-63-1995, a point: no luminous opening) against its own intensities.
TEST(En13201Study, RealIesFileAgainstItsOwnIntensity) {
  const fs::path dir = test_support::scratchDir("en13201", "real_ies");
  const std::string name = "OutdoorRoadway IES OS 8988-2022 03 AM01 60W 4000K.ies";
  fs::copy_file(fs::path(CANDELA_REFERENCE) / "photometry" / "eulumdat-rs" / name, dir / "road.ies");
  const Vec3 pole(15.0, -0.5, 8.0);
  const CaseFile c = writeCase(dir, road("M5"), {pole}, "road.ies");
  const PhotometricWeb web = readPhotometricFile(dir / "road.ies");
  ASSERT_EQ(web.openingWidthM(), 0.0);
  std::vector<double> factors;
  const std::unique_ptr<Scene> scene = sceneOf(c, factors);
  const RoadLight light(*scene, nullptr, factors);
  const RTable& r3 = *findRTable("R3");
  const Vec3 eye(-60.0, 1.75, 1.5);
  for (double x : {1.5, 10.5, 15.0, 22.5, 28.5})
    for (double y : {0.7, 3.5, 6.3}) {
      const Vec3 toPoint = Vec3(x, y, 0.0) - pole;  // aim down, spin 0: the web's frame is the world's
      const double d = glm::length(toPoint);
      const double i = web.intensityCd(toPoint / d);
      const double e = i * pole.z / (d * d * d);
      EXPECT_NEAR(light.illuminanceLux(Vec2(x, y)), e, 1e-12 * e) << x << ", " << y;
      const Vec2 foot = Vec2(pole) - Vec2(x, y), view = Vec2(x, y) - Vec2(eye);
      const double beta = std::acos(glm::dot(foot, view) / (glm::length(foot) * glm::length(view))) / kDeg;
      const double l = reducedLuminanceCoefficient(r3, beta, glm::length(foot) / pole.z) * i / (pole.z * pole.z);
      EXPECT_NEAR(light.luminanceCdM2(Vec2(x, y), eye, r3, 0.07).maintained, l, 1e-12 * l) << x << ", " << y;
      // Hemispherical on the road: I (1 + cos ε)/4d², cos ε = h/d.
      const double hs = i * (1.0 + pole.z / d) / (4.0 * d * d);
      EXPECT_NEAR(light.hemisphericalLux(Vec2(x, y)), hs, 1e-12 * hs) << x << ", " << y;
      // 1.5 m up, facing +x: semi-cylindrical I sin ε (1 + cos α)/πd², vertical I max(0, cos)/d².
      const Vec3 up = pole - Vec3(x, y, kFacialHeightM);
      const double u = glm::length(up), horizontal = std::hypot(up.x, up.y);
      const double iu = web.intensityCd(-up / u);
      const double sc = iu * (horizontal / u) * (1.0 + up.x / horizontal) / (kPi * u * u);
      const double ev = iu * std::max(0.0, up.x / u) / (u * u);
      const std::array<RoadLight::Facing, 2> f = light.facingLux(Vec2(x, y), Vec2(1.0, 0.0));
      EXPECT_NEAR(f[0].semiCylindrical, sc, 1e-12 * sc + 1e-15) << x << ", " << y;
      EXPECT_NEAR(f[0].vertical, ev, 1e-12 * ev + 1e-15) << x << ", " << y;
    }
}

// Bad input: InputError at the offending line.
void expectError(const std::string& body, int line, const std::string& words) {
  const fs::path dir = test_support::scratchDir("en13201", "errors");
  try {
    writeCase(dir, body, {{15.0, -0.5, 8.0}});
    FAIL() << "no error for: " << body;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(En13201Case, BadInputNamesTheLine) {
  // The luminaire takes lines 1-3; the road starts on line 4: name 5, start 6, direction 7,
  // length 8, width 9, lanes 10, class 11, surface 12, then the extra keys and the compliance entry.
  const std::string compliance = "[[compliance]]\nstandard = \"en13201\"\n";
  auto bad = [](const std::string& key, const std::string& value) {
    std::string r = road();
    const std::size_t at = r.find(key + " = ");
    const std::size_t end = r.find('\n', at);
    return r.replace(at, end - at, key + " = " + value);
  };
  expectError(bad("class", "\"M7\""), 11, "unknown road lighting class 'M7'");
  expectError(bad("class", "\"ME3\""), 11, "M1..M6, C0..C5, P1..P6 or HS1..HS3");
  expectError(road("P3", "additional_classes = [\"SC10\"]\n"), 13, "unknown additional class 'SC10' (EN 13201-2: SC1..SC9 or EV1..EV6)");
  expectError(road("P3", "additional_classes = [\"SC3\", \"sc4\"]\n"), 13, "two additional classes of one kind: SC3 and SC4");
  expectError(road("P3", "additional_classes = \"SC3\"\n"), 13, "'additional_classes' must be an array");
  expectError(bad("surface", "\"W4\""), 12, "'surface' W4 is no r-table candela has (CIE 144's standard tables: R1, R2, R3, R4, C1, C2");
  expectError(bad("width", "0.0"), 9, "'width'");
  expectError(bad("length", "-30.0"), 8, "'length'");
  expectError(bad("lanes", "0"), 10, "'lanes'");
  expectError(bad("direction", "[0.0, 0.0]"), 7, "'direction'");
  expectError(road("M3", "q0 = 1.5\n"), 13, "'q0'");
  expectError(road("M3", "spacing = 3.0\n"), 13, "unknown key 'spacing'");
  expectError(road().substr(0, road().find("[[compliance]]")), 4, "en13201");
  expectError(compliance, 4, "nothing to check");
  expectError(road() + "spaces = [\"a\"]\n", 15, "'spaces' is for the daylight standards");
}

TEST(En13201Case, KeysAsRead) {
  const fs::path dir = test_support::scratchDir("en13201", "keys");
  const CaseFile c = writeCase(dir, road("p3", "q0 = 0.08\n"), {{15.0, -0.5, 8.0}});
  ASSERT_EQ(c.roadLighting.roads.size(), 1u);
  const RoadSpec& r = c.roadLighting.roads[0];
  EXPECT_EQ(r.name, "main");
  EXPECT_EQ(r.roadClass.name(), "P3");
  EXPECT_EQ(r.lanes, 2);
  EXPECT_DOUBLE_EQ(r.q0, 0.08);
  EXPECT_EQ(r.surface, "R3");
  ASSERT_NE(en13201Entry(c), nullptr);
}

// The example case, run in-process: every contract key of summary.json and the report section.
TEST(En13201Study, RoadExample) {
  RunRequest request;
  request.outDir = test_support::scratchDir("en13201", "road_example") / "out";
  const fs::path casePath = fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "road" / "case.toml";
  runCase(casePath, request);
  const nlohmann::json j = nlohmann::json::parse(test_support::slurp(request.outDir / "summary.json"));
  const nlohmann::json& e = j["compliance"]["en13201"];
  EXPECT_EQ(e["standard"], "en13201");
  ASSERT_EQ(e["roads"].size(), 2u);
  const nlohmann::json& r = e["roads"][0];
  for (const char* key : {"name", "class", "points", "average_illuminance_lux", "minimum_illuminance_lux",
                          "average_luminance_cd_m2", "overall_uniformity", "longitudinal_uniformity",
                          "threshold_increment_percent", "edge_illuminance_ratio", "verdict"})
    EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(r["points"], 10 * 5);
  // The issue's `roads[i]` at summary.json's top level too: the same objects.
  ASSERT_TRUE(j.contains("roads"));
  EXPECT_EQ(j["roads"], e["roads"]);
  EXPECT_GT(r["average_luminance_cd_m2"].get<double>(), 0.0);
  // The footway: P1 + SC9, 10 × 3 points 2 m wide, its least semi-cylindrical illuminance judged.
  const nlohmann::json& f = e["roads"][1];
  EXPECT_EQ(f["class"], "P1");
  EXPECT_EQ(f["additional_classes"], nlohmann::json::array({"SC9"}));
  EXPECT_EQ(f["points"], 10 * 3);
  EXPECT_TRUE(f.contains("minimum_semi_cylindrical_illuminance_lux"));
  EXPECT_EQ(f["criteria"].back()["name"], "minimum_semi_cylindrical_illuminance_lux");
  EXPECT_EQ(f["criteria"].back()["required"], 0.5);
  const std::string html = test_support::slurp(request.outDir / "report.html");
  EXPECT_NE(html.find("footway: class P1 + SC9"), std::string::npos);
  EXPECT_NE(html.find("EN 13201 road lighting"), std::string::npos);
  EXPECT_NE(html.find("class=\"en13201-plan\""), std::string::npos);
}

}  // namespace
}  // namespace candela
