// The one settings resolution: caller over case over preset.
#include "study/trace_options.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

TEST(TraceOptions, CallerOverCaseOverPreset) {
  Settings c;
  c.quality = Quality::kDraft;
  c.seed = 7;
  c.bounces = 3;
  c.samples = 100;
  c.threads = 1;
  c.method = Method::kPath;
  const ResolvedTrace fromCase = resolveTrace(&c, {}, Method::kCache);
  EXPECT_EQ(fromCase.quality, Quality::kDraft);
  EXPECT_EQ(fromCase.settings.lightSamples, settingsForQuality(Quality::kDraft).lightSamples);
  EXPECT_EQ(fromCase.settings.seed, 7u);
  EXPECT_EQ(fromCase.settings.maxBounces, 3);
  EXPECT_EQ(fromCase.settings.hemisphereSamples, 100);
  EXPECT_EQ(fromCase.threads, 1);
  EXPECT_EQ(fromCase.settings.method, Method::kPath);

  TraceOverrides o;
  o.quality = Quality::kHigh;
  o.seed = 9;
  o.bounces = 0;
  o.samples = 64;
  o.threads = 0;
  o.method = Method::kCache;
  const ResolvedTrace fromCaller = resolveTrace(&c, o, Method::kPath);
  EXPECT_EQ(fromCaller.quality, Quality::kHigh);
  EXPECT_EQ(fromCaller.settings.lightSamples, settingsForQuality(Quality::kHigh).lightSamples);
  EXPECT_EQ(fromCaller.settings.seed, 9u);
  EXPECT_EQ(fromCaller.settings.maxBounces, 0);
  EXPECT_EQ(fromCaller.settings.hemisphereSamples, 64);
  EXPECT_EQ(fromCaller.threads, 0);
  EXPECT_EQ(fromCaller.settings.method, Method::kCache);
}

TEST(TraceOptions, DefaultMethodOnlyWhenNeitherNamesOne) {
  Settings c;  // no method
  EXPECT_EQ(resolveTrace(&c, {}, Method::kCache).settings.method, Method::kCache);
  EXPECT_EQ(resolveTrace(nullptr, {}, Method::kPath).settings.method, Method::kPath);
  const ResolvedTrace preset = resolveTrace(nullptr, {}, Method::kPath);
  EXPECT_EQ(preset.settings.hemisphereSamples, settingsForQuality(Quality::kNormal).hemisphereSamples);
  EXPECT_EQ(preset.settings.seed, 1u);
}

// The per-point target: the preset's (normal and high 0.25 %, at most 16 batches; draft none),
// else the case's target_error, else the caller's --target-error, which may spend 256 batches.
// The grids' target (0.5 % of the larger of a point's value and its grid's mean): the normal and
// high presets', and none once a per-point target is given.
TEST(TraceOptions, TargetErrorFromPresetCaseAndCaller) {
  const ResolvedTrace normal = resolveTrace(nullptr, {}, Method::kPath);
  EXPECT_DOUBLE_EQ(normal.settings.targetRelativeError, 0.0025);
  EXPECT_DOUBLE_EQ(normal.settings.gridTargetRelativeError, 0.005);
  EXPECT_EQ(normal.settings.maxBatches, kPresetMaxBatches);
  TraceOverrides draft;
  draft.quality = Quality::kDraft;
  EXPECT_EQ(resolveTrace(nullptr, draft, Method::kPath).settings.targetRelativeError, 0.0);
  EXPECT_EQ(resolveTrace(nullptr, draft, Method::kPath).settings.gridTargetRelativeError, 0.0);
  TraceOverrides high;
  high.quality = Quality::kHigh;
  EXPECT_DOUBLE_EQ(resolveTrace(nullptr, high, Method::kPath).settings.gridTargetRelativeError, 0.005);

  Settings c;
  c.targetRelativeError = 0.01;
  const ResolvedTrace fromCase = resolveTrace(&c, {}, Method::kPath);
  EXPECT_DOUBLE_EQ(fromCase.settings.targetRelativeError, 0.01);
  EXPECT_EQ(fromCase.settings.gridTargetRelativeError, 0.0);
  EXPECT_EQ(fromCase.settings.maxBatches, kExplicitTargetMaxBatches);
  TraceOverrides off;
  off.targetRelativeError = 0.0;
  EXPECT_EQ(resolveTrace(&c, off, Method::kPath).settings.targetRelativeError, 0.0);
  EXPECT_EQ(resolveTrace(nullptr, off, Method::kPath).settings.gridTargetRelativeError, 0.0);
  EXPECT_DOUBLE_EQ(expectedBatchesPerPoint(normal.settings), 1.25);
  EXPECT_DOUBLE_EQ(expectedBatchesPerPoint(fromCase.settings), 4.0);
  EXPECT_DOUBLE_EQ(expectedBatchesPerPoint(resolveTrace(&c, off, Method::kPath).settings), 1.0);
}

// [settings] patterns and nonplanar are read like the other keys; the command line's override them.
TEST(TraceOptions, SceneReadingPoliciesFromCaseAndCaller) {
  const CaseFile c = parseCaseFile("[settings]\npatterns = \"base\"\nnonplanar = \"triangulate\"\n", "case.toml");
  EXPECT_EQ(c.settings.scene.patterns, PatternPolicy::kBase);
  EXPECT_EQ(c.settings.scene.nonplanar, NonplanarPolicy::kTriangulate);
  EXPECT_EQ(sceneReadOptions(nullptr, {}).patterns, PatternPolicy::kRefuse);
  EXPECT_EQ(sceneReadOptions(nullptr, {}).nonplanar, NonplanarPolicy::kRefuse);
  TraceOverrides o;
  o.patterns = PatternPolicy::kRefuse;
  EXPECT_EQ(sceneReadOptions(&c.settings, o).patterns, PatternPolicy::kRefuse);
  EXPECT_EQ(sceneReadOptions(&c.settings, o).nonplanar, NonplanarPolicy::kTriangulate);
  try {
    parseCaseFile("[settings]\n\npatterns = \"ignore\"\n", "case.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "case.toml:3: unknown pattern policy 'ignore' (expected refuse or base)");
  }
}

}  // namespace
}  // namespace candela
