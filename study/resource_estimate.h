// What a case needs before it is traced (docs/reliability.md, "Resource bounds"): the memory its
// results and scene take, counted from the data structures that hold them, and the work, counted
// in rays and turned into seconds at a measured rate. The studies compute it once every input is
// checked, hand it to their observer (study/observer.h) and refuse, with an InputError at the
// line of the largest item, a case whose memory exceeds the caller's limit. Estimates only add
// checks and output: no number of a run that passes depends on them.
#pragma once

#include "base/error.h"
#include "engine/trace_settings.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

struct Scene;
struct SensorPoint;
class Tracer;
struct CaseFile;
struct ViewSpec;

// One thing of a case that takes memory: a grid, a view, the annual arrays, the luminaires.
struct MemoryItem {
  std::string what;    // "grid 'workplane'", "view 'desk'", ...
  FileLoc loc;         // where the case declares it (refusals point there)
  uint64_t bytes = 0;
  std::string detail;  // the count behind it, e.g. "16384 x 16384 pixels x 94 B"
};

// One step of the work, labelled as the study's StudyObserver step ("tracing", "rendering desk").
struct WorkStep {
  std::string label;
  double rays = 0.0;
};

// Rays (as raysPerSensor counts them) per CPU second of one thread on the development machine
// (2 vCPU Xeon at 2.6 GHz): 1.5–2.6 M on the small room's grids at draft and normal quality, path
// and cache (docs/reliability.md).
inline constexpr double kRaysPerSecondPerThread = 2.0e6;

struct ResourceEstimate {
  uint64_t baseBytes = 0;  // the process and the scene (shapes, accelerator, luminaires)
  std::vector<MemoryItem> memory;
  std::vector<WorkStep> work;
  int threads = 1;         // threads the work is spread over (resolved: >= 1)
  double raysPerSecondPerThread = kRaysPerSecondPerThread;

  uint64_t bytes() const;                        // baseBytes + every item
  double rays() const;                           // every step
  double seconds() const;                        // rays / (rate × threads)
  double seconds(const std::string& label) const;  // of the steps so labelled; < 0 when none
  const MemoryItem* largest() const;             // nullptr when there is no item
};

// The caller's bounds: 0 means none.
struct ResourceLimits {
  uint64_t maxMemoryBytes = 0;
};

// Throws InputError when the estimate's memory exceeds the limit: at the largest item's line,
// "view 'x' needs about 31.5 GiB (16384 x 16384 pixels x 126 B); the case about 31.6 GiB in all,
// more than allowed (--max-memory 1 GiB)"; at `where` when there is no item.
void checkResources(const ResourceEstimate& e, const ResourceLimits& limits, const FileLoc& where);

// "1.5 GiB", "340 MiB", "12 KiB", "900 B".
std::string formatBytes(uint64_t bytes);

// Sizes of what one unit holds, in bytes (from sizeof of the structures that hold it; formulas
// in docs/reliability.md).
// The cache's records count where computeIrradiance builds one (method cache, bounces > 0).
uint64_t bytesPerGridPoint(const TraceSettings& s);   // a point of a point-in-time grid (run)
uint64_t bytesPerInputPoint(const TraceSettings& s);  // a point of `candela points`
uint64_t bytesPerPixel();  // a pixel of a view (one view at a time is in memory)
uint64_t viewReportBytes(const ViewSpec& view);  // the report's pictures of a view (run)
uint64_t sceneBytes(const Scene& scene);
// The case's luminaires as one item at the first [[luminaire]]'s line (none without luminaires).
void addLuminaires(ResourceEstimate& e, const CaseFile& c);

// Rays one sensor point costs: hemisphere samples × the rays of a hemisphere ray's path (its hit
// and shadow ray, then the cache's lookup or firstBounceSplit continuations of ρ/(1 − ρ) further
// vertices at a mean reflectance ρ = 0.5, capped by maxBounces), the light samples of every
// source at the sensor (a far-field luminaire takes one shadow ray), and the light selection at
// every path vertex (a fraction of a ray per source). `sampled` counts the area and distant
// sources and the sky, `luminaires` the photometric ones. Formula in docs/reliability.md.
// `hitFraction`: the share of hemisphere rays that meet a surface (hemispherePilot; 1 in a
// room): a ray that leaves the scene costs itself only, no vertex. `skyRaysPerVertex`: the
// shadow rays a sky adds at every path vertex beyond the light chosen there (skyRaysPerVertex:
// its sample by luminance, and its portal sample where portals are found; 0 without a sky).
double raysPerSensor(const TraceSettings& s, std::size_t sampled, std::size_t luminaires, double hitFraction = 1.0,
                     double skyRaysPerVertex = 0.0);

class PortalSet;
// The sky's shadow rays at a path vertex (engine/integrator_direct.cpp, skyIrradiance): 0
// without a sky, 1 (a sample by luminance), 2 with portals (and a portal sample); `portals` the
// tracer's when built (else found from the scene).
double skyRaysPerVertex(const Scene& scene, const PortalSet* portals = nullptr);

// The irradiance cache's records beyond what raysPerSensor's lookups already count (their share,
// calibrated on dense grids): a room needs about the same records however few points look at it,
// so a sparse grid pays for them alone (issue 37: the sunlit office's 242 points made 14 500
// records, 60 a point). Records: kRecordsPerSquareMetre per m² of `boxSurfaceM2` (the scene's
// bounding box) at Ward's a = 0.2, scaling as (0.2/a)², at most kRecordsPerHemisphereRay of the
// points' hemisphere rays; each costs its record samples' paths and its radius samples. 0 for
// the path method or without bounces. Formula in docs/reliability.md.
// `hitFraction` as raysPerSensor's: records are made where hemisphere rays meet surfaces.
double cacheRecordRays(const TraceSettings& s, double points, double boxSurfaceM2, double hitFraction = 1.0,
                       double skyRaysPerVertex = 0.0);

// What a pilot of the points' hemisphere rays tells the estimate, once the tracer is built: 32
// fixed cosine-distributed directions from each of at most 64 points spread over the list (2 048
// rays, about a millisecond; no random stream of the run drawn, so a run's numbers do not depend
// on it). With settings of the cache method and a target error, and points that see a
// scattering window, also one path-method estimate at up to kScatteringPilotPoints of those
// points (their own streams, streams::kEstimatePilot): the batches such points need.
struct HemispherePilot {
  // The share of the rays that meet a surface (1 for no points). An open site (a car park's
  // ground under its poles) sends most rays out of the scene.
  double hitFraction = 1.0;
  // The share of the points some of whose rays meet a scattering surface first (a BSDF or aBSDF
  // window: MaterialFamily::samplesScattering): the irradiance cache's records see such a window through
  // its function, too noisily for the grids' goal, and the points go on by the path method
  // (docs/bsdf.md), which pastCacheRays counts.
  double scatteringPoints = 0.0;
  // skyRaysPerVertex of the scene with the tracer's portals.
  double skyRaysPerVertex = 0.0;
  // The mean over the pilot's scattering points of the path-method batches each needs past the
  // cache (its one-batch variance over the goal's square, at most the cap; 0 for a point that
  // stays on the cache); negative when not measured (pastCacheRays then takes half the cap).
  double scatteringBatches = -1.0;
};
inline constexpr std::size_t kScatteringPilotPoints = 8;
// `threads` as the run's (0: all cores) for the path-method estimates.
HemispherePilot hemispherePilot(const Tracer& tracer, const std::vector<SensorPoint>& points,
                                const TraceSettings* settings = nullptr, int threads = 0);

// The rays of `points` points estimated again by the path method after the cache (the points
// that see a scattering surface, HemispherePilot): each the path method's rays for the batches
// the pilot measured (HemispherePilot::scatteringBatches), else half the batches the settings
// allow (sampleToTarget's cap). 0 unless the cache method has a target error.
double pastCacheRays(const TraceSettings& s, double points, std::size_t sampled, std::size_t luminaires,
                     const HemispherePilot& pilot);

// The annual study's float arrays for one block of `sensors` sensors over `hours` hours (the
// study holds one block at a time, study/annual_study.h kAnnualSensorsPerBlock): while a block's
// hours are multiplied out, its coefficients (sensors × (patches + sun hours + suns of the set))
// beside its year's total and direct sun (sensors × hours × 2); with the blinds (`states` 2)
// the second pass then holds the closed year beside the open year and direct sun read back
// (sensors × hours × 3), whichever is larger.
uint64_t annualBlockBytes(uint64_t sensors, uint64_t hours, uint64_t patches, uint64_t sunHours, uint64_t suns,
                          int states);

// What the annual study keeps of each sensor of a grid beyond its block: the grid's point and
// plan, its metrics and report values; and of each hour of a grid: the blinds rule's count and
// flag and the temporal map's value.
uint64_t annualGridBytes(uint64_t sensors, uint64_t hours);

// A view's pixels and rays (traced pixels × camera rays × what a camera ray costs).
struct ViewWork {
  int pixelSamples = 4;
  int coarseStep = 4;
  int irradianceSamples = 64;
};
MemoryItem viewMemory(const ViewSpec& view, bool keptForReport);
double viewRays(const ViewSpec& view, const ViewWork& w, const TraceSettings& s, std::size_t sampled,
                std::size_t luminaires);

// The points of each [[grid]] of the case, counted without generating them (points files read).
std::vector<std::size_t> gridPointCounts(const CaseFile& c);

// The point-in-time study of a case: its grids (points per grid, case order; and the cache),
// views and luminaires.
// `pilot`: hemispherePilot's measures (the run takes them once the scene's tracer is built).
// 6 parameters: the case, its grids' sizes, the scene, the settings, the threads, the pilot.
ResourceEstimate estimateGridStudy(const CaseFile& c, const std::vector<std::size_t>& gridPoints, const Scene& scene,
                                   const TraceSettings& s, int threads, const HemispherePilot& pilot = {});

// `candela render`: one view of a case (study/view_study.h).
ResourceEstimate estimateView(const CaseFile& c, const ViewSpec& view, const ViewWork& w, const Scene& scene,
                              const TraceSettings& s, int threads);

// `candela points`: `points` sensor points read from `where`; pilot as estimateGridStudy's.
// 6 parameters: the points' count and file, the scene, the settings, the threads, the pilot.
ResourceEstimate estimatePoints(std::size_t points, const FileLoc& where, const Scene& scene, const TraceSettings& s,
                                int threads, const HemispherePilot& pilot = {});

// The annual study: sensors per grid (case order), the weather year's hours and those with sun.
struct AnnualCounts {
  std::vector<uint64_t> gridSensors;
  uint64_t hours = 0, sunHours = 0;
};
// `sensorsPerBlock`: the study's block (runAnnualStudy's AnnualStudyOptions, rounded). With
// `pointSettings` (the point-in-time settings of the case's [[compliance]] entries), the tracing
// of LEED option 2 is a step of its own ("compliance <name>").
ResourceEstimate estimateAnnualStudy(const CaseFile& c, const Scene& scene, const AnnualCounts& a,
                                     const TraceSettings& s, int threads, uint64_t sensorsPerBlock,
                                     const TraceSettings* pointSettings = nullptr);

}  // namespace candela
