// Engine-core validation cases: area and distant sources against closed forms, the paper's
// sphere on a plane by quadrature, and integrating spheres (closed environments). Every scene is
// plain Radiance text, so each case can be re-run in Radiance (`rtrace -I -h` with -ab ≥ 1).
#include "engine/radiance/reader.h"
#include "engine/sensors.h"
#include "validation/analytic.h"
#include "validation/case_registry.h"
#include "engine/irradiance_estimator.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace candela::validation {

namespace {

struct Probe {
  std::string label;
  SensorPoint sensor;
  double referenceLux;
};

// Runs a Radiance-text scene at the probes and fills a result.
CaseResult runScene(const std::string& radText, const std::vector<Probe>& probes, const RunConfig& cfg,
                    std::string reference, double tolerance) {
  Scene scene;
  readRadianceText(radText, "<validation>", scene);
  const Tracer tracer(scene);
  std::vector<SensorPoint> pts;
  for (const Probe& p : probes) pts.push_back(p.sensor);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<IrradianceEstimate> est = computeIrradiance(tracer, pts, cfg.settings, cfg.threads);
  CaseResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.reference = std::move(reference);
  r.tolerance = tolerance;
  for (size_t i = 0; i < probes.size(); ++i)
    r.points.push_back({probes[i].label, probes[i].referenceLux, est[i].illuminanceLux(), est[i].standardErrorLux()});
  return r;
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

constexpr double kLux = kLumensPerWatt;  // grey scenes: lux = 179 × radiometric value

CaseResult sphereSource(const RunConfig& cfg) {
  // A light sphere r = 0.1 m, L = 100 W/sr/m², centre 2 m above the floor's origin.
  const std::string rad =
      "void light lamp 0 0 3 100 100 100\n"
      "lamp sphere bulb 0 0 4 0 0 2 0.1\n";
  std::vector<Probe> pr;
  for (double x : {0.0, 1.0, 2.0, 4.0}) {
    const double d = std::hypot(x, 2.0);
    pr.push_back({"x=" + fmt("%g", x) + " m", {Vec3(x, 0, 0), Vec3(0, 0, 1)},
                  kLux * analytic::sphereSource(100.0, 0.1, d, 2.0 / d)});
  }
  // A sensor tilted 60° towards the source.
  const Vec3 n(std::sin(degToRad(60.0)), 0.0, std::cos(degToRad(60.0)));
  const Vec3 toC = glm::normalize(Vec3(0, 0, 2) - Vec3(-1, 0, 0));
  pr.push_back({"tilted 60 deg", {Vec3(-1, 0, 0), n},
                kLux * analytic::sphereSource(100.0, 0.1, std::sqrt(5.0), glm::dot(n, toC))});
  return runScene(rad, pr, cfg, "E = pi L r^2 cos(theta) / d^2", 0.01);
}

CaseResult rectangleSource(const RunConfig& cfg) {
  // A 1.2 m × 0.6 m light panel 1.5 m above the floor, facing down (vertices clockwise from above).
  const std::string rad =
      "void light panel 0 0 3 50 50 50\n"
      "panel polygon p 0 0 12  -0.6 -0.3 1.5  -0.6 0.3 1.5  0.6 0.3 1.5  0.6 -0.3 1.5\n";
  std::vector<Probe> pr;
  for (auto [x, y] : {std::pair{0.0, 0.0}, {0.6, 0.3}, {1.0, 0.0}, {2.0, 1.0}, {0.3, -0.2}}) {
    pr.push_back({"(" + fmt("%g", x) + "," + fmt("%g", y) + ")", {Vec3(x, y, 0), Vec3(0, 0, 1)},
                  kLux * analytic::rectangleAbove(50.0, {-0.6, -0.3, 0.6, 0.3}, 1.5, x, y)});
  }
  return runScene(rad, pr, cfg, "configuration factor of a parallel rectangle (corner superposition)", 0.01);
}

CaseResult diskSource(const RunConfig& cfg) {
  // A light disk R = 0.5 m facing down at z = 2; sensors on its axis.
  const std::string rad =
      "void light disk 0 0 3 40 40 40\n"
      "disk ring d 0 0 8  0 0 2  0 0 -1  0 0.5\n";
  std::vector<Probe> pr;
  for (double h : {0.25, 0.5, 1.0, 2.0}) {
    pr.push_back({"h=" + fmt("%g", h) + " m", {Vec3(0, 0, 2.0 - h), Vec3(0, 0, 1)},
                  kLux * analytic::coaxialDisk(40.0, 0.5, h)});
  }
  return runScene(rad, pr, cfg, "E = pi L R^2 / (R^2 + h^2)", 0.01);
}

CaseResult uniformSky(const RunConfig& cfg) {
  // A uniform glow sky of L = 1 over an open grey plane; no ground sky below the horizon.
  const std::string rad =
      "void glow sky 0 0 4 1 1 1 0\n"
      "sky source skydome 0 0 4 0 0 1 180\n"
      "void plastic grey 0 0 5 0.3 0.3 0.3 0 0\n"
      "grey polygon ground 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";
  std::vector<Probe> pr;
  pr.push_back({"horizontal", {Vec3(0, 0, 0.01), Vec3(0, 0, 1)}, kLux * analytic::uniformSky(1.0)});
  // Tilted sensors 1 m up see the sky over (1 + cos β)/2 of π and the lit ground (ρ πL, seen as
  // luminance ρL) over the rest: E = πL[(1 + cos β)/2 + ρ(1 − cos β)/2].
  for (double beta : {45.0, 90.0}) {
    const double c = std::cos(degToRad(beta));
    const Vec3 n(std::sin(degToRad(beta)), 0.0, c);
    pr.push_back({"tilt " + fmt("%g", beta) + " deg", {Vec3(0, 0, 1), n},
                  kLux * kPi * (0.5 * (1 + c) + 0.3 * 0.5 * (1 - c))});
  }
  return runScene(rad, pr, cfg, "E = pi L (horizontal); sky and ground view factors (tilted)", 0.01);
}

CaseResult sphereOnPlane(const RunConfig& cfg, double rho) {
  // The paper's check: a sphere R = 1 m resting on an infinite black plane under a uniform sky.
  const std::string rad = "void glow sky 0 0 4 1 1 1 0\n"
                          "sky source skydome 0 0 4 0 0 1 180\n"
                          "void plastic black 0 0 5 0 0 0 0 0\n"
                          "void plastic ball 0 0 5 " + fmt("%g", rho) + " " + fmt("%g", rho) + " " +
                          fmt("%g", rho) + " 0 0\n"
                          "black polygon plane 0 0 12 -1e5 -1e5 0  1e5 -1e5 0  1e5 1e5 0  -1e5 1e5 0\n"
                          "ball sphere s 0 0 4 0 0 1 1\n";
  std::vector<Probe> pr;
  const double h = 0.01;  // sensors 1 cm above the floor
  for (double x : {0.25, 0.5, 1.0, 2.0, 4.0})
    pr.push_back({"x=" + fmt("%g", x) + " m", {Vec3(x, 0, h), Vec3(0, 0, 1)},
                  kLux * analytic::sphereOnPlane(rho, 1.0, 1.0, x, h)});
  return runScene(rad, pr, cfg, "quadrature of sky + sphere radiance rho L (1 + n_z)/2", 0.01);
}

CaseResult integratingSphere(const RunConfig& cfg, double rho) {
  // A closed sphere R = 1 m of reflectance ρ lit by a small light sphere (r = 2 cm) at its centre:
  // direct irradiance E_d = π L r² / d² is uniform on the wall, and E = E_d / (1 − ρ).
  const std::string rad = "void light lamp 0 0 3 1000 1000 1000\n"
                          "lamp sphere bulb 0 0 4 0 0 0 0.02\n"
                          "void plastic wall 0 0 5 " + fmt("%g", rho) + " " + fmt("%g", rho) + " " +
                          fmt("%g", rho) + " 0 0\n"
                          "wall bubble shell 0 0 4 0 0 0 1\n";
  std::vector<Probe> pr;
  const double d = 0.999;
  const double ed = analytic::sphereSource(1000.0, 0.02, d, 1.0);
  for (Vec3 dir : {Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0, 0.6, 0.8), Vec3(0, 0, 1)})
    pr.push_back({"(" + fmt("%g", dir.x) + "," + fmt("%g", dir.y) + "," + fmt("%g", dir.z) + ")",
                  {d * dir, -dir}, kLux * analytic::integratingSphere(ed, rho)});
  return runScene(rad, pr, cfg, "E = E_d / (1 - rho)", 0.02);
}

}  // namespace

std::vector<Case> engineCases() {
  return {
      {"sphere-source", "engine", true, sphereSource},
      {"rectangle-source", "engine", true, rectangleSource},
      {"disk-source", "engine", true, diskSource},
      {"uniform-sky", "engine", true, uniformSky},
      {"sphere-on-plane-rho0", "engine", true, [](const RunConfig& c) { return sphereOnPlane(c, 0.0); }},
      {"sphere-on-plane-rho0.5", "engine", true, [](const RunConfig& c) { return sphereOnPlane(c, 0.5); }},
      {"integrating-sphere-rho0.2", "engine", true, [](const RunConfig& c) { return integratingSphere(c, 0.2); }},
      {"integrating-sphere-rho0.5", "engine", true, [](const RunConfig& c) { return integratingSphere(c, 0.5); }},
      {"integrating-sphere-rho0.8", "engine", true, [](const RunConfig& c) { return integratingSphere(c, 0.8); }},
  };
}

}  // namespace candela::validation
