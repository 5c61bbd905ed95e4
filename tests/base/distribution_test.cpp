#include "base/distribution.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace candela {
namespace {

TEST(LocalDistribution, ComputesEveryItemOnce) {
  const Distribution& d = localDistribution();
  EXPECT_EQ(d.rank(), 0);
  EXPECT_EQ(d.ranks(), 1);
  EXPECT_TRUE(d.writesOutputs());
  EXPECT_FALSE(d.partial());
  std::vector<int> calls(1001, 0);
  std::vector<double> v(calls.size(), -1.0);
  distributedFill(d, v, ItemUse::kResult, 2, [&](size_t i, double& x) {
    x = 0.5 * static_cast<double>(i);
    ++calls[i];  // each index from one thread only
  });
  for (size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(calls[i], 1) << i;
    EXPECT_EQ(v[i], 0.5 * static_cast<double>(i)) << i;
  }
  EXPECT_EQ(d.sum(41), 41u);
}

TEST(LocalDistribution, RowsAreFilledWhole) {
  std::vector<float> rows(7 * 5, 0.0f);
  distributedRows(localDistribution(), rows, 5, ItemUse::kShared, 1, [&](size_t i) {
    for (size_t j = 0; j < 5; ++j) rows[i * 5 + j] = static_cast<float>(10 * i + j);
  });
  for (size_t i = 0; i < 7; ++i)
    for (size_t j = 0; j < 5; ++j) EXPECT_EQ(rows[i * 5 + j], static_cast<float>(10 * i + j));
}

TEST(LocalDistribution, ListsOfVaryingSize) {
  std::vector<std::vector<std::byte>> lists(50, std::vector<std::byte>(3, std::byte{7}));  // cleared first
  localDistribution().fillLists(lists, ItemUse::kShared, 2, [](size_t i, std::vector<std::byte>& b) {
    b.assign(i % 4, static_cast<std::byte>(i));
  });
  for (size_t i = 0; i < lists.size(); ++i) EXPECT_EQ(lists[i], std::vector<std::byte>(i % 4, static_cast<std::byte>(i)));
}

}  // namespace
}  // namespace candela
