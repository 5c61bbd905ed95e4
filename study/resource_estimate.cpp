#include "study/resource_estimate.h"

#include "engine/irradiance_cache.h"
#include "engine/lights.h"
#include "engine/materials/family.h"
#include "engine/portals.h"
#include "photometry/sky_patches.h"
#include "engine/render.h"
#include "engine/sampling.h"
#include "engine/tracer.h"
#include "engine/sensors.h"
#include "reports/plan_svg.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/compliance/en1838.h"
#include "study/compliance/en1838_grids.h"
#include "study/grids/prepared_grid.h"
#include "study/grids/sensor_grid.h"
#include "study/trace_options.h"
#include "engine/irradiance_estimator.h"
#include "base/parallel.h"
#include "engine/random_streams.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace candela {

namespace {

// The process before any case data: the executable, its libraries, TBB's and Embree's arenas
// (measured: peak RSS of `candela run` on a one-point case, docs/reliability.md).
constexpr uint64_t kProcessBytes = 16ull << 20;

// Text written per CSV row (8 numbers of up to ~12 characters) and the HTML plan's share of a
// cell (one SVG element, up to kMaxSvgCells of them); each is built in memory before it is written.
constexpr uint64_t kCsvRowBytes = 110;
constexpr uint64_t kReportBytesPerCell = 120;

// Ward's records are shared by the points near them: a plane grid at EN 12464-1 spacing gets
// fewer records than points. One record per point is the bound used (dense grids get fewer).
constexpr uint64_t kCacheBytesPerPoint = sizeof(IrradianceRecord) + 3 * sizeof(uint32_t);

// The expected number of diffuse vertices after the first hit at a mean reflectance of 0.5 under
// Russian roulette by albedo: ρ/(1 − ρ) = 1.
constexpr double kMeanReflectance = 0.5;
// What a sensor ray's cache lookup costs in rays, the records' own rays shared out: calibrated
// on cases/small-room's floor at draft (13 400 points) and normal (1 200 points) quality.
constexpr double kCacheRaysPerLookup = 8.0;
// Of those, the records' share (the rest: the lookup's visibility rays).
constexpr double kRecordShareRaysPerLookup = 6.0;
// A room's records at Ward's a = 0.2 per m² of the scene's bounding box: measured 46 (the sunlit
// office, 14 500 records, 312 m²) and 78 (cases/small-room, 4 886, 63 m²) at normal quality; and
// at most this share of the points' hemisphere rays (0.082 in the small room's 29 points).
constexpr double kRecordsPerSquareMetre = 60.0;
constexpr double kRecordsPerHemisphereRay = 0.08;
// Views: the share of pixels traced (the rest interpolated) and the rays of one hemisphere sample
// of a matte surface's irradiance estimate, measured on a 1024 × 1024 view of the small room
// (36.7 µs of CPU per camera ray with 64 samples) and the test views.
constexpr double kTracedPixelFraction = 0.7;
// A pixel of a band of a render pass: its index and, when traced, its value (radiance,
// luminance and standard error as doubles). Under MPI the values gathered from the other
// ranks arrive in place of this process's own.
constexpr uint64_t kBandBytesPerPixel = sizeof(std::size_t) + 5 * sizeof(double);
// The report's copy of a view's pictures is at most 2048 px across (study/view_study.cpp).
constexpr uint64_t kReportPicturePixels = 2048ull * 2048ull;
constexpr double kRaysPerIrradianceSample = 1.0;
// One path vertex's light selection evaluates every source's importance (engine/light_selection.h):
// a fraction of a ray's cost each, fitted to a 100 × 100 luminaire array over 6 points at draft
// (docs/reliability.md; it includes the records' own vertices, which few points share out badly).
// 0.2 until 2026-12-06; 0.09 since a luminaire's importance is inlined into the selection loop.
constexpr double kSelectionCostPerSource = 0.09;

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

struct SourceCounts {
  std::size_t sampled = 0, luminaires = 0;
};

SourceCounts countSources(const Scene& scene) {
  SourceCounts n;
  for (const Light& l : collectSampledSources(scene).lights)
    (l.kind == Light::Kind::kLuminaire ? n.luminaires : n.sampled) += 1;
  if (scene.sky) n.sampled += 1;
  return n;
}

}  // namespace

uint64_t ResourceEstimate::bytes() const {
  uint64_t b = baseBytes;
  for (const MemoryItem& m : memory) b += m.bytes;
  return b;
}

double ResourceEstimate::rays() const {
  double r = 0.0;
  for (const WorkStep& w : work) r += w.rays;
  return r;
}

double ResourceEstimate::seconds() const {
  return rays() / (raysPerSecondPerThread * std::max(1, threads));
}

double ResourceEstimate::seconds(const std::string& label) const {
  double r = 0.0;
  bool any = false;
  for (const WorkStep& w : work)
    if (w.label == label) {
      r += w.rays;
      any = true;
    }
  return any ? r / (raysPerSecondPerThread * std::max(1, threads)) : -1.0;
}

const MemoryItem* ResourceEstimate::largest() const {
  const MemoryItem* best = nullptr;
  for (const MemoryItem& m : memory)
    if (!best || m.bytes > best->bytes) best = &m;
  return best;
}

std::string formatBytes(uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024 * 1024) return fixed(b / (1024.0 * 1024 * 1024), 1) + " GiB";
  if (b >= 1024.0 * 1024) return fixed(b / (1024.0 * 1024), 0) + " MiB";
  if (b >= 1024.0) return fixed(b / 1024.0, 0) + " KiB";
  return std::to_string(bytes) + " B";
}

void checkResources(const ResourceEstimate& e, const ResourceLimits& limits, const FileLoc& where) {
  if (limits.maxMemoryBytes == 0 || e.bytes() <= limits.maxMemoryBytes) return;
  const std::string limit = "(--max-memory " + formatBytes(limits.maxMemoryBytes) + ")";
  const MemoryItem* m = e.largest();
  if (!m)
    throw InputError(where, "the case needs about " + formatBytes(e.bytes()) + " of memory, more than allowed " + limit);
  throw InputError(m->loc, m->what + " needs about " + formatBytes(m->bytes) + " of memory (" + m->detail +
                               "); the case about " + formatBytes(e.bytes()) + " in all, more than allowed " + limit);
}

uint64_t bytesPerGridPoint(const TraceSettings& s) {
  const bool cache = s.method == Method::kCache && s.maxBounces > 0;  // as computeIrradiance
  // Kept for the whole run: the prepared grid (points, plane coordinates, cells; the capacity
  // push_back leaves over is never touched, so never resident) and each point's lux and error.
  const uint64_t kept = sizeof(SensorPoint) + sizeof(Vec2) + sizeof(glm::ivec2) + 2 * sizeof(double);
  // Then one of two phases. Tracing: the list of all points and the cache's records; the
  // estimates come a block at a time (gridBlockBytes) and the CSV rows go out with their block.
  const uint64_t tracing = sizeof(SensorPoint) + (cache ? kCacheBytesPerPoint : 0);
  // Reporting: the report's values and their sorted copy, the plan's cells and plane coordinates
  // (the plan's SVG is bounded by kMaxSvgCells, gridPlanBytes).
  const uint64_t reporting = 2 * sizeof(double) + sizeof(Vec2) + sizeof(glm::ivec2);
  return kept + std::max(tracing, reporting);
}

namespace {

// The block of estimates a grid study holds while it traces (engine/sensors.h).
uint64_t gridBlockBytes() { return kSensorBlockPoints * sizeof(IrradianceEstimate); }

// A grid's plan in the report: an SVG element a cell, or one picture beyond kMaxSvgCells cells.
uint64_t gridPlanBytes(std::size_t points) { return std::min<uint64_t>(points, kMaxSvgCells) * kReportBytesPerCell; }

}  // namespace

uint64_t bytesPerInputPoint(const TraceSettings& s) {
  const bool cache = s.method == Method::kCache && s.maxBounces > 0;
  // The input text and its stream copy (a line each), the points, the estimates and the CSV row.
  return 2 * 60 + sizeof(SensorPoint) + sizeof(IrradianceEstimate) + kCsvRowBytes + (cache ? kCacheBytesPerPoint : 0);
}

uint64_t bytesPerPixel() {
  // Kept till the pictures are written: Image (engine/render.h: float radiance, luminance and
  // standard error; inside, traced and interpolation level, a byte each).
  const uint64_t kept = 3 * sizeof(float) + 2 * sizeof(float) + 3 * sizeof(uint8_t);
  // At most one of these phases at a time: a mean's standard error (a float coefficient a
  // pixel), the glare rating (a bit a pixel), writing (one 8-bit picture; the EXR goes a block of
  // rows at a time).
  const uint64_t transient = std::max<uint64_t>(sizeof(float), 3);
  return kept + transient;
}

uint64_t sceneBytes(const Scene& scene) {
  // Shapes and names, the accelerator (~150 B per surface, docs/performance.md) and vertices;
  // the luminaires are an item of their own (addLuminaires).
  const uint64_t shapes = scene.shapes.size() * (sizeof(Shape) + sizeof(std::string) + 150);
  const uint64_t vertices = scene.vertices.points.size() * (sizeof(Vec3) + sizeof(Vec2));
  // The compact mesh as held (docs/engine.md) plus its accelerator: at most 67 B per triangle
  // and a float copy of each vertex (Embree; the octree's 58 B, docs/performance.md).
  const uint64_t mesh = scene.mesh.memoryBytes() + scene.mesh.triangles.size() * 70 +
                        scene.mesh.vertices.size() * 3 * sizeof(float);
  return kProcessBytes + shapes + vertices + mesh + scene.materials.size() * sizeof(Material);
}

void addLuminaires(ResourceEstimate& e, const CaseFile& c) {
  if (c.luminaires.empty()) return;
  // Each fitting: its placement in the case and its source in the scene, both in vectors grown by
  // push_back (1.5 × on average), its sampled Light in the tracer, two name strings on the heap,
  // and what the TOML table and copies leave (measured: 1.33 KB a luminaire at 10⁶ and at 10⁴,
  // docs/reliability.md). The photometric webs are shared per file.
  const uint64_t per = 3 * (sizeof(LuminaireSource) + sizeof(LuminairePlacement)) / 2 + sizeof(Light) + 2 * 32 + 100;
  MemoryItem m;
  m.what = c.luminaires.size() > 1 ? "the data of " + std::to_string(c.luminaires.size()) + " luminaires" : "the luminaire";
  m.loc = c.luminaires.front().loc;
  m.bytes = c.luminaires.size() * per;
  m.detail = std::to_string(c.luminaires.size()) + " x " + std::to_string(per) + " B";
  e.memory.push_back(std::move(m));
}

double raysPerSensor(const TraceSettings& s, std::size_t sampled, std::size_t luminaires, double hitFraction,
                     double skyRaysPerVertex) {
  const double sources = static_cast<double>(sampled + luminaires);
  // A luminaire's opening is sampled as an area source's (lights.cpp; a point luminaire takes one
  // ray, but most have an opening).
  const double direct = static_cast<double>(s.lightSamples) * static_cast<double>(sampled + luminaires);
  const double hemisphere = static_cast<double>(s.hemisphereSamples);
  if (s.maxBounces <= 0) return hemisphere + direct;  // the rays see glow and sky only
  // A hemisphere ray: the ray to its first hit and that vertex's shadow rays (the light chosen,
  // and under a sky its sample and its portal sample), then either the cache (a lookup with its
  // visibility rays and the records' share, kCacheRaysPerLookup, fitted in a room without sky:
  // their paths' vertices cost as this one's) or firstBounceSplit continuations of ρ/(1 − ρ)
  // further vertices, a ray and the shadow rays each.
  const double further = std::min<double>(s.maxBounces, kMeanReflectance / (1.0 - kMeanReflectance));
  const double vertexRays = 2.0 + skyRaysPerVertex;
  const bool cache = s.method == Method::kCache;
  // The cache's rays are paths too: half of them reach a vertex that selects a light.
  const double vertices = cache ? 1.0 + kCacheRaysPerLookup / 2.0 : 1.0 + std::max(1, s.firstBounceSplit) * further;
  const double perRay = cache ? vertexRays * (1.0 + kCacheRaysPerLookup / 2.0) : vertexRays * vertices;
  const double selection = hemisphere * hitFraction * vertices * kSelectionCostPerSource * sources;
  // A ray that leaves the scene is itself only (hitFraction: the share that meets a surface).
  return hemisphere * (1.0 + hitFraction * (perRay - 1.0)) + direct + selection;
}

double cacheRecordRays(const TraceSettings& s, double points, double boxSurfaceM2, double hitFraction,
                       double skyRaysPerVertex) {
  if (s.method != Method::kCache || s.maxBounces <= 0) return 0.0;
  const double a = std::max(1e-3, s.cache.accuracy);
  const double hemisphereRays = points * static_cast<double>(s.hemisphereSamples);
  const double records = std::min(kRecordsPerSquareMetre * boxSurfaceM2 * (0.2 / a) * (0.2 / a),
                                  kRecordsPerHemisphereRay * hemisphereRays);
  // A record sample is a path: its hit and shadow rays, then ρ/(1 − ρ) further vertices.
  const double further = std::min<double>(s.maxBounces, kMeanReflectance / (1.0 - kMeanReflectance));
  const double vertexRays = 2.0 + skyRaysPerVertex;
  const double perRecord = s.cache.recordSamples * vertexRays * (1.0 + further) + s.cache.radiusSamples;
  return hitFraction *
         std::max(0.0, records * perRecord - hemisphereRays * kRecordShareRaysPerLookup * vertexRays / 2.0);
}

namespace {

// The surface of the scene's bounding box (cacheRecordRays' measure of a room), m².
double boundingBoxSurfaceM2(const Scene& scene) {
  const Vec3 box = scene.bounds().empty() ? Vec3(0.0) : scene.bounds().size();
  return 2.0 * (box.x * box.y + box.y * box.z + box.z * box.x);
}

// The goal's relative size: the grids' target where there is one, else the per-point target.
double pilotTargetRelative(const TraceSettings& s) {
  return s.gridTargetRelativeError > 0.0 ? s.gridTargetRelativeError : s.targetRelativeError;
}

// A point whose one path-method batch has more than kPastCacheBatches times the goal's variance
// is counted past the cache: fitted on the four cases/sidelit-bsdf rooms, where the points past
// the cache are those (the sum of such points' batches within 15 % of the run's path batches in
// each room; docs/reliability.md).
constexpr double kPastCacheBatches = 2.5;

// One path-method estimate at each of up to kScatteringPilotPoints of `chosen` points, in
// parallel, each from its own pilot stream; the mean over them of the batches each needs for the
// goal (target × the larger of its value and the pilot's mean with the grids' target, else × its
// value), counting 0 for a point that stays on the cache (kPastCacheBatches).
double scatteringPilotBatches(const Tracer& tracer, const std::vector<SensorPoint>& chosen, const TraceSettings& s,
                              int threads) {
  TraceSettings path = s;
  path.method = Method::kPath;
  path.targetRelativeError = 0.0;
  path.gridTargetRelativeError = 0.0;
  std::vector<IrradianceEstimate> est(chosen.size());
  parallelFor(chosen.size(), threads, [&](std::size_t k) {
    est[k] = estimateIrradiance(tracer, chosen[k].position, chosen[k].response(), streams::kEstimatePilot.first + k, path);
  });
  double mean = 0.0;
  for (const IrradianceEstimate& e : est) mean += photopic(e.irradiance) / static_cast<double>(est.size());
  const double relative = pilotTargetRelative(s);
  double batches = 0.0;
  for (const IrradianceEstimate& e : est) {
    const double value = photopic(e.irradiance);
    const double goal = relative * (s.gridTargetRelativeError > 0.0 ? std::max(value, mean) : value);
    const double b = goal > 0.0 ? e.variancePhotopic / (goal * goal) : 1.0;
    if (b > kPastCacheBatches) batches += std::min(b, static_cast<double>(std::max(1, s.maxBatches)));
  }
  return batches / static_cast<double>(est.size());
}

}  // namespace

HemispherePilot hemispherePilot(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                const TraceSettings* settings, int threads) {
  constexpr std::size_t kPoints = 64;
  constexpr int kDirections = 32;
  constexpr double kGoldenFraction = 0.38196601125010515;  // 2 − φ: the golden angle over 2π
  HemispherePilot pilot;
  const Scene& scene = tracer.scene();
  pilot.skyRaysPerVertex = skyRaysPerVertex(scene, &tracer.portals());
  if (points.empty()) return pilot;
  const std::size_t step = std::max<std::size_t>(1, points.size() / kPoints);
  int hits = 0, rays = 0, pilots = 0, scattering = 0;
  std::vector<SensorPoint> seeing;  // the pilot's points that see a scattering surface
  for (std::size_t i = 0; i < points.size(); i += step) {
    const SensorPoint& sp = points[i];
    const Frame f = Frame::fromNormal(sp.normal);
    const Vec3 o = sp.position + sp.normal * Tracer::originOffset(sp.position);
    bool seesScattering = false;
    for (int k = 0; k < kDirections; ++k) {
      // A Fibonacci spiral (golden-ratio steps in azimuth), cosine-distributed.
      const double u2 = k * kGoldenFraction - std::floor(k * kGoldenFraction);
      const Vec3 d = f.toWorld(sampleCosineHemisphere((k + 0.5) / kDirections, u2));
      RayHit hit;
      if (tracer.accelerator().intersect(o, d, 0.0, std::numeric_limits<double>::infinity(), hit)) {
        ++hits;
        const Material& m = scene.materials[scene.surfaceMaterial(hit.shape)];
        seesScattering = seesScattering || familyOf(m).samplesScattering(m);
      }
      ++rays;
    }
    ++pilots;
    scattering += seesScattering ? 1 : 0;
    if (seesScattering) seeing.push_back(sp);
  }
  pilot.hitFraction = static_cast<double>(hits) / rays;
  pilot.scatteringPoints = static_cast<double>(scattering) / pilots;
  if (settings && settings->method == Method::kCache && settings->maxBounces > 0 && pilotTargetRelative(*settings) > 0.0 &&
      !seeing.empty()) {
    // Spread over those points: every k-th.
    std::vector<SensorPoint> chosen;
    const std::size_t every = std::max<std::size_t>(1, seeing.size() / kScatteringPilotPoints);
    for (std::size_t i = 0; i < seeing.size() && chosen.size() < kScatteringPilotPoints; i += every) chosen.push_back(seeing[i]);
    pilot.scatteringBatches = scatteringPilotBatches(tracer, chosen, *settings, threads);
  }
  return pilot;
}

double pastCacheRays(const TraceSettings& s, double points, std::size_t sampled, std::size_t luminaires,
                     const HemispherePilot& pilot) {
  if (s.method != Method::kCache || s.maxBounces <= 0 || s.targetRelativeError <= 0.0) return 0.0;
  TraceSettings path = s;
  path.method = Method::kPath;
  // The batches the pilot measured, else half those the settings allow (sampleToTarget's cap).
  const double batches = pilot.scatteringBatches >= 0.0 ? pilot.scatteringBatches : std::max(1.0, 0.5 * s.maxBatches);
  return points * batches *
         raysPerSensor(path, sampled, luminaires, pilot.hitFraction, pilot.skyRaysPerVertex);
}

double skyRaysPerVertex(const Scene& scene, const PortalSet* portals) {
  if (!scene.sky) return 0.0;
  const bool any = portals ? !portals->empty() : !PortalSet(scene).empty();
  return any ? 2.0 : 1.0;
}

uint64_t annualBlockBytes(uint64_t sensors, uint64_t hours, uint64_t patches, uint64_t sunHours, uint64_t suns,
                          int states) {
  const uint64_t coefficients = sensors * (patches + sunHours + suns) * sizeof(float);
  const uint64_t openPass = coefficients + sensors * hours * 2 * sizeof(float);
  const uint64_t closedPass = std::max(openPass, sensors * hours * 3 * sizeof(float));
  return states > 1 ? closedPass : openPass;
}

uint64_t annualGridBytes(uint64_t sensors, uint64_t hours) {
  const uint64_t perSensor = sizeof(SensorPoint) + sizeof(Vec2) + sizeof(glm::ivec2) + 2 * sizeof(Vec3) +
                             sizeof(SensorAnnualMetrics) + 200;
  return sensors * perSensor + hours * (sizeof(int) + sizeof(char) + sizeof(double));
}

uint64_t viewReportBytes(const ViewSpec& view) {
  const uint64_t pixels = static_cast<uint64_t>(view.resolution.x) * static_cast<uint64_t>(view.resolution.y);
  return std::min(pixels, kReportPicturePixels) * 6;
}

MemoryItem viewMemory(const ViewSpec& view, bool keptForReport) {
  MemoryItem m;
  m.what = "view '" + view.name + "'";
  m.loc = view.loc;
  const uint64_t pixels = static_cast<uint64_t>(view.resolution.x) * static_cast<uint64_t>(view.resolution.y);
  const uint64_t per = bytesPerPixel();
  // A band of a pass (RenderSettings::pixelsPerFill pixels at most): its pixel list and values.
  // `run` keeps the report's two pictures
  // (compressed PNG, at most 2048 px across: a few bytes a pixel).
  const uint64_t band = std::min<uint64_t>(pixels, RenderSettings{}.pixelsPerFill) * kBandBytesPerPixel;
  m.bytes = pixels * per + band + (keptForReport ? viewReportBytes(view) : 0);
  m.detail = std::to_string(view.resolution.x) + " x " + std::to_string(view.resolution.y) + " pixels x " +
             std::to_string(per) + " B";
  return m;
}

double viewRays(const ViewSpec& view, const ViewWork& w, const TraceSettings& s, std::size_t sampled,
                std::size_t luminaires) {
  const double pixels = static_cast<double>(view.resolution.x) * view.resolution.y;
  // The coarse lattice is traced whole, refinement traces where the image varies or is noisy:
  // 0.55–0.81 of the pixels in the test views and a 1024 × 1024 view of the small room
  // (docs/reliability.md); every pixel with coarseStep 1.
  const double traced = w.coarseStep <= 1 ? pixels : kTracedPixelFraction * pixels;
  const double sources = static_cast<double>(sampled + luminaires);
  const double further = std::min<double>(std::max(0, s.maxBounces), kMeanReflectance / (1.0 - kMeanReflectance));
  double perRay = 1.0;  // the camera ray
  if (w.irradianceSamples > 0) {
    // A matte surface seen: a stratified irradiance estimate there (renderView: path traced, no
    // split, 4 light samples), measured at about one ray per sample beyond its light samples.
    const double n = w.irradianceSamples;
    perRay += n * kRaysPerIrradianceSample + 4.0 * sampled + luminaires + n * kSelectionCostPerSource * sources;
  } else {
    // One path: its vertices, a ray and a shadow ray each, and their light selection.
    const double vertices = 1.0 + further;
    perRay += 2.0 * vertices + vertices * kSelectionCostPerSource * sources;
  }
  return traced * std::max(1, w.pixelSamples) * perRay;
}

std::vector<std::size_t> gridPointCounts(const CaseFile& c) {
  std::vector<std::size_t> n;
  for (const GridSpec& g : c.grids)
    n.push_back(g.kind == GridKind::kPlane ? countPlaneGrid(g.plane, g.loc) : readPointsFile(g.pointsFile).size());
  return n;
}

ResourceEstimate estimateGridStudy(const CaseFile& c, const std::vector<std::size_t>& gridPoints, const Scene& scene,
                                   const TraceSettings& s, int threads, const HemispherePilot& pilot) {
  const double hitFraction = pilot.hitFraction;
  ResourceEstimate e;
  e.threads = static_cast<int>(threadsUsed(threads));
  e.baseBytes = sceneBytes(scene);
  const SourceCounts n = countSources(scene);
  const uint64_t perPoint = bytesPerGridPoint(s);
  if (!c.grids.empty()) e.baseBytes += gridBlockBytes();
  // A modelling grid's other sensors (study/grid_study.cpp): each a traced point, its estimate,
  // its kept value and error, and its cache records.
  const bool cache = s.method == Method::kCache && s.maxBounces > 0;
  const uint64_t perExtra =
      sizeof(SensorPoint) + sizeof(IrradianceEstimate) + 2 * sizeof(double) + (cache ? kCacheBytesPerPoint : 0);
  double points = 0.0;
  for (std::size_t i = 0; i < c.grids.size() && i < gridPoints.size(); ++i) {
    const int estimates = estimatesPerPoint(c.grids[i]);
    const uint64_t bytes = perPoint + static_cast<uint64_t>(estimates - 1) * perExtra;
    MemoryItem m;
    m.what = "grid '" + c.grids[i].name + "'";
    m.loc = c.grids[i].loc;
    m.bytes = gridPoints[i] * bytes + gridPlanBytes(gridPoints[i]);
    m.detail = std::to_string(gridPoints[i]) + " points x " + std::to_string(bytes) + " B and its plan";
    if (estimates > 1) m.detail += " (" + std::to_string(estimates) + " estimates each: modelling)";
    e.memory.push_back(std::move(m));
    // Every estimate costs the rays of one: the quantities draw as many hemisphere rays and
    // light samples as planar illuminance (engine/response.h).
    points += static_cast<double>(gridPoints[i]) * estimates;
  }
  const double batches = expectedBatchesPerPoint(s);
  const double boxSurfaceM2 = boundingBoxSurfaceM2(scene);
  const double sky = pilot.skyRaysPerVertex;
  e.work.push_back({"tracing", points * batches * raysPerSensor(s, n.sampled, n.luminaires, hitFraction, sky) +
                                   cacheRecordRays(s, points, boxSurfaceM2, hitFraction, sky) +
                                   pastCacheRays(s, points * pilot.scatteringPoints, n.sampled, n.luminaires, pilot)});
  addLuminaires(e, c);
  // EN 1838's points (study/compliance/en1838.h): each a sensor, its estimate, its value and its
  // row of the points table; direct light from the emergency luminaires only.
  if (const ComplianceSpec* entry = en1838Entry(c)) {
    const double n1838 = en1838PointBound(c);
    const double per = sizeof(SensorPoint) + sizeof(IrradianceEstimate) + sizeof(double) + sizeof(En1838PointValue) + 32;
    MemoryItem m;
    m.what = "the EN 1838 study";
    m.loc = entry->loc;
    m.bytes = static_cast<uint64_t>(std::min(n1838 * per, 1.8e19));
    m.detail = "at most " + std::to_string(static_cast<long long>(std::min(n1838, 9e18))) + " points x " +
               std::to_string(static_cast<int>(per)) + " B";
    e.memory.push_back(std::move(m));
    std::size_t emergency = 0;
    for (const LuminairePlacement& l : c.luminaires) emergency += l.emergency;
    e.work.push_back({"EN 1838", n1838 * raysPerSensor(directOnlySettings(s), 0, emergency)});
  }
  // EN 12464-2's glare ratings and EN 13201's road points: a sight line to each luminaire (the
  // point law, a shadow ray each) per view of each GR observer and per road point (EN 13201-3's
  // luminance and illuminance rows at ≤ 3 m, at least 10; 3 a lane and ≥ 3 across at ≤ 1.5 m; the
  // edge strips' 2 and each lane's observer; the illuminance row again for HS classes and for
  // the additional classes' 1.5 m points), no interreflection.
  double sightLines = 0.0;
  for (const GrObserverSpec& o : c.outdoor.observers) sightLines += o.direction ? 1.0 : std::ceil(360.0 / o.stepDeg);
  for (const RoadSpec& r : c.roadLighting.roads) {
    const double along = std::max(10.0, std::ceil(r.lengthM / 3.0));
    const double across = std::max(3.0, std::ceil(r.widthM / 1.5));
    const double extraRows = (r.roadClass.family == RoadClassFamily::kHS) + !r.additional.empty();
    sightLines += along * (3.0 * r.lanes + across * (1.0 + extraRows) + 2.0 + r.lanes);
  }
  if (sightLines > 0.0)
    e.work.push_back({"glare ratings and roads", sightLines * static_cast<double>(scene.luminaires.size())});
  // Views are rendered and written one at a time (study/grid_study.cpp): the largest one's pixels
  // and every view's pictures for the report.
  std::vector<MemoryItem> views;
  for (const ViewSpec& v : c.views) {
    views.push_back(viewMemory(v, true));
    e.work.push_back({"rendering " + v.name, viewRays(v, ViewWork{}, s, n.sampled, n.luminaires)});
  }
  const auto largest = std::max_element(views.begin(), views.end(),
                                        [](const MemoryItem& a, const MemoryItem& b) { return a.bytes < b.bytes; });
  for (std::size_t k = 0; k < views.size(); ++k) {
    if (views.begin() + static_cast<std::ptrdiff_t>(k) != largest) {
      views[k].bytes = viewReportBytes(c.views[k]);
      views[k].detail = "its pictures in the report";
    }
    e.memory.push_back(std::move(views[k]));
  }
  return e;
}

ResourceEstimate estimateView(const CaseFile& c, const ViewSpec& view, const ViewWork& w, const Scene& scene,
                              const TraceSettings& s, int threads) {
  ResourceEstimate e;
  e.threads = static_cast<int>(threadsUsed(threads));
  e.baseBytes = sceneBytes(scene);
  addLuminaires(e, c);
  const SourceCounts n = countSources(scene);
  e.memory.push_back(viewMemory(view, false));
  e.work.push_back({"rendering " + view.name, viewRays(view, w, s, n.sampled, n.luminaires)});
  return e;
}

ResourceEstimate estimatePoints(std::size_t points, const FileLoc& where, const Scene& scene, const TraceSettings& s,
                                int threads, const HemispherePilot& pilot) {
  const double hitFraction = pilot.hitFraction;
  ResourceEstimate e;
  e.threads = static_cast<int>(threadsUsed(threads));
  e.baseBytes = sceneBytes(scene);
  const SourceCounts n = countSources(scene);
  const uint64_t per = bytesPerInputPoint(s);
  e.memory.push_back({"the input of " + std::to_string(points) + " points", where, points * per,
                      std::to_string(points) + " points x " + std::to_string(per) + " B"});
  e.memory.back().bytes += scene.luminaires.size() * (sizeof(LuminaireSource) + sizeof(Light) + 32);
  const double batches = expectedBatchesPerPoint(s);
  const double all = static_cast<double>(points);
  e.work.push_back({"tracing", all * batches * raysPerSensor(s, n.sampled, n.luminaires, hitFraction,
                                                             pilot.skyRaysPerVertex) +
                                   pastCacheRays(s, all * pilot.scatteringPoints, n.sampled, n.luminaires, pilot)});
  return e;
}

ResourceEstimate estimateAnnualStudy(const CaseFile& c, const Scene& scene, const AnnualCounts& a,
                                     const TraceSettings& s, int threads, uint64_t sensorsPerBlock,
                                     const TraceSettings* pointSettings) {
  ResourceEstimate e;
  e.threads = static_cast<int>(threadsUsed(threads));
  // The scene and the year's sky vectors (hours × patches, float).
  const uint64_t patches = static_cast<uint64_t>(SkyPatches(c.annual.skySubdivision).count());
  e.baseBytes = sceneBytes(scene) + a.hours * patches * sizeof(float);
  addLuminaires(e, c);
  const SourceCounts n = countSources(scene);
  // The interreflected sun's set: at most one position per Reinhart MF:2 patch with sun.
  const uint64_t suns = std::min<uint64_t>(a.sunHours, static_cast<uint64_t>(SkyPatches(2).count()));
  // Blinds closed: traced again where there is glass, once per window group (an implicit "other"
  // at most more); with groups a block holds its open, direct-sun and combined years and one
  // group's closed year (study/annual_study.cpp groupsPass).
  // Window states (docs/annual.md) replace the blinds: one more pass (sky, sun and its direct
  // part, each state having its own year) per state beyond a group's first; the direct-sun
  // rule's own direct-sun pass for each state of a group of more than two but its first and last.
  int extraStates = 0, escalationStates = 0;
  for (const WindowGroupSpec& g : c.windowGroups) {
    if (!g.states.empty()) extraStates += static_cast<int>(g.states.size()) - 1;
    if (g.schedule.empty() && g.states.size() > 2) escalationStates += static_cast<int>(g.states.size()) - 2;
  }
  const bool withStates = std::any_of(c.windowGroups.begin(), c.windowGroups.end(),
                                      [](const WindowGroupSpec& g) { return !g.states.empty(); });
  const int closedStates =
      withStates || !c.annual.blinds ? 0 : c.windowGroups.empty() ? 1 : static_cast<int>(c.windowGroups.size()) + 1;
  const int states = withStates ? 3 : !c.annual.blinds ? 1 : c.windowGroups.empty() ? 2 : 3;
  uint64_t sensors = 0;
  for (std::size_t i = 0; i < a.gridSensors.size(); ++i) {
    const uint64_t k = a.gridSensors[i];
    sensors += k;
    MemoryItem m;
    m.what = "the annual results of grid '" + c.grids[i].name + "'";
    m.loc = c.grids[i].loc;
    m.bytes = annualGridBytes(k, a.hours);
    m.detail = std::to_string(k) + " sensors (the hours stream to disk)";
    e.memory.push_back(std::move(m));
  }
  // One block at a time, whatever the grids' sizes (never more sensors than the study has).
  const uint64_t block = std::min(std::max<uint64_t>(1, sensorsPerBlock), std::max<uint64_t>(1, sensors));
  MemoryItem b;
  b.what = "the annual study's block of sensors";
  b.loc = c.annual.present ? c.annual.loc : c.sky.loc;
  b.bytes = annualBlockBytes(block, a.hours, patches, a.sunHours, suns, states);
  b.detail = std::to_string(block) + " sensors x " + std::to_string(a.hours) + " hours x " + std::to_string(states) +
             (states > 1 ? " states" : " state");
  e.memory.push_back(std::move(b));
  // Sky coefficients: the point estimator. Sun coefficients: fewer paths (annual_study.cpp's
  // sunSettings), each diffuse vertex with a shadow ray to every sun of the set. Direct sun:
  // sunSamples rays per sensor and sun hour.
  TraceSettings sun = s;
  sun.hemisphereSamples = std::max(64, s.hemisphereSamples / 8);
  sun.firstBounceSplit = std::max(1, s.firstBounceSplit / 4);
  const double sky = static_cast<double>(sensors) * raysPerSensor(s, n.sampled, n.luminaires);
  // About one vertex per path tests every sun (the others end by Russian roulette first).
  const double sunPaths = static_cast<double>(sensors) * (raysPerSensor(sun, n.sampled, n.luminaires) +
                                                          sun.hemisphereSamples * static_cast<double>(suns));
  const double direct = static_cast<double>(sensors) * a.sunHours * std::max(1, c.annual.sunSamples);
  // The study's steps (annual_study.cpp): both sets of coefficients, block by block, per state.
  e.work.push_back({"coefficients", sky + sunPaths + direct});
  if (closedStates == 1) e.work.push_back({"blinds closed: coefficients", sky + sunPaths});
  if (closedStates > 1)
    e.work.push_back({"blinds closed per window group: coefficients", closedStates * (sky + sunPaths)});
  if (escalationStates > 0) e.work.push_back({"window states: direct sun", escalationStates * direct});
  if (extraStates > 0) e.work.push_back({"window states: coefficients", extraStates * (sky + sunPaths + direct)});
  // LEED option 2 (study/compliance/compliance_leed.cpp): its spaces' sensors at every time, one batch each,
  // under a clear sky (the dome and its sun: two more sampled sources than the annual scene's),
  // and each time's cache records (cacheRecordRays: a sunlit room's are most of the cost).
  if (pointSettings)
    for (const ComplianceSpec& spec : c.compliance) {
      if (spec.standard != ComplianceStandard::kLeedV41Option2) continue;
      uint64_t k = 0;
      for (std::size_t i = 0; i < c.grids.size() && i < a.gridSensors.size(); ++i)
        if (spec.spaces.empty() || std::count(spec.spaces.begin(), spec.spaces.end(), c.grids[i].name) > 0)
          k += a.gridSensors[i];
      TraceSettings once = *pointSettings;
      once.targetRelativeError = 0.0;
      const double times = static_cast<double>(leedOption2Dates(spec, 0).size()) *  // the year changes no count
                           static_cast<double>(spec.leedHours.size());
      // Each time traces its own scene under its own sky, so its own irradiance cache.
      const double sky = std::max(1.0, skyRaysPerVertex(scene));  // its clear sky's rays at each vertex
      e.work.push_back({"compliance " + spec.name,
                        times * (static_cast<double>(k) * raysPerSensor(once, n.sampled + 2, 0, 1.0, sky) +
                                 cacheRecordRays(once, static_cast<double>(k), boundingBoxSurfaceM2(scene), 1.0, sky))});
    }
  return e;
}

}  // namespace candela
