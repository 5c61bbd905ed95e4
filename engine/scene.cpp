#include "engine/scene.h"

#include <algorithm>
#include <cmath>

namespace candela {

Vec3 newellNormal(const std::vector<Vec3>& pts) {
  Vec3 n(0.0);
  for (size_t i = 0; i < pts.size(); ++i) n += glm::cross(pts[i], pts[(i + 1) % pts.size()]);
  return n;
}

Box Scene::bounds() const {
  Box b;
  for (const Shape& s : shapes) b.extend(shapeBounds(s, vertices));
  for (const auto& t : mesh.triangles)
    for (uint32_t v : t) b.extend(mesh.vertices[v]);
  return b;
}

const TriangleMesh::Run& TriangleMesh::runOf(uint32_t tri) const {
  const auto it = std::upper_bound(runs.begin(), runs.end(), tri,
                                   [](uint32_t t, const Run& r) { return t < r.firstTriangle; });
  return *(it - 1);
}

std::optional<Vec3> TriangleMesh::smoothNormal(uint32_t tri, const Vec3& x) const {
  if (tri >= cornerNormals.size() || cornerNormals[tri][0] == kNoCornerNormal) return std::nullopt;
  const auto& t = triangles[tri];
  const Vec3 a = vertices[t[0]], e1 = vertices[t[1]] - a, e2 = vertices[t[2]] - a, d = x - a;
  const Vec3 n = glm::cross(e1, e2);
  const double nn = glm::dot(n, n);
  if (!(nn > 0.0)) return std::nullopt;
  // Barycentric coordinates from the sub-triangles' areas (signed, along n).
  const double w1 = glm::dot(glm::cross(d, e2), n) / nn, w2 = glm::dot(glm::cross(e1, d), n) / nn;
  const auto& c = cornerNormals[tri];
  const Vec3 s = (1.0 - w1 - w2) * normals[c[0]] + w1 * normals[c[1]] + w2 * normals[c[2]];
  const double l = glm::length(s);
  if (!(l > 0.0)) return std::nullopt;
  const Vec3 u = s / l;
  return glm::dot(u, n) >= 0.0 ? u : -u;  // on the front's side, as the texture leaves it
}

size_t TriangleMesh::memoryBytes() const {
  size_t n = vertices.capacity() * sizeof(Vec3) + triangles.capacity() * sizeof(triangles[0]) +
             runs.capacity() * sizeof(Run) + names.capacity() * sizeof(std::string) +
             normals.capacity() * sizeof(Vec3) + cornerNormals.capacity() * sizeof(cornerNormals[0]);
  for (const std::string& s : names) n += s.capacity();
  return n;
}

Shape Scene::surface(uint32_t id) const {
  if (id < shapes.size()) return shapes[id];
  const uint32_t k = id - static_cast<uint32_t>(shapes.size());
  const auto& tri = mesh.triangles[k];
  Shape s;
  s.type = ShapeType::kTriangle;
  s.material = mesh.runOf(k).material;
  s.a = mesh.vertices[tri[0]];
  s.b = mesh.vertices[tri[1]] - s.a;
  s.c = mesh.vertices[tri[2]] - s.a;
  s.n = glm::normalize(glm::cross(s.b, s.c));
  return s;
}

uint32_t Scene::surfaceMaterial(uint32_t id) const {
  if (id < shapes.size()) return shapes[id].material;
  return mesh.runOf(id - static_cast<uint32_t>(shapes.size())).material;
}

const std::string& Scene::surfaceName(uint32_t id) const {
  static const std::string kNone;
  if (id < shapes.size()) return id < shapeNames.size() ? shapeNames[id] : kNone;
  return mesh.names[mesh.runOf(id - static_cast<uint32_t>(shapes.size())).name];
}

uint32_t Scene::addMaterial(Material m) {
  deriveMaterial(m);
  materials.push_back(std::move(m));
  return static_cast<uint32_t>(materials.size() - 1);
}

uint32_t Scene::addPolygon(const std::vector<Vec3>& pts, uint32_t material, const std::string& name) {
  Shape s;
  s.material = material;
  s.n = glm::normalize(newellNormal(pts));
  if (pts.size() == 3) {
    s.type = ShapeType::kTriangle;
    s.a = pts[0];
    s.b = pts[1] - pts[0];
    s.c = pts[2] - pts[0];
  } else {
    s.type = ShapeType::kPolygon;
    // Plane offset from the centroid: the best plane for slightly non-planar input.
    Vec3 centroid(0.0);
    for (const Vec3& p : pts) centroid += p;
    centroid /= static_cast<double>(pts.size());
    s.a = pts[0];
    s.d = glm::dot(s.n, centroid);
  }
  // Project onto the plane that drops the normal's dominant axis.
  const Vec3 an = glm::abs(s.n);
  const int drop = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  s.axisU = static_cast<uint8_t>((drop + 1) % 3);
  s.axisV = static_cast<uint8_t>((drop + 2) % 3);
  s.firstVertex = static_cast<uint32_t>(vertices.points.size());
  s.vertexCount = static_cast<uint32_t>(pts.size());
  for (const Vec3& p : pts) {
    vertices.points.push_back(p);
    vertices.projected.emplace_back(p[s.axisU], p[s.axisV]);
  }
  shapes.push_back(s);
  shapeNames.push_back(name);
  return static_cast<uint32_t>(shapes.size() - 1);
}

uint32_t Scene::addSphere(const Vec3& centre, double radiusM, uint32_t material, bool inward,
                          const std::string& name) {
  Shape s;
  s.type = ShapeType::kSphere;
  s.material = material;
  s.inward = inward;
  s.a = centre;
  s.r0 = radiusM;
  shapes.push_back(s);
  shapeNames.push_back(name);
  return static_cast<uint32_t>(shapes.size() - 1);
}

uint32_t Scene::addRing(const Vec3& centre, const Vec3& normal, double innerM, double outerM, uint32_t material,
                        const std::string& name) {
  Shape s;
  s.type = ShapeType::kRing;
  s.material = material;
  s.a = centre;
  s.n = glm::normalize(normal);
  s.r0 = innerM;
  s.r1 = outerM;
  shapes.push_back(s);
  shapeNames.push_back(name);
  return static_cast<uint32_t>(shapes.size() - 1);
}

uint32_t Scene::addCone(const Vec3& a, const Vec3& b, double ra, double rb, uint32_t material, bool inward,
                        const std::string& name) {
  Shape s;
  s.type = ShapeType::kCone;
  s.material = material;
  s.inward = inward;
  s.a = a;
  s.b = b;
  s.d = glm::length(b - a);
  s.n = (b - a) / s.d;
  s.r0 = ra;
  s.r1 = rb;
  shapes.push_back(s);
  shapeNames.push_back(name);
  return static_cast<uint32_t>(shapes.size() - 1);
}

void Scene::addDistant(const Vec3& dir, double fullAngleDeg, uint32_t material, const std::string& name) {
  DistantSource d;
  d.direction = glm::normalize(dir);
  d.halfAngleRad = degToRad(0.5 * fullAngleDeg);
  d.cosHalfAngle = std::cos(d.halfAngleRad);
  d.solidAngleSr = kTwoPi * (1.0 - d.cosHalfAngle);
  d.material = material;
  d.name = name;
  distant.push_back(d);
}

}  // namespace candela
