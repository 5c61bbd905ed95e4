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
      if (shapeOverlapsBox(scene_.shapes[surf], scene_.vertices, clo, h))
        addSurface(nodes_[node].children + c, clo, h, surf, depth + 1);
    }
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
  for (uint32_t i = 0; i < scene.shapes.size(); ++i)
    if (shapeOverlapsBox(scene.shapes[i], scene.vertices, cube_.lo, size)) builder.addSurface(0, cube_.lo, size, i, 0);

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
}

struct Octree::RayState {
  Vec3 o, d, inv;
  double tMin, best;
  uint32_t hit = kNoShape;
  uint32_t skipA, skipB;
};

template <bool kAnyHit>
bool Octree::traverse(RayState& r, uint32_t ni, const Vec3& centre, double half, double ta, double tb) const {
  const Node node = nodes_[ni];
  if (node.count != kInternal) {
    const Shape* shapes = scene_->shapes.data();
    const VertexStore& vs = scene_->vertices;
    for (uint32_t k = 0; k < node.count; ++k) {
      const uint32_t s = items_[node.first + k];
      if (s == r.skipA || s == r.skipB) continue;
      double t;
      if (intersectShape(shapes[s], vs, r.o, r.d, r.tMin, r.best, t)) {
        if (kAnyHit) return true;
        r.best = t;
        r.hit = s;
      }
    }
    // A hit inside this voxel is the nearest; one beyond it may yet be beaten by a later voxel.
    return !kAnyHit && r.hit != kNoShape && r.best <= tb;
  }
  // Parametric distances to the three mid-planes (Revelles, Ureña & Lastra 2000).
  double tm[3];
  int child = 0;
  for (int a = 0; a < 3; ++a) {
    if (r.d[a] != 0.0) {
      tm[a] = (centre[a] - r.o[a]) * r.inv[a];
      const bool crossed = tm[a] <= ta;
      if (crossed == (r.d[a] > 0.0)) child |= 1 << a;
    } else {
      tm[a] = std::numeric_limits<double>::infinity();
      if (r.o[a] >= centre[a]) child |= 1 << a;
    }
  }
  const double q = 0.5 * half;
  double t = ta;
  for (;;) {
    double tNext = tb;
    for (int a = 0; a < 3; ++a)
      if (tm[a] > t && tm[a] < tNext) tNext = tm[a];
    const Vec3 cc(centre.x + ((child & 1) ? q : -q), centre.y + ((child & 2) ? q : -q),
                  centre.z + ((child & 4) ? q : -q));
    if (traverse<kAnyHit>(r, node.first + child, cc, q, t, tNext)) return true;
    if (!kAnyHit && r.best <= tNext) return r.hit != kNoShape && r.best <= tb;
    if (tNext >= tb) return false;
    for (int a = 0; a < 3; ++a)
      if (tm[a] == tNext) child ^= 1 << a;
    t = tNext;
  }
}

template <bool kAnyHit>
bool Octree::run(RayState& r) const {
  if (nodes_.empty()) return false;
  double ta = r.tMin, tb = r.best;
  for (int a = 0; a < 3; ++a) {
    r.inv[a] = 1.0 / r.d[a];
    if (r.d[a] == 0.0) {
      if (r.o[a] < cube_.lo[a] || r.o[a] > cube_.hi[a]) return false;
      continue;
    }
    double t0 = (cube_.lo[a] - r.o[a]) * r.inv[a];
    double t1 = (cube_.hi[a] - r.o[a]) * r.inv[a];
    if (t0 > t1) std::swap(t0, t1);
    ta = std::max(ta, t0);
    tb = std::min(tb, t1);
  }
  if (ta > tb) return false;
  const double half = 0.5 * (cube_.hi.x - cube_.lo.x);
  return traverse<kAnyHit>(r, 0, cube_.center(), half, ta, tb) || (!kAnyHit && r.hit != kNoShape);
}

bool Octree::intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, Hit& hit, uint32_t skipA,
                       uint32_t skipB) const {
  RayState r{o, dir, Vec3(0.0), tMin, tMax, kNoShape, skipA, skipB};
  if (!run<false>(r) || r.hit == kNoShape) return false;
  hit.t = r.best;
  hit.shape = r.hit;
  return true;
}

bool Octree::occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA,
                      uint32_t skipB) const {
  RayState r{o, dir, Vec3(0.0), tMin, tMax, kNoShape, skipA, skipB};
  return run<true>(r);
}

OctreeStats Octree::stats() const {
  OctreeStats s;
  s.nodes = nodes_.size();
  s.items = items_.size();
  for (const Node& n : nodes_) s.leaves += (n.count != kInternal);
  s.memoryBytes = nodes_.size() * sizeof(Node) + items_.size() * sizeof(uint32_t);
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
