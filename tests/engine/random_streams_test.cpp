// The registry of random-stream families (engine/random_streams.h): its compile-time check is
// asserted where it is declared; here, that the check catches an overlap and that each family's
// documented extent holds the streams its users make.
#include "engine/random_streams.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

TEST(RandomStreams, TheCheckFindsAnOverlap) {
  auto all = streams::kAll;
  EXPECT_TRUE(streams::disjoint(all));
  all.back() = {streams::kCameraPixels.first + 5, 1};  // inside the camera's pixels
  EXPECT_FALSE(streams::disjoint(all));
}

TEST(RandomStreams, FamiliesHoldTheirUsersStreams) {
  // The last batch of the last point a grid can have, without the cache.
  const uint64_t lastPoint = streams::kWithoutCacheOffset - 1;
  const uint64_t last = lastPoint + streams::kWithoutCacheOffset + 255 * streams::kBatchStride;
  EXPECT_LT(last, streams::kSensorPoints.end());
  // The grids' target's pilot of that point.
  EXPECT_LT(streams::kGridPilot.first + lastPoint, streams::kGridPilot.end());
  // A derived stream of the largest top-level one stays in its family.
  for (const streams::Range& d : {streams::kSkyPatches, streams::kSuns, streams::kDirections})
    EXPECT_LE(d.first + streams::kTopLevelEnd - 1, d.end() - 1);
  // A record's direction stream stays in its family.
  EXPECT_LT(streams::kRecords.first + (uint64_t{1} << 56) - 1 + streams::kRecordDirectionOffset,
            streams::kRecords.end());
}

}  // namespace
}  // namespace candela
