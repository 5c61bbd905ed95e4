// Wavefront OBJ files, `mesh` primitives and the compact mesh: each OBJ construct, obj2rad's
// modifier rules and mapping files, one fixture per error (checking its line), the refusals of
// compiled meshes and octree instances on Radiance's own test scenes, non-planar polygons
// triangulated, both accelerators on a mesh against the same triangles as Shapes, and a
// tessellated room against the same room written as Radiance polygons.
#include "engine/obj_reader.h"

#include "engine/embree_accelerator.h"
#include "engine/octree.h"
#include "engine/polygon_split.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "tests/engine/test_materials.h"
#include "tests/support/peer_suite.h"
#include "tests/support/temp_files.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path objDir() { return fs::path(CANDELA_TEST_DATA) / "obj"; }

uint32_t materialIndex(const Scene& sc, const std::string& name) {
  for (uint32_t i = 0; i < sc.materials.size(); ++i)
    if (sc.materials[i].name == name) return i;
  ADD_FAILURE() << "no material " << name;
  return 0;
}

// Reads `files` in order through one reader.
Scene readFiles(const std::vector<fs::path>& files, const SceneReadOptions& opt = {}) {
  Scene sc;
  SceneReader reader(sc, opt);
  for (const fs::path& f : files) reader.readFile(f);
  return sc;
}

double triangleArea(const Scene& sc, uint32_t surface) {
  const Shape s = sc.surface(surface);
  return 0.5 * glm::length(glm::cross(s.b, s.c));
}

// The reader throws with `line` of `file` and `text` in the message ("<file>:<line>: ...").
void expectError(const std::function<void()>& read, const fs::path& file, int line, const std::string& text) {
  try {
    read();
    ADD_FAILURE() << file << ": no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.loc().line, line) << what;
    EXPECT_EQ(what.rfind(file.string() + ":" + std::to_string(line) + ": ", 0), 0u) << what;
    EXPECT_NE(what.find(text), std::string::npos) << "'" << what << "' lacks '" << text << "'";
  }
}

void expectObjError(const std::string& obj, int line, const std::string& text) {
  expectError([&] { readFiles({objDir() / "constructs.rad", objDir() / obj}); }, objDir() / obj, line, text);
}

TEST(ObjReader, ReadsEveryConstruct) {
  const Scene sc = readFiles({objDir() / "constructs.rad", objDir() / "constructs.obj"});
  EXPECT_TRUE(sc.shapes.empty());
  ASSERT_EQ(sc.mesh.vertices.size(), 4u);
  // The quad split in two, then three triangles (one through negative indices, one continued
  // over two lines).
  ASSERT_EQ(sc.mesh.triangles.size(), 5u);
  EXPECT_EQ(sc.surfaceCount(), 5u);
  const std::array<uint32_t, 3> negative = sc.mesh.triangles[3];  // f -4//1 -3//1 -1//1: 1 2 4
  EXPECT_EQ(negative, (std::array<uint32_t, 3>{0, 1, 3}));
  const std::array<uint32_t, 3> continued = sc.mesh.triangles[4];  // f 1/1/1 3/1/1 \ 4/1/1
  EXPECT_EQ(continued, (std::array<uint32_t, 3>{0, 2, 3}));
  // Areas: the unit quad, then three half squares; every front faces +z (counter-clockwise).
  EXPECT_DOUBLE_EQ(triangleArea(sc, 0) + triangleArea(sc, 1), 1.0);
  for (uint32_t i = 2; i < 5; ++i) EXPECT_DOUBLE_EQ(triangleArea(sc, i), 0.5);
  for (uint32_t i = 0; i < 5; ++i) EXPECT_EQ(sc.surface(i).n, Vec3(0, 0, 1)) << i;
  // obj2rad's modifiers: the group without usemtl, then usemtl over the groups; names: the
  // group, the groups joined by '.', then the `o` name.
  const uint32_t floor = materialIndex(sc, "floor"), red = materialIndex(sc, "red");
  const uint32_t wantMat[5] = {floor, floor, red, red, red};
  const char* const wantName[5] = {"floor", "floor", "floor", "a.b", "thing"};
  for (uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(sc.surfaceMaterial(i), wantMat[i]) << i;
    EXPECT_EQ(sc.surfaceName(i), wantName[i]) << i;
  }
  EXPECT_EQ(sc.mesh.runs.size(), 4u);  // (floor, floor) (red, floor) (red, a.b) (red, thing)
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "obj_mtllib_ignored");
  EXPECT_EQ(sc.inputWarnings[0].loc.line, 2);
}

// `vn` normals smooth a face as obj2rad does (convertobj.c's checksmooth): the shading normal at
// a point is its corners' normals weighted by its barycentric coordinates (at a corner, that
// corner's; at the centroid, their mean), unit; normals equal to the face's leave it flat, and
// normals all against it turn it round, flat.
TEST(ObjReader, VertexNormalsSmoothTheFaceAsObj2radDoes) {
  const fs::path dir = test_support::scratchDir("obj_reader", "smooth");
  std::ofstream(dir / "m.rad") << "void plastic white 0 0 5 .5 .5 .5 0 0\n";
  const Vec3 n0 = glm::normalize(Vec3(0.3, 0.0, 1.0)), n1 = glm::normalize(Vec3(-0.2, 0.1, 1.0));
  const Vec3 n2 = glm::normalize(Vec3(0.0, -0.4, 1.0));
  std::ofstream(dir / "smooth.obj") << "v 0 0 0\nv 2 0 0\nv 0 2 0\n"
                                    << "vn " << n0.x << " " << n0.y << " " << n0.z << "\nvn " << n1.x << " " << n1.y << " "
                                    << n1.z << "\nvn " << n2.x << " " << n2.y << " " << n2.z << "\n"
                                    << "vn 0 0 1\nvn 0 0 -3\n"
                                    << "f 1//1 2//2 3//3\n"     // smoothed
                                    << "f 1//4 2//4 3//4\n"     // the face's own normal: flat
                                    << "f 1//5 2//5 3//5\n"     // all against it: turned round, flat
                                    << "f 1//1 2//2 3\n";       // a corner without a normal: flat
  const Scene sc = readFiles({dir / "m.rad", dir / "smooth.obj"});
  ASSERT_EQ(sc.mesh.triangles.size(), 4u);
  ASSERT_EQ(sc.mesh.cornerNormals.size(), 1u);  // only the first triangle is smoothed
  const Vec3 corners[3] = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  const Vec3 normals[3] = {n0, n1, n2};
  for (int k = 0; k < 3; ++k) {
    const std::optional<Vec3> at = sc.smoothNormal(0, corners[k]);
    ASSERT_TRUE(at.has_value());
    EXPECT_NEAR(glm::length(*at - normals[k]), 0.0, 1e-6) << k;  // the file's 6 digits
  }
  const Vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
  EXPECT_NEAR(glm::length(*sc.smoothNormal(0, centroid) - glm::normalize(n0 + n1 + n2)), 0.0, 1e-6);
  EXPECT_FALSE(sc.smoothNormal(1, centroid).has_value());
  EXPECT_FALSE(sc.smoothNormal(2, centroid).has_value());
  EXPECT_FALSE(sc.smoothNormal(3, centroid).has_value());
  EXPECT_EQ(sc.surface(1).n, Vec3(0, 0, 1));
  EXPECT_EQ(sc.surface(2).n, Vec3(0, 0, -1));  // turned round
}

// A smoothed floor lights as its shading normal says: one huge triangle whose three normals lean
// 30° towards +x, under a sun at the zenith (a Radiance `light` source), white plastic ρ = 0.5: its
// radiance is ρ E cos 30° / π everywhere, so a sensor 1 m above facing it reads ρ E cos 30° (flat:
// ρ E), to the sensor's 4 standard errors.
TEST(ObjReader, ASmoothedFloorReflectsByItsShadingNormal) {
  const fs::path dir = test_support::scratchDir("obj_reader", "smooth_floor");
  std::ofstream(dir / "m.rad") << "void plastic white 0 0 5 .5 .5 .5 0 0\n"
                                  "void light sunl 0 0 3 1e5 1e5 1e5\nsunl source sun 0 0 4 0 0 1 0.5\n";
  const double s = std::sin(degToRad(30.0)), c = std::cos(degToRad(30.0));
  std::ofstream(dir / "floor.obj") << "v -1e4 -1e4 0\nv 1e4 -1e4 0\nv 0 1e4 0\nvn " << s << " 0 " << c
                                   << "\nf 1//1 2//1 3//1\n";
  const Scene sc = readFiles({dir / "m.rad", dir / "floor.obj"});
  ASSERT_EQ(sc.mesh.cornerNormals.size(), 1u);
  TraceSettings ts;
  ts.seed = 4;
  ts.hemisphereSamples = 4096;
  ts.maxBounces = 1;
  const Tracer tracer(sc);
  const IrradianceEstimate down = estimateIrradiance(tracer, Vec3(0.3, 0.2, 1.0), Vec3(0, 0, -1), 0, ts);
  // The sun's illuminance on a surface facing it: its radiance times its solid angle.
  const double sunLux = 1e5 * kLumensPerWatt * 2.0 * kPi * (1.0 - std::cos(degToRad(0.25)));
  const double want = 0.5 * sunLux * c;
  EXPECT_NEAR(down.illuminanceLux(), want, 4.0 * down.standardErrorLux() + 1e-3 * want);
  EXPECT_LT(down.standardErrorLux(), 0.02 * want);
  EXPECT_GT(std::abs(down.illuminanceLux() - 0.5 * sunLux), 5.0 * down.standardErrorLux());  // not the flat floor's
}

TEST(ObjReader, DefaultModifierIsWhite) {
  const Scene sc = readFiles({objDir() / "constructs.rad", objDir() / "defaults.obj"});
  ASSERT_EQ(sc.mesh.triangles.size(), 1u);
  EXPECT_EQ(sc.surfaceMaterial(0), materialIndex(sc, "white"));
  EXPECT_EQ(sc.surfaceName(0), "unnamed");
}

TEST(ObjReader, MappingFileRules) {
  SceneReadOptions opt;
  opt.objMapping = objDir() / "mapping.txt";
  const Scene sc = readFiles({objDir() / "constructs.rad", objDir() / "constructs.obj"}, opt);
  // Face 1 (group floor) and 2: the rule red (Group "floor") comes after white; face 3 is
  // voided by its Face range; face 4 (usemtl red, object thing) takes the last rule, floor.
  ASSERT_EQ(sc.mesh.triangles.size(), 4u);
  const uint32_t red = materialIndex(sc, "red"), floor = materialIndex(sc, "floor");
  EXPECT_EQ(sc.surfaceMaterial(0), red);
  EXPECT_EQ(sc.surfaceMaterial(1), red);
  EXPECT_EQ(sc.surfaceMaterial(2), red);
  EXPECT_EQ(sc.surfaceMaterial(3), floor);
  EXPECT_EQ(sc.mesh.triangles[3], (std::array<uint32_t, 3>{0, 2, 3}));  // face 4, not face 3
}

TEST(ObjReader, MappingFileErrorNamesItsLine) {
  SceneReadOptions opt;
  opt.objMapping = objDir() / "bad_mapping.txt";
  expectError([&] { readFiles({objDir() / "constructs.rad", objDir() / "constructs.obj"}, opt); },
              objDir() / "bad_mapping.txt", 3, "unknown qualifier 'Grp'");
  EXPECT_THROW(parseObjMapping("w (Face [5:2]) ;", "m"), InputError);  // reversed range
  EXPECT_THROW(parseObjMapping("w (Group \"a\") (Group \"b\") ;", "m"), InputError);  // repeated
}

TEST(ObjReader, ErrorsNameTheirLine) {
  expectObjError("bad_index.obj", 5, "face vertex '4' names no vertex: 3 are defined before this line");
  expectObjError("too_few.obj", 4, "face needs at least 3 vertices, got 2");
  expectObjError("undefined_modifier.obj", 7,
                 "modifier 'nosuch' (usemtl) is not defined in the Radiance files read before");
  expectObjError("far_vertex.obj", 2, "beyond 1e7 m");
  expectObjError("bad_number.obj", 2, "vertex coordinate 'zero' is not a number");
}

TEST(ObjReader, DegenerateFacesAreLeftOutWithAWarning) {
  const Scene sc = readFiles({objDir() / "constructs.rad", objDir() / "degenerate.obj"});
  EXPECT_EQ(sc.mesh.triangles.size(), 1u);
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "obj_degenerate_faces");
  EXPECT_EQ(sc.inputWarnings[0].loc.line, 6);
  EXPECT_EQ(sc.inputWarnings[0].message.rfind("2 face(s)", 0), 0u) << sc.inputWarnings[0].message;
}

// Area along the outline's Newell normal and orientation: what a triangulation of a non-planar
// outline must keep (the projected area of any triangulation of a closed outline is half its
// Newell vector's length).
void expectTrianglesCoverOutline(const std::vector<Shape>& tris, const std::vector<Vec3>& outline) {
  const Vec3 nn = newellNormal(outline);
  const Vec3 n = glm::normalize(nn);
  double projected = 0.0;
  for (const Shape& t : tris) {
    EXPECT_GT(glm::dot(t.n, n), 0.0);  // each faces the outline's front
    projected += 0.5 * glm::dot(glm::cross(t.b, t.c), n);
  }
  EXPECT_NEAR(projected, 0.5 * glm::length(nn), 1e-14);
}

TEST(ObjReader, NonPlanarFaceIsTriangulated) {
  const Scene sc = readFiles({objDir() / "constructs.rad", objDir() / "nonplanar.obj"});
  ASSERT_EQ(sc.mesh.triangles.size(), 2u);
  expectTrianglesCoverOutline({sc.surface(0), sc.surface(1)}, sc.mesh.vertices);
  EXPECT_TRUE(sc.inputWarnings.empty());  // as obj2rad: an OBJ face is what its triangles say
}

TEST(ObjReader, NonPlanarRadiancePolygonRefusedOrTriangulated) {
  const fs::path file = fs::path(CANDELA_TEST_DATA) / "rad" / "nonplanar_polygon.rad";
  expectError([&] { readFiles({file}); }, file, 7, "run with --nonplanar triangulate");
  SceneReadOptions opt;
  opt.nonplanar = NonplanarPolicy::kTriangulate;
  const Scene sc = readFiles({file}, opt);
  ASSERT_EQ(sc.shapes.size(), 2u);
  for (const Shape& s : sc.shapes) EXPECT_EQ(s.type, ShapeType::kTriangle);
  expectTrianglesCoverOutline(sc.shapes, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.2}, {0, 1, 0}});
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  EXPECT_EQ(sc.inputWarnings[0].code, "nonplanar_triangulated");
  EXPECT_EQ(sc.inputWarnings[0].loc.line, 7);
  EXPECT_NE(sc.inputWarnings[0].message.find("polygon 'warped' is not planar"), std::string::npos);
  EXPECT_EQ(sc.shapeNames[0], "warped");
}

// Many polygons split in one file give one warning (100 000 quads gave 20 MB of them): the count,
// the triangles, and the farthest polygon's message at its line.
TEST(ObjReader, TriangulatedPolygonsWarnOncePerFile) {
  std::string text = "void plastic m 0 0 5 .5 .5 .5 0 0\n";
  for (int i = 0; i < 50; ++i) {
    const double lift = i == 17 ? 0.3 : 0.2, x = 2.0 * i;
    text += "m polygon q" + std::to_string(i) + " 0 0 12 " + std::to_string(x) + " 0 0 " + std::to_string(x + 1) +
            " 0 0 " + std::to_string(x + 1) + " 1 " + std::to_string(lift) + " " + std::to_string(x) + " 1 0\n";
  }
  Scene sc;
  SceneReadOptions opt;
  opt.nonplanar = NonplanarPolicy::kTriangulate;
  SceneReader(sc, opt).readText(text, "quads.rad");
  EXPECT_EQ(sc.shapes.size(), 100u);
  ASSERT_EQ(sc.inputWarnings.size(), 1u);
  const Warning& w = sc.inputWarnings[0];
  EXPECT_EQ(w.code, "nonplanar_triangulated");
  EXPECT_EQ(w.loc.line, 19);  // q17, the farthest from its plane
  EXPECT_NE(w.message.find("50 polygons beyond the planarity tolerance were split into 100 triangles"), std::string::npos)
      << w.message;
  EXPECT_NE(w.message.find("polygon 'q17' is not planar"), std::string::npos) << w.message;
}

// The ear clipper's work is bounded per file as well as per face: one comb of 200 teeth splits
// within a bound of 2·10^5 point tests a file; three of them are refused at the face that passes
// the bound.
TEST(ObjReader, EarClippingWorkIsBoundedPerFile) {
  std::string comb;
  for (int i = 0; i < 200; ++i) comb += "v " + std::to_string(i) + " 0 0\nv " + std::to_string(i + 0.5) + " 1 0\n";
  comb += "v 199.5 -1 0\nv 0 -1 0\n";
  std::string face = "f";
  for (int i = 1; i <= 402; ++i) face += " " + std::to_string(i);
  auto read = [&](int faces) {
    Scene sc;
    Material m;
    m.type = MaterialType::kPlastic;
    m.name = "white";
    m.color = Rgb(0.5);
    sc.addMaterial(m);
    ObjReadOptions opt;
    opt.maxSplitTests = 200000;
    opt.resolve = [](const std::string&, const std::string&, const FileLoc&) { return 0; };
    std::string text = comb;
    for (int k = 0; k < faces; ++k) text += face + "\n";
    readObjText(text, "comb.obj", sc, opt);
    return sc.mesh.triangles.size();
  };
  EXPECT_EQ(read(1), 400u);
  try {
    read(3);
    ADD_FAILURE() << "three combs were split";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the file's faces need more than 200000 point tests"), std::string::npos)
        << e.what();
  }
}

// A bow tie (edges 1-2 and 3-4 cross) is refused under --nonplanar triangulate, saying so,
// instead of triangles that cover another region; a quadrilateral as warped that does not cross
// itself is split.
TEST(ObjReader, SelfCrossingPolygonIsRefusedNotTriangulated) {
  SceneReadOptions opt;
  opt.nonplanar = NonplanarPolicy::kTriangulate;
  Scene sc;
  try {
    SceneReader(sc, opt).readText("void plastic m 0 0 5 .5 .5 .5 0 0\nm polygon tie 0 0 12 0 0 0  3 1 0.1  3 0 0  0 2 0\n",
                                  "tie.rad");
    ADD_FAILURE() << "the bow tie was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tie.rad:2: polygon 'tie' crosses itself: its edges 1-2 and 3-4 cross"),
              std::string::npos)
        << e.what();
  }
  Scene ok;
  SceneReader(ok, opt).readText("void plastic m 0 0 5 .5 .5 .5 0 0\nm polygon q 0 0 12 0 0 0  3 0 0  3 1 0.1  0 2 0\n",
                                "quad.rad");
  EXPECT_EQ(ok.shapes.size(), 2u);
}

TEST(ObjReader, ConcaveFaceSplitsInsideItsOutline) {
  // An L-shaped hexagon (concave at (1, 1)): area 3; a fan from vertex 1 would cover (2, 2).
  const std::vector<Vec3> l = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  std::vector<std::array<uint32_t, 3>> tris;
  ASSERT_TRUE(splitPolygon(l, Vec3(0, 0, 1), tris));
  ASSERT_EQ(tris.size(), 4u);
  double area = 0.0;
  for (const auto& t : tris) {
    const double a = 0.5 * glm::cross(l[t[1]] - l[t[0]], l[t[2]] - l[t[0]]).z;
    EXPECT_GT(a, 0.0);
    area += a;
    const Vec3 c = (l[t[0]] + l[t[1]] + l[t[2]]) / 3.0;
    EXPECT_FALSE(c.x > 1.0 && c.y > 1.0) << "triangle outside the L";
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
  // Time stays bounded: past its budget of point tests the split gives up (the readers refuse).
  std::vector<std::array<uint32_t, 3>> none;
  EXPECT_FALSE(splitPolygon(l, Vec3(0, 0, 1), none, 10));
}

TEST(ObjReader, MeshPrimitiveWithTransform) {
  const Scene sc = readFiles({objDir() / "mesh_transform.rad"});
  ASSERT_EQ(sc.mesh.triangles.size(), 2u);
  // -rz 90 -s 2 -t 10 0 0 (applied left to right): (x, y) → (−2y + 10, 2x).
  const Shape turned = sc.surface(0);
  EXPECT_NEAR(glm::length(turned.a - Vec3(10, 0, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(turned.a + turned.b - Vec3(10, 2, 0)), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(turned.a + turned.c - Vec3(6, 0, 0)), 0.0, 1e-14);
  EXPECT_NEAR(glm::dot(turned.n, Vec3(0, 0, 1)), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(triangleArea(sc, 0), 4.0);  // scaled by 2: area × 4
  // -mx: x → −x, the vertex order reversed (xform) so the front still faces +z.
  const Shape mirrored = sc.surface(1);
  EXPECT_NEAR(glm::dot(mirrored.n, Vec3(0, 0, 1)), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(triangleArea(sc, 1), 1.0);
  // The mesh's modifier replaces the faces' own (obj2mesh.1): tri.obj has no usemtl and no
  // "white" is defined, yet it reads.
  EXPECT_EQ(sc.surfaceMaterial(0), materialIndex(sc, "red"));
}

TEST(ObjReader, XformOfAMeshAppliesAfterTheMeshsOwnTransform) {
  const Scene sc = readFiles({objDir() / "xform_mesh.rad"});
  ASSERT_EQ(sc.mesh.triangles.size(), 2u);
  // -rz 90 -s 2 -t 10 0 0, then xform's -t 0 0 5: (x, y, z) → (−2y + 10, 2x, z + 5).
  const Shape turned = sc.surface(0);
  EXPECT_NEAR(glm::length(turned.a - Vec3(10, 0, 5)), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(turned.a + turned.c - Vec3(6, 0, 5)), 0.0, 1e-14);
  EXPECT_NEAR(glm::dot(sc.surface(1).n, Vec3(0, 0, 1)), 1.0, 1e-15);
}

TEST(ObjReader, CompiledMeshesAndInstancesAreRefused) {
  expectError([&] { readFiles({objDir() / "mesh_rtm.rad"}); }, objDir() / "mesh_rtm.rad", 6,
              "mesh 'compiled' names a Radiance compiled mesh (thing.RTM); pass its source OBJ file instead");
}

// Radiance's own test scenes with compiled meshes and octree instances (tests/support/peer_suite.h).
TEST(ObjReaderPeerSuite, RadianceScenesWithCompiledMeshesAndInstancesAreRefused) {
  CANDELA_PEER_SUITE_DIR(suite);
  expectError([&] { readFiles({suite / "woman.rad"}); }, suite / "woman.rad", 6,
              "mesh 'woman' names a Radiance compiled mesh (woman.rtm); pass its source OBJ file instead");
  SceneReadOptions base;  // vase.rad's colorpict comes first
  base.patterns = PatternPolicy::kBase;
  expectError([&] { readFiles({suite / "vase.rad"}, base); }, suite / "vase.rad", 23,
              "mesh 'vase' names a Radiance compiled mesh (vase.rtm)");
  expectError([&] { readFiles({suite / "porsches.rad"}); }, suite / "porsches.rad", 6,
              "instance 'porsche #1' places a Radiance octree (porsche.octf), which candela does not read; pass the "
              "scene files the octree was made from");
}

TEST(ObjReader, SourcesAndMirrorsAreShapes) {
  // Light sampling and the mirrors' virtual sources enumerate Shapes: such faces are stored as
  // Shapes with obj2rad's names (OBJECT.face), planar faces as one polygon.
  const fs::path dir = test_support::scratchDir("obj_reader", "shapes");
  std::ofstream(dir / "m.rad") << "void light lamp 0 0 3 10 10 10\nvoid mirror silver 0 0 3 .9 .9 .9\n"
                                  "void plastic white 0 0 5 .5 .5 .5 0 0\n";
  std::ofstream(dir / "s.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\no fixture\nusemtl lamp\nf 1 2 3 4\n"
                                  "usemtl silver\nf 4 3 2 1\nusemtl white\nf 1 2 3\n";
  const Scene sc = readFiles({dir / "m.rad", dir / "s.obj"});
  ASSERT_EQ(sc.shapes.size(), 2u);
  EXPECT_EQ(sc.shapes[0].type, ShapeType::kPolygon);
  EXPECT_EQ(sc.shapes[0].material, materialIndex(sc, "lamp"));
  EXPECT_EQ(sc.shapeNames[0], "fixture.1");
  EXPECT_EQ(sc.shapes[1].material, materialIndex(sc, "silver"));
  EXPECT_EQ(sc.shapeNames[1], "fixture.2");
  EXPECT_DOUBLE_EQ(shapeArea(sc.shapes[0], sc.vertices), 1.0);
  ASSERT_EQ(sc.mesh.triangles.size(), 1u);
  EXPECT_EQ(sc.surfaceMaterial(2), materialIndex(sc, "white"));  // surface ids: shapes first
  const Tracer tracer(sc);
  EXPECT_EQ(tracer.sources().mirrors.size(), 1u);
}

TEST(ObjReader, MaterialsListedAfterTheObjFileApply) {
  Scene sc;
  readSceneFiles({objDir() / "constructs.obj", objDir() / "constructs.rad"}, sc);
  EXPECT_EQ(sc.mesh.triangles.size(), 5u);
  EXPECT_EQ(sc.surfaceMaterial(0), materialIndex(sc, "floor"));
}

TEST(ObjReaderPeerSuite, RadianceCabLoads) {
  CANDELA_PEER_SUITE_DIR(suite);
  // cab.obj (Radiance's test scene, no usemtl): the first group names the modifier, a bare `g`
  // falls back to "white".
  const fs::path dir = test_support::scratchDir("obj_reader", "cab");
  std::ofstream(dir / "cab.rad") << "void plastic white 0 0 5 .8 .8 .8 0 0\n"
                                    "void plastic default 0 0 5 .5 .5 .5 0 0\n"
                                    "void plastic CAB-CEILING 0 0 5 .7 .7 .7 0 0\n"
                                    "void plastic CAB-WALL-TOP 0 0 5 .6 .6 .6 0 0\n"
                                    "void plastic cab_floor 0 0 5 .2 .2 .2 0 0\n";
  const Scene sc = readFiles({dir / "cab.rad", suite / "cab.obj"});
  EXPECT_GE(sc.mesh.triangles.size(), 124u);  // 124 faces, quads and polygons split
  // With a mapping of one rule, one material for everything.
  std::ofstream(dir / "one.map") << "white ;\n";
  SceneReadOptions opt;
  opt.objMapping = dir / "one.map";
  const Scene one = readFiles({dir / "cab.rad", suite / "cab.obj"}, opt);
  EXPECT_EQ(one.mesh.triangles.size(), sc.mesh.triangles.size());
  ASSERT_EQ(one.mesh.runs.size() > 0, true);
  for (const auto& r : one.mesh.runs) EXPECT_EQ(r.material, materialIndex(one, "white"));
  // Without any material defined: the first face names its line and modifier.
  expectError([&] { readFiles({suite / "cab.obj"}); }, suite / "cab.obj", 247,
              "modifier 'default' (the group name (no usemtl))");
}

// ---- the compact mesh in the accelerators ----

// `n` × `n` squares of two triangles each over [0, 1]², randomly tilted out of plane.
void addRandomMesh(Scene& mesh, Scene& shapes, uint32_t mat, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> z(-0.2, 0.2);
  std::vector<Vec3> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.emplace_back(double(i) / n, double(j) / n, z(rng));
  mesh.mesh.vertices = v;
  mesh.mesh.runs.push_back({0, mat, 0});
  mesh.mesh.names.push_back("grid");
  auto at = [&](int i, int j) { return static_cast<uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      for (const auto& t : {std::array<uint32_t, 3>{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                            std::array<uint32_t, 3>{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}) {
        mesh.mesh.triangles.push_back(t);
        shapes.addPolygon({v[t[0]], v[t[1]], v[t[2]]}, mat);
      }
    }
}

TEST(ObjReader, AcceleratorsFindMeshTrianglesAsShapes) {
  std::mt19937 rng(7);
  Scene mesh, shapes;
  const uint32_t m = test_support::addMaterial(mesh, MaterialType::kPlastic, 0.5, "grey");
  const uint32_t m2 = test_support::addMaterial(shapes, MaterialType::kPlastic, 0.5, "grey");
  ASSERT_EQ(m, m2);
  addRandomMesh(mesh, shapes, m, 40, rng);
  ASSERT_EQ(mesh.surfaceCount(), shapes.surfaceCount());
  const Octree om(mesh), os(shapes);
  const EmbreeAccelerator em(mesh), es(shapes);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  int hits = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 o(u(rng), u(rng), 1.5);
    const Vec3 d = glm::normalize(Vec3(u(rng), u(rng), -1.0 - u(rng)) - Vec3(0.5, 0.5, 0.0));
    RayHit a, b, c, e;
    const bool ha = om.intersect(o, d, 0.0, 1e30, a), hb = os.intersect(o, d, 0.0, 1e30, b);
    const bool hc = em.intersect(o, d, 0.0, 1e30, c), he = es.intersect(o, d, 0.0, 1e30, e);
    ASSERT_EQ(ha, hb) << k;
    ASSERT_EQ(hc, he) << k;
    ASSERT_EQ(ha, hc) << k;
    if (!ha) continue;
    ++hits;
    // The same triangle (surface ids agree: shapes 0..N−1 against mesh triangles 0..N−1, with no
    // shapes before them) and the same t to the last bit (the same intersectTriangle on the
    // same doubles).
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(c.shape, e.shape);
    EXPECT_EQ(c.t, e.t);
    EXPECT_EQ(a.t, c.t);
    // Skipping the surface hit (a ray leaving it) finds the next one, or none, alike.
    RayHit a2, c2;
    const bool ha2 = om.intersect(o, d, 0.0, 1e30, a2, a.shape), hc2 = em.intersect(o, d, 0.0, 1e30, c2, c.shape);
    EXPECT_EQ(ha2, hc2);
    EXPECT_EQ(om.occluded(o, d, 0.0, 1e30, a.shape), ha2);
    EXPECT_EQ(em.occluded(o, d, 0.0, 1e30, c.shape), hc2);
  }
  EXPECT_GT(hits, 5000);  // about a third of the rays meet the grid
}


// ---- a tessellated room against the same room as Radiance polygons ----

struct RoomFace {
  Vec3 o, u, v;  // corner and edges; u × v is the inward normal
};

std::vector<RoomFace> roomFaces() {
  const double X = 4.0, Y = 3.0, Z = 2.7;
  return {{{0, 0, 0}, {X, 0, 0}, {0, Y, 0}},  {{0, 0, Z}, {0, Y, 0}, {X, 0, 0}},  // floor, ceiling
          {{0, 0, 0}, {0, 0, Z}, {X, 0, 0}},  {{0, Y, 0}, {X, 0, 0}, {0, 0, Z}},  // y = 0, y = Y
          {{0, 0, 0}, {0, Y, 0}, {0, 0, Z}},  {{X, 0, 0}, {0, 0, Z}, {0, Y, 0}}};  // x = 0, x = X
}
const RoomFace kLamp{{1.5, 1.0, 2.69}, {0, 1, 0}, {1, 0, 0}};  // 1 m², facing down

void writeVertex(std::ofstream& f, const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", p.x, p.y, p.z);
  f << buf;
}

// The room as Radiance polygons, and as an OBJ of 6·2·n² triangles plus the lamp (a quad whose
// light material makes it a polygon Shape), with its materials in a .rad file.
void writeRooms(const fs::path& dir, int n) {
  const char* materials = "void plastic wall 0 0 5 .5 .5 .5 0 0\nvoid light lamp 0 0 3 100 100 100\n";
  std::ofstream rad(dir / "room.rad");
  rad << materials;
  int k = 0;
  for (const RoomFace& f : roomFaces()) {
    rad << "wall polygon w" << k++ << " 0 0 12";
    for (const Vec3& p : {f.o, f.o + f.u, f.o + f.u + f.v, f.o + f.v}) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g", p.x, p.y, p.z);
      rad << buf;
    }
    rad << "\n";
  }
  rad << "lamp polygon lamp 0 0 12";
  for (const Vec3& p : {kLamp.o, kLamp.o + kLamp.u, kLamp.o + kLamp.u + kLamp.v, kLamp.o + kLamp.v}) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g", p.x, p.y, p.z);
    rad << buf;
  }
  rad << "\n";
  std::ofstream(dir / "materials.rad") << materials;
  std::ofstream obj(dir / "room.obj");
  obj << "usemtl wall\n";
  long base = 1;
  for (const RoomFace& f : roomFaces()) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        obj << "v ";
        writeVertex(obj, f.o + (double(i) / n) * f.u + (double(j) / n) * f.v);
        obj << "\n";
      }
    auto at = [&](int i, int j) { return base + j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        obj << "f " << at(i, j) << ' ' << at(i + 1, j) << ' ' << at(i + 1, j + 1) << "\n";
        obj << "f " << at(i, j) << ' ' << at(i + 1, j + 1) << ' ' << at(i, j + 1) << "\n";
      }
    base += (n + 1) * (n + 1);
  }
  obj << "usemtl lamp\n";
  for (const Vec3& p : {kLamp.o, kLamp.o + kLamp.u, kLamp.o + kLamp.u + kLamp.v, kLamp.o + kLamp.v}) {
    obj << "v ";
    writeVertex(obj, p);
    obj << "\n";
  }
  obj << "f -4 -3 -2 -1\n";
}

TEST(ObjReader, TessellatedRoomGivesTheIlluminanceOfItsPolygons) {
  const int n = 92;  // 6 · 2 · 92² = 101 568 triangles
  const fs::path dir = test_support::scratchDir("obj_reader", "room");
  writeRooms(dir, n);
  Scene polygons, mesh;
  readSceneFiles({dir / "room.rad"}, polygons);
  readSceneFiles({dir / "room.obj", dir / "materials.rad"}, mesh);  // materials after the OBJ
  ASSERT_EQ(mesh.mesh.triangles.size(), 6u * 2u * n * n);
  ASSERT_EQ(mesh.shapes.size(), 1u);  // the lamp
  ASSERT_EQ(polygons.shapes.size(), 7u);
  TraceSettings s;
  s.hemisphereSamples = 1024;
  for (AcceleratorKind kind : {AcceleratorKind::kEmbree, AcceleratorKind::kOctree}) {
    const Tracer tp(polygons, kind), tm(mesh, kind);
    uint64_t index = 0;
    for (const Vec2 xy : {Vec2(1.0, 1.0), Vec2(2.0, 1.5), Vec2(3.0, 2.5), Vec2(0.5, 2.8), Vec2(3.6, 0.3)}) {
      const Vec3 p(xy, 0.8), up(0, 0, 1);
      const IrradianceEstimate a = estimateIrradiance(tp, p, up, index, s), b = estimateIrradiance(tm, p, up, index, s);
      ++index;
      // Both estimates use the same random streams, so they are positively correlated and the
      // difference's standard error is at most the root sum of squares used here.
      const double se = std::hypot(a.standardErrorLux(), b.standardErrorLux());
      std::printf("[ measured ] room (%s) at (%.1f, %.1f): polygons %.6g lux, mesh %.6g lux, error bar %.3g lux\n",
                  kind == AcceleratorKind::kEmbree ? "embree" : "octree", xy.x, xy.y, a.illuminanceLux(),
                  b.illuminanceLux(), se);
      EXPECT_GT(se, 0.0);
      EXPECT_NEAR(b.illuminanceLux(), a.illuminanceLux(), 4.0 * se);
    }
  }
}

}  // namespace
}  // namespace candela
