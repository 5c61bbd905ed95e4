// The Radiance scene reader: a scene using every supported primitive and material, and one
// fixture per error the reader reports, each checking the line named in the message.
#include "engine/radiance/reader.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path radDir() { return fs::path(CANDELA_TEST_DATA) / "rad"; }

const Material& material(const Scene& sc, const std::string& name) {
  for (const Material& m : sc.materials)
    if (m.name == name) return m;
  ADD_FAILURE() << "no material " << name;
  static const Material none;
  return none;
}

uint32_t shapeIndex(const Scene& sc, const std::string& name) {
  for (uint32_t i = 0; i < sc.shapeNames.size(); ++i)
    if (sc.shapeNames[i] == name) return i;
  ADD_FAILURE() << "no shape " << name;
  return 0;
}

void expectRgb(const Rgb& got, const Rgb& want) {
  EXPECT_NEAR(got.x, want.x, 1e-15);
  EXPECT_NEAR(got.y, want.y, 1e-15);
  EXPECT_NEAR(got.z, want.z, 1e-15);
}

TEST(RadReader, ReadsEveryPrimitiveAndMaterial) {
  Scene sc;
  readRadianceFile(radDir() / "good.rad", sc);
  ASSERT_EQ(sc.materials.size(), 10u);
  // Radiance reference manual, "Materials": plastic's diffuse reflectance is colour·(1 − spec),
  // its specular part uncoloured spec.
  const Material& wall = material(sc, "wall");
  EXPECT_EQ(wall.type, MaterialType::kPlastic);
  EXPECT_EQ(wall.loc.line, 4);
  EXPECT_DOUBLE_EQ(wall.roughness, 0.02);
  expectRgb(wall.diffuseReflectance, Rgb(0.5, 0.6, 0.7) * 0.95);
  expectRgb(wall.specularReflectance, Rgb(0.05));
  // Metal: the specular part takes the colour.
  const Material& metal = material(sc, "brushed");
  EXPECT_EQ(metal.type, MaterialType::kMetal);
  expectRgb(metal.diffuseReflectance, Rgb(0.8, 0.7, 0.6) * 0.1);
  expectRgb(metal.specularReflectance, Rgb(0.8, 0.7, 0.6) * 0.9);
  // Trans (colour c, spec s, transmissivity t, transmitted specular ts): reflected diffuse
  // c(1−s)(1−t), transmitted diffuse c(1−s)t(1−ts), transmitted specular c(1−s)t·ts.
  const Material& tr = material(sc, "frosted");
  EXPECT_EQ(tr.type, MaterialType::kTrans);
  expectRgb(tr.diffuseReflectance, Rgb(0.6 * 0.96 * 0.5));
  expectRgb(tr.diffuseTransmittance, Rgb(0.6 * 0.96 * 0.5 * 0.2));
  expectRgb(tr.specularTransmittance, Rgb(0.6 * 0.96 * 0.5 * 0.8));
  expectRgb(tr.specularReflectance, Rgb(0.04));
  const Material& mirror = material(sc, "silver");
  EXPECT_EQ(mirror.type, MaterialType::kMirror);
  expectRgb(mirror.specularReflectance, Rgb(0.9));
  expectRgb(mirror.diffuseReflectance, Rgb(0.0));
  EXPECT_EQ(material(sc, "pane").type, MaterialType::kGlass);
  EXPECT_DOUBLE_EQ(material(sc, "pane").refractiveIndex, 1.52);  // Radiance's default
  EXPECT_DOUBLE_EQ(material(sc, "crystal").refractiveIndex, 1.6);
  expectRgb(material(sc, "crystal").color, Rgb(0.9));
  const Material& lamp = material(sc, "lamp");
  EXPECT_EQ(lamp.type, MaterialType::kLight);
  expectRgb(lamp.color, Rgb(100.0));
  EXPECT_TRUE(lamp.isSampledSource());
  const Material& window = material(sc, "window");
  EXPECT_EQ(window.type, MaterialType::kIllum);
  ASSERT_GE(window.alternate, 0);
  EXPECT_EQ(sc.materials[static_cast<size_t>(window.alternate)].name, "wall");
  const Material& sky = material(sc, "sky");
  EXPECT_EQ(sky.type, MaterialType::kGlow);
  EXPECT_TRUE(sky.isEmitter());
  EXPECT_FALSE(sky.isSampledSource());
  expectRgb(material(sc, "sun").color, Rgb(6e6));

  // Surfaces (the void ones are dropped).
  ASSERT_EQ(sc.shapes.size(), 11u);
  const Shape& floor = sc.shapes[shapeIndex(sc, "floor")];
  EXPECT_EQ(floor.type, ShapeType::kPolygon);
  EXPECT_EQ(floor.vertexCount, 4u);
  EXPECT_EQ(floor.n, Vec3(0, 0, 1));
  EXPECT_EQ(sc.materials[floor.material].name, "wall");
  EXPECT_EQ(sc.vertices.points[floor.firstVertex + 2], Vec3(4, 3, 0));
  EXPECT_EQ(sc.shapes[shapeIndex(sc, "tri")].type, ShapeType::kTriangle);
  const Shape& ball = sc.shapes[shapeIndex(sc, "ball")];
  EXPECT_EQ(ball.type, ShapeType::kSphere);
  EXPECT_FALSE(ball.inward);
  EXPECT_EQ(ball.a, Vec3(1, 1, 0.5));
  EXPECT_DOUBLE_EQ(ball.r0, 0.25);  // written "+2.5e-1"
  EXPECT_EQ(sc.materials[ball.material].name, "brushed");
  EXPECT_TRUE(sc.shapes[shapeIndex(sc, "inside")].inward);  // bubble
  const Shape& disk = sc.shapes[shapeIndex(sc, "disk")];
  EXPECT_EQ(disk.type, ShapeType::kRing);
  EXPECT_EQ(disk.n, Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(disk.r0, 0.1);
  EXPECT_DOUBLE_EQ(disk.r1, 0.3);
  const Shape& cone = sc.shapes[shapeIndex(sc, "funnel")];
  EXPECT_EQ(cone.type, ShapeType::kCone);
  EXPECT_FALSE(cone.inward);
  EXPECT_DOUBLE_EQ(cone.r0, 0.5);
  EXPECT_DOUBLE_EQ(cone.r1, 0.2);
  EXPECT_DOUBLE_EQ(cone.d, 1.0);
  EXPECT_TRUE(sc.shapes[shapeIndex(sc, "funnel_in")].inward);  // cup
  const Shape& pipe = sc.shapes[shapeIndex(sc, "pipe")];
  EXPECT_EQ(pipe.type, ShapeType::kCone);
  EXPECT_DOUBLE_EQ(pipe.r0, 0.1);
  EXPECT_DOUBLE_EQ(pipe.r1, 0.1);
  EXPECT_DOUBLE_EQ(pipe.d, 2.0);
  EXPECT_FALSE(pipe.inward);
  EXPECT_TRUE(sc.shapes[shapeIndex(sc, "pipe_in")].inward);  // tube
  EXPECT_EQ(sc.materials[sc.shapes[shapeIndex(sc, "pane_surface")].material].name, "window");
  EXPECT_EQ(sc.materials[sc.shapes[shapeIndex(sc, "screen")].material].name, "frosted");

  // Distant sources (the void one is dropped).
  ASSERT_EQ(sc.distant.size(), 2u);
  const DistantSource& sun = sc.distant[0];
  EXPECT_EQ(sun.name, "solar");
  EXPECT_NEAR(sun.direction.y, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(sun.direction.z, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(sun.halfAngleRad, degToRad(0.533 / 2), 1e-15);
  EXPECT_NEAR(sun.solidAngleSr, kTwoPi * (1 - std::cos(degToRad(0.2665))), 1e-15);
  EXPECT_EQ(sc.distant[1].name, "skydome");
  EXPECT_NEAR(sc.distant[1].solidAngleSr, 4 * kPi, 1e-12);
  EXPECT_EQ(sc.materials[sc.distant[1].material].name, "sky");
}

// Files are read in order into one scene: a later file uses an earlier file's modifiers.
TEST(RadReader, LaterTextUsesEarlierModifiers) {
  Scene sc;
  readRadianceText("void plastic red 0 0 5 0.8 0.1 0.1 0 0\n", "materials.rad", sc);
  readRadianceText("# geometry\nred sphere s 0 0 4 0 0 0 1\n", "geometry.rad", sc);
  ASSERT_EQ(sc.shapes.size(), 1u);
  EXPECT_EQ(sc.materials[sc.shapes[0].material].name, "red");
  // ...and a modifier defined later in the same text is an error at the using line.
  Scene sc2;
  try {
    readRadianceText("\n\nblue sphere s 0 0 4 0 0 0 1\nvoid plastic blue 0 0 5 0 0 1 0 0\n", "order.rad", sc2);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 3);
    EXPECT_NE(std::string(e.what()).find("order.rad:3:"), std::string::npos) << e.what();
  }
}

// Runs the reader on fixture `file` and checks that it throws with `line` and `text` in the
// message, which reads "<path>:<line>: ...".
void expectError(const std::string& file, int line, const std::string& text) {
  Scene sc;
  const fs::path path = radDir() / file;
  ASSERT_TRUE(fs::exists(path)) << path;
  try {
    readRadianceFile(path, sc);
    ADD_FAILURE() << file << ": no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.loc().line, line) << what;
    EXPECT_EQ(what.rfind(path.string() + ":" + std::to_string(line) + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(text), std::string::npos) << "'" << what << "' lacks '" << text << "'";
  }
}

// What is not a scene is said to be so: an octree (as oconv writes it: a header naming its
// scene files, FORMAT=Radiance_octree, then binary data) and any binary file, at line 1.
TEST(RadReader, OctreesAndBinaryFilesAreNotScenes) {
  auto errorOf = [](const std::string& text) {
    try {
      Scene sc;
      readRadianceText(text, "scene.oct", sc);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string octree = "#?RADIANCE\noconv model/scene/envelope.rad\nFORMAT=Radiance_octree\n\n";
  octree += std::string("\x03\x00\x08\x01", 4);
  EXPECT_NE(errorOf(octree).find("scene.oct:1: a Radiance octree (oconv's output), not a scene file"), std::string::npos);
  EXPECT_NE(errorOf(std::string("void plastic p 0 0 5 1 1 1 0 0\n\x00\x01", 34)).find("scene.oct:1: a binary file"),
            std::string::npos);
}

TEST(RadReader, UnknownModifier) {
  expectError("unknown_modifier.rad", 3, "modifier 'nosuch' of polygon 'p' is not defined before use");
}

TEST(RadReader, WrongArgumentCount) {
  expectError("sphere_three_reals.rad", 7, "sphere 'ball' needs 4 real arguments, got 3");
}

TEST(RadReader, PolygonWithTwoVertices) {
  expectError("polygon_two_vertices.rad", 6, "polygon 'sliver' needs at least 3 vertices, got 2");
}

TEST(RadReader, DegeneratePolygon) {
  expectError("degenerate_polygon.rad", 7, "polygon 'line' is degenerate");
}

TEST(RadReader, NonPlanarPolygon) {
  expectError("nonplanar_polygon.rad", 7, "polygon 'warped' is not planar: vertex");
}

TEST(RadReader, NegativeRadius) {
  expectError("negative_radius.rad", 6, "ring 'disk' has a negative radius");
}

TEST(RadReader, PhysicallyImpossibleMaterials) {
  expectError("reflects_too_much.rad", 1, "plastic 'bright' reflects more than it receives");
  expectError("negative_roughness.rad", 1, "plastic 'rough' has a negative roughness");
  expectError("transmits_too_much.rad", 1, "trans 't' needs its transmission and transmitted specularity in [0, 1]");
  // 1e308 W/sr/m² once gave -nan lux with exit 0.
  expectError("overflowing_light.rad", 2, "light 'lamp' has a radiance above 1e30 W/sr/m2");
}

TEST(RadReader, CoordinatesBeyondTheExactRange) {
  // A centre at 1e30 m once aborted the process inside Embree.
  expectError("far_sphere.rad", 6, "sphere 'far' has a coordinate or size beyond 1e7 m");
}

TEST(RadReader, ByteOrderMarkIsNotAModifier) {
  Scene scene;
  readRadianceFile(std::string(CANDELA_TEST_DATA) + "/rad/bom.rad", scene);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "panel_light");
}

TEST(RadReader, QuotedStringsAreOneArgument) {
  // Radiance's own torus.rad: a quoted expression with blanks and commas is one string argument
  // (the mixture's coefficient), not "'PI/20,' is not a valid count".
  Scene scene;
  readRadianceText("void plastic m 0 0 5 .5 .5 .5 0 0\n"
                   "void mixfunc striped\n4 m m \"if(mod(atan2(Py-A2,Px-A1),PI/10) - PI/20, 1, 0)\" .\n0\n3 -4 2.5 1.5\n",
                   "torus.rad", scene);
  ASSERT_EQ(scene.patterns.size(), 1u);
  ASSERT_EQ(scene.patterns[0].strings.size(), 4u);
  EXPECT_EQ(scene.patterns[0].strings[2], "if(mod(atan2(Py-A2,Px-A1),PI/10) - PI/20, 1, 0)");
  EXPECT_EQ(scene.patterns[0].args, (std::vector<double>{-4, 2.5, 1.5}));
  // Single quotes too (Radiance's patterns.mat).
  Scene single;
  readRadianceText("void brightfunc noisepat\n2 '1 - .35*(1+fnoise3(3*Px,3*Py,3*Pz))' .\n0\n0\n", "patterns.mat", single);
  ASSERT_EQ(single.patterns.size(), 1u);
  EXPECT_EQ(single.patterns[0].strings[0], "1 - .35*(1+fnoise3(3*Px,3*Py,3*Pz))");
  // A quoted alternate material name of an illum reads as the name.
  Scene ok;
  readRadianceText("void plastic m 0 0 5 .5 .5 .5 0 0\nvoid illum win\n1 \"m\"\n0\n3 1 1 1\n", "q.rad", ok);
  ASSERT_EQ(ok.materials.size(), 2u);
  EXPECT_EQ(ok.materials[1].alternate, 0);
}

TEST(RadReader, UnclosedQuoteNamesItsLine) {
  Scene scene;
  try {
    readRadianceText("void plastic m 0 0 5 .5 .5 .5 0 0\nvoid mixfunc x\n4 a b \"if(1,\n", "q.rad", scene);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("a quoted string is not closed"), std::string::npos) << e.what();
  }
}

TEST(RadReader, NumberThatDoesNotParse) {
  expectError("bad_number.rad", 6, "'0.5x' is not a number");
}

// The primitive starts on line 7; the bad number ("O", a letter) is on line 13.
TEST(RadReader, BadNumberOnLaterLineOfMultiLinePrimitive) {
  expectError("bad_number_multiline.rad", 13, "'O' is not a number");
}

TEST(RadReader, InlineCommandIsRefused) {
  expectError("inline_command.rad", 6, "'!pkgBSDF' is not a generator candela can expand");
}

// A pipeline runs only generators: each stage is looked up, a shell command anywhere is refused,
// and a dangling '|' is an error on the command's line.
TEST(RadReader, PipelineStagesAreGeneratorsOnly) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"\n!cat /etc/passwd | xform -t 1 0 0\n", "alias.rad:2: '!cat' is not a generator candela can expand"},
           {"\n!genbox m b 1 1 1 | sh -c 'rm -rf /'\n", "alias.rad:2: '!"},
           {"\n!genbox m b 1 1 1 |\n", "alias.rad:2: an inline command ends with '|'"},
           {"\n!| xform\n", "alias.rad:2: an inline command has an empty stage before '|'"}}) {
    Scene sc;
    try {
      readRadianceText(text, "alias.rad", sc);
      ADD_FAILURE() << text << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
    }
  }
}

TEST(RadReader, UnsupportedTypeListsSupportedOnes) {
  expectError("unsupported_type.rad", 6, "primitive type 'shimmer' is not supported");
  expectError("unsupported_type.rad", 6, "supported: polygon, sphere, bubble, ring, cone, cup, cylinder, tube, source");
}

// A pattern is refused by default with a message that says how to proceed; with the base policy
// the material is used unmodified and the replacement is a warning naming the pattern's line.
TEST(RadReader, PatternRefusedByDefaultAndReplacedByItsBaseOnRequest) {
  expectError("pattern.rad", 2, "specfunc 'dimmer': function file 'rainbow.cal' is not in the working directory");
  expectError("pattern.rad", 2, "--patterns base");
  Scene sc;
  SceneReadOptions options;
  options.patterns = PatternPolicy::kBase;
  readSceneFiles({radDir() / "pattern.rad"}, sc, options);
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "pattern_replaced");
  EXPECT_EQ(sc.inputWarnings[0].loc.line, 2);
  EXPECT_NE(sc.inputWarnings[0].message.find("specfunc 'dimmer'"), std::string::npos);
  ASSERT_EQ(sc.shapes.size(), 1u);
  const Material& grey = material(sc, "grey");
  EXPECT_EQ(grey.pattern, -1);
  expectRgb(grey.diffuseReflectance, Rgb(0.5));
}

// A mixture is a material of its own; one that cannot be read stands, under the base policy, for
// its foreground material (it is itself a surface's modifier, so its own modifier would make the
// surface void).
TEST(RadReader, MixtureReadOrReplacedByItsForegroundMaterial) {
  const char* materials = "void plastic red 0 0 5 .8 .1 .1 0 0\nvoid plastic blue 0 0 5 .1 .1 .8 0 0\n";
  Scene read;
  readRadianceText(std::string(materials) +
                       "void mixfunc mix 4 red blue if(Pz,1,0) .\n0\n0\nmix polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n",
                   "mix.rad", read);
  ASSERT_EQ(read.shapes.size(), 1u);
  const Material& mix = read.materials[read.shapes[0].material];
  EXPECT_EQ(mix.type, MaterialType::kMixture);
  EXPECT_EQ(read.materials[static_cast<size_t>(mix.foreground)].name, "red");
  EXPECT_EQ(read.materials[static_cast<size_t>(mix.background)].name, "blue");
  Scene sc;
  SceneReadOptions options;
  options.patterns = PatternPolicy::kBase;
  SceneReader(sc, options)
      .readText(std::string(materials) +
                    "void mixfunc mix 4 red blue v nofile.cal\n0\n0\nmix polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n",
                "mix.rad");
  ASSERT_EQ(sc.shapes.size(), 1u);
  EXPECT_EQ(sc.materials[sc.shapes[0].material].name, "red");
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_NE(sc.inputWarnings[0].message.find("foreground material 'red'"), std::string::npos);
  EXPECT_NE(sc.inputWarnings[0].message.find("function file 'nofile.cal'"), std::string::npos);
}

// `mod alias new old` stands for old; `inherit` keeps old's modifier.
TEST(RadReader, AliasStandsForItsMaterial) {
  Scene sc;
  readRadianceText("void plastic grey 0 0 5 .5 .5 .5 0 0\ninherit alias g2 grey\nvoid alias g3 grey\n"
                   "g2 polygon a 0 0 9 0 0 0 1 0 0 0 1 0\ng3 polygon b 0 0 9 0 0 0 1 0 0 0 1 0\n",
                   "alias.rad", sc);
  ASSERT_EQ(sc.shapes.size(), 2u);
  EXPECT_EQ(sc.materials[sc.shapes[0].material].name, "grey");
  EXPECT_EQ(sc.materials[sc.shapes[1].material].name, "grey");
  try {
    Scene bad;
    readRadianceText("void alias g2 nothing\n", "alias.rad", bad);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "alias.rad:1: alias 'g2' stands for 'nothing', which is not a material defined before use");
  }
}

// The sphere starting on line 6 declares 4 reals but the file (9 lines, the last one ending in a
// newline) ends after 3: the error names the last line of the file, where the text ran out.
TEST(RadReader, UnexpectedEndOfFile) {
  expectError("unexpected_eof.rad", 9, "unexpected end of file: expected a real argument");
}

TEST(RadReader, MissingFileNamesTheFile) {
  Scene sc;
  const fs::path path = radDir() / "no_such_scene.rad";
  try {
    readRadianceFile(path, sc);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_scene.rad"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

// Errors in text without a file still carry the name given and the line.
TEST(RadReader, TextErrorsCarryTheGivenName) {
  Scene sc;
  try {
    readRadianceText("void plastic g 0 0 5 .5 .5 .5 0 0\n\n\n\ng cone c 0 0 8 0 0 0 0 0 1 -1 0.5\n", "inline.rad", sc);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "inline.rad:5: cone 'c' has a negative radius");
  }
}

// The dielectric material (traced in tests/engine/dielectric_test.cpp).
TEST(RadReader, DielectricPrimitive) {
  Scene sc;
  readRadianceText("void dielectric water\n0\n0\n5 0.9 0.95 0.98 1.33 0.01\n", "water.rad", sc);
  ASSERT_EQ(sc.materials.size(), 1u);
  const Material& m = sc.materials[0];
  EXPECT_EQ(m.type, MaterialType::kDielectric);
  EXPECT_STREQ(materialTypeName(m.type), "dielectric");
  EXPECT_EQ(m.color, Rgb(0.9, 0.95, 0.98));
  EXPECT_EQ(m.refractiveIndex, 1.33);
  EXPECT_EQ(m.hartmannConstant, 0.01);
}

TEST(RadReader, DielectricErrors) {
  expectError("dielectric_four_reals.rad", 1, "dielectric 'water' needs 5 real arguments, got 4");
  expectError("dielectric_zero_index.rad", 2, "dielectric 'vacuum' needs a refractive index > 0");
  expectError("dielectric_bad_transmission.rad", 7,
              "dielectric 'bright' needs a transmission per metre in (0, 1] for each channel");
  // Zero transmission (opaque) is refused as well: the range is open at 0.
  Scene sc;
  EXPECT_THROW(readRadianceText("void dielectric black 0 0 5 0 1 1 1.5 0\n", "t.rad", sc), InputError);
  EXPECT_THROW(readRadianceText("void dielectric neg 0 0 5 1 1 1 -1.5 0\n", "t.rad", sc), InputError);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Within 0.1 mm of its plane a polygon is read as it is, however small; beyond, the 0.1 % rule.
TEST(RadReader, NonplanarWithinATenthOfAMillimetreIsRead) {
  Scene small;
  // A 1 cm square, one corner 0.05 mm up: 0.35 % of its size, but within 0.1 mm.
  readRadianceText("void plastic m 0 0 5 .5 .5 .5 0 0\nm polygon p 0 0 12 0 0 0 .01 0 0 .01 .01 .00005 0 .01 0\n",
                   "small.rad", small);
  EXPECT_EQ(small.shapes.size(), 1u);
  Scene big;
  try {
    // A 10 cm square, one corner 2 mm up (about 0.5 mm from the best plane): beyond both.
    readRadianceText("void plastic m 0 0 5 .5 .5 .5 0 0\nm polygon p 0 0 12 0 0 0 .1 0 0 .1 .1 .002 0 .1 0\n",
                     "big.rad", big);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("big.rad:2: polygon 'p' is not planar"), std::string::npos) << e.what();
  }
}

// `skyfunc source skydome`: a source of a pattern with no material is invisible, with a warning.
TEST(RadReader, SourceOfAPatternIsInvisibleWithAWarning) {
  Scene sc;
  readRadianceText("void brightfunc skyfunc 2 skybr skybright.cal 0 7 1 3.2 2.1 .2 .5 .6 .7\n"
                   "skyfunc source skydome 0 0 4 0 0 1 180\n",
                   "sky.rad", sc);
  EXPECT_TRUE(sc.distant.empty());
  EXPECT_FALSE(sc.sky.has_value());
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "source_without_material");
  EXPECT_EQ(sc.inputWarnings[0].loc.line, 2);
}

// A compiled mesh whose OBJ file lies beside it: the OBJ is read, with a warning.
TEST(RadReader, CompiledMeshWithItsObjBesideIsReadFromTheObj) {
  const std::filesystem::path dir = test_support::scratchDir("rad_reader", "rtm");
  std::ofstream(dir / "thing.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl grey\nf 1 2 3\n";
  std::ofstream(dir / "scene.rad") << "void plastic grey 0 0 5 .5 .5 .5 0 0\nvoid mesh thing 1 thing.rtm 0 0\n";
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  EXPECT_EQ(sc.mesh.triangles.size(), 1u);
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "compiled_mesh_replaced");
  EXPECT_NE(sc.inputWarnings[0].message.find("the OBJ file beside it, thing.obj"), std::string::npos);
}

}  // namespace
}  // namespace candela
