#include "study/sunlight_exposure.h"

#include "base/parallel.h"
#include "photometry/sun_spa.h"
#include "study/sight_line.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace candela {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEdgeToleranceHours = 1.0 / 3600.0;  // bisection stops within 1 s

// The sun at one local standard hour of the day: apparent altitude (SPA, refraction at the
// report's standard atmosphere) and unit direction in the model frame.
struct SunSample {
  double hour = 0.0;
  double altitudeDeg = -90.0;
  Vec3 dirModel{0.0, 0.0, 1.0};
};

class SunPath {
 public:
  SunPath(const Site& site, const CivilDate& date) : site_(site), date_(date) {
    LocalTime t;
    t.year = date.year;
    t.month = date.month;
    t.day = date.day;
    deltaTSec_ = estimateDeltaTSec(date.year + (t.dayOfYear() - 0.5) / 365.25);
  }

  SunSample at(double hour) const {
    SpaInput in;
    in.year = date_.year;
    in.month = date_.month;
    in.day = date_.day;
    in.hourOfDay = hour;
    in.timezoneHours = site_.timezoneHours;
    in.latitudeDeg = site_.latitudeDeg;
    in.longitudeDeg = site_.longitudeDeg;
    in.elevationM = site_.elevationM;
    in.deltaTSec = deltaTSec_;
    const SpaResult r = computeSunPositionOnly(in);
    SunSample s;
    s.hour = hour;
    s.altitudeDeg = r.altitudeDeg;
    s.dirModel = directionFromAzAlt(r.azimuthDeg, r.altitudeDeg, site_.trueNorthDeg());
    return s;
  }

 private:
  Site site_;
  CivilDate date_;
  double deltaTSec_ = 69.0;
};

// The stretches of the day during which state(sun) holds: the samples' runs, each change located
// by bisection between the two samples around it (or put halfway without refinement).
template <class State>
std::vector<SunlitInterval> intervalsWhere(const std::vector<SunSample>& day, const SunPath& path, bool refine,
                                           const State& state) {
  std::vector<SunlitInterval> out;
  bool prev = false;
  for (size_t i = 0; i < day.size(); ++i) {
    const bool now = state(day[i]);
    if (i == 0 && now) out.push_back({day[0].hour, day[0].hour});
    if (i > 0 && now != prev) {
      double lo = day[i - 1].hour, hi = day[i].hour;
      while (refine && hi - lo > kEdgeToleranceHours) {
        const double mid = 0.5 * (lo + hi);
        (state(path.at(mid)) == prev ? lo : hi) = mid;
      }
      const double h = 0.5 * (lo + hi);
      if (now) out.push_back({h, h});
      else out.back().endHour = h;
    }
    prev = now;
  }
  if (prev) out.back().endHour = day.back().hour;
  return out;
}

double totalHours(const std::vector<SunlitInterval>& intervals) {
  double h = 0.0;
  for (const SunlitInterval& iv : intervals) h += iv.endHour - iv.startHour;
  return h;
}

SunlightPoint pointExposure(const Tracer& tracer, const Vec3& p, const std::vector<SunSample>& day,
                            const SunPath& path, double minAltitudeDeg, bool refine) {
  uint64_t rays = 0;
  auto sunlit = [&](const SunSample& s) {
    return s.altitudeDeg >= minAltitudeDeg && !traceSightLine(tracer, p, s.dirModel, kInf, rays).blocked;
  };
  SunlightPoint out;
  out.position = p;
  out.intervals = intervalsWhere(day, path, refine, sunlit);
  out.hours = totalHours(out.intervals);
  out.level = sunlightExposureLevel(out.hours);
  tracer.addRays(rays);
  return out;
}

}  // namespace

void checkSunlightDate(const CivilDate& d, const FileLoc& loc) {
  const std::string text = std::to_string(d.year) + "-" + std::to_string(d.month) + "-" + std::to_string(d.day);
  if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > daysInMonth(d.year, d.month))
    throw InputError(loc, "sunlight date " + text + " is not a date");
  if (!inSunlightDateRange(d))
    throw InputError(loc, "sunlight date " + text +
                              " must lie between 1 February and 21 March (EN 17037 5.3: the reference day)");
}

SunlightExposure sunlightExposure(const Tracer& tracer, const Site& site, const CivilDate& date,
                                  const std::vector<Vec3>& points, double minAltitudeDeg,
                                  const SunlightOptions& options, const FileLoc& dateLoc) {
  checkSunlightDate(date, dateLoc);
  if (!(options.stepMinutes > 0.0 && options.stepMinutes <= 60.0))
    throw std::invalid_argument("sunlight step must be in (0, 60] minutes");
  if (!(minAltitudeDeg >= -90.0 && minAltitudeDeg <= 90.0))
    throw std::invalid_argument("minimum sun altitude must be in [-90, 90] degrees");

  const SunPath path(site, date);
  // Samples at every step from 0:00, the last one at 24:00 exactly.
  const size_t steps = static_cast<size_t>(std::ceil(24.0 * 60.0 / options.stepMinutes - 1e-9));
  std::vector<SunSample> day(steps + 1);
  for (size_t i = 0; i <= steps; ++i) day[i] = path.at(std::min(24.0, i * options.stepMinutes / 60.0));

  SunlightExposure out;
  out.date = date;
  out.minAltitudeDeg = minAltitudeDeg;
  out.sunAboveMinHours = totalHours(intervalsWhere(
      day, path, options.refineEdges, [&](const SunSample& s) { return s.altitudeDeg >= minAltitudeDeg; }));
  out.points.resize(points.size());
  parallelFor(points.size(), options.threads, [&](size_t i) {
    out.points[i] = pointExposure(tracer, points[i], day, path, minAltitudeDeg, options.refineEdges);
  });
  return out;
}

}  // namespace candela
