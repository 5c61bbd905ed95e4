#include "engine/embree_accelerator.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace candela {

// One query's state, handed to Embree's callbacks through the intersection context (Embree's
// documented extension pattern: the RTCIntersectContext is the first member and the callbacks
// cast its address back). It lives on the caller's stack: no allocation per ray, and concurrent
// queries share nothing.
struct EmbreeAccelerator::Query {
  RTCIntersectContext context;
  const EmbreeAccelerator* self = nullptr;
  Vec3 o{0.0}, d{0.0};  // the double ray, in scene coordinates
  double tMin = 0.0, tMax = 0.0;
  uint32_t skipA = kNoShape, skipB = kNoShape;
  bool exact = false;  // triangle candidates must also pass intersectShape (the context filter)
  // The last user-geometry hit accepted, with its double t (Embree keeps only a float).
  uint32_t userShape = kNoShape;
  double userT = 0.0;
};

// Embree's callbacks; a friend of EmbreeAccelerator for its tables. Every query is a single
// ray (rtcIntersect1/rtcOccluded1), so the callbacks see N = 1.
struct EmbreeCallbacks {
  using Query = EmbreeAccelerator::Query;

  static Query& query(RTCIntersectContext* c) { return *reinterpret_cast<Query*>(c); }
  static bool skipped(const Query& q, uint32_t s) { return s == q.skipA || s == q.skipB; }

  // Context filter, run on triangle candidates only when needed (skips given or exact mode).
  static void filter(const RTCFilterFunctionNArguments* args) {
    const Query& q = query(args->context);
    const EmbreeAccelerator& self = *q.self;
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] == 0) continue;
      const uint32_t s =
          self.toShape(RTCHitN_geomID(args->hit, args->N, i), RTCHitN_primID(args->hit, args->N, i));
      double t;
      if (skipped(q, s) ||
          (q.exact && !self.scene_.intersectSurface(s, q.o, q.d, q.tMin, q.tMax, t)))
        args->valid[i] = 0;
    }
  }

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const auto& self = *static_cast<const EmbreeAccelerator*>(args->geometryUserPtr);
    const uint32_t s = self.userShapes_[args->primID];
    const Box b = shapeBounds(self.scene_.shapes[s], self.scene_.vertices);
    const Vec3 lo = b.lo - self.centre_, hi = b.hi - self.centre_;
    // Rounded outwards and padded by a few float ulps of the coordinates, so that Embree's float
    // box tests can never cull a shape the double test would hit.
    const double pad = 0x1p-20 * std::max({1.0, std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x),
                                           std::abs(hi.y), std::abs(hi.z)});
    auto down = [&](double x) { return std::nextafter(static_cast<float>(x - pad), -INFINITY); };
    auto up = [&](double x) { return std::nextafter(static_cast<float>(x + pad), INFINITY); };
    RTCBounds& o = *args->bounds_o;
    o.lower_x = down(lo.x), o.lower_y = down(lo.y), o.lower_z = down(lo.z);
    o.upper_x = up(hi.x), o.upper_y = up(hi.y), o.upper_z = up(hi.z);
  }

  static void userIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->valid[0] == 0) return;
    Query& q = query(args->context);
    const EmbreeAccelerator& self = *q.self;
    const uint32_t s = self.userShapes_[args->primID];
    if (skipped(q, s)) return;
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    float& tfar = RTCRayN_tfar(ray, args->N, 0);
    // Only nearer than the current nearest candidate, and never past the caller's tMax.
    const double hi = std::min(q.tMax, static_cast<double>(tfar));
    double t;
    if (!intersectShape(self.scene_.shapes[s], self.scene_.vertices, q.o, q.d, q.tMin, hi, t)) return;
    tfar = static_cast<float>(t);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    RTCHitN_Ng_x(hit, args->N, 0) = 0.0f;  // unused: the tracer asks shapeNormal
    RTCHitN_Ng_y(hit, args->N, 0) = 0.0f;
    RTCHitN_Ng_z(hit, args->N, 0) = 1.0f;
    RTCHitN_u(hit, args->N, 0) = 0.0f;
    RTCHitN_v(hit, args->N, 0) = 0.0f;
    RTCHitN_primID(hit, args->N, 0) = args->primID;
    RTCHitN_geomID(hit, args->N, 0) = args->geomID;
    RTCHitN_instID(hit, args->N, 0, 0) = args->context->instID[0];
    q.userShape = s;
    q.userT = t;
  }

  static void userOccluded(const RTCOccludedFunctionNArguments* args) {
    if (args->valid[0] == 0) return;
    const Query& q = query(args->context);
    const EmbreeAccelerator& self = *q.self;
    const uint32_t s = self.userShapes_[args->primID];
    if (skipped(q, s)) return;
    double t;
    if (intersectShape(self.scene_.shapes[s], self.scene_.vertices, q.o, q.d, q.tMin, q.tMax, t))
      RTCRayN_tfar(args->ray, args->N, 0) = -INFINITY;  // Embree's mark for "occluded"
  }

  static bool memoryMonitor(void* ptr, ssize_t bytes, bool /*post*/) {
    static_cast<EmbreeAccelerator*>(ptr)->embreeBytes_ += bytes;
    return true;
  }
};

namespace {


// The float ray Embree traverses: origin relative to the scene centre. tfar is widened by a few
// float ulps of the ray's extent so that a surface lying just before tMax in double is not lost
// to float rounding (the double test then decides); tnear is not widened, since a surface just
// past tMin is, within float tolerance, where the ray starts (documented in docs/performance.md).
void setRay(RTCRay& r, const Vec3& oRel, const Vec3& d, double tMin, double tMax) {
  r.org_x = static_cast<float>(oRel.x), r.org_y = static_cast<float>(oRel.y), r.org_z = static_cast<float>(oRel.z);
  r.dir_x = static_cast<float>(d.x), r.dir_y = static_cast<float>(d.y), r.dir_z = static_cast<float>(d.z);
  r.tnear = std::max(0.0f, static_cast<float>(tMin));
  const double scale = std::max({1.0, std::abs(oRel.x), std::abs(oRel.y), std::abs(oRel.z)});
  r.tfar = std::isfinite(tMax) ? static_cast<float>(tMax + 0x1p-18 * (scale + tMax)) : INFINITY;
  r.time = 0.0f;
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
}

}  // namespace

EmbreeAccelerator::EmbreeAccelerator(const Scene& scene, EmbreeOptions options) : scene_(scene) {
  const Box b = scene.bounds();
  if (!b.empty()) centre_ = b.center();

  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& s = scene.shapes[i];
    if (s.type != ShapeType::kTriangle) {
      userShapes_.push_back(i);
      continue;
    }
    triangleShapes_.push_back(i);
    for (const Vec3& v : {s.a, s.a + s.b, s.a + s.c}) {
      const Vec3 rel = v - centre_;
      for (int k = 0; k < 3; ++k) vertices_.push_back(static_cast<float>(rel[k]));
    }
  }
  vertices_.push_back(0.0f);  // Embree reads the last vertex with a 16-byte load
  indices_.resize(3 * triangleShapes_.size());
  for (uint32_t k = 0; k < indices_.size(); ++k) indices_[k] = k;

  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error("Embree: rtcNewDevice failed (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeCallbacks::memoryMonitor, this);
  rtcScene_ = rtcNewScene(device_);
  int flags = RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION;
  if (options.robust) flags |= RTC_SCENE_FLAG_ROBUST;
  if (options.compact) flags |= RTC_SCENE_FLAG_COMPACT;
  rtcSetSceneFlags(rtcScene_, static_cast<RTCSceneFlags>(flags));
  rtcSetSceneBuildQuality(rtcScene_, options.highQuality ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);

  if (!triangleShapes_.empty()) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices_.data(), 0, 3 * sizeof(float),
                               3 * triangleShapes_.size());
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices_.data(), 0, 3 * sizeof(uint32_t),
                               triangleShapes_.size());
    rtcSetGeometryBuildQuality(g, options.highQuality ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
    rtcCommitGeometry(g);
    triangleGeom_ = rtcAttachGeometry(rtcScene_, g);
    rtcReleaseGeometry(g);
  }
  if (!userShapes_.empty()) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(userShapes_.size()));
    rtcSetGeometryUserData(g, this);
    rtcSetGeometryBoundsFunction(g, &EmbreeCallbacks::bounds, this);
    rtcSetGeometryIntersectFunction(g, &EmbreeCallbacks::userIntersect);
    rtcSetGeometryOccludedFunction(g, &EmbreeCallbacks::userOccluded);
    rtcCommitGeometry(g);
    userGeom_ = rtcAttachGeometry(rtcScene_, g);
    rtcReleaseGeometry(g);
  }
  if (!scene.mesh.empty()) attachMesh(options);
  rtcCommitScene(rtcScene_);
  const RTCError e = rtcGetDeviceError(device_);
  if (e != RTC_ERROR_NONE) {  // the destructor will not run: release here
    rtcReleaseScene(rtcScene_);
    rtcReleaseDevice(device_);
    throw std::runtime_error("Embree: building the scene failed (error " + std::to_string(e) + ")");
  }
}

// The scene's compact mesh as one more Embree triangle geometry, attached last (the other
// geometries keep their ids): float vertices relative to the centre, one per mesh vertex, and
// the mesh's own index array shared with Embree (no copy); primID + meshBase_ is the surface id.
void EmbreeAccelerator::attachMesh(const EmbreeOptions& options) {
  const TriangleMesh& mesh = scene_.mesh;
  meshBase_ = static_cast<uint32_t>(scene_.shapes.size());
  meshVertices_.reserve(3 * mesh.vertices.size() + 1);
  for (const Vec3& v : mesh.vertices) {
    const Vec3 rel = v - centre_;
    for (int k = 0; k < 3; ++k) meshVertices_.push_back(static_cast<float>(rel[k]));
  }
  meshVertices_.push_back(0.0f);  // Embree reads the last vertex with a 16-byte load
  static_assert(sizeof(mesh.triangles[0]) == 3 * sizeof(uint32_t), "Embree reads the indices as UINT3");
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, meshVertices_.data(), 0,
                             3 * sizeof(float), mesh.vertices.size());
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(), 0,
                             3 * sizeof(uint32_t), mesh.triangles.size());
  rtcSetGeometryBuildQuality(g, options.highQuality ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
  rtcCommitGeometry(g);
  meshGeom_ = rtcAttachGeometry(rtcScene_, g);
  rtcReleaseGeometry(g);
}

EmbreeAccelerator::~EmbreeAccelerator() {
  if (rtcScene_) rtcReleaseScene(rtcScene_);
  if (device_) rtcReleaseDevice(device_);
}

bool EmbreeAccelerator::nearest(Query& q, bool exact, RayHit& hit) const {
  q.exact = exact;
  q.userShape = kNoShape;
  // Without skips the fast pass runs no filter at all (the context filter is per query).
  q.context.filter = (exact || q.skipA != kNoShape || q.skipB != kNoShape) ? &EmbreeCallbacks::filter : nullptr;
  RTCRayHit rh;
  setRay(rh.ray, q.o - centre_, q.d, q.tMin, q.tMax);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &q.context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  const uint32_t s = toShape(rh.hit.geomID, rh.hit.primID);
  if (rh.hit.geomID == userGeom_) {  // already the double result
    hit.t = q.userT;
    hit.shape = s;
    return true;
  }
  double t;
  if (scene_.intersectSurface(s, q.o, q.d, q.tMin, q.tMax, t)) {
    hit.t = t;
    hit.shape = s;
    return true;
  }
  // The float test hit a triangle the double test misses (the ray passes within float
  // tolerance of its edge, or its t lies just outside (tMin, tMax)). Trace again with every
  // triangle candidate checked in double: Embree then walks on to the next surface. In exact
  // mode the filter has already checked, so this cannot recurse further.
  return exact ? false : nearest(q, true, hit);
}

bool EmbreeAccelerator::intersect(const Vec3& o, const Vec3& dir, double tMin, double tMax, RayHit& hit,
                                  uint32_t skipA, uint32_t skipB) const {
  if (!(tMax > tMin)) return false;
  Query q;
  rtcInitIntersectContext(&q.context);
  q.self = this;
  q.o = o, q.d = dir, q.tMin = tMin, q.tMax = tMax;
  q.skipA = skipA, q.skipB = skipB;
  return nearest(q, false, hit);
}

bool EmbreeAccelerator::occluded(const Vec3& o, const Vec3& dir, double tMin, double tMax, uint32_t skipA,
                                 uint32_t skipB) const {
  if (!(tMax > tMin)) return false;
  Query q;
  rtcInitIntersectContext(&q.context);
  q.self = this;
  q.o = o, q.d = dir, q.tMin = tMin, q.tMax = tMax;
  q.skipA = skipA, q.skipB = skipB;
  // Always exact: Embree stops at the first candidate the filter accepts, so this costs about
  // one double test per occluded ray, and the answer is the double test's.
  q.exact = true;
  q.context.filter = &EmbreeCallbacks::filter;
  RTCRay r;
  setRay(r, o - centre_, dir, tMin, tMax);
  rtcOccluded1(rtcScene_, &q.context, &r);
  return r.tfar == -INFINITY;
}

EmbreeStats EmbreeAccelerator::stats() const {
  EmbreeStats s;
  s.triangles = triangleShapes_.size() + scene_.mesh.triangles.size();
  s.userShapes = userShapes_.size();
  s.memoryBytes = static_cast<size_t>(std::max<int64_t>(0, embreeBytes_.load())) +
                  sizeof(float) * (vertices_.capacity() + meshVertices_.capacity()) +
                  sizeof(uint32_t) * indices_.capacity() +
                  sizeof(uint32_t) * (triangleShapes_.capacity() + userShapes_.capacity());
  return s;
}

}  // namespace candela
