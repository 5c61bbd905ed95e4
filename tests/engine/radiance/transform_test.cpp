// Radiance's transform arguments: each option against the matrix it must be, the order of
// application, -i repeats, and the errors.
#include "engine/radiance/transform.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

RadTransform parse(const std::vector<std::string>& w, size_t* end = nullptr) {
  RadTransform t;
  const size_t e = parseRadTransform(w, 0, t, FileLoc{"x.rad", 3, 0}, "xform");
  if (end) *end = e;
  return t;
}

void expectVec(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
  EXPECT_NEAR(got.z, want.z, 1e-12);
}

// Counter-clockwise looking down each axis: x → y about z, y → z about x, z → x about y.
TEST(RadTransform, RotationsAreCounterClockwiseLookingDownTheAxis) {
  expectVec(parse({"-rz", "90"}).point(Vec3(1, 0, 0)), Vec3(0, 1, 0));
  expectVec(parse({"-rx", "90"}).point(Vec3(0, 1, 0)), Vec3(0, 0, 1));
  expectVec(parse({"-ry", "90"}).point(Vec3(0, 0, 1)), Vec3(1, 0, 0));
}

// Operations apply in the order written: translate then rotate differs from rotate then translate.
TEST(RadTransform, OptionsApplyInTheOrderGiven) {
  expectVec(parse({"-t", "1", "0", "0", "-rz", "90"}).point(Vec3(0.0)), Vec3(0, 1, 0));
  expectVec(parse({"-rz", "90", "-t", "1", "0", "0"}).point(Vec3(0.0)), Vec3(1, 0, 0));
  const RadTransform s = parse({"-s", "2", "-mx", "-t", "0", "0", "1"});
  expectVec(s.point(Vec3(1, 1, 1)), Vec3(-2, 2, 3));
  EXPECT_DOUBLE_EQ(s.scale, -2.0);
  expectVec(s.direction(Vec3(0, 0, 1)), Vec3(0, 0, 2));
  expectVec(s.inverse().point(s.point(Vec3(0.3, -0.2, 5))), Vec3(0.3, -0.2, 5));
}

// -i N repeats what was written since the previous -i: "-t 1 0 0 -i 3 -rz 30" is a translation
// followed by a 90° turn.
TEST(RadTransform, IRepeatsThePrecedingBlock) {
  expectVec(parse({"-t", "1", "0", "0", "-i", "3", "-rz", "30"}).point(Vec3(0.0)), Vec3(0, 1, 0));
  expectVec(parse({"-i", "0", "-t", "5", "0", "0"}).point(Vec3(0.0)), Vec3(0.0));
}

TEST(RadTransform, StopsAtTheFirstWordThatIsNotAnOption) {
  size_t end = 0;
  parse({"-t", "1", "2", "3", "-n", "name", "file.rad"}, &end);
  EXPECT_EQ(end, 4u);
  parse({"file.rad"}, &end);
  EXPECT_EQ(end, 0u);
}

TEST(RadTransform, BadArgumentsNameTheLine) {
  for (const auto& words : std::vector<std::vector<std::string>>{{"-t", "1", "2"}, {"-rz", "ten"}, {"-s", "0"},
                                                                  {"-i", "-2"}}) {
    try {
      parse(words);
      ADD_FAILURE() << words[0] << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("x.rad:3: xform: " + words[0], 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace candela
