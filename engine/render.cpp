#include "engine/render.h"

#include "base/rng.h"
#include "base/parallel.h"
#include "engine/fresnel.h"
#include "engine/integrator_direct.h"
#include "engine/integrator_path.h"
#include "engine/materials/family.h"
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/source_distribution.h"
#include "engine/trace_context.h"
#include "engine/random_streams.h"
#include "engine/irradiance_estimator.h"

#include <algorithm>
#include <optional>
#include <atomic>
#include <bit>
#include <cmath>

namespace candela {

namespace {

// Camera rays use streams far above any sensor point index, so that a view and a grid in the same
// run never share random numbers.
constexpr uint64_t kCameraStreamBase = streams::kCameraPixels.first;
constexpr uint64_t kIrradianceStreamBase = streams::kCameraIrradiance.first;

// Opaque and purely diffuse: all its reflected light is ρ E / π (no specular lobe, nothing
// transmitted), so the irradiance estimate may stand in for a path.
bool isMatteOpaque(const Material& m) {
  return familyOf(m).matteOpaque(m) && photopic(m.diffuseTransmittance) <= 0.0 &&
         photopic(m.specularTransmittance) <= 0.0;
}

struct PixelValue {
  Rgb radiance{0.0};
  double luminance = 0.0;
  double standardError = 0.0;
};

// The luminous opening of a luminaire hit by the ray (o, d) nearer than tMax: returns its
// luminance towards the ray's origin (RGB radiance, grey) and shortens tMax, or 0.
Rgb luminaireRadiance(const std::vector<LuminaireSource>& lums, const Vec3& o, const Vec3& d, double& tMax) {
  Rgb out(0.0);
  for (const LuminaireSource& l : lums) {
    if (l.widthM <= 0.0) continue;
    const double dn = glm::dot(d, l.axisZ);
    if (std::abs(dn) < 1e-9) continue;
    const double t = glm::dot(l.position - o, l.axisZ) / dn;
    // Within 1e-9 of tMax: the opening's own surface (opening_reflectance) in the same plane.
    if (!(t > 0.0) || t >= tMax * (1.0 + 1e-9)) continue;
    const Vec3 q = o + t * d - l.position;
    const double u = glm::dot(q, l.axisX), v = glm::dot(q, l.axisY);
    double area;
    if (l.circular) {
      const double r = 0.5 * l.widthM;
      if (u * u + v * v > r * r) continue;
      area = kPi * r * r;
    } else {
      if (std::abs(u) > 0.5 * l.widthM || std::abs(v) > 0.5 * l.lengthM) continue;
      area = l.widthM * l.lengthM;
    }
    // Mean luminance of the opening towards the eye: I / (A |cos|) in cd/m², as a grey radiance.
    const double lum = l.intensityCd(-d) / (area * std::abs(dn));
    out = Rgb(lum / kLumensPerWatt);
    tMax = t;
  }
  return out;
}

// A camera ray as the view's estimator follows it: specular events (mirror, thin glass,
// dielectric, trans's straight-on part) deterministically, splitting into both branches while
// each carries a useful share of the pixel; at a diffusely reflecting or transmitting surface
// ρ E / π (and τd E_back / π) from the sensor estimator's irradiance, and a glossy lobe from
// `glossySamples` paths. Paths elsewhere (and beyond the limits) as the path tracer's.
struct CameraRay {
  TraceContext& ctx;
  const TraceSettings& irradianceSettings;  // the irradiance estimates at surfaces seen
  const RenderSettings& render;
  bool showLuminaires = false;
  uint64_t nextStream = 0;  // the next irradiance estimate's random stream
  int estimatesLeft = 0;    // irradiance estimates this camera ray may still take
};

// Both branches of a specular event are followed while each carries at least this share of the
// camera ray (clear glass at normal incidence: 0.88 transmitted, 0.08 reflected, both followed;
// a reflection of a reflection, 0.006, is chosen by roulette: unbiased, rarely noisy in print).
constexpr double kSplitShare = 0.02;
// Specular events followed per branch before the path tracer takes over (it has its own cap).
constexpr int kMaxSpecularEvents = 16;
// Irradiance estimates per camera ray (each branch that meets a diffuse surface takes one); the
// irradiance streams of a camera ray are kMaxEstimates consecutive ones.
constexpr int kMaxEstimates = 32;

Rgb cameraRadiance(CameraRay& cr, const Vec3& o, const Vec3& d, uint32_t skip, double share, int events);
Rgb seenSurfaceRadiance(CameraRay& cr, const Vec3& o, const Vec3& d, uint32_t skip, const RayHit& h, double share,
                        int events);

// The path tracer's answer for the ray (o, d), as seen from the camera (sources count).
Rgb plainPath(CameraRay& cr, const Vec3& o, const Vec3& d, uint32_t skip) {
  PathState st;
  st.skip = skip;
  st.countSources = true;
  return pathRadiance(cr.ctx, o, d, st);
}

// A two-way specular event: weights wa, wb (RGB) of the branches (oa, da) and (ob, db). Both
// followed while each keeps kSplitShare of the camera ray; else one chosen by its photopic share.
Rgb specularSplit(CameraRay& cr, const Rgb& wa, const Vec3& oa, const Vec3& da, const Rgb& wb, const Vec3& ob,
                  const Vec3& db, uint32_t skip, double share, int events) {
  const double pa = photopic(wa), pb = photopic(wb);
  if (pa + pb <= 0.0) return Rgb(0.0);
  if (share * pa >= kSplitShare && share * pb >= kSplitShare)
    return wa * cameraRadiance(cr, oa, da, skip, share * pa, events + 1) +
           wb * cameraRadiance(cr, ob, db, skip, share * pb, events + 1);
  if (cr.ctx.rng.uniform() * (pa + pb) < pa)
    return wa * ((pa + pb) / pa) * cameraRadiance(cr, oa, da, skip, share * (pa + pb), events + 1);
  return wb * ((pa + pb) / pb) * cameraRadiance(cr, ob, db, skip, share * (pa + pb), events + 1);
}

// Light leaving a plastic, metal or trans surface at x towards the camera ray d: the diffuse
// parts from irradiance estimates, the straight-on transmission followed, the glossy lobe
// sampled. The decomposition is diffuseVertex's (engine/integrator_path.cpp), term by term.
// 10 parameters: the hit (material, point, direction, both normals, offset, shape) and the
// camera ray's state (its share and events).
Rgb surfaceRadiance(CameraRay& cr, const Material& m, const Vec3& x, const Vec3& d, const Vec3& nf, const Vec3& ns,
                    double off, uint32_t flatSkip, double share, int events) {
  const Tracer& tracer = cr.ctx.tracer;
  // Light received on the shading normal ns (a texture turns it), the points off the surface by nf.
  const bool textured = ns != nf;
  const Vec3 xf = x + off * nf, xb = x - off * nf;
  Rgb out(0.0);
  if (photopic(m.diffuseReflectance) > 0.0)
    out += m.diffuseReflectance * kInvPi * estimateIrradiance(tracer, xf, ns, cr.nextStream++, cr.irradianceSettings).irradiance;
  if (photopic(m.diffuseTransmittance) > 0.0)
    out += m.diffuseTransmittance * kInvPi *
           estimateIrradiance(tracer, xb, -ns, cr.nextStream++, cr.irradianceSettings).irradiance;
  const double pTs = photopic(m.specularTransmittance);
  if (pTs > 0.0) out += m.specularTransmittance * cameraRadiance(cr, xb, d, flatSkip, share * pTs, events + 1);
  if (photopic(m.specularReflectance) > 0.0) {
    // As the path tracer's glossyBounce: a sample carries the lobe's weight (ρ_s for the Ward
    // lobes), counts sources and is a bounce.
    const int n = m.roughness > 0.0 ? std::max(1, cr.render.glossySamples) : 1;
    PathState next;
    next.skip = flatSkip;
    next.countSources = true;
    next.diffuse = 1;
    Rgb sum(0.0);
    for (int k = 0; k < n; ++k) {
      Vec3 dir(0.0);
      if (familyOf(m).sampleLobe(m, d, ns, cr.ctx.rng, dir) && !(textured && glm::dot(dir, nf) <= 0.0))
        sum += familyOf(m).lobeWeight(m, d, ns, dir) * pathRadiance(cr.ctx, xf, dir, next);
    }
    out += sum / static_cast<double>(n);
  }
  return out;
}

// The radiance the camera ray (o, d) sees, `share` its photopic weight in the pixel so far and
// `events` the specular events on its way.
Rgb cameraRadiance(CameraRay& cr, const Vec3& o, const Vec3& d, uint32_t skip, double share, int events) {
  if (events > kMaxSpecularEvents) return plainPath(cr, o, d, skip);
  const Scene& scene = cr.ctx.tracer.scene();
  RayHit h;
  const bool hit = cr.ctx.intersect(o, d, 0.0, 1e300, h, skip);
  Rgb emitted(0.0);
  if (cr.showLuminaires) {
    double tMax = hit ? h.t : 1e300;
    emitted = luminaireRadiance(scene.luminaires, o, d, tMax);
    // An opening met before any surface is all the ray sees; met on its own opening surface
    // (opening_reflectance, in the same plane), its luminance plus what that surface reflects.
    if (photopic(emitted) > 0.0 && !(hit && tMax >= h.t * (1.0 - 1e-9))) return emitted;
  }
  if (!hit) return distantRadiance(cr.ctx, o, d, true, SkyMis{});  // seen, not sampled: no MIS weight
  return emitted + seenSurfaceRadiance(cr, o, d, skip, h, share, events);
}

// The radiance of the surface the camera ray (o, d) meets at h (cameraRadiance's part after
// the luminaires' openings).
Rgb seenSurfaceRadiance(CameraRay& cr, const Vec3& o, const Vec3& d, uint32_t skip, const RayHit& h, double share,
                        int events) {
  const Scene& scene = cr.ctx.tracer.scene();
  const Shape shape = scene.surface(h.shape);  // a shape or a mesh triangle
  const Material* m = &scene.materials[shape.material];
  const Vec3 x = o + h.t * d;
  const Vec3 ng = shapeNormal(shape, x);
  const bool front = glm::dot(d, ng) < 0.0;
  const Vec3 nf = front ? ng : -ng;
  const double off = Tracer::originOffset(x);
  const uint32_t flatSkip = isFlat(shape) ? h.shape : kNoShape;
  std::optional<Material> patternedHere;  // the hook's copy when patterns modify m
  m = materialAt(scene, *m, {x, d, ng, h.t}, cr.ctx.patternEval, cr.ctx.rng, patternedHere);
  if (!m) return cameraRadiance(cr, x - off * nf, d, flatSkip, share, events + 1);  // invisible here
  const MaterialFamily& family = familyOf(*m);
  // A proxy (BSDF with a thickness) shows the primary rays what lies behind it.
  if (events == 0 && family.passesPrimaryRays(*m)) return cameraRadiance(cr, x - off * nf, d, flatSkip, share, 0);
  switch (family.role()) {
    case HitRole::kEmit:
      if (!front) return Rgb(0.0);
      return m->pattern < 0 ? m->color : emittedRadiance(scene, *m, d, -glm::dot(d, nf));
    case HitRole::kAbsorb:
    case HitRole::kMix:  // resolved above
      return Rgb(0.0);
    case HitRole::kSpecular: {
      // Every specular part followed (or one chosen: specularSplit), scaled by what the surface
      // absorbs on the way.
      const SpecularSplit sp = family.splitSpecular(*m, {d, ng, nf, front, h.t});
      const double seen = sp.scaled ? share * photopic(sp.factor) : share;
      auto origin = [&](const SpecularSplit::Part& part) { return part.transmitted ? x - off * nf : x + off * nf; };
      Rgb value(0.0);
      if (sp.count == 1)
        value = cameraRadiance(cr, origin(sp.parts[0]), sp.parts[0].dir, flatSkip, seen, events + 1);
      else if (sp.count == 2)
        value = specularSplit(cr, sp.parts[0].weight, origin(sp.parts[0]), sp.parts[0].dir, sp.parts[1].weight,
                              origin(sp.parts[1]), sp.parts[1].dir, flatSkip, seen, events);
      return sp.scaled ? sp.factor * value : value;
    }
    case HitRole::kScatter:
      break;
  }
  // plastic, metal, trans. A material whose sources' light depends on its direction (plasfunc,
  // BRTDfunc's directional functions) has no irradiance to stand for it: the path tracer's answer.
  // A rough transmission's lobe (WGMDfunc) is the path tracer's too.
  if (cr.estimatesLeft < 2 || family.directionalSources(*m) || family.roughTransmission(*m))
    return plainPath(cr, o, d, skip);
  cr.estimatesLeft -= 2;  // at most two estimates (front and back)
  const std::optional<Vec3> smooth = scene.smoothNormal(h.shape, x);  // OBJ `vn`
  const Vec3 ns = smooth ? smoothShadingNormal(*m, *smooth, nf, front) : shadingNormal(*m, nf, front);
  return surfaceRadiance(cr, *m, x, d, nf, ns, off, flatSkip, share, events);
}

// Traces pixel (x, y): `spp` rays stratified over the pixel, from the pixel's own random stream.
// 8 parameters: the pixel, its camera, both settings (paths, seen surfaces) and the shared ray count.
PixelValue tracePixel(const Tracer& tracer, const Camera& cam, int x, int y, const TraceSettings& s,
                      const TraceSettings& irradianceSettings, const RenderSettings& r,
                      std::atomic<std::size_t>& rays) {
  const uint64_t pixel = static_cast<uint64_t>(y) * cam.width() + x;
  Rng rng(s.seed, kCameraStreamBase + pixel);
  // The pixel's camera rays share one context (its rays, scratch), as rayRadiance's own.
  TraceContext ctx(tracer, s, rng);
  const int n = std::max(1, r.samplesPerPixel);
  const int m = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))));
  const bool showLums = r.showLuminaires && !tracer.scene().luminaires.empty();
  Rgb sum(0.0);
  double y1 = 0.0, y2 = 0.0;
  int used = 0;
  for (int k = 0; k < n; ++k) {
    // m × m strata, the rest jittered over the whole pixel.
    double ju = rng.uniform(), jv = rng.uniform();
    if (k < m * m) {
      ju = ((k % m) + ju) / m;
      jv = ((k / m) + jv) / m;
    }
    const auto dir = cam.direction(x + ju, y + jv);
    if (!dir) continue;
    CameraRay cr{ctx, irradianceSettings, r, showLums,
                 kIrradianceStreamBase + (pixel * static_cast<uint64_t>(n) + k) * kMaxEstimates,
                 r.irradianceSamples > 0 ? kMaxEstimates : 0};
    Rgb value(0.0);
    // With antimatter the camera ray is a path (engine/antimatter.h: the clip set is carried by
    // paths; the seen surfaces' irradiance estimates would start without it).
    if (r.irradianceSamples > 0 && !tracer.hasAntimatter()) {
      value = cameraRadiance(cr, cam.position(), *dir, kNoShape, 1.0, 0);
    } else {
      // Plain paths: one per camera ray (the luminaires' openings drawn where the ray meets them).
      // An opening on its own surface (opening_reflectance) adds that surface's reflection.
      double tMax = 1e300;
      RayHit h;
      const bool hit = showLums && tracer.accelerator().intersect(cam.position(), *dir, 0.0, 1e300, h);
      if (hit) tMax = h.t;
      value = showLums ? luminaireRadiance(tracer.scene().luminaires, cam.position(), *dir, tMax) : Rgb(0.0);
      if (!(photopic(value) > 0.0) || (hit && tMax >= h.t * (1.0 - 1e-9)))
        value += plainPath(cr, cam.position(), *dir, kNoShape);
    }
    sum += value;
    const double l = luminanceFromRadiance(value);
    y1 += l;
    y2 += l * l;
    ++used;
  }
  rays.fetch_add(static_cast<std::size_t>(n), std::memory_order_relaxed);
  PixelValue p;
  if (used == 0) return p;
  p.radiance = sum / static_cast<double>(used);
  p.luminance = luminanceFromRadiance(p.radiance);
  if (used > 1) {
    const double mean = y1 / used;
    p.standardError = std::sqrt(std::max(0.0, (y2 / used - mean * mean) / (used - 1)));
  }
  return p;
}

// Lattice lines of a refinement level: multiples of `step`, and the last pixel.
std::vector<int> latticeLines(int size, int step) {
  std::vector<int> v;
  for (int c = 0; c < size; c += step) v.push_back(c);
  if (v.back() != size - 1) v.push_back(size - 1);
  return v;
}

// Index of the interval [lines[k], lines[k+1]] containing c (the first one when c is a line).
int intervalOf(const std::vector<int>& lines, int c) {
  const auto it = std::upper_bound(lines.begin(), lines.end(), c);
  const int k = static_cast<int>(it - lines.begin()) - 1;
  return std::clamp(k, 0, std::max(0, static_cast<int>(lines.size()) - 2));
}

bool isLine(const std::vector<int>& lines, int c) { return std::binary_search(lines.begin(), lines.end(), c); }

}  // namespace

LatticeInterval interpolationInterval(int size, int spacing, int c) {
  // latticeLines(size, spacing) and intervalOf, in closed form: the interval [k s, min((k+1) s,
  // size − 1)] holding c, and for the last pixel the last interval.
  LatticeInterval r;
  if (size <= 1) return r;
  if (c >= size - 1) {
    r.c0 = ((size - 2) / spacing) * spacing;
    r.c1 = size - 1;
  } else {
    r.c0 = (c / spacing) * spacing;
    r.c1 = std::min(r.c0 + spacing, size - 1);
  }
  r.f = r.c1 > r.c0 ? static_cast<double>(c - r.c0) / (r.c1 - r.c0) : 0.0;
  return r;
}

namespace {

// The four corners of pixel i's block on the lattice of spacing `spacing`, and their bilinear
// weights, in the order (x0, y0), (x1, y0), (x0, y1), (x1, y1).
struct Corners {
  std::size_t pixel[4];
  double weight[4];
};

Corners interpolationCorners(const Image& img, std::size_t i, int spacing) {
  const int x = static_cast<int>(i % img.width), y = static_cast<int>(i / img.width);
  const LatticeInterval ix = interpolationInterval(img.width, spacing, x), iy = interpolationInterval(img.height, spacing, y);
  const double fx = ix.f, fy = iy.f;
  return Corners{{img.index(ix.c0, iy.c0), img.index(ix.c1, iy.c0), img.index(ix.c0, iy.c1), img.index(ix.c1, iy.c1)},
                 {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}};
}

}  // namespace

// About 130 lines: the coarse pass and the refinement passes share the lattice, the image and the
// trace/store lambdas; a split would pass all of them.
Image renderView(const Tracer& tracer, const View& view, const TraceSettings& settings, int threads,
                 const RenderSettings& render, const RenderProgress& progress, const Distribution& distribution) {
  const Camera cam(view);
  // The tracer counts diffuse reflections along a path, and the surface a camera ray meets is the
  // first: with N + 1, an image shows the light of N interreflections, as a grid computed with
  // `--bounces N` does (N = 0: direct light on the surfaces seen).
  TraceSettings s = settings;
  s.maxBounces = settings.maxBounces + 1;
  // The irradiance at a surface seen counts its N bounces from there, as a sensor does.
  TraceSettings si = settings;
  si.hemisphereSamples = std::max(1, render.irradianceSamples);
  si.lightSamples = std::max(1, render.irradianceLightSamples);
  si.firstBounceSplit = 1;
  Image img;
  img.width = cam.width();
  img.height = cam.height();
  const std::size_t total = static_cast<std::size_t>(img.width) * img.height;
  img.radiance.assign(total, glm::vec3(0.0f));
  img.luminance.assign(total, 0.0f);
  img.standardError.assign(total, 0.0f);
  img.inside.assign(total, 0);
  img.traced.assign(total, 0);
  img.interpolationLevel.assign(total, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) img.inside[img.index(x, y)] = cam.pixelDirection(x, y) ? 1 : 0;

  int step = 1;
  while (step * 2 <= std::max(1, render.coarseStep)) step *= 2;

  std::atomic<std::size_t> rays{0}, settled{0};
  auto report = [&](std::size_t n) {
    if (progress) progress(settled.fetch_add(n, std::memory_order_relaxed) + n, total);
  };
  auto store = [&](std::size_t i, const PixelValue& p) {
    img.radiance[i] = glm::vec3(p.radiance);
    img.luminance[i] = static_cast<float>(p.luminance);
    img.standardError[i] = static_cast<float>(p.standardError);
  };
  // The pixels of a band of a pass, shared between the processes: the next pass's refinement
  // reads them (kShared). The last pass's pixels steer nothing (its interpolated pixels come from
  // the lattice before it), so they go to the outputs only (kResult: shards split them).
  std::vector<PixelValue> values;
  auto traceList = [&](const std::vector<std::size_t>& list, ItemUse use) {
    values.assign(list.size(), PixelValue{});
    distributedFill(distribution, values, use, threads, [&](std::size_t k, PixelValue& v) {
      const std::size_t i = list[k];
      const int x = static_cast<int>(i % img.width), y = static_cast<int>(i / img.width);
      if (img.inside[i]) v = tracePixel(tracer, cam, x, y, s, si, render, rays);
      report(1);
    });
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (img.inside[list[k]]) store(list[k], values[k]);
      img.traced[list[k]] = 1;
    }
  };
  // Pixels interpolated from the lattice of spacing 2^fromLevel (settled before this pass).
  auto interpolate = [&](const std::vector<std::size_t>& list, int fromLevel) {
    for (std::size_t i : list) {
      if (!img.inside[i]) {
        store(i, PixelValue{});
        continue;
      }
      const Corners c = interpolationCorners(img, i, 1 << fromLevel);
      PixelValue p;
      for (int k = 0; k < 4; ++k) {
        p.radiance += c.weight[k] * Rgb(img.radiance[c.pixel[k]]);
        p.standardError += c.weight[k] * img.standardError[c.pixel[k]];
      }
      p.luminance = luminanceFromRadiance(p.radiance);
      img.interpolationLevel[i] = static_cast<uint8_t>(fromLevel);
      store(i, p);
    }
    report(list.size());
  };
  // A pass's pixels in bands of whole lattice rows of at least pixelsPerFill pixels (one band
  // for images of up to that many), each band traced and interpolated before the next is listed.
  std::vector<std::size_t> toTrace, toInterpolate;
  auto bandFull = [&] { return toTrace.size() + toInterpolate.size() >= std::max<std::size_t>(1, render.pixelsPerFill); };

  // Pass 0: the coarse lattice.
  std::vector<int> xs = latticeLines(img.width, step), ys = latticeLines(img.height, step);
  const ItemUse coarseUse = step > 1 ? ItemUse::kShared : ItemUse::kResult;
  for (std::size_t r = 0; r < ys.size(); ++r) {
    for (int x : xs) toTrace.push_back(img.index(x, ys[r]));
    if (bandFull() || r + 1 == ys.size()) {
      traceList(toTrace, coarseUse);
      toTrace.clear();
    }
  }

  // Refinement: halve the lattice spacing; the new pixels of a block whose corners disagree are
  // traced, the others interpolated bilinearly from the corners.
  while (step > 1) {
    const int half = step / 2;
    const std::vector<int> nxs = latticeLines(img.width, half), nys = latticeLines(img.height, half);
    const int bw = std::max(1, static_cast<int>(xs.size()) - 1), bh = std::max(1, static_cast<int>(ys.size()) - 1);
    std::vector<uint8_t> busy(static_cast<std::size_t>(bw) * bh, 0);
    for (int by = 0; by < bh; ++by)
      for (int bx = 0; bx < bw; ++bx) {
        const int x0 = xs[bx], x1 = xs[std::min<std::size_t>(bx + 1, xs.size() - 1)];
        const int y0 = ys[by], y1 = ys[std::min<std::size_t>(by + 1, ys.size() - 1)];
        const std::size_t c[4] = {img.index(x0, y0), img.index(x1, y0), img.index(x0, y1), img.index(x1, y1)};
        double lo = 1e300, hi = -1e300, mean = 0.0, se = 0.0;
        int in = 0;
        for (std::size_t i : c) {
          const double l = img.luminance[i];
          lo = std::min(lo, l);
          hi = std::max(hi, l);
          mean += 0.25 * l;
          se = std::max(se, static_cast<double>(img.standardError[i]));
          in += img.inside[i];
        }
        const bool edge = in != 0 && in != 4;  // the fisheye's circle crosses the block
        // Corners too noisy to tell whether the block varies (standard error above the threshold)
        // are refined as well: interpolating noise would print the lattice into the image.
        const bool noisy = se > render.refineThreshold * mean;
        busy[static_cast<std::size_t>(by) * bw + bx] =
            edge || noisy || hi - lo > render.refineThreshold * mean + render.noiseAllowance * std::sqrt(2.0) * se;
      }
    const ItemUse use = half > 1 ? ItemUse::kShared : ItemUse::kResult;
    for (std::size_t r = 0; r < nys.size(); ++r) {
      const int y = nys[r];
      for (int x : nxs) {
        const bool oldX = isLine(xs, x), oldY = isLine(ys, y);
        if (oldX && oldY) continue;
        // Every block of the old lattice that contains the pixel (two along a shared edge).
        bool anyBusy = false;
        const int kx = intervalOf(xs, x), ky = intervalOf(ys, y);
        for (int dy = (oldY && ky > 0 && ys[ky] == y) ? -1 : 0; dy <= 0; ++dy)
          for (int dx = (oldX && kx > 0 && xs[kx] == x) ? -1 : 0; dx <= 0; ++dx)
            anyBusy = anyBusy || busy[static_cast<std::size_t>(ky + dy) * bw + (kx + dx)];
        (anyBusy ? toTrace : toInterpolate).push_back(img.index(x, y));
      }
      // A band's pixels read only the old lattice: bands are independent within a pass.
      if (bandFull() || r + 1 == nys.size()) {
        traceList(toTrace, use);
        interpolate(toInterpolate, std::countr_zero(static_cast<unsigned>(step)));  // log2 step
        toTrace.clear();
        toInterpolate.clear();
      }
    }
    xs = nxs;
    ys = nys;
    step = half;
  }

  for (uint8_t t : img.traced) img.tracedPixels += t;
  img.cameraRays = rays.load();
  img.samplesPerPixel = std::max(1, render.samplesPerPixel);
  return img;
}

double meanStandardError(const Image& img, const PixelWeight& weight) {
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height;
  if (img.samplesPerPixel < 2 || img.standardError.size() != n || img.interpolationLevel.size() != n)
    return std::nan("");
  double total = 0.0;
  int levels = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total += weight(i);
    levels = std::max<int>(levels, img.interpolationLevel[i]);
  }
  if (!(total > 0.0)) return std::nan("");
  // Each pixel's coefficient in the mean; an interpolated pixel's passes to its corners, the
  // finest level first (a level's corners were settled before it). A pixel's coefficient comes
  // only from the coarse blocks around it (corners are in the pixel's own block of every coarser
  // lattice), so bands of rows are done one at a time with a margin of one coarse spacing: the
  // same sums in the same order as over the whole image, in a band's memory (float, 4 B a pixel).
  const int spacing = 1 << levels;
  constexpr int kBandRows = 256;
  std::vector<float> c;
  double variance = 0.0;
  for (int y0 = 0; y0 < img.height; y0 += kBandRows) {
    const int y1 = std::min(img.height, y0 + kBandRows);
    const int w0 = std::max(0, y0 - spacing), w1 = std::min(img.height, y1 + spacing);
    const std::size_t first = img.index(0, w0), last = img.index(0, w1);  // the window's pixels
    c.assign(last - first, 0.0f);
    for (std::size_t i = first; i < last; ++i) c[i - first] = static_cast<float>(weight(i));
    for (int level = 1; level <= levels; ++level)
      for (std::size_t i = last; i-- > first;) {
        if (img.interpolationLevel[i] != level) continue;
        const double ci = c[i - first];
        c[i - first] = 0.0f;
        const Corners k = interpolationCorners(img, i, 1 << level);
        for (int j = 0; j < 4; ++j)
          if (k.pixel[j] >= first && k.pixel[j] < last)  // corners outside feed pixels outside the band
            c[k.pixel[j] - first] = static_cast<float>(c[k.pixel[j] - first] + k.weight[j] * ci);
      }
    for (std::size_t i = img.index(0, y0); i < img.index(0, y1); ++i)
      if (img.traced[i]) {
        const double ci = c[i - first], se = img.standardError[i];
        variance += ci * ci * se * se;
      }
  }
  return std::sqrt(variance) / total;
}

ViewGeometry::ViewGeometry(const View& view) : cam_(view) {}

void ViewGeometry::operator()(std::size_t i, Vec3& directionView, double& solidAngleSr) const {
  const int x = static_cast<int>(i % cam_.width()), y = static_cast<int>(i / cam_.width());
  const auto d = cam_.pixelDirection(x, y);
  if (!d) {
    directionView = Vec3(0.0);
    solidAngleSr = 0.0;
    return;
  }
  directionView = Vec3(glm::dot(*d, cam_.right()), glm::dot(*d, cam_.up()), glm::dot(*d, cam_.forward()));
  solidAngleSr = cam_.pixelSolidAngleSr(x, y);
}

std::vector<SeenLuminaire> seenLuminaires(const Tracer& tracer, const Vec3& eye, const Vec3& viewDirIn) {
  const Vec3 viewDir = glm::normalize(viewDirIn);
  std::vector<SeenLuminaire> out;
  for (const LuminaireSource& l : tracer.scene().luminaires) {
    if (l.widthM <= 0.0) continue;
    const Vec3 toLum = l.position - eye;
    const double d = glm::length(toLum);
    if (!(d > 0.0)) continue;
    const Vec3 dir = toLum / d;
    const double cosView = glm::dot(dir, viewDir);
    if (cosView <= 0.0) continue;  // behind the observer
    const double area = l.circular ? 0.25 * kPi * l.widthM * l.widthM : l.widthM * l.lengthM;
    const double cosOpening = std::abs(glm::dot(dir, l.axisZ));
    if (cosOpening < 1e-9) continue;  // seen edge-on
    SeenLuminaire s;
    s.name = l.name;
    s.directionWorld = dir;
    s.distanceM = d;
    const double intensity = l.intensityCd(-dir);
    s.luminanceCdM2 = intensity / (area * cosOpening);
    s.solidAngleSr = area * cosOpening / (d * d);
    // Direct illuminance on the plane facing viewDir: the opening integrated as an area source
    // (each point carrying I/A, as the tracer's near field and the image do) by the midpoint rule
    // on 8 × 8 cells, with a shadow ray per cell; exact to O(cell²) whatever the distance, where
    // the point law I cos ι / d² is off by O((size/d)²) (1–3 % at 5 sizes).
    constexpr int kCells = 8;
    double e = 0.0, eFree = 0.0;
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j) {
        const double u = (i + 0.5) / kCells, w = (j + 0.5) / kCells;
        Vec3 q = l.position;
        if (l.circular) {
          const double r = 0.5 * l.widthM * std::sqrt(u), phi = kTwoPi * w;  // equal-area cells
          q += r * std::cos(phi) * l.axisX + r * std::sin(phi) * l.axisY;
        } else {
          q += (u - 0.5) * l.widthM * l.axisX + (w - 0.5) * l.lengthM * l.axisY;
        }
        const Vec3 toQ = q - eye;
        const double dq = glm::length(toQ);
        const Vec3 dirQ = toQ / dq;
        const double cosI = glm::dot(dirQ, viewDir);
        if (cosI <= 0.0 || !(dq > 0.0)) continue;
        const double de = l.intensityCd(-dirQ) / (kCells * kCells) * cosI / (dq * dq);
        eFree += de;
        e += de * photopic(tracer.transmittance(eye, dirQ, dq * (1.0 - 1e-9), kNoShape, l.openingShape));
      }
    s.illuminanceLux = e;
    s.transmittance = eFree > 0.0 ? e / eFree : 0.0;
    out.push_back(std::move(s));
  }
  return out;
}

double EyeLight::backgroundLuminanceCdM2() const { return std::max(verticalLux - directLuminaireLux, 0.0) / kPi; }

EyeLight eyeLight(const Tracer& tracer, const View& view, const TraceSettings& settings, uint64_t stream) {
  const Camera cam(view);
  EyeLight e;
  e.luminaires = seenLuminaires(tracer, cam.position(), cam.forward());
  for (SeenLuminaire& l : e.luminaires) {
    const Vec3& d = l.directionWorld;
    l.directionView = Vec3(glm::dot(d, cam.right()), glm::dot(d, cam.up()), glm::dot(d, cam.forward()));
    e.directLuminaireLux += l.illuminanceLux;
  }
  e.verticalLux = estimateIrradiance(tracer, cam.position(), cam.forward(), stream, settings).illuminanceLux();
  return e;
}

double luminanceToward(const Tracer& tracer, const Vec3& eye, const Vec3& target, const TraceSettings& settings,
                       uint64_t stream, int pathSamples) {
  const Vec3 d = glm::normalize(target - eye);
  RayHit h;
  if (!tracer.accelerator().intersect(eye, d, 0.0, 1e300, h)) return 0.0;
  const Shape shape = tracer.scene().surface(h.shape);  // a shape or a mesh triangle
  const Material& mat = tracer.scene().materials[shape.material];
  if (isMatteOpaque(mat) && !tracer.hasAntimatter()) {  // with antimatter: a path (below)
    const Vec3 x = eye + h.t * d;
    const Vec3 ng = shapeNormal(shape, x);
    const Vec3 nf = glm::dot(d, ng) < 0.0 ? ng : -ng;
    const Vec3 p = x + Tracer::originOffset(x) * nf;
    return luminanceFromRadiance(mat.diffuseReflectance * kInvPi * estimateIrradiance(tracer, p, nf, stream, settings).irradiance);
  }
  TraceSettings s = settings;
  s.maxBounces = settings.maxBounces + 1;  // as renderView: the surface seen is the first reflection
  Rng rng(settings.seed, stream);
  TraceContext ctx(tracer, s, rng);  // one context for the eye's paths, as a pixel's
  PathState eyeRay;
  eyeRay.countSources = true;
  Rgb sum(0.0);
  const int n = std::max(1, pathSamples);
  for (int k = 0; k < n; ++k) sum += pathRadiance(ctx, eye, d, eyeRay);
  return luminanceFromRadiance(sum / static_cast<double>(n));
}

uint32_t shapeToward(const Tracer& tracer, const Vec3& eye, const Vec3& target) {
  RayHit h;
  return tracer.accelerator().intersect(eye, glm::normalize(target - eye), 0.0, 1e300, h) ? h.shape : kNoShape;
}

Scene referenceSphereScene(const Scene& scene, const std::vector<uint32_t>& keepShapes, double luminanceCdM2) {
  Scene ref;
  ref.materials = scene.materials;
  ref.patterns = scene.patterns;  // materials index into them
  for (Material& m : ref.materials)
    if (m.isEmitter()) m.color = Rgb(0.0);
  ref.vertices = scene.vertices;  // shapes index into it: kept whole
  for (std::size_t k = 0; k < keepShapes.size(); ++k) {
    const uint32_t i = keepShapes[k];
    if (i >= scene.surfaceCount()) continue;
    if (std::find(keepShapes.begin(), keepShapes.begin() + k, i) != keepShapes.begin() + k) continue;  // listed twice
    // A mesh triangle is kept as a triangle Shape: under the uniform sphere a lone surface's
    // luminance does not depend on its extent, so the triangle seen stands for its object.
    ref.shapes.push_back(scene.surface(i));
    ref.shapeNames.push_back(scene.surfaceName(i));
  }
  Material sphere;
  sphere.type = MaterialType::kGlow;
  sphere.name = "reference_sphere";
  sphere.color = Rgb(luminanceCdM2 / kLumensPerWatt);
  ref.addDistant({0.0, 0.0, 1.0}, 360.0, ref.addMaterial(sphere), "reference_sphere");
  return ref;
}

}  // namespace candela
