#include "engine/radiance/polygon_reader.h"

#include "engine/polygon_split.h"

#include <sstream>

namespace candela {

namespace {

[[noreturn]] void fail(const RadPrimitive& p, const std::string& msg) { throw InputError(p.loc, msg); }

// The first two edges of the outline `pts` that cross each other seen along n
// (outlineSelfCrossing), or none; outlines of more than 4096 vertices are not checked (the pairs
// would cost more than the rest of the reading).
std::optional<std::pair<size_t, size_t>> selfCrossing(const std::vector<Vec3>& pts, const Vec3& n) {
  if (pts.size() < 4 || pts.size() > 4096) return std::nullopt;
  const Frame f = Frame::fromNormal(n);
  std::vector<glm::dvec2> q;
  for (const Vec3& v : pts) q.emplace_back(glm::dot(v, f.t), glm::dot(v, f.b));
  return outlineSelfCrossing(q);
}

}  // namespace

std::optional<Vec3> PolygonReader::add(const RadPrimitive& p, uint32_t mat, Scene& target, bool counted) {
  if (p.reals.size() % 3 != 0)
    fail(p, "polygon '" + p.name + "' needs a multiple of 3 real arguments, got " + std::to_string(p.reals.size()));
  const size_t nv = p.reals.size() / 3;
  if (nv < 3) fail(p, "polygon '" + p.name + "' needs at least 3 vertices, got " + std::to_string(nv));
  std::vector<Vec3> pts;
  for (size_t i = 0; i < nv; ++i) pts.emplace_back(p.reals[3 * i], p.reals[3 * i + 1], p.reals[3 * i + 2]);
  Box b;
  for (const Vec3& v : pts) b.extend(v);
  const double diameter = glm::length(b.size());
  const Vec3 nn = newellNormal(pts);
  const double area = 0.5 * glm::length(nn);
  if (!(diameter > 0.0) || area <= kDegenerateTolerance * diameter * diameter)
    fail(p, "polygon '" + p.name + "' is degenerate (zero area)");
  const Vec3 n = nn / (2.0 * area);
  size_t worst = 0;
  const double off = planeDeviation(pts, n, &worst);
  // Within 0.1 mm of its plane a polygon is read as it is (CAD exports' tessellation noise);
  // beyond, within 0.1 % of its size.
  if (off > kPlanarTolerance * diameter && off > kPlanarAbsoluteToleranceM) {
    std::ostringstream msg;
    msg << "polygon '" << p.name << "' is not planar: vertex " << (worst + 1) << " is " << off
        << " m from its plane (tolerance 0.1 mm, or 0.1 % of its size: " << kPlanarTolerance * diameter << " m)";
    if (policy_ == NonplanarPolicy::kRefuse)
      fail(p, msg.str() + "; run with --nonplanar triangulate to split it into triangles, with a warning");
    // A polygon that crosses itself (a bow tie) has no plane its deviation could be measured
    // from and no triangles that mean what the file meant: refused, saying so.
    if (const std::optional<std::pair<size_t, size_t>> cross = selfCrossing(pts, n))
      fail(p, "polygon '" + p.name + "' crosses itself: its edges " + std::to_string(cross->first + 1) + "-" +
                  std::to_string((cross->first + 1) % pts.size() + 1) + " and " + std::to_string(cross->second + 1) +
                  "-" + std::to_string((cross->second + 1) % pts.size() + 1) +
                  " cross, seen along its mean plane; it cannot be split into triangles that mean what the file "
                  "meant: fix it in the modelling tool");
    addTriangulated(p, pts, n, mat, target, counted, msg.str(), off);
    return std::nullopt;
  }
  target.addPolygon(pts, mat, p.name);
  return n;
}

// A non-planar polygon as the triangles of its outline seen along its Newell normal (ear
// clipping, engine/polygon_split.h): each vertex is kept where it is, so the surface passes
// through every vertex; each triangle is planar by construction.
void PolygonReader::addTriangulated(const RadPrimitive& p, const std::vector<Vec3>& pts, const Vec3& n, uint32_t mat,
                                    Scene& target, bool counted, const std::string& why, double off) {
  std::vector<std::array<uint32_t, 3>> tris;
  if (!splitPolygon(pts, n, tris))
    fail(p, why + "; it is too intricate to split into triangles (more than 10^8 point tests)");
  for (const auto& t : tris) target.addPolygon({pts[t[0]], pts[t[1]], pts[t[2]]}, mat, p.name);
  if (!counted) return;
  // One warning per file read (100 000 nearly planar quads gave 20 MB of warnings): the count,
  // and the worst polygon's message at its line.
  Triangulated& t = triangulated_[p.loc.file];
  ++t.polygons;
  t.triangles += tris.size();
  if (off >= t.worst) {
    t.worst = off;
    t.message = why + ": split into " + std::to_string(tris.size()) + " triangles";
    t.loc = p.loc;
  }
}

void PolygonReader::flush(std::vector<Warning>& out) {
  for (auto& [file, t] : triangulated_) {
    const std::string text = t.polygons == 1 ? t.message
                                             : std::to_string(t.polygons) + " polygons beyond the planarity tolerance "
                                               "were split into " + std::to_string(t.triangles) +
                                               " triangles; the farthest from its plane: " + t.message;
    out.push_back(Warning{"nonplanar_triangulated", text, t.loc});
  }
  triangulated_.clear();
}

}  // namespace candela
