#include "base/rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {

TEST(Rng, SameSeedAndStreamGiveSameSequence) {
  Rng a(7, 3), b(7, 3), c(7, 4);
  int same = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform();
    EXPECT_EQ(x, b.uniform());
    same += (x == c.uniform());
  }
  EXPECT_EQ(same, 0);
}

TEST(Rng, UniformMeanAndVarianceWithinStandardError) {
  // Mean of U(0,1) is 1/2 with variance 1/12; n = 1e6 gives a standard error of 2.9e-4.
  Rng r(1, 0);
  const int n = 1000000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = r.uniform();
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    s += x;
    s2 += x * x;
  }
  const double mean = s / n;
  EXPECT_NEAR(mean, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(s2 / n - mean * mean, 1.0 / 12.0, 4.0 * std::sqrt(1.0 / 180.0 / n));
}

}  // namespace candela
