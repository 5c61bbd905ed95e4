// [[grid]] quantity, facing and modelling run whole (study/grid_study.cpp): a point luminaire
// alone gives each quantity's closed form at every point, the modelling ratio of their averages
// and its verdict in the report data and summary.json, the quantity's CSV column and the
// modelling_height warning; a vertical grid in a room is planar illuminance on its facing,
// number for number; a modelling grid in a room gives the same files on 1 and 2 threads.
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/grids/prepared_grid.h"
#include "study/run_case.h"
#include "study/trace_options.h"
#include "engine/irradiance_estimator.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(CANDELA_TEST_DATA) / "study";

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The closed forms of docs/quantities.md for a point source of intensity I (cd) at `source`:
// d the distance, ε the angle at the point from the vertical, α in plan from `facing` to the
// source.
double closedForm(GridQuantity q, const Vec3& p, const Vec3& source, double intensity, const Vec2& facing) {
  const Vec3 e = source - p;
  const double d2 = glm::dot(e, e), d = std::sqrt(d2);
  const double cosEps = e.z / d, sinEps = std::sqrt(e.x * e.x + e.y * e.y) / d;
  const Vec2 plan = glm::normalize(Vec2(e.x, e.y)), f = glm::normalize(facing);
  const double cosAlpha = glm::dot(plan, f);
  switch (q) {
    case GridQuantity::kHorizontal: return intensity * cosEps / d2;
    case GridQuantity::kVertical: return intensity * sinEps * std::max(0.0, cosAlpha) / d2;
    case GridQuantity::kCylindrical: return intensity * sinEps / (kPi * d2);
    case GridQuantity::kSemiCylindrical: return intensity * sinEps * (1.0 + cosAlpha) / (kPi * d2);
    case GridQuantity::kHemispherical: return intensity * (1.0 + cosEps) / (4.0 * d2);
  }
  return 0.0;
}

TEST(QuantitiesStudy, PointLuminaireGridsReadTheirClosedForms) {
  const fs::path casePath = kData / "quantities.toml";
  const CaseFile c = readCaseFile(casePath);
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  ASSERT_EQ(scene->luminaires.size(), 1u);
  const LuminaireSource& lum = scene->luminaires[0];
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  RunRequest request;
  request.outDir = freshDir("study_quantities");
  const RunResult r = runCase(casePath, request);
  ASSERT_EQ(r.data.grids.size(), grids.size());
  auto intensityAt = [&](const Vec3& p) {
    const Vec3 e = p - lum.position;
    return lum.intensityCd(e / glm::length(e));
  };
  // Each grid's values against the closed form of its quantity (the desk grid: horizontal, the
  // default of an upward plane grid). Nothing is random: one shadow ray per point, no surface.
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const GridSpec& spec = *grids[gi].spec;
    const GridQuantity q = spec.quantity.value_or(GridQuantity::kHorizontal);
    const GridReport& g = r.data.grids[gi];
    ASSERT_EQ(g.values.size(), grids[gi].grid.size()) << spec.name;
    for (std::size_t k = 0; k < g.values.size(); ++k) {
      const Vec3 p = grids[gi].grid.points[k].position;
      const double want = closedForm(q, p, lum.position, intensityAt(p), spec.facing);
      EXPECT_NEAR(g.values[k], want, 1e-9 * want + 1e-9) << spec.name << " point " << k;  // 1e-9 lx: a 0 facing away
    }
    EXPECT_EQ(g.quantity, spec.quantity ? gridQuantityName(*spec.quantity) : "Illuminance") << spec.name;
    // Modelling: the ratio of the closed forms' averages.
    EXPECT_EQ(g.modelling.has_value(), spec.modelling) << spec.name;
    if (!g.modelling) continue;
    double sz = 0.0, sh = 0.0;
    for (const SensorPoint& s : grids[gi].grid.points) {
      sz += closedForm(GridQuantity::kCylindrical, s.position, lum.position, intensityAt(s.position), spec.facing);
      sh += closedForm(GridQuantity::kHorizontal, s.position, lum.position, intensityAt(s.position), spec.facing);
    }
    const double n = static_cast<double>(grids[gi].grid.size());
    EXPECT_NEAR(g.modelling->cylindricalAverageLux, sz / n, 1e-9 * sz / n) << spec.name;
    EXPECT_NEAR(g.modelling->horizontalAverageLux, sh / n, 1e-9 * sh / n) << spec.name;
    EXPECT_NEAR(g.modelling->ratio, sz / sh, 1e-9 * sz / sh) << spec.name;
    const bool within = sz / sh >= 0.30 && sz / sh <= 0.60;
    EXPECT_EQ(g.modelling->verdict, within ? Verdict::kPass : Verdict::kFail) << spec.name;
  }

  // summary.json names the quantity and carries the modelling figures.
  const nlohmann::json j = nlohmann::json::parse(readText(r.outDir / "summary.json"));
  EXPECT_EQ(j["grids"][0]["quantity"], "Cylindrical illuminance Ē_z");
  EXPECT_EQ(j["grids"][0]["quantity_key"], "cylindrical");
  EXPECT_FALSE(j["grids"][4].contains("quantity_key"));
  const nlohmann::json& m = j["grids"][0]["modelling"];
  EXPECT_DOUBLE_EQ(m["ratio"].get<double>(), r.data.grids[0].modelling->ratio);
  EXPECT_DOUBLE_EQ(m["cylindrical_average_lux"].get<double>(), r.data.grids[0].modelling->cylindricalAverageLux);
  EXPECT_DOUBLE_EQ(m["horizontal_average_lux"].get<double>(), r.data.grids[0].modelling->horizontalAverageLux);
  EXPECT_EQ(m["verdict"], verdictName(r.data.grids[0].modelling->verdict));
  EXPECT_FALSE(j["grids"][1].contains("modelling"));

  // The CSVs: the quantity's column, a semi-cylinder's facing as its direction, a modelling
  // grid's extra columns.
  const std::string cyl = readText(r.outDir / "cylindrical.csv");
  EXPECT_EQ(cyl.substr(0, cyl.find('\n')),
            "x,y,z,dx,dy,dz,cylindrical_illuminance_lux,error_lux,horizontal_illuminance_lux,horizontal_error_lux,"
            "modelling_ratio");
  const std::string semi = readText(r.outDir / "semi.csv");
  EXPECT_EQ(semi.substr(0, semi.find('\n')), "x,y,z,dx,dy,dz,semi_cylindrical_illuminance_lux,error_lux");
  EXPECT_NE(semi.find(",0,-1,0,"), std::string::npos) << semi;
  const std::string desk = readText(r.outDir / "desk.csv");
  EXPECT_EQ(desk.substr(0, desk.find('\n')),
            "x,y,z,dx,dy,dz,illuminance_lux,error_lux,cylindrical_illuminance_lux,cylindrical_error_lux,"
            "horizontal_illuminance_lux,horizontal_error_lux,modelling_ratio");
  EXPECT_NE(readText(r.outDir / "report.html").find("Modelling ratio"), std::string::npos);

  // The desk grid at 0.8 m: modelling there is warned of, at its `modelling` line; 1.2 and 1.6 m
  // are not.
  int warned = 0;
  for (const Warning& w : r.data.warnings)
    if (w.code == "modelling_height") {
      ++warned;
      EXPECT_EQ(w.loc.line, grids[4].spec->modellingLoc.line);
      EXPECT_NE(w.message.find("grid 'desk'"), std::string::npos) << w.message;
    }
  EXPECT_EQ(warned, 1);
}

TEST(QuantitiesStudy, VerticalGridIsPlanarIlluminanceOnItsFacing) {
  // The study's numbers against the engine's planar estimate on the normal (1, 0, 0) at the
  // same points and random streams, with the settings the run resolves: the same to the bit.
  const fs::path casePath = kData / "vertical_room.toml";
  const CaseFile c = readCaseFile(casePath);
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  const std::vector<PreparedGrid> grids = prepareGrids(c, gridBounds(*scene));
  ASSERT_EQ(grids.size(), 1u);
  std::vector<SensorPoint> planar;
  for (const SensorPoint& s : grids[0].grid.points) planar.push_back({s.position, Vec3(1.0, 0.0, 0.0)});
  const Tracer tracer(*scene);
  const ResolvedTrace trace = resolveTrace(&c.settings, {}, Method::kCache);
  const std::vector<IrradianceEstimate> want = computeIrradiance(tracer, planar, trace.settings, 2);
  RunRequest request;
  request.outDir = freshDir("study_vertical_room");
  const RunResult r = runCase(casePath, request);
  ASSERT_EQ(r.data.grids[0].values.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    EXPECT_EQ(r.data.grids[0].values[k], want[k].illuminanceLux()) << "point " << k;
    EXPECT_GT(want[k].illuminanceLux(), 0.0);
  }
  EXPECT_EQ(r.data.grids[0].quantity, "Vertical illuminance Ē_v");
}

TEST(QuantitiesStudy, ModellingGridGivesTheSameFilesOnOneAndTwoThreads) {
  const fs::path casePath = kData / "modelling_room.toml";
  RunRequest one, two;
  one.outDir = freshDir("study_modelling_t1");
  one.trace.threads = 1;
  two.outDir = freshDir("study_modelling_t2");
  two.trace.threads = 2;
  const RunResult a = runCase(casePath, one), b = runCase(casePath, two);
  EXPECT_EQ(readText(a.outDir / "seated.csv"), readText(b.outDir / "seated.csv"));
  ASSERT_TRUE(a.data.grids[0].modelling && b.data.grids[0].modelling);
  const ModellingResult& ma = *a.data.grids[0].modelling;
  EXPECT_EQ(ma.ratio, b.data.grids[0].modelling->ratio);
  EXPECT_EQ(ma.cylindricalAverageLux, b.data.grids[0].modelling->cylindricalAverageLux);
  // The horizontal values are the grid's own (an upward plane grid): its average is Ē_h.
  EXPECT_DOUBLE_EQ(ma.horizontalAverageLux, a.data.grids[0].stats.averageLux);
  EXPECT_GT(ma.cylindricalAverageLux, 0.0);
  EXPECT_NEAR(ma.ratio, ma.cylindricalAverageLux / ma.horizontalAverageLux, 1e-15);
}

}  // namespace
}  // namespace candela
