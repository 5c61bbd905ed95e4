#include "base/error.h"

#include <gtest/gtest.h>

namespace candela {

TEST(InputError, MessageNamesFileAndLine) {
  const InputError e(FileLoc{"office.rad", 14, 3}, "polygon 'desk' needs at least 3 vertices, got 2");
  EXPECT_STREQ(e.what(), "office.rad:14: polygon 'desk' needs at least 3 vertices, got 2");
  EXPECT_EQ(e.loc().line, 14);
}

TEST(InputError, WithoutLineNamesFileOnly) {
  const InputError e(FileLoc{"missing.rad", 0, 0}, "cannot open file");
  EXPECT_STREQ(e.what(), "missing.rad: cannot open file");
}

}  // namespace candela
