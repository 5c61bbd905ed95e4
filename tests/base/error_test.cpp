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

namespace candela {

TEST(InputError, ControlCharactersAreEscaped) {
  // An IES first line with a window-title and a clear-screen sequence must not reach the terminal.
  const InputError e(FileLoc{"evil.ies", 1, 0}, "unknown IES edition 'x\x1b]0;pwned\x07\x1b[2J'");
  EXPECT_STREQ(e.what(), "evil.ies:1: unknown IES edition 'x\\x1b]0;pwned\\x07\\x1b[2J'");
  EXPECT_EQ(printable("tab\tand\r"), "tab\\x09and\\x0d");
  EXPECT_EQ(printable("caf\xc3\xa9 ok"), "caf\xc3\xa9 ok");  // UTF-8 is kept
}

}  // namespace candela

namespace candela {
namespace {

// 1e308 was quoted in messages with std::to_string: 309 digits and six decimals.
TEST(InputError, CompactNumbers) {
  EXPECT_EQ(compactNumber(1e308), "1e+308");
  EXPECT_EQ(compactNumber(0.1), "0.1");
  EXPECT_EQ(compactNumber(2.5), "2.5");
  EXPECT_EQ(compactNumber(-1000.0), "-1000");
  EXPECT_EQ(compactNumber(123456789.0), "123456789");
  EXPECT_LE(compactNumber(-1.2345678901234e-300).size(), 16u);
}

}  // namespace
}  // namespace candela
