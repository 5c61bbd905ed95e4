// Luminaire validation: a photometric file traced as a point source (inverse-square and cosine
// laws on a plane and a wall) and a Lambertian panel in its near field (an area source).
#include "engine/luminaire_source.h"
#include "engine/sensors.h"
#include "photometry/ies_lm63.h"
#include "validation/analytic.h"
#include "validation/case_registry.h"

#include <chrono>
#include <cmath>
#include <sstream>

namespace candela::validation {

namespace {

// An IES LM-63-2002 type C file written here: I(C, γ) tabulated every 5° in γ and 15° in C, with
// a luminous opening of width × length metres (0: a point).
std::string iesText(double (*intensity)(double c, double g), double widthM, double lengthM) {
  std::ostringstream o;
  o << "IESNA:LM-63-2002\n[TEST] analytic distribution written by candela validate\nTILT=NONE\n";
  o << "1 -1 1 19 25 1 2 " << widthM << " " << lengthM << " 0\n1 1 50\n";
  for (int g = 0; g <= 90; g += 5) o << g << " ";
  o << "\n";
  for (int c = 0; c <= 360; c += 15) o << c << " ";
  o << "\n";
  o.precision(12);
  for (int c = 0; c <= 360; c += 15) {
    for (int g = 0; g <= 90; g += 5) o << intensity(c, g) << " ";
    o << "\n";
  }
  return o.str();
}

double asymmetric(double c, double g) {
  return 1000.0 * std::cos(degToRad(g)) * (1.0 + 0.5 * std::cos(degToRad(c - 30.0)));
}
double lambertian(double, double g) { return 1000.0 * std::cos(degToRad(g)); }

CaseResult runLuminaire(const std::string& ies, const Vec3& pos, const std::vector<SensorPoint>& pts,
                        const std::vector<std::string>& labels, const std::vector<double>& refs,
                        const RunConfig& cfg, std::string reference, double tol, int lightSamples = 0) {
  Scene scene;
  LuminaireMounting p;
  p.positionM = pos;
  scene.luminaires.push_back(
      placeLuminaire(std::make_shared<const PhotometricWeb>(parseIes(ies, "<validation>.ies", ".")), p));
  const Tracer tracer(scene);
  TraceSettings s = cfg.settings;
  if (lightSamples > 0) s.lightSamples = std::max(s.lightSamples, lightSamples);
  const auto t0 = std::chrono::steady_clock::now();
  const auto est = computeIrradiance(tracer, pts, s, cfg.threads);
  CaseResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.reference = std::move(reference);
  r.tolerance = tol;
  for (size_t i = 0; i < pts.size(); ++i)
    r.points.push_back({labels[i], refs[i], est[i].illuminanceLux(), est[i].standardErrorLux()});
  return r;
}

CaseResult pointLaw(const RunConfig& cfg) {
  // Aimed down 3 m above the floor; sensors in directions on the file's grid (where bilinear
  // interpolation is exact): E = I(C, γ) cos ι / d².
  const double h = 3.0;
  std::vector<SensorPoint> pts;
  std::vector<std::string> labels;
  std::vector<double> refs;
  for (double c : {30.0, 135.0, 270.0}) {
    for (double g : {15.0, 40.0, 60.0}) {
      const Vec3 dir(std::sin(degToRad(g)) * std::cos(degToRad(c)), std::sin(degToRad(g)) * std::sin(degToRad(c)),
                     -std::cos(degToRad(g)));
      const double d = h / std::cos(degToRad(g));
      pts.push_back({Vec3(0, 0, h) + d * dir, Vec3(0, 0, 1)});
      labels.push_back("C" + std::to_string(static_cast<int>(c)) + " g" + std::to_string(static_cast<int>(g)));
      refs.push_back(asymmetric(c, g) * std::cos(degToRad(g)) / (d * d));
    }
  }
  return runLuminaire(iesText(asymmetric, 0.0, 0.0), Vec3(0, 0, h), pts, labels, refs, cfg,
                      "E = I(C, gamma) cos(i) / d^2", 0.005);
}

CaseResult nearField(const RunConfig& cfg) {
  // A Lambertian 0.6 m × 0.6 m panel (I = 1000 cos γ cd, so L = I0/A) 0.3–1.5 m above sensors:
  // Lambert's configuration factor of the square, not the point law.
  const double l = 1000.0 / 0.36;
  std::vector<SensorPoint> pts;
  std::vector<std::string> labels;
  std::vector<double> refs;
  for (auto [x, h] : {std::pair{0.0, 0.3}, {0.3, 0.3}, {0.5, 0.6}, {0.0, 1.5}}) {
    pts.push_back({Vec3(x, 0.0, 2.0 - h), Vec3(0, 0, 1)});
    labels.push_back("x=" + std::to_string(x).substr(0, 3) + " h=" + std::to_string(h).substr(0, 3));
    refs.push_back(analytic::rectangleAbove(l, {-0.3, -0.3, 0.3, 0.3}, h, x, 0.0));
  }
  return runLuminaire(iesText(lambertian, 0.6, 0.6), Vec3(0, 0, 2.0), pts, labels, refs, cfg,
                      "Lambert: E = L pi F of the 0.6 m square opening", 0.01, 1024);
}

}  // namespace

std::vector<Case> luminaireCases() {
  return {
      {"luminaire-point-law", "luminaires", true, pointLaw},
      {"luminaire-near-field-panel", "luminaires", true, nearField},
  };
}

}  // namespace candela::validation
