// Indirect-illumination validation cases (docs/accuracy.md): the irradiance cache on the closed
// forms (integrating spheres, the paper's sphere on a plane) and both methods on scenes where
// interreflection dominates against a converged path-traced reference.
#include "engine/radiance/reader.h"
#include "engine/sensors.h"
#include "validation/analytic.h"
#include "validation/case_registry.h"
#include "validation/speed_accuracy.h"
#include "engine/irradiance_estimator.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace candela::validation {

namespace {

// The converged reference of a scene for a tolerance (referenceEstimates), computed once per
// process and tolerance (cases run one after another; both methods of a scene share it).
const std::vector<double>& referenceLux(const IndirectScene& sc, double tolerance, int threads) {
  static std::map<std::pair<std::string, double>, std::vector<double>> done;
  const auto key = std::make_pair(sc.name, tolerance);
  auto it = done.find(key);
  if (it != done.end()) return it->second;
  std::vector<double> ref = sc.closedFormLux;
  if (ref.empty())
    for (const IrradianceEstimate& e : referenceEstimates(sc, tolerance, threads)) ref.push_back(e.illuminanceLux());
  return done[key] = ref;
}

IndirectScene sceneNamed(const std::string& name) {
  for (IndirectScene& s : indirectScenes())
    if (s.name == name) return s;
  return {};
}

CaseResult runIndirect(const RunConfig& cfg, const std::string& scene, Method method, double tolerance) {
  const IndirectScene sc = sceneNamed(scene);
  const std::vector<double>& ref = referenceLux(sc, tolerance, cfg.threads);
  TraceSettings s = cfg.settings;
  s.method = method;
  CaseResult r;
  const std::vector<IrradianceEstimate> est = runIndirectScene(sc, s, cfg.threads, &r.seconds);
  r.reference = sc.closedFormLux.empty() ? "path tracer, 8192 samples, all bounces, batches to a standard error of tolerance/10"
                                         : sc.reference;
  r.tolerance = tolerance;
  for (size_t i = 0; i < est.size(); ++i) {
    char label[64];
    std::snprintf(label, sizeof label, "(%.2g,%.2g,%.2g)", sc.points[i].position.x, sc.points[i].position.y,
                  sc.points[i].position.z);
    r.points.push_back({label, ref[i], est[i].illuminanceLux(), est[i].standardErrorLux()});
  }
  return r;
}

CaseResult cacheSphereOnPlane(const RunConfig& cfg) {
  // The engine's sphere-on-plane-rho0.5 case (sphere R = 1 m, ρ 0.5, on a black plane under a
  // uniform sky) through the cache: the records sit on the sphere.
  IndirectScene sc;
  sc.name = "cache-sphere-on-plane-rho0.5";
  sc.rad = "void glow sky 0 0 4 1 1 1 0\nsky source skydome 0 0 4 0 0 1 180\n"
           "void plastic black 0 0 5 0 0 0 0 0\nvoid plastic ball 0 0 5 0.5 0.5 0.5 0 0\n"
           "black polygon plane 0 0 12 -1e5 -1e5 0  1e5 -1e5 0  1e5 1e5 0  -1e5 1e5 0\n"
           "ball sphere s 0 0 4 0 0 1 1\n";
  for (double x : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    sc.points.push_back({Vec3(x, 0, 0.01), Vec3(0, 0, 1)});
    sc.closedFormLux.push_back(kLumensPerWatt * analytic::sphereOnPlane(0.5, 1.0, 1.0, x, 0.01));
  }
  TraceSettings s = cfg.settings;
  s.method = Method::kCache;
  CaseResult r;
  const std::vector<IrradianceEstimate> est = runIndirectScene(sc, s, cfg.threads, &r.seconds);
  r.reference = "quadrature of sky + sphere radiance rho L (1 + n_z)/2";
  r.tolerance = 0.01;
  for (size_t i = 0; i < est.size(); ++i) {
    char label[32];
    std::snprintf(label, sizeof label, "x=%g m", sc.points[i].position.x);
    r.points.push_back({label, sc.closedFormLux[i], est[i].illuminanceLux(), est[i].standardErrorLux()});
  }
  return r;
}

Case indirect(const std::string& scene, Method m, double tol, bool quick) {
  return {std::string(m == Method::kCache ? "cache-" : "path-") + scene, "indirect", quick,
          [scene, m, tol](const RunConfig& c) { return runIndirect(c, scene, m, tol); }};
}

}  // namespace

std::vector<Case> indirectCases() {
  return {
      indirect("integrating-sphere-rho0.5", Method::kCache, 0.02, true),
      indirect("integrating-sphere-rho0.8", Method::kCache, 0.02, true),
      {"cache-sphere-on-plane-rho0.5", "indirect", true, cacheSphereOnPlane},
      // 3 %: floor points a few cm from the contact point, in the shadow (130 lux) beside the
      // sunlit sphere (35 000 lux), carry standard errors of 1–2 % at every preset.
      indirect("sphere-on-plane-sun-sky", Method::kCache, 0.03, false),
      indirect("sphere-on-plane-sun-sky", Method::kPath, 0.03, false),
      indirect("uplit-room", Method::kCache, 0.02, false),
      indirect("uplit-room", Method::kPath, 0.02, false),
      indirect("furnished-office", Method::kCache, 0.02, false),
      indirect("furnished-office", Method::kPath, 0.02, false),
  };
}

}  // namespace candela::validation
