// Wavefront OBJ geometry as Radiance's obj2rad reads it (Radiance src/cv/obj2rad.c and
// doc/man/man1/obj2rad.1): `v` vertices, `f` faces (v, v/vt, v//vn, v/vt/vn; negative indices
// count back from the last vertex), `g` groups, `o` object names, `usemtl` names, `\` line
// continuation. vt, vn, vp, s, usemap, mtllib and the rest are read past (mtllib with a warning:
// the .mtl's colours are not used, usemtl names are Radiance modifiers). Faces become triangles
// of the scene's compact mesh (Scene::mesh), or polygons (Shapes) when their material is a light
// source or a mirror (sampled as sources or virtual sources). docs/engine.md, "OBJ files".
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "engine/radiance/transform.h"
#include "engine/scene.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// One rule of an obj2rad mapping file (obj2rad -m): `modifier (Qualifier value) ... ;` with the
// qualifiers Material, Map, Group, Object and Face; a value is "a name", a number or an
// inclusive range [lo:hi]. The last rule a face satisfies names its modifier; a face matching no
// rule, or matching one whose modifier is void, is left out (obj2rad.1).
struct ObjRule {
  struct Condition {
    bool set = false;
    bool isName = false;
    std::string name;
    long lo = 0, hi = 0;
  };
  enum Qualifier { kMaterial, kMap, kGroup, kObject, kFace, kQualifiers };
  std::string modifier;
  Condition conditions[kQualifiers];
  FileLoc loc;
};

struct ObjMapping {
  std::vector<ObjRule> rules;
};

// Parses a mapping file; errors name its line ("map.txt:3: unknown qualifier 'Grp' ...").
ObjMapping parseObjMapping(std::string_view text, const std::string& fileName);
ObjMapping readObjMapping(const std::filesystem::path& path);

struct ObjReadOptions {
  const ObjMapping* mapping = nullptr;  // obj2rad -m rules (none: usemtl, group, default)
  std::string defaultModifier = "white";  // obj2rad's default material
  // A `mesh` primitive's non-void modifier: every face takes it (Radiance reference manual,
  // obj2mesh.1: "the given material will be substituted on all the mesh surfaces").
  std::optional<std::string> forcedModifier;
  RadTransform transform;  // applied to every vertex; a mirroring one reverses each face's order
  // The material a modifier name stands for (-1: void, the face is left out); throws an
  // InputError at `where` when the name is not defined. `why` says where the name came from.
  std::function<int(const std::string& name, const std::string& why, const FileLoc& where)> resolve;
  // Point-in-triangle tests the ear clipper may make for all of one file's faces (10^9: about
  // 3 s; faces shaped to cost just under the per-face bound of 10^8 loaded at 30 s/MB).
  uint64_t maxSplitTests = 1000000000;
};

struct ObjReadStats {
  size_t vertices = 0, faces = 0;
  size_t meshTriangles = 0;  // triangles added to Scene::mesh
  size_t shapes = 0;         // polygons or triangles added as Shapes (sources, mirrors)
  size_t nonplanar = 0;      // faces triangulated because they are not planar
  size_t degenerate = 0;     // faces left out: zero area (a warning, as obj2rad counts them)
  size_t dropped = 0;        // faces left out: void modifier or no mapping rule
  size_t smoothed = 0;       // mesh triangles smoothed by their corners' `vn` normals (as obj2rad)
};

// Appends the OBJ text's faces to `scene`; faces whose `vn` normals depart from the face's are
// smoothed as obj2rad smooths them (TriangleMesh::cornerNormals). Throws InputError(file:line)
// for a bad statement, a vertex index out of range, a face of fewer than 3 vertices, an
// undefined modifier, a coordinate beyond kMaxCoordinateM or more than 2³² − 2 vertices or
// triangles. Warnings (degenerate faces, mtllib) go to scene.inputWarnings.
ObjReadStats readObjText(std::string_view text, const std::string& fileName, Scene& scene, const ObjReadOptions& options);
ObjReadStats readObjFile(const std::filesystem::path& path, Scene& scene, const ObjReadOptions& options);

// ".obj" in any case.
bool isObjPath(const std::filesystem::path& path);

}  // namespace candela
