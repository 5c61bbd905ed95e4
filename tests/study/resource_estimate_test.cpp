// The resource estimate (study/resource_estimate.h): closed counts of bytes, scaling, and the
// refusal at the largest item's line.
#include "study/resource_estimate.h"

#include "engine/render.h"
#include "engine/scene.h"
#include "engine/radiance/reader.h"
#include "engine/sampling.h"
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "study/case/case_file.h"
#include "tests/engine/bsdf_test_xml.h"
#include "tests/support/material_harness.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

TEST(ResourceEstimate, AnnualBlockBytesAreTheBlocksFloatArrays) {
  // A block of 100 sensors, 8760 hours, 146 patches, 4000 sun hours, 300 suns. Blinds open only:
  // the coefficients beside the year's total and direct sun. With the closed state: its pass
  // holds the closed year and the open year and direct sun read back, when that is larger.
  const uint64_t s = 100, h = 8760, p = 146, sun = 4000, j = 300;
  const uint64_t open = s * (p + sun + j) * 4 + s * h * 2 * 4;
  EXPECT_EQ(annualBlockBytes(s, h, p, sun, j, 1), open);
  EXPECT_EQ(annualBlockBytes(s, h, p, sun, j, 2), std::max(open, s * h * 3 * 4));
  EXPECT_EQ(annualBlockBytes(s, h, p, sun, j, 2), s * h * 3 * 4);  // 8760 > 146 + 4000 + 300
  // Many patches (Reinhart MF:6, 5185): the coefficients' pass is the larger.
  EXPECT_EQ(annualBlockBytes(s, h, 5185, sun, j, 2), s * (5185 + sun + j) * 4 + s * h * 2 * 4);
}

TEST(ResourceEstimate, AnnualGridBytesGrowWithSensorsNotWithTheirHours) {
  // What a grid keeps beyond the block: per sensor a fixed size, per hour 13 bytes (count, flag,
  // the temporal map's double); no sensors × hours term.
  const uint64_t perSensor = annualGridBytes(2, 8760) - annualGridBytes(1, 8760);
  EXPECT_LT(perSensor, 1024u);
  EXPECT_EQ(annualGridBytes(100000, 8760), 100000 * perSensor + 8760 * 13);
  EXPECT_EQ(annualGridBytes(100000, 8761) - annualGridBytes(100000, 8760), 13u);
}

TEST(ResourceEstimate, AnnualStudyIsBoundedByTheBlock) {
  // Issue 17's contract: 100 000 sensors × 8760 hours within 2 GB a rank. The hours stream to disk,
  // so the estimate is the scene, the sky vectors, one block and the grid's per-sensor records.
  CaseFile c;
  c.annual.present = true;
  c.annual.loc = FileLoc{"case.toml", 9, 1};
  c.grids.resize(1);
  c.grids[0].name = "floor";
  c.grids[0].loc = FileLoc{"case.toml", 20, 1};
  const Scene scene;
  const uint64_t hours = 8760, sun = 4437, patches = 146, suns = 189;
  auto estimate = [&](uint64_t sensors, uint64_t block) {
    AnnualCounts a;
    a.gridSensors = {sensors};
    a.hours = hours;
    a.sunHours = sun;
    return estimateAnnualStudy(c, scene, a, TraceSettings{}, 2, block);
  };
  const ResourceEstimate big = estimate(100000, 1024);
  ASSERT_EQ(big.memory.size(), 2u);
  EXPECT_EQ(big.memory[1].bytes, annualBlockBytes(1024, hours, patches, sun, suns, 2));
  EXPECT_EQ(big.memory[1].loc.line, 9);
  EXPECT_EQ(big.memory[0].bytes, annualGridBytes(100000, hours));
  EXPECT_LT(big.bytes(), 2000000000u);
  // Ten times the sensors: only the per-sensor records grow; a study smaller than a block holds
  // its own sensors only.
  EXPECT_EQ(estimate(1000000, 1024).bytes() - big.bytes(), annualGridBytes(1000000, hours) - annualGridBytes(100000, hours));
  EXPECT_EQ(estimate(100, 1024).memory[1].bytes, annualBlockBytes(100, hours, patches, sun, suns, 2));
}

// LEED option 2's clear-sky traces are a step of the annual study's estimate: its spaces' sensors
// (here grid "b" only) at every time (two dates × three hours), one batch each whatever the
// settings' target error, with the sky and its sun as two sampled sources, and each time's
// irradiance cache (its records, for the scene's bounding box of 4 × 6 × 3 m: 108 m²).
TEST(ResourceEstimate, AnnualStudyCountsLeedOption2) {
  CaseFile c;
  c.grids.resize(2);
  c.grids[0].name = "a";
  c.grids[1].name = "b";
  ComplianceSpec leed;
  leed.standard = ComplianceStandard::kLeedV41Option2;
  leed.name = "leed2";
  leed.spaces = {"b"};
  leed.leedHours = {9.0, 12.0, 15.0};
  c.compliance = {leed};
  Scene scene;
  SceneReader(scene).readText("void plastic g 0 0 5 .2 .2 .2 0 0\n"
                              "g polygon floor 0 0 12 0 0 0 0 6 0 4 6 0 4 0 0\n"
                              "g polygon ceiling 0 0 12 0 0 3 4 0 3 4 6 3 0 6 3\n",
                              "room.rad", ".");
  AnnualCounts a;
  a.gridSensors = {100, 40};
  a.hours = 8760;
  TraceSettings point;
  point.method = Method::kCache;
  point.maxBounces = 2;
  point.targetRelativeError = 0.0025;
  const ResourceEstimate without = estimateAnnualStudy(c, scene, a, TraceSettings{}, 2, 1024);
  const ResourceEstimate with = estimateAnnualStudy(c, scene, a, TraceSettings{}, 2, 1024, &point);
  ASSERT_EQ(with.work.size(), without.work.size() + 1);
  EXPECT_EQ(with.work.back().label, "compliance leed2");
  point.targetRelativeError = 0.0;
  // Its clear sky adds a shadow ray at every path vertex (no glazing here: no portal sample).
  const double records = cacheRecordRays(point, 40.0, 108.0, 1.0, 1.0);
  EXPECT_GT(records, 0.0);
  EXPECT_DOUBLE_EQ(with.work.back().rays, 6.0 * (40.0 * raysPerSensor(point, 2, 0, 1.0, 1.0) + records));
  EXPECT_GT(with.seconds("compliance leed2"), 0.0);
}

// Window states replace the blinds' passes: one more pass (sky, sun and direct sun) per state
// beyond each group's first, and the direct-sun rule's direct sun of a middle state; the blinds'
// closed passes are gone.
TEST(ResourceEstimate, AnnualStudyCountsWindowStates) {
  CaseFile c;
  c.grids.resize(1);
  c.grids[0].name = "room";
  c.windowGroups.resize(2);
  c.windowGroups[0].states.resize(3);
  c.windowGroups[1].states.resize(2);
  const Scene scene;
  AnnualCounts a;
  a.gridSensors = {50};
  a.hours = 8760;
  a.sunHours = 4000;
  const ResourceEstimate e = estimateAnnualStudy(c, scene, a, TraceSettings{}, 2, 1024);
  double first = 0.0, states = 0.0, sunRule = 0.0;
  for (const auto& w : e.work) {
    EXPECT_EQ(w.label.rfind("blinds closed", 0), std::string::npos) << w.label;
    if (w.label == "coefficients") first = w.rays;
    if (w.label == "window states: coefficients") states = w.rays;
    if (w.label == "window states: direct sun") sunRule = w.rays;
  }
  EXPECT_GT(first, 0.0);
  EXPECT_DOUBLE_EQ(states, 3.0 * first);  // (3 − 1) + (2 − 1) passes, each the first's work
  // The direct-sun rule's pass for the three-state group's middle state: its direct sun only.
  EXPECT_DOUBLE_EQ(sunRule, 50.0 * 4000.0 * std::max(1, c.annual.sunSamples));
}

TEST(ResourceEstimate, PixelBytesFromTheImage) {
  // Kept per pixel: Image's radiance, luminance and standard error (float32), inside, traced and
  // interpolation level (a byte each), as the type holds them.
  const Image img;
  const uint64_t kept = sizeof(img.radiance[0]) + sizeof(img.luminance[0]) + sizeof(img.standardError[0]) +
                        sizeof(img.inside[0]) + sizeof(img.traced[0]) + sizeof(img.interpolationLevel[0]);
  EXPECT_EQ(kept, 23u);
  EXPECT_GT(bytesPerPixel(), kept);
  ViewSpec v;
  v.name = "x";
  v.loc = FileLoc{"case.toml", 12, 1};
  v.resolution = glm::ivec2(16384, 16384);
  const MemoryItem m = viewMemory(v, false);
  EXPECT_GT(m.bytes, 16384ull * 16384ull * bytesPerPixel());
  EXPECT_EQ(m.detail, "16384 x 16384 pixels x " + std::to_string(bytesPerPixel()) + " B");
  // The report keeps a copy of at most 2048 × 2048 pixels of each picture.
  EXPECT_EQ(viewMemory(v, true).bytes - m.bytes, viewReportBytes(v));
  v.resolution = glm::ivec2(8192, 8192);
  EXPECT_EQ(viewReportBytes(v), 2048ull * 2048ull * 6);
  // The bound: an 8k × 8k view within 2 GB.
  EXPECT_LT(viewMemory(v, true).bytes, 2000000000ull);
}

TEST(ResourceEstimate, RefusedAtTheLargestItem) {
  ResourceEstimate e;
  e.baseBytes = 40ull << 20;
  ViewSpec small, big;
  small.name = "small";
  small.loc = FileLoc{"case.toml", 5, 1};
  small.resolution = glm::ivec2(64, 48);
  big.name = "x";
  big.loc = FileLoc{"case.toml", 12, 1};
  big.resolution = glm::ivec2(16384, 16384);
  e.memory = {viewMemory(small, false), viewMemory(big, false)};
  EXPECT_NO_THROW(checkResources(e, ResourceLimits{}, FileLoc{"case.toml", 0, 0}));  // no limit
  EXPECT_NO_THROW(checkResources(e, ResourceLimits{e.bytes()}, FileLoc{"case.toml", 0, 0}));
  try {
    checkResources(e, ResourceLimits{1ull << 30}, FileLoc{"case.toml", 0, 0});
    FAIL() << "not refused";
  } catch (const InputError& err) {
    const std::string msg = err.what();
    EXPECT_EQ(msg.rfind("case.toml:12: view 'x' needs about ", 0), 0u) << msg;
    EXPECT_NE(msg.find(" GiB of memory (16384 x 16384 pixels x "), std::string::npos) << msg;
    EXPECT_NE(msg.find("(--max-memory 1.0 GiB)"), std::string::npos) << msg;
  }
}

TEST(ResourceEstimate, RaysPerSensor) {
  TraceSettings s;
  s.hemisphereSamples = 1000;
  s.lightSamples = 10;
  s.firstBounceSplit = 16;
  s.maxBounces = 0;  // direct light only: the hemisphere rays, the light samples, no selection
  EXPECT_DOUBLE_EQ(raysPerSensor(s, 2, 5), 1000.0 + 10.0 * (2 + 5));  // openings sampled as areas
  s.maxBounces = 100;
  s.method = Method::kPath;  // 1 + 16 × 1 vertices a ray, a ray and a shadow ray each; selection over 7
  EXPECT_DOUBLE_EQ(raysPerSensor(s, 2, 5), 1000.0 * 2 * 17 + 70.0 + 1000.0 * 17 * 0.09 * 7);
  s.method = Method::kCache;  // the hit, its shadow ray and 8 for the lookup; 1 + 4 vertices
  EXPECT_DOUBLE_EQ(raysPerSensor(s, 2, 5), 1000.0 * 10 + 70.0 + 1000.0 * 5 * 0.09 * 7);
  // A million luminaires dominate: each path vertex weighs them all (1000 × 5 × 0.09 × 10⁶).
  EXPECT_GT(raysPerSensor(s, 0, 1000000), 4.5e8);
  // Where a quarter of the hemisphere rays meet a surface, the rest cost themselves only.
  EXPECT_DOUBLE_EQ(raysPerSensor(s, 2, 5, 0.25), 1000.0 * (1.0 + 0.25 * 9.0) + 70.0 + 0.25 * 1000.0 * 5 * 0.09 * 7);
}

// EN 12464-2's observers and EN 13201's roads: sight lines to each luminaire, counted as rays.
// An observer looking all round at 45° steps (8 views), one looking one way, and a road of 60 m ×
// 7 m in 2 lanes (20 rows along; 3 × 2 luminance and ⌈7/1.5⌉ = 5 illuminance points across, 2
// edge points and 2 observers a row): (8 + 1 + 20 × 15) × 3 luminaires.
TEST(ResourceEstimate, GlareRatingsAndRoadsAreSightLines) {
  CaseFile c;
  GrObserverSpec all, one;
  one.direction = Vec2(1.0, 0.0);
  c.outdoor.observers = {all, one};
  RoadSpec road;
  road.lengthM = 60.0;
  road.widthM = 7.0;
  road.lanes = 2;
  c.roadLighting.roads.push_back(road);
  Scene scene;
  scene.luminaires.resize(3);
  const ResourceEstimate e = estimateGridStudy(c, {}, scene, TraceSettings{}, 1);
  const auto step = std::find_if(e.work.begin(), e.work.end(), [](const WorkStep& w) { return w.label == "glare ratings and roads"; });
  ASSERT_NE(step, e.work.end());
  EXPECT_DOUBLE_EQ(step->rays, (8.0 + 1.0 + 20.0 * 15.0) * 3.0);
}

// The pilot's share of hemisphere rays meeting the scene, over one large floor: none from points
// above it facing up, all from points facing down; from a point facing sideways, the directions
// of the fixed pattern that point below the horizon, counted here from the same pattern (the
// Fibonacci spiral of 32 cosine-distributed directions about the normal).
TEST(ResourceEstimate, HemisphereHitFractionOfAnOpenSite) {
  Scene sc;
  SceneReader(sc).readText("void plastic g 0 0 5 .2 .2 .2 0 0\n"
                           "g polygon floor 0 0 12 -1e3 -1e3 0 1e3 -1e3 0 1e3 1e3 0 -1e3 1e3 0\n",
                           "site.rad", ".");
  const Tracer tracer(sc);
  auto points = [](const Vec3& n) {
    std::vector<SensorPoint> ps;
    for (int i = 0; i < 100; ++i) ps.push_back(SensorPoint{Vec3(0.37 * i, 0.21 * i, 1.0), n});
    return ps;
  };
  EXPECT_EQ(hemispherePilot(tracer, points(Vec3(0, 0, 1))).hitFraction, 0.0);
  EXPECT_EQ(hemispherePilot(tracer, points(Vec3(0, 0, -1))).hitFraction, 1.0);
  const Frame f = Frame::fromNormal(Vec3(1, 0, 0));
  int below = 0;
  for (int k = 0; k < 32; ++k) {
    const double u2 = k * 0.38196601125010515 - std::floor(k * 0.38196601125010515);
    below += f.toWorld(sampleCosineHemisphere((k + 0.5) / 32.0, u2)).z < 0.0;
  }
  EXPECT_GT(below, 8);  // the pattern covers both halves
  EXPECT_LT(below, 24);
  EXPECT_DOUBLE_EQ(hemispherePilot(tracer, points(Vec3(1, 0, 0))).hitFraction, below / 32.0);
  EXPECT_EQ(hemispherePilot(tracer, {}).hitFraction, 1.0);
}

// A sky adds its shadow rays at every path vertex: one sample by luminance, and a portal sample
// where glazing is found (engine/integrator_direct.cpp, skyIrradiance).
TEST(ResourceEstimate, ASkyAddsItsShadowRaysAtEveryVertex) {
  Scene dark;
  SceneReader(dark).readText("void plastic g 0 0 5 .2 .2 .2 0 0\n"
                             "g polygon floor 0 0 12 0 0 0 0 6 0 4 6 0 4 0 0\n",
                             "room.rad", ".");
  EXPECT_EQ(skyRaysPerVertex(dark), 0.0);
  Scene open = dark;
  test_support::addUniformSky(open);
  EXPECT_EQ(skyRaysPerVertex(open), 1.0);
  Scene glazed;
  SceneReader(glazed).readText("void glass clear 0 0 3 .9 .9 .9\n"
                               "clear polygon pane 0 0 12 0 0 1 0 1 1 1 1 1 1 0 1\n",
                               "window.rad", ".");
  test_support::addUniformSky(glazed);
  EXPECT_EQ(skyRaysPerVertex(glazed), 2.0);
  // Path method: every vertex (1 + split × 1 further) of every hemisphere ray pays them.
  TraceSettings path;
  path.method = Method::kPath;
  path.maxBounces = 5;
  path.hemisphereSamples = 100;
  path.firstBounceSplit = 4;
  EXPECT_DOUBLE_EQ(raysPerSensor(path, 1, 0, 1.0, 2.0) - raysPerSensor(path, 1, 0, 1.0, 0.0), 100.0 * 2.0 * (1 + 4));
}

// Points that see a BSDF window (a scattering surface) are counted past the cache; without the
// pilot's measurement (below) the rays of each are the path method's for half the settings'
// batches, none without the cache or a target.
TEST(ResourceEstimate, PointsThatSeeABsdfWindowAreCountedPastTheCache) {
  const fs::path dir = test_support::scratchDir("resource_estimate", "bsdf_pilot");
  std::ofstream(dir / "w.xml") << test_support::bsdfXml(
      {{"Transmission Front", std::vector<double>(145 * 145, 0.5 / kPi)}});
  // A BSDF pane over x < 0, plastic over x > 0, both 1 m above points that face up.
  const Scene sc = test_support::readSceneText(dir,
                                               "void BSDF win 6 0 w.xml 0 1 0 . 0 0\n"
                                               "void plastic white 0 0 5 .5 .5 .5 0 0\n"
                                               "win polygon pane 0 0 12 -1e3 -1e3 1 -1e3 1e3 1 -1e-3 1e3 1 -1e-3 -1e3 1\n"
                                               "white polygon roof 0 0 12 0 -1e3 1 0 1e3 1 1e3 1e3 1 1e3 -1e3 1\n",
                                               false);
  const Tracer tracer(sc);
  // 40 points under the pane (x = -50), 60 under the roof (x = 50): each sees only its own.
  std::vector<SensorPoint> ps;
  for (int i = 0; i < 100; ++i) ps.push_back(SensorPoint{Vec3(i < 40 ? -50.0 : 50.0, 0.1 * i, 0.0), Vec3(0, 0, 1)});
  const HemispherePilot pilot = hemispherePilot(tracer, ps);
  EXPECT_DOUBLE_EQ(pilot.hitFraction, 1.0);
  EXPECT_DOUBLE_EQ(pilot.scatteringPoints, 0.4);
  TraceSettings s;
  s.method = Method::kCache;
  s.maxBounces = 2;
  s.targetRelativeError = 0.0025;
  s.maxBatches = 16;
  TraceSettings path = s;
  path.method = Method::kPath;
  EXPECT_DOUBLE_EQ(pastCacheRays(s, 40.0, 2, 3, pilot), 40.0 * 8 * raysPerSensor(path, 2, 3, 1.0));
  EXPECT_EQ(pastCacheRays(path, 40.0, 2, 3, pilot), 0.0);
  TraceSettings oneBatch = s;
  oneBatch.targetRelativeError = 0.0;
  EXPECT_EQ(pastCacheRays(oneBatch, 40.0, 2, 3, pilot), 0.0);
}

// With the run's settings the pilot also measures the batches of the points that see the window:
// one path-method batch at up to 8 of them (their own streams). The same for any thread count;
// inversely proportional to the target's square while every point needs more than 2.5 batches
// and fewer than the cap (the same estimates, the goal halved: exactly 4 times the batches); 0
// when every point's one batch meets 1/2.5 of the goal's variance (they stay on the cache); and
// the rays past the cache follow it.
TEST(ResourceEstimate, PilotMeasuresTheBatchesOfPointsThatSeeTheWindow) {
  const fs::path dir = test_support::scratchDir("resource_estimate", "bsdf_pilot_batches");
  std::ofstream(dir / "w.xml") << test_support::bsdfXml(
      {{"Transmission Front", std::vector<double>(145 * 145, 0.5 / kPi)}});
  Scene sc = test_support::readSceneText(dir,
                                         "void BSDF win 6 0 w.xml 0 1 0 . 0 0\n"
                                         "void plastic white 0 0 5 .5 .5 .5 0 0\n"
                                         "win polygon pane 0 0 12 -1e3 -1e3 1 -1e3 1e3 1 -1e-3 1e3 1 -1e-3 -1e3 1\n"
                                         "white polygon roof 0 0 12 0 -1e3 1 0 1e3 1 1e3 1e3 1 1e3 -1e3 1\n"
                                         "void plastic black 0 0 5 0 0 0 0 0\n"
                                         "black polygon shade 0 0 12 -51 -1e3 2 -51 1e3 2 -49 1e3 2 -49 -1e3 2\n",
                                         false);
  // The sky seen through the pane, partly hidden by a black strip above it: the window's
  // continuations differ, so one batch has a variance.
  test_support::addUniformSky(sc);
  const Tracer tracer(sc);
  std::vector<SensorPoint> ps;
  for (int i = 0; i < 100; ++i) ps.push_back(SensorPoint{Vec3(i < 40 ? -50.0 : 50.0, 0.1 * i, 0.0), Vec3(0, 0, 1)});
  TraceSettings s;
  s.method = Method::kCache;
  s.maxBounces = 2;
  s.hemisphereSamples = 64;
  s.maxBatches = 1 << 30;
  s.targetRelativeError = 1e-4;
  const HemispherePilot one = hemispherePilot(tracer, ps, &s, 1), two = hemispherePilot(tracer, ps, &s, 2);
  ASSERT_GT(one.scatteringBatches, 2.5);
  EXPECT_EQ(one.scatteringBatches, two.scatteringBatches);
  TraceSettings half = s;
  half.targetRelativeError = 0.5e-4;
  EXPECT_NEAR(hemispherePilot(tracer, ps, &half, 2).scatteringBatches, 4.0 * one.scatteringBatches,
              1e-9 * one.scatteringBatches);
  TraceSettings loose = s;
  loose.targetRelativeError = 10.0;  // a 1000 % goal: every point's one batch meets it
  EXPECT_EQ(hemispherePilot(tracer, ps, &loose, 2).scatteringBatches, 0.0);
  TraceSettings path = s;
  path.method = Method::kPath;
  const double rays = raysPerSensor(path, 2, 3, one.hitFraction, one.skyRaysPerVertex);
  EXPECT_NEAR(pastCacheRays(s, 40.0, 2, 3, one), 40.0 * one.scatteringBatches * rays, 1e-9 * 40.0 * one.scatteringBatches * rays);
  // Without the settings nothing is measured: half the cap.
  EXPECT_LT(hemispherePilot(tracer, ps).scatteringBatches, 0.0);
}

// The cache's records beyond the lookups' share: a room's worth (60 per m² of the box at
// a = 0.2), at most 0.08 of the hemisphere rays, each 256 paths of 2 × 2 rays and 128 radius rays,
// less 6 rays a lookup already counted.
TEST(ResourceEstimate, CacheRecordRays) {
  TraceSettings s;
  s.hemisphereSamples = 2048;
  s.maxBounces = 1000;
  s.method = Method::kCache;
  s.cache.accuracy = 0.2;
  s.cache.recordSamples = 256;
  s.cache.radiusSamples = 128;
  const double perRecord = 256.0 * 4.0 + 128.0;
  // A sparse grid in a 312 m² box: the room's 18 720 records.
  EXPECT_NEAR(cacheRecordRays(s, 242, 312.0), 18720.0 * perRecord - 242.0 * 2048.0 * 6.0, 1e-3);
  // Few points: the hemisphere rays bound the records.
  EXPECT_NEAR(cacheRecordRays(s, 5, 312.0), 0.08 * 5 * 2048 * perRecord - 5.0 * 2048.0 * 6.0, 1e-3);
  // A dense grid: the lookups' share already counts more than the room's records.
  EXPECT_EQ(cacheRecordRays(s, 20000, 312.0), 0.0);
  // Half of a: four times the records (a 100 m² box: 4 × 6 000, below the hemisphere bound
  // 0.08 × 242 × 2048 = 39 649).
  s.cache.accuracy = 0.1;
  EXPECT_NEAR(cacheRecordRays(s, 242, 100.0), 4.0 * 6000.0 * perRecord - 242.0 * 2048.0 * 6.0, 1e-3);
  // The path method has no records.
  s.method = Method::kPath;
  EXPECT_EQ(cacheRecordRays(s, 242, 312.0), 0.0);
}

TEST(ResourceEstimate, Seconds) {
  ResourceEstimate e;
  e.threads = 2;
  e.raysPerSecondPerThread = 1e6;
  e.work = {{"tracing", 4e6}, {"rendering a", 2e6}, {"rendering b", 2e6}};
  EXPECT_DOUBLE_EQ(e.seconds(), 4.0);
  EXPECT_DOUBLE_EQ(e.seconds("tracing"), 2.0);
  EXPECT_DOUBLE_EQ(e.seconds("rendering a"), 1.0);
  EXPECT_LT(e.seconds("sky coefficients"), 0.0);
}

TEST(ResourceEstimate, FormatBytes) {
  EXPECT_EQ(formatBytes(900), "900 B");
  EXPECT_EQ(formatBytes(12 * 1024), "12 KiB");
  EXPECT_EQ(formatBytes(340ull << 20), "340 MiB");
  EXPECT_EQ(formatBytes(3ull << 29), "1.5 GiB");
}

}  // namespace
}  // namespace candela
