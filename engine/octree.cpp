#include "engine/octree.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace candela {

namespace {

// Build-time tree: leaves keep growable lists; flattened into Octree's arrays afterwards.
struct BuildNode {
  int children = -1;  // index of the first of 8 children, or -1 for a leaf
  std::vector<uint32_t> items;
};

class Builder {
 public:
  Builder(const Scene& scene, const Box& cube, const OctreeOptions& opt) : scene_(scene), opt_(opt) {
    lo_ = cube.lo;
    size_ = cube.hi.x - cube.lo.x;
    nodes_.push_back({});
  }

  // The paper's AddSurface(cube, surface): a leaf takes the surface while it holds fewer than N
  // surfaces or is at the minimum size; otherwise it is split in eight and its surfaces (and the
  // new one) go to every child cube they overlap.
  void addSurface(int node, const Vec3& lo, double size, uint32_t surf, int depth) {
    maxDepth_ = std::max(maxDepth_, depth);
    if (nodes_[node].children < 0) {
      if (static_cast<int>(nodes_[node].items.size()) < opt_.maxSetSize || size * 0.5 < opt_.minCubeSizeM) {
        nodes_[node].items.push_back(surf);
        return;
      }
      std::vector<uint32_t> old;
      old.swap(nodes_[node].items);
      const int first = static_cast<int>(nodes_.size());
      nodes_.resize(nodes_.size() + 8);
      nodes_[node].children = first;
      for (uint32_t s : old) addToChildren(node, lo, size, s, depth);
    }
    addToChildren(node, lo, size, surf, depth);
  }

  void addToChildren(int node, const Vec3& lo, double size, uint32_t surf, int depth) {
    const double h = 0.5 * size;
    for (int c = 0; c < 8; ++c) {
      const Vec3 clo = lo + Vec3((c & 1) ? h : 0.0, (c & 2) ? h : 0.0, (c & 4) ? h : 0.0);
      if (overlaps(surf, clo, h)) addSurface(nodes_[node].children + c, clo, h, surf, depth + 1);
    }
  }

  // Surface `surf` (a shape or a mesh triangle) overlaps the cube [lo, lo + size]³.
  bool overlaps(uint32_t surf, const Vec3& lo, double size) const {
    if (surf < scene_.shapes.size()) return shapeOverlapsBox(scene_.shapes[surf], scene_.vertices, lo, size);
    return shapeOverlapsBox(scene_.surface(surf), scene_.vertices, lo, size);
  }

  const Scene& scene_;
  OctreeOptions opt_;
  Vec3 lo_;
  double size_;
  std::vector<BuildNode> nodes_;
  int maxDepth_ = 0;
};

}  // namespace

Octree::Octree(const Scene& scene, OctreeOptions options) : scene_(&scene) {
  Box b = scene.bounds();
  if (b.empty()) b = Box{Vec3(-1.0), Vec3(1.0)};
  const double size = std::max({b.size().x, b.size().y, b.size().z, 1e-6}) * (1.0 + 1e-6);
  const Vec3 c = b.center();
  cube_ = Box{c - Vec3(0.5 * size), c + Vec3(0.5 * size)};
  if (options.minCubeSizeM <= 0.0) options.minCubeSizeM = size / 4096.0;

  Builder builder(scene, cube_, options);
  meshBase_ = static_cast<uint32_t>(scene.shapes.size());
  for (uint32_t i = 0; i < scene.surfaceCount(); ++i)
    if (builder.overlaps(i, cube_.lo, size)) builder.addSurface(0, cube_.lo, size, i, 0);

  // Flatten breadth-first so that the eight children of a node are contiguous.
  nodes_.resize(1);
  std::vector<std::pair<int, uint32_t>> queue{{0, 0}};
  for (size_t q = 0; q < queue.size(); ++q) {
    const auto [bi, oi] = queue[q];
    const BuildNode& bn = builder.nodes_[bi];
    if (bn.children < 0) {
      nodes_[oi].first = static_cast<uint32_t>(items_.size());
      nodes_[oi].count = static_cast<uint32_t>(bn.items.size());
      items_.insert(items_.end(), bn.items.begin(), bn.items.end());
    } else {
      const uint32_t first = static_cast<uint32_t>(nodes_.size());
      nodes_[oi].first = first;
      nodes_[oi].count = kInternal;
      nodes_.resize(nodes_.size() + 8);
      for (int c = 0; c < 8; ++c) queue.emplace_back(bn.children + c, first + c);
    }
  }
  nodes_.shrink_to_fit();
  items_.shrink_to_fit();
  // Renumber primitives in depth-first order of their first leaf.
  shapeToLocal_.assign(scene.shapes.size(), kNoShape);
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t ni = stack.back();
    stack.pop_back();
    const Node& nd = nodes_[ni];
    if (nd.count == kInternal) {
      for (int c = 7; c >= 0; --c) stack.push_back(nd.first + c);
      continue;
    }
    for (uint32_t k = 0; k < nd.count; ++k) {
      const uint32_t sh = items_[nd.first + k];
      if (sh >= meshBase_) continue;  // mesh triangles keep their surface ids
      if (shapeToLocal_[sh] == kNoShape) {
        shapeToLocal_[sh] = static_cast<uint32_t>(localToShape_.size());
        localToShape_.push_back(sh);
      }
    }
  }
  for (uint32_t& it : items_)
    if (it < meshBase_) it = shapeToLocal_[it];
  triangles_.resize(localToShape_.size());
  isTriangle_.resize(localToShape_.size());
  for (size_t i = 0; i < localToShape_.size(); ++i) {
    const Shape& sh = scene.shapes[localToShape_[i]];
    isTriangle_[i] = sh.type == ShapeType::kTriangle;
    if (isTriangle_[i]) triangles_[i] = Triangle{sh.a, sh.b, sh.c};
  }
}

struct Octree::RayState {
  Vec3 o, d;
  double tMin, best;
  uint32_t hit = kNoShape;
  uint32_t skipA, skipB;
  // Mailbox: the last shapes tested along this ray; a shape spanning several voxels is tested
  // once (Amanatides & Woo 1987). A fixed array: no allocation per ray.
  // Direct-mapped on the primitive number: one compare per test.
  static constexpr int kMail = 16;
  uint32_t mail[kMail] = {kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape,
                          kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape, kNoShape};
  int mirror = 0;
  bool seen(uint32_t s) {
    uint32_t& slot = mail[s & (kMail - 1)];
    if (slot == s) return true;
    slot = s;
    return false;
  }
};

namespace {

using Octree_Triangle = Octree::Triangle;

inline bool hitTriangle(const Octree_Triangle& tri, const Vec3& o, const Vec3& d, double tMin, double tMax, double& t) {
  return intersectTriangle(tri.v0, tri.e1, tri.e2, o, d, tMin, tMax, t);
}

}  // namespace

// Revelles, Ureña & Lastra (2000), "An efficient parametric algorithm for octree traversal":
// with the ray mirrored so that every direction component is positive, a node is given by the
// slab distances (t0, t1) per axis; children's slabs are halves of these (additions only) and
// the next child follows from which mid-plane the ray leaves through first. Child bits here:
// x = 1, y = 2, z = 4; `r.mirror` maps a mirrored child to its stored index.
template <bool kAnyHit>
bool Octree::traverse(RayState& r, uint32_t ni, const Vec3& t0, const Vec3& t1) const {
  const double tEnter = std::max({t0.x, t0.y, t0.z});
  const double tExit = std::min({t1.x, t1.y, t1.z});
  if (tExit < r.tMin || tEnter > r.best || tEnter > tExit) return false;
  const Node node = nodes_[ni];
  if (node.count != kInternal) {
    const Shape* shapes = scene_->shapes.data();
    const VertexStore& vs = scene_->vertices;
    for (uint32_t k = 0; k < node.count; ++k) {
      const uint32_t s = items_[node.first + k];  // local number
      if (s == r.skipA || s == r.skipB || r.seen(s)) continue;
      double t;
      const bool h = s >= meshBase_  ? scene_->intersectSurface(s, r.o, r.d, r.tMin, r.best, t)
                     : isTriangle_[s] ? hitTriangle(triangles_[s], r.o, r.d, r.tMin, r.best, t)
                                      : intersectShape(shapes[localToShape_[s]], vs, r.o, r.d, r.tMin, r.best, t);
      if (h) {
        if (kAnyHit) return true;
        r.best = t;
        r.hit = s;
      }
    }
    // A hit inside this voxel is the nearest; one beyond it may yet be beaten by a later voxel.
    return !kAnyHit && r.hit != kNoShape && r.best <= tExit;
  }
  const Vec3 tm = 0.5 * (t0 + t1);
  // First child: the entry face is the slab entered last.
  int c = 0;
  if (t0.x >= t0.y && t0.x >= t0.z) {
    if (tm.y < t0.x) c |= 2;
    if (tm.z < t0.x) c |= 4;
  } else if (t0.y >= t0.z) {
    if (tm.x < t0.y) c |= 1;
    if (tm.z < t0.y) c |= 4;
  } else {
    if (tm.x < t0.z) c |= 1;
    if (tm.y < t0.z) c |= 2;
  }
  while (c < 8) {
    const Vec3 c0((c & 1) ? tm.x : t0.x, (c & 2) ? tm.y : t0.y, (c & 4) ? tm.z : t0.z);
    const Vec3 c1((c & 1) ? t1.x : tm.x, (c & 2) ? t1.y : tm.y, (c & 4) ? t1.z : tm.z);
    if (traverse<kAnyHit>(r, node.first + (c ^ r.mirror), c0, c1)) return true;
    // Next child: cross the nearest of the child's exit planes that is still inside this node.
    const double ex = (c & 1) ? 1e300 : c1.x, ey = (c & 2) ? 1e300 : c1.y, ez = (c & 4) ? 1e300 : c1.z;
    if (ex <= ey && ex <= ez) {
      c = (c & 1) ? 8 : c | 1;
    } else if (ey <= ez) {
      c = (c & 2) ? 8 : c | 2;
    } else {
      c = (c & 4) ? 8 : c | 4;
    }
    if (c < 8 && !kAnyHit && r.hit != kNoShape && r.best <= std::max({(c & 1) ? tm.x : t0.x, (c & 2) ? tm.y : t0.y,
                                                                        (c & 4) ? tm.z : t0.z}))
      return r.best <= tExit;
  }
  return false;
}

template <bool kAnyHit>
bool Octree::run(RayState& r) const {
  if (nodes_.empty()) return false;
  // Mirror the ray into the positive octant of directions about the cube's centre.
  const Vec3 centre = cube_.center();
  Vec3 om = r.o, dm = r.d;
  r.mirror = 0;
  for (int a = 0; a < 3; ++a) {
    if (dm[a] < 0.0) {
      om[a] = 2.0 * centre[a] - om[a];
      dm[a] = -dm[a];
      r.mirror |= 1 << a;
    }
    if (dm[a] < 1e-300) dm[a] = 1e-300;  // parallel to a slab: effectively infinite distances
  }
  const Vec3 inv = 1.0 / dm;
  const Vec3 t0 = (cube_.lo - om) * inv;
  const Vec3 t1 = (cube_.hi - om) * inv;
  return traverse<kAnyHit>(r, 0, t0, t1) || (!kAnyHit && r.hit != kNoShape);
}

bool Octree::intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, Hit& hit, uint32_t skipA,
                       uint32_t skipB) const {
  RayState r{o, dir, tMin, tMax, kNoShape, local(skipA), local(skipB)};
  if (!run<false>(r) || r.hit == kNoShape) return false;
  hit.t = r.best;
  hit.shape = r.hit >= meshBase_ ? r.hit : localToShape_[r.hit];
  return true;
}

bool Octree::occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA,
                      uint32_t skipB) const {
  RayState r{o, dir, tMin, tMax, kNoShape, local(skipA), local(skipB)};
  return run<true>(r);
}

OctreeStats Octree::stats() const {
  OctreeStats s;
  s.nodes = nodes_.size();
  s.items = items_.size();
  for (const Node& n : nodes_) s.leaves += (n.count != kInternal);
  s.memoryBytes = nodes_.size() * sizeof(Node) + items_.size() * sizeof(uint32_t) +
                  triangles_.size() * sizeof(Triangle) + isTriangle_.size() +
                  (localToShape_.size() + shapeToLocal_.size()) * sizeof(uint32_t);
  // Depth by walking down.
  std::function<int(uint32_t)> depth = [&](uint32_t i) -> int {
    if (nodes_[i].count != kInternal) return 0;
    int m = 0;
    for (int c = 0; c < 8; ++c) m = std::max(m, depth(nodes_[i].first + c));
    return m + 1;
  };
  if (!nodes_.empty()) s.depth = depth(0);
  return s;
}

}  // namespace candela
