#include "photometry/luminaire_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace candela {

namespace {

double planeIntensity(const PhotometricWeb& web, double cDeg, double angleDeg) {
  return angleDeg >= 0.0 ? web.intensityCd(cDeg, angleDeg) : web.intensityCd(cDeg + 180.0, -angleDeg);
}

std::string printf1(const char* f, double a) {
  char buf[128];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

}  // namespace

PlaneCurve planeCurve(const PhotometricWeb& web, double cDeg, double stepDeg) {
  PlaneCurve p;
  const int n = int(std::lround(180.0 / stepDeg));
  for (int k = -n; k <= n; ++k) {
    const double a = 180.0 * k / n;
    p.angleDeg.push_back(a);
    p.intensityCd.push_back(planeIntensity(web, cDeg, a));
  }
  return p;
}

double spreadAngleDeg(const PhotometricWeb& web, double cDeg, double fraction) {
  const double step = 0.05;
  const PlaneCurve p = planeCurve(web, cDeg, step);
  const auto& v = p.intensityCd;
  const size_t m = size_t(std::max_element(v.begin(), v.end()) - v.begin());
  if (!(v[m] > 0.0)) return 0.0;
  const double t = fraction * v[m];
  double right = std::numeric_limits<double>::quiet_NaN(), left = right;
  for (size_t k = m + 1; k < v.size(); ++k)
    if (v[k] < t) {  // crossing between k-1 and k
      right = p.angleDeg[k - 1] + step * (v[k - 1] - t) / (v[k - 1] - v[k]);
      break;
    }
  for (size_t k = m; k-- > 0;)
    if (v[k] < t) {
      left = p.angleDeg[k + 1] - step * (v[k + 1] - t) / (v[k + 1] - v[k]);
      break;
    }
  if (std::isnan(right) || std::isnan(left)) return 360.0;
  return std::min(360.0, right - left);
}

LuminaireSummary summarizeLuminaire(const PhotometricWeb& web) {
  LuminaireSummary s;
  const PhotometricInfo& info = web.info();
  s.fileName = info.fileName;
  s.format = web.format();
  const auto kw = [&](const char* k) {
    const auto it = info.keywords.find(k);
    return it == info.keywords.end() ? std::string() : it->second.substr(0, it->second.find('\n'));
  };
  s.luminaire = kw("LUMINAIRE");
  s.manufacturer = kw("MANUFAC");
  s.type = web.type();
  s.totalLumens = web.totalLumens();
  s.lampLumens = web.lampLumens();
  s.lightOutputRatio = web.lightOutputRatio();
  s.maxIntensityCd = web.maxIntensityCd();
  s.maxDirection = web.maxIntensityDirection();
  s.beamC0Deg = spreadAngleDeg(web, 0.0, 0.5);
  s.fieldC0Deg = spreadAngleDeg(web, 0.0, 0.1);
  s.beamC90Deg = spreadAngleDeg(web, 90.0, 0.5);
  s.fieldC90Deg = spreadAngleDeg(web, 90.0, 0.1);
  s.zonalLumens = web.zonalLumens(10.0);
  s.downwardLumens = web.lumensBetween(0.0, 90.0);
  s.upwardLumens = web.lumensBetween(90.0, 180.0);
  s.inputWatts = web.inputWatts();
  s.efficacyLmPerW = s.inputWatts > 0.0 ? s.totalLumens / s.inputWatts
                                        : std::numeric_limits<double>::quiet_NaN();
  s.openingWidthM = web.openingWidthM();
  s.openingLengthM = web.openingLengthM();
  s.openingHeightM = web.openingHeightM();
  s.openingShape = web.openingShape();
  return s;
}

std::string formatSummary(const LuminaireSummary& s) {
  std::string o;
  const auto line = [&o](const std::string& label, const std::string& value) {
    std::string l = label + ":";
    l.resize(std::max<size_t>(l.size() + 1, 22), ' ');
    o += l + value + "\n";
  };
  line("File", s.fileName);
  line("Format", s.format + (s.type == PhotometricType::kB ? " (type B)" : " (type C)"));
  if (!s.luminaire.empty()) line("Luminaire", s.luminaire);
  if (!s.manufacturer.empty()) line("Manufacturer", s.manufacturer);
  line("Luminous flux", printf1("%.1f lm", s.totalLumens));
  if (s.lampLumens > 0.0) {
    line("Lamp lumens", printf1("%.1f lm", s.lampLumens));
    line("Light output ratio", printf1("%.1f %%", 100.0 * s.lightOutputRatio));
  } else {
    line("Lamp lumens", "absolute photometry (not given)");
  }
  line("Maximum intensity", printf1("%.1f cd", s.maxIntensityCd) + printf1(" at C %.1f deg", s.maxDirection.cDeg) +
                                printf1(", gamma %.1f deg", s.maxDirection.gammaDeg));
  line("Beam angle (50%)", printf1("C0-C180 %.1f deg", s.beamC0Deg) + printf1(", C90-C270 %.1f deg", s.beamC90Deg));
  line("Field angle (10%)", printf1("C0-C180 %.1f deg", s.fieldC0Deg) + printf1(", C90-C270 %.1f deg", s.fieldC90Deg));
  line("Downward flux", printf1("%.1f lm", s.downwardLumens) +
                            printf1(" (%.1f %%)", s.totalLumens > 0 ? 100.0 * s.downwardLumens / s.totalLumens : 0.0));
  line("Upward flux", printf1("%.1f lm", s.upwardLumens));
  if (s.inputWatts > 0.0) {
    line("Input power", printf1("%.1f W", s.inputWatts));
    line("Efficacy", printf1("%.1f lm/W", s.efficacyLmPerW));
  } else {
    line("Input power", "not given");
  }
  line("Luminous opening", std::string(openingShapeName(s.openingShape)) +
                               printf1(", width %.3f m", s.openingWidthM) + printf1(", length %.3f m", s.openingLengthM) +
                               printf1(", height %.3f m", s.openingHeightM));
  o += "Zonal lumens (gamma from nadir):\n";
  for (size_t k = 0; k < s.zonalLumens.size(); ++k) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "  %3d-%3d deg  %10.1f lm  %5.1f %%\n", int(10 * k), int(10 * (k + 1)),
                  s.zonalLumens[k], s.totalLumens > 0 ? 100.0 * s.zonalLumens[k] / s.totalLumens : 0.0);
    o += buf;
  }
  return o;
}

}  // namespace candela
