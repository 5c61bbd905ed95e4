#include "study/compliance/compliance_leed.h"

#include "engine/sensors.h"
#include "metrics/leed.h"
#include "reports/report_data.h"
#include "study/annual_glare.h"
#include "study/case/case_scene.h"
#include "engine/irradiance_estimator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>

namespace candela {

namespace {

double spaceArea(const ComplianceGrid& g) { return gridFloorAreaM2(static_cast<int>(g.count), g.sensorAreaM2); }

}  // namespace

ComplianceReport leedOption1(const ComplianceInputs& in, const ComplianceSpec& s) {
  const ComplianceTallies& t = *in.tallies;
  std::vector<LeedSpace> spaces;
  for (int g : complianceSpaces(s, t)) {
    const AnnualGridReport& a = *(*in.annualGrids)[static_cast<std::size_t>(g)].annual;
    // LM-83: sDA with the shading operated (the grid's year: blinds or window states switched),
    // ASE without operable shading. With window states that is the reference year (every group
    // in its first state, the first entry of windowStates), not the switched year's ASE.
    const double ase = a.windowStates.empty() ? a.summary.ASE1000_250 : a.windowStates.front().summary.ASE1000_250;
    spaces.push_back({t.grids()[static_cast<std::size_t>(g)].name, spaceArea(t.grids()[static_cast<std::size_t>(g)]),
                      a.summary.sDA300_50, ase});
  }
  const LeedOption1Result r = leedV41Option1(spaces);
  ComplianceReport out;
  LeedReport l;
  for (const LeedSpaceResult& sp : r.spaces) {
    LeedSpaceReport q;
    q.space = sp.name, q.areaM2 = sp.floorAreaM2, q.sdaPct = sp.sdaPercent, q.asePct = sp.asePercent;
    q.aseAbove10 = sp.aseAbove10;
    l.aseExceeds10Percent = l.aseExceeds10Percent || sp.aseAbove10;
    l.spaces.push_back(q);
  }
  l.averagePct = r.averageSdaPercent;
  l.points = r.points;
  l.eachSpaceAbove55 = r.eachSpaceAtLeast55;
  out.verdict = r.points > 0 ? "pass" : "fail";
  out.verdictLines.push_back(r.verdict);
  out.leed = std::move(l);
  return out;
}

int leedOption2Points(double averageInRangePct) {
  return averageInRangePct >= 90.0 ? 3 : averageInRangePct >= 75.0 ? 2 : averageInRangePct >= 55.0 ? 1 : 0;
}

namespace {

// The case under the CIE clear sky with the site's sun at `time`, their intensities `light`, its
// geometry alone (LEED's daylight; no luminaires), at the site the annual study used.
CaseFile clearSkyCase(const ComplianceInputs& in, const std::string& time, const EquinoxLight& light) {
  CaseFile c = *in.caseFile;
  c.luminaires.clear();
  c.luminaireEntries.clear();
  c.compliance.clear();
  c.sky = SkySpec{};
  c.sky.present = true;
  c.sky.type.kind = SkyKind::kCieClear;
  c.sky.time = time;
  c.sky.groundReflectance = in.caseFile->sky.groundReflectance;
  c.sky.diffuseHorizontalIlluminanceLux = light.diffuseHorizontalLux;
  c.sky.directNormalIlluminanceLux = light.directNormalLux;
  c.sky.loc = in.caseFile->sky.loc;
  c.sky.timeLoc = in.caseFile->sky.loc;
  c.site = SiteSpec{};
  c.site.present = true;
  c.site.latitudeDeg = in.site.latitudeDeg;
  c.site.longitudeDeg = in.site.longitudeDeg;
  c.site.elevationM = in.site.elevationM;
  c.site.timezoneHours = in.site.timezoneHours;
  c.site.northDeg = in.site.trueNorthDeg();
  c.site.loc = in.caseFile->sky.loc;
  return c;
}

}  // namespace

EquinoxLight equinoxWindowLight(const AnnualSky& sky, const CivilDate& date, double hourOfDay) {
  const int equinoxMonth = date.month <= 6 ? 3 : 9;
  int equinoxDay = -1;
  for (const AnnualHour& h : sky.hours)
    if (h.month == equinoxMonth && h.day == 21) equinoxDay = h.dayOfYear;
  if (equinoxDay < 0) throw std::invalid_argument("the weather year has no 21 March or 21 September");
  // The instant between the middles of the records ending i + 1 and i + 2 (middles at i + 0.5, i + 1.5).
  const double u = hourOfDay - 0.5;
  const int i = static_cast<int>(std::floor(u));
  const double w = u - i;
  const int first = std::clamp(i + 1, 1, 24), second = std::clamp(i + 2, 1, 24);
  EquinoxLight out;
  for (const AnnualHour& h : sky.hours) {
    if (std::abs(h.dayOfYear - equinoxDay) > 15) continue;
    const double weight = (h.hour == first ? 1.0 - w : 0.0) + (h.hour == second ? w : 0.0);
    out.diffuseHorizontalLux += weight * h.diffuseHorizontalLux;
    out.directNormalLux += weight * h.directNormalLux;
    out.days += h.hour == first ? 1 : 0;
  }
  if (out.days > 0) {
    out.diffuseHorizontalLux /= out.days;
    out.directNormalLux /= out.days;
  }
  return out;
}

ComplianceReport leedOption2(const ComplianceInputs& in, const ComplianceSpec& s) {
  const ComplianceTallies& t = *in.tallies;
  const std::vector<int> grids = complianceSpaces(s, t);
  const std::vector<CivilDate> dates = leedOption2Dates(s, in.weatherYear);
  LeedReport l;
  // One batch of samples per point: the share in range carries each point's standard error
  // (inRangeShare), so the preset's target error, which sends the points that sun patches make
  // noisy to 16 batches, would multiply the time (the office demo: 67 min) for a share that
  // moves by less than its own standard error.
  TraceSettings settings = in.pointSettings;
  settings.targetRelativeError = 0.0;
  std::size_t perTime = 0;
  for (int g : grids) perTime += t.grids()[static_cast<std::size_t>(g)].count;
  const ObservedStep step(in.observer ? *in.observer : silentObserver(), "compliance " + s.name,
                          perTime * dates.size() * s.leedHours.size());
  std::size_t done = 0;
  for (int g : grids) {
    LeedSpaceReport q;
    q.space = t.grids()[static_cast<std::size_t>(g)].name;
    q.areaM2 = spaceArea(t.grids()[static_cast<std::size_t>(g)]);
    l.spaces.push_back(q);
  }
  for (const CivilDate& d : dates)
    for (double hour : s.leedHours) {
      char time[32];
      const int minutes = static_cast<int>(std::lround(hour * 60.0));
      std::snprintf(time, sizeof time, "%04d-%02d-%02dT%02d:%02d", d.year, d.month, d.day, minutes / 60, minutes % 60);
      l.times.push_back(time);
      const EquinoxLight light = equinoxWindowLight(*in.sky, d, hour);
      l.skyByTime.push_back({light.diffuseHorizontalLux, light.directNormalLux, light.days});
      const std::unique_ptr<Scene> scene = loadCaseScene(clearSkyCase(in, time, light));
      const Tracer tracer(*scene);
      for (std::size_t k = 0; k < grids.size(); ++k) {
        const ComplianceGrid& cg = t.grids()[static_cast<std::size_t>(grids[k])];
        std::vector<SensorPoint> points;
        for (std::size_t i = cg.first; i < cg.first + cg.count; ++i)
          points.push_back({(*in.positions)[i], (*in.normals)[i]});
        std::vector<double> lux, sigma;
        const auto progress = [&step, done](std::size_t n) { step(done + n); };
        double sum = 0.0, variance = 0.0;
        for (const IrradianceEstimate& e : computeIrradiance(tracer, points, settings, in.threads, progress)) {
          lux.push_back(e.illuminanceLux());
          sigma.push_back(e.standardErrorLux());
          sum += lux.back();
          variance += sigma.back() * sigma.back();
        }
        const double n = static_cast<double>(std::max<std::size_t>(1, lux.size()));
        l.spaces[k].meanLuxByTime.push_back(sum / n);
        l.spaces[k].meanLuxByTimeStandardError.push_back(std::sqrt(variance) / n);
        const InRangeShare share = inRangeShare(lux, sigma, 300.0, 3000.0);
        l.spaces[k].inRangeByTimePct.push_back(share.sharePct);
        l.spaces[k].inRangeByTimeStandardErrorPct.push_back(share.standardErrorPct);
        done += points.size();
      }
    }
  double area = 0.0, weighted = 0.0, weightedVariance = 0.0;
  l.eachSpaceAbove55 = true;
  for (LeedSpaceReport& q : l.spaces) {
    double sum = 0.0, variance = 0.0;
    for (double v : q.inRangeByTimePct) sum += v;
    for (double se : q.inRangeByTimeStandardErrorPct) variance += se * se;
    const double times = static_cast<double>(q.inRangeByTimePct.size());
    q.inRangePct = times > 0.0 ? sum / times : 0.0;
    q.inRangeStandardErrorPct = times > 0.0 ? std::sqrt(variance) / times : 0.0;
    area += q.areaM2;
    weighted += q.areaM2 * q.inRangePct;
    weightedVariance += q.areaM2 * q.areaM2 * q.inRangeStandardErrorPct * q.inRangeStandardErrorPct;
    l.eachSpaceAbove55 = l.eachSpaceAbove55 && q.inRangePct >= 55.0;
  }
  l.averagePct = area > 0.0 ? weighted / area : 0.0;
  l.averageStandardErrorPct = area > 0.0 ? std::sqrt(weightedVariance) / area : 0.0;
  l.points = leedOption2Points(l.averagePct);
  ComplianceReport out;
  out.verdict = l.points > 0 ? "pass" : "fail";
  out.verdictLines.push_back("LEED v4.1 EQ Daylight option 2: " + countOf(l.points, "point", "points") + " (" +
                             formatFixed(l.averagePct, 1) + " % of the floor area between 300 and 3000 lx, standard error " +
                             formatFixed(l.averageStandardErrorPct, 1) + " %, mean of " +
                             countOf(static_cast<long long>(l.times.size()), "clear-sky time", "clear-sky times") + ")");
  out.leed = std::move(l);
  return out;
}

}  // namespace candela
