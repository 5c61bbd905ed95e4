// A Radiance `polygon` read into a scene (Radiance reference manual, "Polygon"; the reader's
// rules, docs/engine.md): its vertices, its plane (a polygon within 0.1 mm, or 0.1 % of its size,
// of its mean plane is read as it is), and beyond that either a refusal or, under --nonplanar
// triangulate, the triangles of its outline seen along its Newell normal with one warning a file
// (a bow tie refused either way). Used by engine/radiance/reader.cpp.
#pragma once

#include "base/warning.h"
#include "engine/radiance/parse.h"
#include "engine/radiance/reader.h"
#include "engine/scene.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class PolygonReader {
 public:
  explicit PolygonReader(NonplanarPolicy policy) : policy_(policy) {}

  // Reads polygon p of material `mat` into `target`; InputError at p's line when it cannot be.
  // Returns its unit front normal when it is added as one planar polygon, nothing when it is
  // split into triangles. `counted`: its splitting counts towards the file's warning (false for
  // the scratch scene void surfaces are checked in).
  std::optional<Vec3> add(const RadPrimitive& p, uint32_t mat, Scene& target, bool counted);

  // The warning of each file whose polygons were split since the last call (the count, and the
  // polygon farthest from its plane at its line), appended to `out`.
  void flush(std::vector<Warning>& out);

 private:
  struct Triangulated {
    size_t polygons = 0, triangles = 0;
    double worst = -1.0;
    std::string message;
    FileLoc loc;
  };

  // A non-planar polygon as the triangles of its outline (polygon_reader.cpp).
  // 8 parameters: the primitive, its outline, normal and material, the target, whether it counts,
  // and the warning's text and deviation.
  void addTriangulated(const RadPrimitive& p, const std::vector<Vec3>& pts, const Vec3& n, uint32_t mat,
                       Scene& target, bool counted, const std::string& why, double off);

  NonplanarPolicy policy_;
  std::map<std::string, Triangulated> triangulated_;  // per file: the polygons split
};

}  // namespace candela
