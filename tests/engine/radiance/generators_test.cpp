// Radiance's generators interpreted by candela (xform, genbox, genprism): geometry against
// coordinates computed here by hand or from closed forms, names as the programs write them,
// orientation, file resolution, and the refusals with their file and line.
#include "base/input_file.h"
#include "engine/radiance/gen.h"
#include "engine/radiance/generators.h"
#include "engine/materials/pattern_hook.h"
#include "engine/radiance/reader.h"
#include "engine/scene.h"
#include "engine/shapes.h"
#include "tests/support/peer_suite.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path genDir() { return fs::path(CANDELA_TEST_DATA) / "rad" / "gen"; }

std::vector<RadPrimitive> expandText(const std::string& text, const std::string& name, const fs::path& folder,
                                     int depth = 0);

// The reader's expansion, without the scene: files' commands expanded relative to their folder,
// at most 32 files deep (the reader's bound, tested through it below).
std::vector<RadPrimitive> expandFile(const fs::path& file, int depth = 0) {
  return expandText(readInputFile(file, "scene file"), file.string(), file.parent_path(), depth);
}

RadExpandContext contextFor(const fs::path& folder, int depth = 0) {
  RadExpandContext ctx;
  ctx.folder = folder;
  ctx.readFile = [depth](const fs::path& f, const FileLoc& from) {
    if (depth >= 32) throw InputError(from, "too deep");
    return expandFile(f, depth + 1);
  };
  return ctx;
}

std::vector<RadPrimitive> expandText(const std::string& text, const std::string& name, const fs::path& folder,
                                     int depth) {
  std::vector<RadPrimitive> out;
  const RadExpandContext ctx = contextFor(folder, depth);
  parseRadiance(
      text, name, [&](RadPrimitive&& p) { out.push_back(std::move(p)); },
      [&](RadCommand&& c) {
        for (RadPrimitive& p : expandRadCommand(c, ctx)) out.push_back(std::move(p));
      });
  return out;
}

// A command line as a scene file in the fixture folder would hold it, at line 3.
std::vector<RadPrimitive> run(const std::string& command) {
  return expandText("\n\n" + command + "\n", "x.rad", genDir());
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// -s: a generator's output read into a scene after a plastic `m`.
Scene smoothScene(const std::string& command) {
  Scene sc;
  SceneReader(sc).readText("void plastic m 0 0 5 .5 .5 .5 0 0\n" + command + "\n", "x.rad", genDir());
  return sc;
}

// The shading normal of surface `shape` at point x on it, met from its front: the material as
// the hit sees it (patterned, engine/materials/pattern_hook.h) turning the geometric normal.
Vec3 shadingNormalAt(const Scene& sc, uint32_t shape, const Vec3& x) {
  const Shape& s = sc.shapes[shape];
  const Vec3 ng = shapeNormal(s, x);
  PatternEvaluator eval(sc);
  Material copy;
  const Material& m = patterned(sc, sc.materials[s.material], PatternPoint{x, -ng, ng, 1.0}, eval, copy);
  return shadingNormal(m, ng, true);
}

// A polygon's or triangle's vertices.
std::vector<Vec3> verticesOf(const Scene& sc, const Shape& s) {
  if (s.type == ShapeType::kTriangle) return {s.a, s.a + s.b, s.a + s.c};
  return {sc.vertices.points.begin() + s.firstVertex, sc.vertices.points.begin() + s.firstVertex + s.vertexCount};
}

// The message of running `command` at line 3 of x.rad; checks the location it names.
std::string runError(const std::string& command) {
  const std::string what = errorOf([&] { run(command); });
  EXPECT_EQ(what.rfind("x.rad:3: ", 0), 0u) << what;
  return what;
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

const RadPrimitive& find(const std::vector<RadPrimitive>& ps, const std::string& name) {
  for (const RadPrimitive& p : ps)
    if (p.name == name) return p;
  ADD_FAILURE() << "no primitive " << name;
  static const RadPrimitive none;
  return none;
}

std::vector<Vec3> points(const RadPrimitive& p) {
  std::vector<Vec3> v;
  for (size_t i = 0; i + 2 < p.reals.size(); i += 3) v.emplace_back(p.reals[i], p.reals[i + 1], p.reals[i + 2]);
  return v;
}

Vec3 at(const RadPrimitive& p, size_t i) { return Vec3(p.reals[i], p.reals[i + 1], p.reals[i + 2]); }

// Twice the vector area (Newell), pointing along the normal by the right-hand rule.
Vec3 vectorArea(const std::vector<Vec3>& v) {
  Vec3 n(0.0);
  for (size_t i = 0; i < v.size(); ++i) n += glm::cross(v[i], v[(i + 1) % v.size()]);
  return 0.5 * n;
}

Vec3 centroid(const std::vector<Vec3>& v) {
  Vec3 c(0.0);
  for (const Vec3& p : v) c += p;
  return c / double(v.size());
}

void expectVec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// Rotations written out (xform(1): counter-clockwise looking down the axis).
Vec3 rotZ(double deg, const Vec3& p) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return Vec3(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
}
Vec3 rotX(double deg, const Vec3& p) {
  const double a = deg * kPi / 180, c = std::cos(a), s = std::sin(a);
  return Vec3(p.x, c * p.y - s * p.z, s * p.y + c * p.z);
}

// The polyhedron's volume by the divergence theorem, V = Σ (1/3) c_f · A_f over planar faces.
double volume(const std::vector<RadPrimitive>& ps) {
  double v = 0.0;
  for (const RadPrimitive& p : ps)
    if (p.type == "polygon") v += glm::dot(centroid(points(p)), vectorArea(points(p))) / 3.0;
  return v;
}

// ------------------------------------------------------------------------------------- xform

TEST(Xform, TranslatesThenRotatesInTheOrderGiven) {
  const auto ps = run("!xform -t 1 2 3 -rz 90 unit.rad");
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_EQ(ps[0].name, "sq");
  EXPECT_EQ(ps[0].modifier, "grey");
  // (x, y, z) + (1, 2, 3), then (x, y) → (−y, x).
  const std::vector<Vec3> v = points(ps[0]);
  ASSERT_EQ(v.size(), 4u);
  expectVec(v[0], Vec3(-2, 1, 3));
  expectVec(v[1], Vec3(-2, 2, 3));
  expectVec(v[2], Vec3(-3, 2, 3));
  expectVec(v[3], Vec3(-3, 1, 3));
}

TEST(Xform, EveryPrimitiveTypeTransformsAsXformDoes) {
  const auto ps = run("!xform -s 2 -rx 90 -t 0 0 1 shapes.rad");
  // Scale 2, then (x, y, z) → (x, −z, y), then z + 1.
  auto xf = [](const Vec3& p) { return Vec3(2 * p.x, -2 * p.z, 2 * p.y + 1); };
  auto dir = [](const Vec3& d) { return Vec3(2 * d.x, -2 * d.z, 2 * d.y); };
  const RadPrimitive& ball = find(ps, "ball");
  expectVec(at(ball, 0), xf(Vec3(1, 2, 3)));
  EXPECT_DOUBLE_EQ(ball.reals[3], 1.0);
  EXPECT_EQ(find(ps, "hollow").type, "bubble");
  const RadPrimitive& disk = find(ps, "disk");
  expectVec(at(disk, 0), xf(Vec3(0, 0, 1)));
  expectVec(at(disk, 3), dir(Vec3(0, 0, 1)));  // not renormalised (xform.c's multv3)
  EXPECT_DOUBLE_EQ(disk.reals[6], 0.5);
  EXPECT_DOUBLE_EQ(disk.reals[7], 1.5);
  const RadPrimitive& tip = find(ps, "tip");
  expectVec(at(tip, 3), xf(Vec3(0, 0, 2)));
  EXPECT_DOUBLE_EQ(tip.reals[6], 2.0);
  EXPECT_DOUBLE_EQ(tip.reals[7], 1.0);
  EXPECT_EQ(find(ps, "dent").type, "cup");
  const RadPrimitive& post = find(ps, "post");
  expectVec(at(post, 3), xf(Vec3(0, 0, 3)));
  EXPECT_DOUBLE_EQ(post.reals[6], 0.4);
  EXPECT_EQ(find(ps, "pipe").type, "tube");
  expectVec(at(find(ps, "sun"), 0), dir(Vec3(0, 1, 1)));
  EXPECT_DOUBLE_EQ(find(ps, "sun").reals[3], 0.5);  // the angle is no length
  // Materials: a glow's radius is a length; a dielectric's transmission is per unit length,
  // so over lengths twice as long the same glass transmits t^(1/2) per new unit.
  EXPECT_DOUBLE_EQ(find(ps, "halo").reals[3], 4.0);
  const RadPrimitive& water = find(ps, "water");
  EXPECT_NEAR(water.reals[0], std::sqrt(0.9), 1e-15);
  EXPECT_NEAR(water.reals[2], std::sqrt(0.7), 1e-15);
  EXPECT_DOUBLE_EQ(water.reals[3], 1.33);
  const RadPrimitive& boundary = find(ps, "boundary");
  EXPECT_NEAR(boundary.reals[4], std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(boundary.reals[7], 1.5);
  // Patterns take the transform after their strings, behind "-i 1" that ends any repeat of theirs.
  const std::vector<std::string> tail = {"-i", "1", "-s", "2", "-rx", "90", "-t", "0", "0", "1"};
  std::vector<std::string> want = {"wave", "wave.cal"};
  want.insert(want.end(), tail.begin(), tail.end());
  EXPECT_EQ(find(ps, "wave").strings, want);
  want = {"wave", "wave.cal", "-rz", "10"};
  want.insert(want.end(), tail.begin(), tail.end());
  EXPECT_EQ(find(ps, "tilted").strings, want);
  // alias and an unknown type pass on unchanged.
  EXPECT_EQ(find(ps, "other").strings, std::vector<std::string>{"grey"});
  const RadPrimitive& thing = find(ps, "thing");
  EXPECT_EQ(thing.type, "fancy");
  EXPECT_EQ(thing.reals, (std::vector<double>{1.5, 2.5}));
}

TEST(Xform, NamesPrefixObjectsAndModifiersKeepTheirs) {
  const auto ps = run("!xform -n a -n b -m other shapes.rad");
  // Objects (surfaces, sources) get "a.b." and the new modifier; materials, patterns, aliases keep
  // their names and modifiers (xform.c's xfobject tests ismodifier).
  EXPECT_EQ(find(ps, "a.b.ball").modifier, "other");
  EXPECT_EQ(find(ps, "a.b.sun").modifier, "other");
  EXPECT_EQ(find(ps, "grey").modifier, "void");
  EXPECT_EQ(find(ps, "wave").modifier, "void");
  EXPECT_EQ(find(ps, "other").modifier, "void");
  EXPECT_EQ(find(ps, "thing").name, "thing");  // an unknown type is left for the reader to refuse
  // Only the first -m counts.
  EXPECT_EQ(run("!xform -m m1 -m m2 unit.rad")[0].modifier, "m1");
}

TEST(Xform, InvertAndMirrorsFlipOrientationAsXformDoes) {
  const Vec3 up = vectorArea(points(run("!xform unit.rad")[0]));
  expectVec(up, Vec3(0, 0, 1));
  // -mz: the mirrored square faces −z, so its vertices must run the other way round (they stay
  // in z = 0). -mx mirrors within the plane: the normal stays +z, again by reversing the order.
  expectVec(vectorArea(points(run("!xform -mz unit.rad")[0])), Vec3(0, 0, -1));
  const RadPrimitive mx = run("!xform -mx unit.rad")[0];
  expectVec(vectorArea(points(mx)), Vec3(0, 0, 1));
  expectVec(points(mx)[0], Vec3(0, 1, 0));  // the last vertex (0 1 0), mirrored, comes first
  // -I turns surfaces inside out; with a mirror as well the two cancel for polygons.
  expectVec(vectorArea(points(run("!xform -I unit.rad")[0])), Vec3(0, 0, -1));
  expectVec(vectorArea(points(run("!xform -I -mz unit.rad")[0])), Vec3(0, 0, 1));
  const auto inv = run("!xform -I shapes.rad");
  EXPECT_EQ(find(inv, "ball").type, "bubble");
  EXPECT_EQ(find(inv, "hollow").type, "sphere");
  EXPECT_EQ(find(inv, "tip").type, "cup");
  EXPECT_EQ(find(inv, "dent").type, "cone");
  EXPECT_EQ(find(inv, "post").type, "tube");
  EXPECT_EQ(find(inv, "pipe").type, "cylinder");
  expectVec(at(find(inv, "disk"), 3), Vec3(0, 0, -1));
  // A mirror alone keeps a sphere a sphere and a ring's normal is the mirrored one.
  const auto mir = run("!xform -mz shapes.rad");
  EXPECT_EQ(find(mir, "ball").type, "sphere");
  expectVec(at(find(mir, "disk"), 3), Vec3(0, 0, -1));
  expectVec(at(find(mir, "disk"), 0), Vec3(0, 0, -1));
  // -I twice is no inversion.
  EXPECT_EQ(find(run("!xform -I -I shapes.rad"), "ball").type, "sphere");
}

// A polygon without vertices is the reader's to refuse, inverted or not.
TEST(Xform, PolygonWithoutVerticesPassesToTheReader) {
  const auto ps = expandText("!xform -I -mz empty.rad\n", "x.rad", genDir());
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_TRUE(ps[0].reals.empty());
  const std::string what = errorOf([] {
    Scene sc;
    SceneReader(sc).readText("void plastic grey 0 0 5 .5 .5 .5 0 0\n!xform -I empty.rad\n", "x.rad", genDir());
  });
  EXPECT_HAS(what, "empty.rad:2: polygon 'nothing' needs at least 3 vertices");
}

TEST(Xform, RepeatCountAppliesTheTransformThatFollows) {
  // "-i 3 -t 1 0 0": the translation three times.
  expectVec(points(run("!xform -i 3 -t 1 0 0 unit.rad")[0])[0], Vec3(3, 0, 0));
  expectVec(points(run("!xform -t 1 0 0 -i 2 -rz 90 unit.rad")[0])[0], Vec3(-1, 0, 0));
}

TEST(Xform, ArraysStepTheirTransformAndNumberTheNames) {
  auto ps = run("!xform -n row -a 3 -t 2 0 0 unit.rad");
  ASSERT_EQ(ps.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(ps[i].name, "row." + std::to_string(i) + ".sq");
    expectVec(points(ps[i])[0], Vec3(2.0 * i, 0, 0));  // the first copy has zero steps
  }
  // Without -n: "a0", "a1", ...; two arrays nest (the second inside each copy of the first).
  ps = run("!xform -a 2 -t 1 0 0 -a 3 -t 0 1 0 unit.rad");
  ASSERT_EQ(ps.size(), 6u);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) {
      const RadPrimitive& p = ps[3 * i + j];
      EXPECT_EQ(p.name, std::string("a").append(std::to_string(i)).append(".").append(std::to_string(j)).append(".sq"));
      expectVec(points(p)[0], Vec3(i, j, 0));
    }
  // The man page's example: -rz 90, then 5 × 4 steps, then a final translation after "-i 1".
  ps = run("!xform -c -rz 90 -a 5 -t 2 0 0 -a 4 -t 0 1.5 0 -i 1 -t 0 0 10 unit.rad");
  ASSERT_EQ(ps.size(), 20u);
  expectVec(points(find(ps, "a4.3.sq"))[1], rotZ(90, Vec3(1, 0, 0)) + Vec3(8, 4.5, 10));
  // Patterns in an array copy get the copy's own "-i k" (no "-i 1" needed before it).
  ps = run("!xform -a 2 -t 1 0 0 shapes.rad");
  const std::vector<std::string> second = {"wave", "wave.cal", "-i", "1", "-t", "1", "0", "0"};
  bool found = false;
  for (const RadPrimitive& p : ps) found |= p.name == "wave" && p.strings == second;
  EXPECT_TRUE(found);
}

// Radiance's own test scene mesh_inline1.rad: 9 copies of woman.rad (here a stand-in) rotated
// 40° apart about the origin, each named plainclothes.k.
TEST(XformPeerSuite, RadianceTestSceneMeshInline1) {
  CANDELA_PEER_SUITE_DIR(suite);
  const fs::path ref = suite / "mesh_inline1.rad";
  std::vector<RadCommand> cmds;
  parseRadiance(readInputFile(ref, "scene file"), ref.string(), [](RadPrimitive&&) {},
                [&](RadCommand&& c) { cmds.push_back(std::move(c)); });
  ASSERT_EQ(cmds.size(), 1u);
  const auto ps = expandRadCommand(cmds[0], contextFor(genDir()));  // ./woman.rad: the stand-in
  ASSERT_EQ(ps.size(), 18u);
  for (int k = 0; k < 9; ++k) {
    // -s 1.5 -rx 90 -rz -80 -t 1 0 0, then -rz 40 k times, then -t -5 2.5 0.
    auto xf = [k](const Vec3& p) {
      return rotZ(40.0 * k, rotZ(-80, rotX(90, 1.5 * p)) + Vec3(1, 0, 0)) + Vec3(-5, 2.5, 0);
    };
    const RadPrimitive& body = find(ps, "plainclothes." + std::to_string(k) + ".body");
    expectVec(points(body)[2], xf(Vec3(0, 0.2, 1.7)));
    const RadPrimitive& head = find(ps, "plainclothes." + std::to_string(k) + ".head");
    expectVec(at(head, 0), xf(Vec3(0.1, 0.05, 1.6)));
    EXPECT_DOUBLE_EQ(head.reals[3], 0.15);
  }
}

// ball_in_cube.rad: genbox piped into xform, as Radiance scenes write it.
TEST(XformPeerSuite, ReadsAGeneratorThroughAPipe) {
  CANDELA_PEER_SUITE_DIR(suite);
  const fs::path ref = suite / "ball_in_cube.rad";
  std::vector<RadCommand> cmds;
  parseRadiance(readInputFile(ref, "scene file"), ref.string(), [](RadPrimitive&&) {},
                [&](RadCommand&& c) { cmds.push_back(std::move(c)); });
  ASSERT_FALSE(cmds.empty());
  ASSERT_EQ(cmds[0].words.front(), "genbox");
  const auto ps = expandRadCommand(cmds[0], contextFor(genDir()));
  ASSERT_EQ(ps.size(), 6u);
  // genbox clear_water watery 1 1 1 | xform -t -.5 -.5 -.5 -rz 17 -t -4 2.5 1.5: face .1540's
  // second corner (1, 0, 1).
  const RadPrimitive& f = find(ps, "watery.1540");
  expectVec(points(f)[1], rotZ(17, Vec3(0.5, -0.5, 0.5)) + Vec3(-4, 2.5, 1.5));
}

TEST(Xform, ArgumentFileLinesAreSeparateCopies) {
  auto ps = run("!xform -f args.txt");
  ASSERT_EQ(ps.size(), 3u);
  // Line k without -n gets "ik"; with -n X, "X.k"; comments and empty lines are no invocation;
  // "!xform" and "xform" at the start of a line are ignored; a backslash continues a line.
  EXPECT_EQ(ps[0].name, "i0.sq");
  expectVec(points(ps[0])[0], Vec3(1, 0, 0));
  EXPECT_EQ(ps[1].name, "named.1.sq");
  expectVec(points(ps[1])[0], Vec3(2, 0, 0));
  EXPECT_EQ(ps[2].name, "i2.sq");
  expectVec(points(ps[2])[1], Vec3(0, 1, 0));
  // Options before -f come first on each line: the first -n takes the line number.
  ps = run("!xform -n outer -f args.txt");
  EXPECT_EQ(ps[0].name, "outer.0.sq");
  EXPECT_EQ(ps[1].name, "outer.1.named.sq");
  // A nested -f: outer.txt's line ends in "-f inner.txt".
  ps = run("!xform -f outer.txt");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].name, "i0.0.sq");
  expectVec(points(ps[0])[0], Vec3(1, 0, 5));
  EXPECT_EQ(ps[1].name, "i0.1.sq");
  expectVec(points(ps[1])[0], Vec3(2, 0, 5));
}

TEST(Xform, NestedFilesResolveRelativeToTheIncludingFile) {
  const auto ps = expandFile(genDir() / "a.rad");
  // c.rad (in sub/sub2, named from sub/b.rad as sub2/c.rad) holds a material, a triangle and an
  // inline genbox: all moved by (0, 1, 0) then (1, 0, 0), objects named top.*.
  ASSERT_EQ(ps.size(), 8u);
  EXPECT_EQ(ps[0].name, "grey");
  expectVec(points(find(ps, "top.tri"))[1], Vec3(2, 1, 0));
  const RadPrimitive& face = find(ps, "top.box.1540");  // genbox's y = 0 face, corners 1 5 4 0
  expectVec(points(face)[0], Vec3(2, 1, 0));
  expectVec(points(face)[1], Vec3(2, 1, 1));
  // And the whole chain through the reader into a scene.
  Scene sc;
  readRadianceFile(genDir() / "a.rad", sc);
  EXPECT_NE(std::find(sc.shapeNames.begin(), sc.shapeNames.end(), "top.box.6457"), sc.shapeNames.end());
}

// An array of a file that defines its own material, through the reader: the material's
// repeated definition replaces itself (Radiance's rule), every copy's surfaces are in the scene.
TEST(Xform, ArrayOfAFileWithItsMaterialReadsIntoAScene) {
  Scene sc;
  SceneReader(sc).readText("!xform -n c -a 3 -t 0 0 2 sub/sub2/c.rad\n", "array.rad", genDir());
  for (int k = 0; k < 3; ++k)
    for (const char* id : {"tri", "box.1540", "box.6457"}) {
      const std::string name = "c." + std::to_string(k) + "." + id;
      EXPECT_NE(std::find(sc.shapeNames.begin(), sc.shapeNames.end(), name), sc.shapeNames.end()) << name;
    }
}

TEST(Xform, SelfInclusionIsRefusedAtTheIncludeDepth) {
  Scene sc;
  const std::string what = errorOf([&] { readRadianceFile(genDir() / "self.rad", sc); });
  EXPECT_HAS(what, "self.rad:2: files include each other more than 32 levels deep");
  EXPECT_HAS(runError("!xform -f selfargs.txt"), "argument files name each other more than 32 levels deep");
}

TEST(Xform, BadOptionsNameTheCommandLine) {
  EXPECT_HAS(runError("!xform -t 1 2 unit.rad"), "xform: -t needs a number, not 'unit.rad'");
  EXPECT_HAS(runError("!xform -t 1 0 0 -n late unit.rad"), "'-n' is not an option here");
  EXPECT_HAS(runError("!xform -rz 10"), "no file named: xform would read the standard input");
  EXPECT_HAS(runError("!xform -a 0 -t 1 0 0 unit.rad"), "-a needs a whole count from 1 to 1000000, not '0'");
  EXPECT_HAS(runError("!xform -a 2.5 -t 1 0 0 unit.rad"), "-a needs a whole count");
  EXPECT_HAS(runError("!xform -f"), "-f needs an argument file");
  EXPECT_HAS(runError("!xform -f - unit.rad"), "standard input");
  EXPECT_HAS(runError("!xform -f nosuch.txt"), "argument file 'nosuch.txt' is not in the working directory, in RAYPATH or in");
  EXPECT_HAS(runError("!xform -f empty.txt"), "the argument file 'empty.txt' has no argument lines");
  EXPECT_HAS(runError("!xform -f badargs.txt"),
             "xform: -t needs a number, not 'unit.rad' (argument file 'badargs.txt' line 3)");
  EXPECT_HAS(runError("!xform -t 1 0 0 nosuch.rad"), "file 'nosuch.rad' is not in the working directory, in RAYPATH or in");
  // Files only from the places Radiance looks (engine/radiance/file_lookup.h): never an absolute
  // name or one with '..', and no message quotes what such a file holds.
  for (const char* outside : {"!xform /etc/passwd", "!xform -f /etc/passwd", "!xform ../gen/unit.rad"}) {
    const std::string e = runError(outside);
    EXPECT_HAS(e, "must be a name relative to the working directory, RAYPATH or the scene's folder");
    EXPECT_EQ(e.find("root"), std::string::npos) << e;
  }
  EXPECT_HAS(runError("!xform -s 0 unit.rad"), "-s needs a non-zero factor");
}

// Nested arrays edit one list of words in place: 999 `-a 1` (each nesting the command once
// more) make the one copy, named by every level (a0.0.0…: xform.c's names), where copying the
// words at each level took memory in the square of their number (4000: 1 GB); more than 1000
// such options are refused before anything is made.
// A mesh counts as the triangles of its OBJ file (faces.obj: a quadrilateral and a pentagon, 5):
// 3·10⁶ copies of it would make 1.5·10⁷ triangles, refused before any is made.
TEST(Xform, MeshesCountByTheirTriangles) {
  EXPECT_HAS(runError("!xform -a 1000 -a 1000 -a 3 mesh.rad"), "makes about 15000000 primitives (5 per copy");
  EXPECT_EQ(run("!xform -a 3 mesh.rad").size(), 3u);
}

// --max-memory bounds what a command may make before it makes it (about 1.2 KB a primitive once
// read): 1 MiB holds 873 primitives, so -a 1000 of one polygon is refused, -a 800 made.
TEST(Xform, MaxMemoryBoundsWhatACommandMakes) {
  RadExpandContext ctx;
  ctx.folder = genDir();
  ctx.maxMemoryBytes = 1 << 20;
  ctx.readFile = [](const fs::path& f, const FileLoc&) { return expandFile(f, 1); };
  auto expand = [&](const std::string& words) {
    std::vector<RadPrimitive> out;
    parseRadiance("\n\n" + words + "\n", "x.rad", [&](RadPrimitive&& p) { out.push_back(std::move(p)); },
                  [&](RadCommand&& c) {
                    for (RadPrimitive& p : expandRadCommand(c, ctx)) out.push_back(std::move(p));
                  });
    return out;
  };
  EXPECT_DOUBLE_EQ(generatedPrimitivesAllowed(ctx), 873.0);
  EXPECT_EQ(expand("!xform -a 800 unit.rad").size(), 800u * run("!xform unit.rad").size());
  EXPECT_NE(errorOf([&] { expand("!xform -a 1000 unit.rad"); })
                .find("more than the 873 primitives --max-memory 0.000977 GiB holds (about 1.2 KB each once read)"),
            std::string::npos)
      << errorOf([&] { expand("!xform -a 1000 unit.rad"); });
  EXPECT_NE(errorOf([&] { expand("!genbox m b 1 1 1 -r .1 -n 16"); }).find("polygons, more than the 873 primitives"),
            std::string::npos);
}

TEST(Xform, ManyNestedArraysAreLinear) {
  std::string many = "!xform";
  for (int i = 0; i < 999; ++i) many += " -a 1";
  const auto ps = run(many + " unit.rad");
  ASSERT_FALSE(ps.empty());
  EXPECT_EQ(ps.size(), run("!xform unit.rad").size());
  EXPECT_EQ(ps[0].name.rfind("a0.0.0.0", 0), 0u) << ps[0].name.substr(0, 40);
  EXPECT_HAS(runError(many + " -a 1 -a 1 unit.rad"), "1001 -a and -f options in one command, more than 1000");
}

TEST(Xform, ArrayCountsAreBoundedBeforeAnythingIsMade) {
  auto t0 = std::chrono::steady_clock::now();
  EXPECT_HAS(runError("!xform -a 1000 -t 1 0 0 -a 1000 -t 0 1 0 -a 100 -t 0 0 1 unit.rad"),
             "makes 100000000 copies (-a 1000 × -a 1000 × -a 100)");
  // 16 primitives a copy: 10⁶ copies would be 1.6·10⁷ primitives.
  EXPECT_HAS(runError("!xform -a 1000000 -t 1 0 0 shapes.rad"), "makes about 16000000 primitives");
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(s, 5.0) << "the refusal should come before the copies are made";
}

TEST(Generators, UnknownCommandsAreRefusedAndNeverRun) {
  const fs::path marker = fs::temp_directory_path() / "candela_gen_geometry_marker";
  fs::remove(marker);
  EXPECT_HAS(runError("!pkgBSDF -s blinds20c.xml"), "'!pkgBSDF' is not a generator candela can expand; it expands: ");
  const std::string rm = runError("!rm -rf /");
  EXPECT_HAS(rm, "'!rm' is not a generator candela can expand; it expands: ");
  EXPECT_HAS(rm, "genbox");
  EXPECT_HAS(rm, "genprism");
  EXPECT_HAS(rm, "xform");
  EXPECT_HAS(runError("!touch " + marker.string()), "'!touch' is not a generator");
  EXPECT_HAS(runError("!genbox grey b 1 1 1 ; touch " + marker.string()), "genbox: unknown option ';'");
  EXPECT_HAS(runError("!genbox grey b 1 1 1 | sh -c 'touch " + marker.string() + "'"),
             "'!sh' is not a generator candela can expand");
  EXPECT_FALSE(fs::exists(marker));
}

// ------------------------------------------------------------------------------------ genbox

// The faces of a plain box, by genbox.c's names (the corners' codes), all facing out.
TEST(Genbox, BoxFacesFaceOutwardWithTheirAreas) {
  const auto ps = run("!genbox grey b 2 3 4");
  ASSERT_EQ(ps.size(), 6u);
  const Vec3 centre(1, 1.5, 2);
  const std::vector<std::pair<std::string, Vec3>> want = {
      {"b.1540", Vec3(0, -8, 0)}, {"b.4620", Vec3(-12, 0, 0)}, {"b.2310", Vec3(0, 0, -6)},
      {"b.3267", Vec3(0, 8, 0)},  {"b.5137", Vec3(12, 0, 0)},  {"b.6457", Vec3(0, 0, 6)}};
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(ps[i].name, want[i].first);
    EXPECT_EQ(ps[i].modifier, "grey");
    expectVec(vectorArea(points(ps[i])), want[i].second);
    EXPECT_GT(glm::dot(centroid(points(ps[i])) - centre, want[i].second), 0.0);
  }
  EXPECT_NEAR(volume(ps), 24.0, 1e-12);
  // -i swaps near and far in every coordinate (genbox.c's rev): each name now sits on the
  // opposite side, facing the same way, that is in (the divergence-theorem volume turns negative).
  const auto in = run("!genbox grey b 2 3 4 -i");
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(in[i].name, want[i].first);
    expectVec(vectorArea(points(in[i])), want[i].second);
    EXPECT_LT(glm::dot(centroid(points(in[i])) - centre, want[i].second), 0.0);
  }
  EXPECT_NEAR(volume(in), -24.0, 1e-12);
}

// -b: six inset faces, twelve chamfers of width b√2 and eight corner triangles.
TEST(Genbox, BevelledBoxMatchesTheChamferedSolid) {
  const double x = 2, y = 3, z = 4, b = 0.25;
  const auto ps = run("!genbox grey b 2 3 4 -b 0.25");
  ASSERT_EQ(ps.size(), 26u);
  double area = 0.0;
  Vec3 closure(0.0);
  for (const RadPrimitive& p : ps) {
    const Vec3 a = vectorArea(points(p));
    area += glm::length(a);
    closure += a;
    EXPECT_GT(glm::dot(centroid(points(p)) - Vec3(x / 2, y / 2, z / 2), a), 0.0) << p.name;
  }
  expectVec(closure, Vec3(0.0));
  const double faces = 2 * ((x - 2 * b) * (y - 2 * b) + (y - 2 * b) * (z - 2 * b) + (x - 2 * b) * (z - 2 * b));
  const double chamfers = 4 * b * std::sqrt(2.0) * ((x - 2 * b) + (y - 2 * b) + (z - 2 * b));
  const double corners = 8 * std::sqrt(3.0) / 4 * 2 * b * b;  // equilateral, side b√2
  EXPECT_NEAR(area, faces + chamfers + corners, 1e-12);
  // Each edge loses a prism of section b²/2 along its inner length, each corner 5b³/6 of its b³.
  const double v = x * y * z - 4 * b * b / 2 * ((x - 2 * b) + (y - 2 * b) + (z - 2 * b)) - 8 * 5 * b * b * b / 6;
  EXPECT_NEAR(volume(ps), v, 1e-12);
  EXPECT_EQ(ps[0].name, "b.dhgc");  // side(051, 055, 054, 050): letters 41 45 44 40
  EXPECT_EQ(ps[25].name, "b.Trj");  // corner(037, 067, 057): letters 31 55 47
}

// -r: edges as cylinders and corners as spheres of the radius about the inner box.
TEST(Genbox, RoundedBoxIsCylindersAndSpheresAboutTheInnerBox) {
  const double r = 0.25;
  const Vec3 lo(r), hi(2 - r, 3 - r, 4 - r);
  const auto ps = run("!genbox grey b 2 3 4 -r 0.25");
  ASSERT_EQ(ps.size(), 26u);
  int cylinders = 0, spheres = 0;
  for (const RadPrimitive& p : ps) {
    if (p.type == "cylinder") {
      ++cylinders;
      EXPECT_DOUBLE_EQ(p.reals[6], r);
      // Both ends are corners of the inner box, differing in one coordinate.
      for (size_t e : {0, 3})
        for (int c = 0; c < 3; ++c)
          EXPECT_TRUE(p.reals[e + c] == lo[c] || p.reals[e + c] == hi[c]) << p.name;
    } else if (p.type == "sphere") {
      ++spheres;
      EXPECT_DOUBLE_EQ(p.reals[3], r);
    }
  }
  EXPECT_EQ(cylinders, 12);
  EXPECT_EQ(spheres, 8);
  EXPECT_EQ(ps[6].name, "b.st");  // cylinder(070, 071): letters 56, 57
  expectVec(at(ps[6], 0), lo);
  expectVec(at(ps[6], 3), Vec3(hi.x, lo.y, lo.z));
  EXPECT_EQ(ps[25].name, "b.z");  // sphere(077)
  expectVec(at(ps[25], 0), hi);
}

// -r with -n 4 (or -i): polygons, named b.1, b.2, ... in the reverse of their making.
TEST(Genbox, FacetedRoundedBoxLiesOnTheRoundedSurface) {
  const double r = 0.25;
  const Vec3 lo(r), hi(2 - r, 3 - r, 4 - r);
  for (const bool inward : {false, true}) {
    const auto ps = run(std::string("!genbox grey b 2 3 4 -r 0.25 -n 4") + (inward ? " -i" : ""));
    // -n 4 asks for 4 strips a quarter (2²), each corner 4² triangles: 6 + 12·4 + 8·16 faces.
    ASSERT_EQ(ps.size(), 182u);
    Vec3 closure(0.0);
    for (size_t i = 0; i < ps.size(); ++i) {
      EXPECT_EQ(ps[i].name, "b." + std::to_string(i + 1));
      const std::vector<Vec3> v = points(ps[i]);
      for (const Vec3& p : v) EXPECT_NEAR(glm::length(p - glm::clamp(p, lo, hi)), r, 1e-12) << ps[i].name;
      const Vec3 c = centroid(v), a = vectorArea(v);
      closure += a;
      EXPECT_GT((inward ? -1.0 : 1.0) * glm::dot(c - glm::clamp(c, lo, hi), a), 0.0) << ps[i].name;
    }
    expectVec(closure, Vec3(0.0), 1e-12);
  }
  // The last face written is the first made: the inset face at y = 0.
  const auto ps = run("!genbox grey b 2 3 4 -r 0.25 -n 4");
  expectVec(points(ps.back())[0], Vec3(2 - r, 0, r));
  // -i alone rounds with 32 strips: 6 + 12·32 + 8·1024 faces.
  EXPECT_EQ(run("!genbox grey b 2 3 4 -r 0.25 -i").size(), 8582u);
}

// -r with -n and -s (convertobj.c's smoothed triangles, tmesh.cal built in): the rounded
// parts are triangles, each after its texture; at each corner of each triangle the shading
// normal is the rounded surface's (away from the inner box, towards it with -i); the inset
// faces stay flat polygons. Names and order are genbox's (b.1 … after the smoothed triangles).
TEST(Genbox, SmoothedRoundingTakesTheRoundedSurfacesNormalsAtTheVertices) {
  const double r = 0.25;
  const Vec3 lo(r), hi(2 - r, 3 - r, 4 - r);
  for (const bool inward : {false, true}) {
    const std::string cmd = std::string("!genbox m b 2 3 4 -r 0.25 -n 4 -s") + (inward ? " -i" : "");
    const auto ps = run(cmd);
    // 12·4 strips in two triangles each and 8·16 corner triangles, each after its texfunc, then
    // the 6 inset faces.
    ASSERT_EQ(ps.size(), 2u * (12 * 4 * 2 + 8 * 16) + 6u);
    EXPECT_EQ(ps[0].type, "texfunc");
    EXPECT_EQ(ps[1].modifier, "T-nor");
    EXPECT_EQ(ps[1].name, "b.1");
    EXPECT_EQ(ps.back().modifier, "m");
    EXPECT_EQ(ps.back().name, "b." + std::to_string(12 * 4 * 2 + 8 * 16 + 6));
    const Scene sc = smoothScene(cmd);
    EXPECT_EQ(sc.functionFiles, (std::vector<std::string>{"tmesh.cal (built in)"}));
    int checked = 0;
    for (uint32_t i = 0; i < sc.shapes.size(); ++i) {
      if (sc.materials[sc.shapes[i].material].pattern < 0) continue;  // an inset face
      for (const Vec3& p : verticesOf(sc, sc.shapes[i])) {
        const Vec3 out = (p - glm::clamp(p, lo, hi)) / r;
        expectVec(shadingNormalAt(sc, i, p), inward ? -out : out, 1e-9);
        ++checked;
      }
    }
    EXPECT_EQ(checked, 3 * (12 * 4 * 2 + 8 * 16));
  }
}

TEST(Genbox, BadArgumentsAreRefused) {
  EXPECT_HAS(runError("!genbox grey b 1 1"), "genbox needs a material, a name and three sizes");
  EXPECT_HAS(runError("!genbox grey b 1 0 1"), "genbox: the sizes must be positive, not '0'");
  EXPECT_HAS(runError("!genbox grey b 1 x 1"), "genbox: the size needs a number, not 'x'");
  EXPECT_HAS(runError("!genbox grey b 1 1 1 -b"), "genbox: -b needs a number after it");
  EXPECT_HAS(runError("!genbox grey b 1 1 1 -r 0.6"), "more than half the smallest size");
  EXPECT_HAS(runError("!genbox grey b 1 1 1 -o"), "-o writes a Wavefront .OBJ file");
  // -n 1024: 2¹⁰ strips, 6 + 12·2¹⁰ + 8·4¹⁰ ≈ 8.4·10⁶ polygons, allowed; -n 1025 rounds up to 2¹¹.
  EXPECT_HAS(runError("!genbox grey b 1 1 1 -r .1 -n 1025"), "makes 33579014 polygons, more than the 10000000 primitives a command may make");
}

// ---------------------------------------------------------------------------------- genprism

// genprism(1)'s example: an equilateral triangle extruded by (0, 0, 1).
TEST(Genprism, ExtrudedTriangleIsClosedAndOutward) {
  const auto ps = run("!genprism clear_plastic prism 3 0 0 .5 .866 1 0");
  ASSERT_EQ(ps.size(), 5u);
  const std::vector<std::string> names = {"prism.b", "prism.t", "prism.1", "prism.2", "prism.3"};
  Vec3 closure(0.0);
  for (size_t i = 0; i < ps.size(); ++i) {
    EXPECT_EQ(ps[i].name, names[i]);
    closure += vectorArea(points(ps[i]));
  }
  expectVec(closure, Vec3(0.0));
  expectVec(vectorArea(points(ps[0])), Vec3(0, 0, -0.433));  // the bottom faces down
  EXPECT_NEAR(volume(ps), 0.433, 1e-12);                      // base area × height
  // A slanted length vector keeps the volume base × its z.
  const auto slant = run("!genprism m p 3 0 0 .5 .866 1 0 -l 0.3 -0.2 2");
  expectVec(points(slant[1])[0], Vec3(1.3, -0.2, 2));  // the top, in reverse order
  EXPECT_NEAR(volume(slant), 0.866, 1e-12);
  // -c leaves out the side from the last vertex to the first, -e the two ends.
  const auto open = run("!genprism m p 3 0 0 .5 .866 1 0 -c -e");
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].name, "p.1");
  EXPECT_EQ(open[1].name, "p.2");
  expectVec(points(open[1])[0], Vec3(.5, .866, 0));
  // A downward extrusion.
  const auto down = run("!genprism m p 3 0 0 1 0 .5 .866 -l 0 0 -1");
  EXPECT_NEAR(volume(down), 0.433, 1e-12);
}

TEST(Genprism, VerticesFromAFileRelativeToTheScene) {
  const auto ps = run("!genprism m sq vertices.txt -l 0 0 3");
  ASSERT_EQ(ps.size(), 6u);
  EXPECT_NEAR(volume(ps), 12.0, 1e-12);
  EXPECT_HAS(runError("!genprism m sq badvertices.txt"), "vertex file 'badvertices.txt' line 2: 'x' is not a number");
}

// -r: a 2 × 2 × 1 square prism with rounded edges is the inner box [r, 2−r]² × [r, 1−r] grown by r.
TEST(Genprism, RoundedCornersAreSpheresAndCylindersAboutTheInnerPrism) {
  const double r = 0.25;
  const Vec3 lo(r), hi(2 - r, 2 - r, 1 - r);
  const auto ps = run("!genprism m sq 4 0 0 0 2 2 2 2 0 -r 0.25");
  // 2 ends, 4 + 4 rim spheres and cylinders at the bottom and top, 4 sides and 4 side cylinders.
  ASSERT_EQ(ps.size(), 2u + 16u + 8u);
  int spheres = 0, cylinders = 0;
  for (const RadPrimitive& p : ps) {
    if (p.type == "polygon") {
      for (const Vec3& v : points(p)) EXPECT_NEAR(glm::length(v - glm::clamp(v, lo, hi)), r, 1e-12) << p.name;
      const Vec3 c = centroid(points(p));
      EXPECT_GT(glm::dot(c - glm::clamp(c, lo, hi), vectorArea(points(p))), 0.0) << p.name;
    } else {
      const bool sphere = p.type == "sphere";
      (sphere ? spheres : cylinders)++;
      EXPECT_DOUBLE_EQ(p.reals[sphere ? 3 : 6], r);
      for (size_t e = 0; e < (sphere ? 3u : 6u); ++e)
        EXPECT_TRUE(std::abs(p.reals[e] - lo[e % 3]) < 1e-12 || std::abs(p.reals[e] - hi[e % 3]) < 1e-12) << p.name;
    }
  }
  EXPECT_EQ(spheres, 8);
  EXPECT_EQ(cylinders, 12);
  expectVec(at(find(ps, "sq.bc1"), 0), Vec3(r, r, r));
  expectVec(at(find(ps, "sq.tc3"), 0), Vec3(2 - r, 2 - r, 1 - r));
  const RadPrimitive& e1 = find(ps, "sq.e1");  // the vertical edge at vertex 2, (0, 2)
  expectVec(at(e1, 0), Vec3(r, 2 - r, r));
  expectVec(at(e1, 3), Vec3(r, 2 - r, 1 - r));
}

// Radiance's rect_opening.rad: a wall with a rectangular hole (the outline, a seam, the hole; -c
// leaves the seam's second side out), through xform -ry -90 -t -8 0 0.
TEST(GenprismPeerSuite, RadianceTestSceneRectOpening) {
  CANDELA_PEER_SUITE_DIR(suite);
  const auto ps = expandFile(suite / "rect_opening.rad");
  ASSERT_EQ(ps.size(), 2u + 9u);
  // The bottom end: 3.2 × 5.2 less the 1 × 3 hole, facing −z; -ry −90 sends (x, y, z) to
  // (−z, y, x), so it faces +x, and sits at x = −8.
  const RadPrimitive& b = find(ps, "end_wall.b");
  expectVec(vectorArea(points(b)), Vec3(3.2 * 5.2 - 3.0, 0, 0), 1e-12);
  expectVec(points(b)[0], Vec3(-8, -0.1, -0.1));
  EXPECT_EQ(ps.back().name, "end_wall.9");
}

// Radiance's sawtooth profile (203 vertices) rounded with -r .1: a sphere at each convex corner,
// centred a radius away from both edges that meet there.
TEST(GenprismPeerSuite, RoundedSawtoothCornersAreARadiusFromBothEdges) {
  CANDELA_PEER_SUITE_DIR(suite);
  const fs::path pts = suite / "sawtooth.pts";
  std::vector<glm::dvec2> v;
  {
    std::istringstream in(readInputFile(pts, "points"));
    double x, y;
    while (in >> x >> y) v.emplace_back(x, y);
  }
  ASSERT_EQ(v.size(), 203u);
  const size_t n = v.size();
  auto cross = [](const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; };
  double area2 = 0.0;
  for (size_t i = 0; i < n; ++i) area2 += cross(v[i], v[(i + 1) % n]);
  ::setenv("RAYPATH", suite.string().c_str(), 1);  // the suite's file found as Radiance finds it
  const auto ps = run("!genprism alum sawtooth sawtooth.pts -l 0 0 300 -r .1");
  ::unsetenv("RAYPATH");
  size_t convex = 0;
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 p = v[(i + n - 1) % n], c = v[i], q = v[(i + 1) % n];
    if (cross(c - p, q - c) * area2 <= 0.0) continue;  // turns against the outline: concave
    ++convex;
    const RadPrimitive& s = find(ps, "sawtooth.bc" + std::to_string(i + 1));
    const glm::dvec2 o(s.reals[0], s.reals[1]);
    for (const glm::dvec2& e : {p, q})
      EXPECT_NEAR(std::abs(cross(e - c, o - c)) / glm::length(e - c), 0.1, 1e-12) << s.name;
    EXPECT_DOUBLE_EQ(s.reals[2], 0.1);
  }
  size_t spheres = 0;
  for (const RadPrimitive& p : ps) spheres += p.type == "sphere";
  EXPECT_GT(convex, 0u);
  EXPECT_EQ(spheres, 2 * convex);  // bottom and top
}

TEST(Genprism, BadArgumentsAreRefused) {
  EXPECT_HAS(runError("!genprism m p 2 0 0 1 1"), "a prism needs at least 3 vertices, got 2");
  EXPECT_HAS(runError("!genprism m p 3 0 0 1 1"), "3 vertices need 6 numbers");
  EXPECT_HAS(runError("!genprism m p -"), "standard input");
  EXPECT_HAS(runError("!genprism m p 3 0 0 1 0 0 1 -l 1 1 0"), "-l needs a length vector with a z component");
  EXPECT_HAS(runError("!genprism m p 3 0 0 1 0 0 1 -r 2"), "more than the height");
  EXPECT_HAS(runError("!genprism m p 3 0 0 1 0 0 1 -i"), "genprism: unknown option '-i'");
  EXPECT_HAS(runError("!genprism m p 3 0 0 0 0 1 1 -r .1"), "has no length");
  EXPECT_HAS(runError("!genprism m p nosuch.txt"), "vertex file 'nosuch.txt' is not in the working directory");
  EXPECT_HAS(runError("!genprism m p /etc/passwd"), "vertex file '/etc/passwd' must be a name relative");
}


}  // namespace
}  // namespace candela

namespace candela {
namespace {

// genrev: the surface of revolution of (r(t), z(t)), its pieces as genrev.c writes them.
TEST(Genrev, PiecesByHowZAndRChange) {
  // z rises, r stays: cylinders; z rises, r shrinks: cones; z stays, r grows: rings facing down;
  // z falls: a tube or cup.
  auto ps = run("!genrev m cyl t 1 4");
  ASSERT_EQ(ps.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(ps[i].type, "cylinder");
    EXPECT_EQ(ps[i].name, "cyl." + std::to_string(i + 1));
    EXPECT_EQ(ps[i].reals, (std::vector<double>{0, 0, 0.25 * i, 0, 0, 0.25 * (i + 1), 1}));
  }
  ps = run("!genrev m c 't' '1-t' 2");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].type, "cone");
  EXPECT_EQ(ps[0].reals, (std::vector<double>{0, 0, 0, 0, 0, 0.5, 1, 0.5}));
  ps = run("!genrev m d 0 t 2");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[1].type, "ring");
  EXPECT_EQ(ps[1].reals, (std::vector<double>{0, 0, 0, 0, 0, -1, 0.5, 1}));
  ps = run("!genrev m down '1-t' '1+t' 1");
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_EQ(ps[0].type, "cup");
  ps = run("!genrev m flat 0 1 3");  // neither changes: nothing
  EXPECT_TRUE(ps.empty());
}

// Radiance's torus.rad: genrev of (2 + cos 2πt, sin 2πt) in 32 segments, -s. The frustums' area,
// π (r0 + r1) × slant, summed independently, approaches the torus's 4π² R a (R = 2, a = 1) as
// the polygon's perimeter approaches the circle's: 32 sin(π/32)/π of it.
TEST(Genrev, TorusOfRadiancesTestScene) {
  const auto ps = run("!genrev striped torus \"sin(2*PI*t)\" \"2+cos(2*PI*t)\" 32 -s");
  ASSERT_EQ(ps.size(), 64u);  // -s: each piece after its texture
  double area = 0.0;
  int cones = 0, cups = 0;
  for (const RadPrimitive& p : ps) {
    if (p.type == "texfunc") {
      EXPECT_EQ(p.modifier, "striped");
      continue;
    }
    EXPECT_EQ(p.modifier, "Phong");
    cones += p.type == "cone";
    cups += p.type == "cup";
    const double z0 = p.reals[2], z1 = p.reals[5], r0 = p.reals[6], r1 = p.reals[7];
    area += kPi * (r0 + r1) * std::hypot(z1 - z0, r1 - r0);
  }
  EXPECT_EQ(cones, 16);
  EXPECT_EQ(cups, 16);
  // Each chord's midpoint lies at cos(π/32) of the tube's radius from its centre: the frustums
  // sweep a circle of radius 2 + a cos(θ) cos(π/32) with chords 2 sin(π/32) long.
  double want = 0.0;
  for (int i = 0; i < 32; ++i) {
    const double mid = kTwoPi * (i + 0.5) / 32.0;
    want += kTwoPi * (2.0 + std::cos(mid) * std::cos(kPi / 32.0)) * 2.0 * std::sin(kPi / 32.0);
  }
  EXPECT_NEAR(area, want, 1e-9 * want);
}

// -s on a sphere of 8 pieces (genrev.c's smoothing, rev.cal built in): at each end of a piece
// the shading normal is the bisector of the piece's normal and its neighbour's, which for a
// polygon inscribed in a circle is the circle's radius through their common vertex (inwards: z
// falls, so the pieces are cups). The first and last pieces (the caps) have no neighbour at the
// poles: checked at their inner end only.
TEST(Genrev, SmoothedPiecesTurnTheirNormalsToTheSpheresAtTheVertices) {
  const int n = 8;
  const Scene sc = smoothScene("!genrev m ball 'cos(PI*t)' 'sin(PI*t)' 8 -s");
  ASSERT_EQ(sc.shapes.size(), 8u);
  EXPECT_EQ(sc.functionFiles, (std::vector<std::string>{"rev.cal (built in)"}));
  for (int i = 0; i < n; ++i) {
    const double t0 = kPi * i / n, t1 = kPi * (i + 1) / n, phi = 0.3 + i;  // any azimuth
    const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
    for (const double f : {1e-7, 1.0 - 1e-7}) {  // just inside each end of the piece
      if ((i == 0 && f < 0.5) || (i == n - 1 && f > 0.5)) continue;
      const double z = std::cos(t0) + f * (std::cos(t1) - std::cos(t0));
      const double r = std::sin(t0) + f * (std::sin(t1) - std::sin(t0));
      const double tv = f < 0.5 ? t0 : t1;  // the vertex
      const Vec3 want = -(std::sin(tv) * radial + Vec3(0, 0, std::cos(tv)));
      expectVec(shadingNormalAt(sc, static_cast<uint32_t>(i), r * radial + Vec3(0, 0, z)), want, 1e-6);
    }
  }
  // Unsmoothed, the shading normal is the piece's own.
  const Scene flat = smoothScene("!genrev m ball 'cos(PI*t)' 'sin(PI*t)' 8");
  const Vec3 x(std::sin(kPi / 8), 0, std::cos(kPi / 8));
  expectVec(shadingNormalAt(flat, 1, x), shapeNormal(flat.shapes[1], x), 1e-12);
}

TEST(Genrev, BadCommandsAreRefusedAtTheirLine) {
  EXPECT_NE(errorOf([] { run("!genrev m x t 1"); }).find("x.rad:3: genrev: usage"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genrev m x t -1 2"); }).find("r(t) is negative"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genrev m x t 1 0"); }).find("the number of segments must be 1"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genrev m x 't+' 1 2"); }).find("z(t) 't+' is not an expression"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genrev m x t 1 2 -q"); }).find("unknown option '-q'"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genrev m x f(t) 1 2"); }).find("'f'"), std::string::npos);
  // Definitions from -e.
  EXPECT_EQ(run("!genrev m x 'h*t' 1 2 -e 'h = 3'")[1].reals[5], 3.0);
}


// gensurf: the Newell vector (twice the area along the normal) of a generated polygon.
Vec3 areaVector(const RadPrimitive& p) {
  std::vector<Vec3> pts;
  for (size_t i = 0; i + 2 < p.reals.size(); i += 3) pts.emplace_back(p.reals[i], p.reals[i + 1], p.reals[i + 2]);
  return 0.5 * newellNormal(pts);
}

// A flat unit square in 2 × 3 cells: six quadrilaterals name.1 … name.6, facing +z (∂/∂s × ∂/∂t
// = x × y), their areas summing to 1.
TEST(Gensurf, FlatSquareInQuadrilateralsByTheRightHandRule) {
  const auto ps = run("!gensurf m sq s t 0 2 3");
  ASSERT_EQ(ps.size(), 6u);
  Vec3 sum(0.0);
  for (size_t i = 0; i < ps.size(); ++i) {
    EXPECT_EQ(ps[i].name, "sq." + std::to_string(i + 1));
    EXPECT_EQ(ps[i].type, "polygon");
    EXPECT_EQ(ps[i].reals.size(), 12u);
    sum += areaVector(ps[i]);
  }
  expectVec(sum, Vec3(0, 0, 1), 1e-12);
}

// A cylinder of radius 1 and height 1 in 64 facets: the inscribed prism's lateral area
// 64 · 2 sin(π/64), each facet a planar quadrilateral facing outwards.
TEST(Gensurf, CylinderIsTheInscribedPrism) {
  const auto ps = run("!gensurf m cyl 'cos(2*PI*t)' 'sin(2*PI*t)' s 1 64");
  ASSERT_EQ(ps.size(), 64u);
  double area = 0.0;
  for (const RadPrimitive& p : ps) {
    const Vec3 a = areaVector(p);
    area += glm::length(a);
    const Vec3 centre(p.reals[0] + p.reals[6], p.reals[1] + p.reals[7], 0.0);
    EXPECT_LT(glm::dot(a, centre), 0.0) << p.name;  // s × t = z × tangent: inwards, as gensurf's rule gives
  }
  EXPECT_NEAR(area, 64.0 * 2.0 * std::sin(kPi / 64.0), 1e-9);
}

// A saddle z = s·t in one cell is not planar: two triangles, (p0 p1 p2) and (p2 p1 p3) of the
// cell's corners, whose areas are those of the triangles (1,0,0) (1,1,1) (0,0,0) and
// (0,0,0) (1,1,1) (0,1,0): √3/2 · … computed here from the corners.
TEST(Gensurf, NonPlanarCellsAreTwoTrianglesAndValidLeavesPointsOut) {
  const auto ps = run("!gensurf m saddle s t s*t 1 1");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].reals.size(), 9u);
  EXPECT_EQ(ps[1].name, "saddle.2");
  const Vec3 a(1, 0, 0), b(1, 1, 1), c(0, 0, 0), d(0, 1, 0);
  const double want = 0.5 * glm::length(glm::cross(b - a, c - a)) + 0.5 * glm::length(glm::cross(b - c, d - c));
  EXPECT_NEAR(glm::length(areaVector(ps[0])) + glm::length(areaVector(ps[1])), want, 1e-12);
  // valid(s, t) > 0 only for s < 0.75: of the rows s = 0, 0.5, 1 the last is left out.
  EXPECT_EQ(run("!gensurf m v s t 0 2 3 -e 'valid(s,t) = .75 - s'").size(), 3u);
}

// -s on the unit sphere (s the polar angle over π, t the azimuth over 2π) in 6 × 8 cells
// (gensurf.c's smoothing, surf.cal built in): a point's normal is the cross product of its
// neighbours' differences, chords of a meridian and a parallel parallel to their tangents, so the
// radius; the fit through a cell's four points takes those normals at its corners. Every corner
// off the poles (where the cells have no fit and stay flat) reads the sphere's normal, and so
// does the middle of each cell (a trapezoid symmetric about its middle meridian) within 1e-6 rad
// (measured: 2e-8), where the flat facet's own normal is off by up to half a cell, 22°.
TEST(Gensurf, SmoothedCellsTakeTheSpheresNormalsAtTheirCorners) {
  const Scene sc = smoothScene("!gensurf m ball 'sin(PI*s)*cos(2*PI*t)' 'sin(PI*s)*sin(2*PI*t)' 'cos(PI*s)' 6 8 -s");
  EXPECT_EQ(sc.functionFiles, (std::vector<std::string>{"surf.cal (built in)"}));
  int corners = 0, smoothed = 0;
  double worstMiddle = 0.0;
  for (uint32_t i = 0; i < sc.shapes.size(); ++i) {
    if (sc.materials[sc.shapes[i].material].pattern < 0) continue;  // at the poles
    ++smoothed;
    const std::vector<Vec3> v = verticesOf(sc, sc.shapes[i]);
    Vec3 mid(0.0);
    for (const Vec3& p : v) mid += p / static_cast<double>(v.size());
    // gensurf's orientation, ∂/∂s × ∂/∂t (south × east), faces this sphere out.
    for (const Vec3& p : v) {
      if (std::abs(p.z) > 1.0 - 1e-9) continue;
      expectVec(shadingNormalAt(sc, i, p), glm::normalize(p), 1e-9);
      ++corners;
    }
    worstMiddle = std::max(worstMiddle, std::acos(std::min(1.0, glm::dot(shadingNormalAt(sc, i, mid), glm::normalize(mid)))));
  }
  EXPECT_EQ(smoothed, 6 * 8 - 2 * 8);  // the 8 cells at each pole are flat
  EXPECT_GT(corners, 0);
  EXPECT_LT(worstMiddle, 1e-6);  // radians
  // A function not finite one step past the ends (where -s only looks for the normals) leaves
  // those points out: the flat square of 4 × 4 cells, each a polygon after its texture.
  const auto ps = run("!gensurf m sq s t 'if(s - 1.01, 1e308 * 1e308, 0)' 4 4 -s");
  EXPECT_EQ(std::count_if(ps.begin(), ps.end(), [](const RadPrimitive& p) { return p.type == "polygon"; }), 16);
}

TEST(Gensurf, DataFileAndBounds) {
  // z from a data file of (m+1)(n+1) = 6 corner values, all 2: the square lifted to z = 2.
  const auto ps = run("!gensurf m d s t surf.dat 1 2");
  ASSERT_EQ(ps.size(), 2u);
  for (size_t k = 2; k < ps[0].reals.size(); k += 3) EXPECT_DOUBLE_EQ(ps[0].reals[k], 2.0);
  EXPECT_NE(errorOf([] { run("!gensurf m x s t 0 10000 10000"); }).find("more than the 10000000 primitives a command may make"), std::string::npos);
  // -s: each polygon with its texture counts as 4 (gen.h): 2 · 2500 · 1000 · 4 > 10⁷.
  EXPECT_NE(errorOf([] { run("!gensurf m x s t 0 2500 1000 -s"); }).find("5000000 polygons (smoothed: each counts as 4), more than the 10000000"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!gensurf m x s t 0 0 3"); }).find("m must be a whole number"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!gensurf m x s t 0 2"); }).find("x.rad:3: gensurf: usage"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!gensurf m x s 't+' 0 2 2"); }).find("y(s,t) 't+' is not an expression"),
            std::string::npos);
  EXPECT_NE(errorOf([] { run("!gensurf m x s t surf.dat 2 2"); }).find("holds 6 values"), std::string::npos);
}

// genworm: spheres at the points, cylinders where the radius stays, and where it changes a cone
// tangent to both spheres: in the plane of the axis, its slant line lies at each sphere's radius
// from the sphere's centre.
TEST(Genworm, SpheresJoinedByCylindersAndTangentCones) {
  const auto straight = run("!genworm m w t 0 0 .1 4");
  ASSERT_EQ(straight.size(), 9u);
  EXPECT_EQ(straight[0].name, "w.s0");
  EXPECT_EQ(straight[1].name, "w.c1");
  EXPECT_EQ(straight[1].type, "cylinder");
  EXPECT_EQ(straight[8].name, "w.s4");
  const auto cone = run("!genworm m k t 0 0 '.2-.1*t' 1");
  ASSERT_EQ(cone.size(), 3u);
  const RadPrimitive& c = cone[1];
  ASSERT_EQ(c.type, "cone");
  // The slant line through (x0, r0) and (x1, r1) in the (x, ρ) plane.
  const double x0 = c.reals[0], x1 = c.reals[3], r0 = c.reals[6], r1 = c.reals[7];
  auto distance = [&](double x) {
    return std::abs((r1 - r0) * x - (x1 - x0) * 0.0 + x1 * r0 - r1 * x0) / std::hypot(r1 - r0, x1 - x0);
  };
  EXPECT_NEAR(distance(0.0), 0.2, 1e-12);
  EXPECT_NEAR(distance(1.0), 0.1, 1e-12);
  EXPECT_NE(errorOf([] { run("!genworm m w t 0 0 '-1' 2"); }).find("r(t) is negative"), std::string::npos);
  EXPECT_NE(errorOf([] { run("!genworm m w t 0 0 1 2.5"); }).find("whole number"), std::string::npos);
}

}  // namespace
}  // namespace candela
