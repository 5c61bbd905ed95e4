// A scene: materials, surfaces (in the octree) and distant sources (at infinity).
#pragma once

#include "base/error.h"
#include "base/units.h"
#include "base/warning.h"
#include "engine/luminaire_source.h"
#include "engine/materials/material.h"
#include "engine/radiance/transform.h"
#include "engine/radiance/cal/cal.h"
#include "engine/radiance/data_file.h"
#include "engine/shapes.h"
#include "photometry/sky_model.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class SourceDistribution;

// The pattern primitives candela implements: natively, recognised by their function file
// (gensky's skybright.cal, gendaylit's perezlum.cal, ies2rad's source.cal distributions), or
// through the function language (brightfunc and colorfunc of any other function file:
// engine/materials/pattern_hook.h).
enum class PatternKind { kSkyBright, kPerezLum, kSourceDistribution, kFunction };

class RadText;
class Bsdf;

// One such pattern as read (its arguments as written, transform arguments included).
struct ScenePattern {
  PatternKind kind = PatternKind::kSkyBright;
  std::string type, name;  // Radiance type (brightfunc, brightdata) and identifier
  FileLoc loc;
  std::vector<std::string> strings;
  std::vector<double> reals;
  // kSourceDistribution: the distribution as evaluated (engine/source_distribution.h), read with
  // its data file when the pattern is read.
  std::shared_ptr<const SourceDistribution> source;
  // kFunction: its expressions in Scene::functions (brightfunc: one, colorfunc: red, green,
  // blue), its real arguments (A1...), the transform from world to the function's coordinates
  // and the function's scale (S), and the pattern it is itself modified by (-1: none).
  int channels = 0;
  std::array<int32_t, 3> functions{-1, -1, -1};
  // Data patterns (brightdata, colordata, colorpict, mixdata, mixpict; kFunction too): the arrays
  // looked up (one; or one a channel, a picture's three), the functions giving the lookup point
  // (one a dimension; a picture's u then v) and, in `functions`, the functions the looked-up
  // values are passed to (one value each for brightdata and mixdata, three for the others).
  std::array<std::shared_ptr<const RadDataArray>, 3> data;
  std::vector<int32_t> coordinates;
  bool picture = false;
  // texfunc, texdata: the three values perturb the surface normal (in the function's
  // coordinates, turned to the world) instead of multiplying the colour.
  bool texture = false;
  // spectrum, specfile: a constant colour (the spectrum reduced to RGB: engine/radiance/spectrum.h).
  bool constant = false;
  Rgb constantColour{1.0};
  // specfunc, specdata (spectra of the ray, reduced to RGB at each hit): the wavelengths (nm) its
  // function is evaluated at, increasing, and the RGB a unit value at each contributes
  // (spectrumNodeWeights, engine/radiance/spectrum.h); empty for the other patterns.
  std::vector<double> spectralNodesNm;
  std::vector<Rgb> spectralWeights;
  bool spectral() const { return !spectralNodesNm.empty(); }
  // brighttext, colortext, mixtext (kFunction too): the laid-out text whose glyphs give the
  // foreground (engine/radiance/text_pattern.h); none for other patterns.
  std::shared_ptr<const RadText> text;
  std::vector<double> args;
  RadTransform toFunction, toWorld;
  double functionScale = 1.0;
  int next = -1;
};

class RadianceSkyFunction;

// A source at infinity: Radiance's `source` primitive (a cone of directions).
struct DistantSource {
  Vec3 direction{0.0, 0.0, 1.0};  // unit, towards the source
  double halfAngleRad = 0.0;
  double cosHalfAngle = 1.0;
  double solidAngleSr = 0.0;      // 2π(1 − cos half-angle)
  uint32_t material = 0;
  std::string name;
};

// The daylight environment seen by escaping rays: a sky model (luminance in cd/m², true frame)
// rotated by the site's north, and the ground below the horizon. Filled by addDaylight().
struct SkyDome {
  std::shared_ptr<const SkyModel> model;
  double northDeg = 0.0;                  // true north, clockwise from model +Y
  double groundLuminanceCdM2 = 0.0;       // ρg · E_h,outside / π
  double horizontalSkyLux = 0.0;          // sky only, open horizontal plane
  double horizontalSunLux = 0.0;          // sun only, open horizontal plane
  Vec3 sunDirModel{0.0, 0.0, 1.0};
  double sunAltitudeDeg = 90.0, sunAzimuthDeg = 0.0;
  // A sky read from the scene's own sky functions (engine/radiance/sky.h): where it is defined, and
  // which of Scene::distant is its sun (-1: none), so that a case's sky can replace both
  // (replaceSceneSky, engine/daylight.h).
  bool fromScene = false;
  FileLoc sceneLoc;
  int sceneSun = -1;
  // A scene's sky function over the ground hemisphere too (skybright.cal, perezlum.cal: the ground
  // blends into the sky near the horizon), times the ground source's factor (cd/m² per unit of
  // the function); none: the ground is the uniform groundLuminanceCdM2.
  std::shared_ptr<const RadianceSkyFunction> groundFunction;
  double groundFactorCdM2 = 0.0;
  // Outside horizontal illuminance (sky + sun, no ground): the daylight factor's denominator.
  double outsideHorizontalLux() const { return horizontalSkyLux + horizontalSunLux; }
};

// An opening declared to guide sky sampling (docs/daylight.md#portals): a planar polygon through
// which the sky is seen, e.g. a hole in a roof. Not a surface: rays pass it untouched. Glazing
// (glass, trans, dielectric, illum polygons) is found as portals without being declared
// (engine/portals.h).
struct Portal {
  std::vector<Vec3> outline;  // m, ≥ 3 vertices, planar
  std::string name;
  FileLoc loc;
};

// Triangles stored compactly (OBJ files and `mesh` primitives, engine/obj_reader.h): shared
// vertices, three vertex indices per triangle, and runs of consecutive triangles that share a
// material and a name (obj2rad's object name: the `o` name or the groups). No Shape and no name
// per triangle: a triangle costs 12 bytes plus its share of the vertices (docs/engine.md).
struct TriangleMesh {
  struct Run {
    uint32_t firstTriangle = 0;  // the run holds triangles [firstTriangle, next run's first)
    uint32_t material = 0;       // index into Scene::materials
    uint32_t name = 0;           // index into names
  };
  std::vector<Vec3> vertices;  // m
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from the front
  std::vector<Run> runs;
  std::vector<std::string> names;
  // Smoothing (OBJ `vn`, as obj2rad's tmesh.cal textures): unit normals, and for each triangle the
  // indices of its corners' normals, kNoCornerNormal for a flat one; `cornerNormals` is empty
  // when no triangle is smoothed, else as long as `triangles`.
  static constexpr uint32_t kNoCornerNormal = 0xFFFFFFFFu;
  std::vector<Vec3> normals;
  std::vector<std::array<uint32_t, 3>> cornerNormals;

  bool empty() const { return triangles.empty(); }
  // The shading normal of triangle `tri` at x (on its plane): its corners' normals weighted by
  // x's barycentric coordinates, unit, on the side of the triangle's front; nullopt when flat.
  std::optional<Vec3> smoothNormal(uint32_t tri, const Vec3& x) const;
  // The run holding triangle `tri` (binary search over the runs).
  const Run& runOf(uint32_t tri) const;
  // Bytes held by the vectors (capacity), names included.
  size_t memoryBytes() const;
};

// Surfaces are numbered shapes first, then mesh triangles: surface id = shapes.size() + triangle.
// The accelerators return these ids (RayHit::shape); Scene::surface gives either as a Shape.
struct Scene {
  std::vector<Material> materials;
  std::vector<ScenePattern> patterns;
  // The function files and inline expressions the patterns use (none: no function pattern), and
  // the paths of the function files read, in order (summary.json's function_files).
  std::shared_ptr<const cal::Program> functions;
  std::vector<std::string> functionFiles;
  // The window systems' scattering the BSDF and aBSDF materials name (engine/bsdf.h), each file once.
  std::vector<std::shared_ptr<const Bsdf>> bsdfs;
  std::vector<Shape> shapes;
  std::vector<std::string> shapeNames;
  TriangleMesh mesh;
  std::vector<DistantSource> distant;
  std::vector<LuminaireSource> luminaires;  // photometric light sources (no geometry of their own)
  std::optional<SkyDome> sky;               // daylight (engine/daylight.h); none indoors
  std::vector<Portal> portals;              // declared openings (sky sampling only)
  VertexStore vertices;
  // What reading the scene files replaced or repaired (engine/radiance/reader.h), for the study's
  // warnings.
  std::vector<Warning> inputWarnings;

  Box bounds() const;
  uint32_t surfaceCount() const { return static_cast<uint32_t>(shapes.size() + mesh.triangles.size()); }
  bool isMeshSurface(uint32_t id) const { return id >= shapes.size(); }
  // The smoothed shading normal of surface `id` at x (TriangleMesh::smoothNormal), nullopt for a
  // flat surface; a branch on an empty vector where nothing is smoothed.
  std::optional<Vec3> smoothNormal(uint32_t id, const Vec3& x) const {
    if (mesh.cornerNormals.empty() || id < shapes.size()) return std::nullopt;
    return mesh.smoothNormal(id - static_cast<uint32_t>(shapes.size()), x);
  }
  // Surface `id` as a Shape: a copy of shapes[id], or a mesh triangle as a kTriangle Shape
  // (a = v0, b = v1 − v0, c = v2 − v0, n = unit b × c, its run's material).
  Shape surface(uint32_t id) const;
  uint32_t surfaceMaterial(uint32_t id) const;
  const std::string& surfaceName(uint32_t id) const;
  // intersectShape for surface `id`; a mesh triangle gives the value a kTriangle Shape of the
  // same vertices gives, to the last bit (the same intersectTriangle on the same doubles).
  // 6 parameters: a ray query's own (surface, ray, interval, result).
  bool intersectSurface(uint32_t id, const Vec3& o, const Vec3& dir, double tMin, double tMax, double& t) const {
    if (id < shapes.size()) return intersectShape(shapes[id], vertices, o, dir, tMin, tMax, t);
    const auto& tri = mesh.triangles[id - shapes.size()];
    const Vec3& v0 = mesh.vertices[tri[0]];
    return intersectTriangle(v0, mesh.vertices[tri[1]] - v0, mesh.vertices[tri[2]] - v0, o, dir, tMin, tMax, t);
  }
  // Adds a material and returns its index.
  uint32_t addMaterial(Material m);
  // Adds a polygon (≥ 3 vertices, planar; checked by the reader) or triangle; returns its index.
  uint32_t addPolygon(const std::vector<Vec3>& pts, uint32_t material, const std::string& name = {});
  uint32_t addSphere(const Vec3& centre, double radiusM, uint32_t material, bool inward = false,
                     const std::string& name = {});
  uint32_t addRing(const Vec3& centre, const Vec3& normal, double innerM, double outerM, uint32_t material,
                   const std::string& name = {});
  // 7 parameters: a cone's geometry (two ends, two radii, side), material and name.
  uint32_t addCone(const Vec3& a, const Vec3& b, double ra, double rb, uint32_t material, bool inward = false,
                   const std::string& name = {});
  void addDistant(const Vec3& dir, double fullAngleDeg, uint32_t material, const std::string& name = {});
};

// Newell's normal of a polygon (not normalised; its length is twice the area).
Vec3 newellNormal(const std::vector<Vec3>& pts);

}  // namespace candela
