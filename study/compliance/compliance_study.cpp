#include "study/compliance/compliance_study.h"

#include "base/error.h"
#include "metrics/annual_glare.h"
#include "metrics/en17037_view_sunlight.h"
#include "photometry/sky_cie.h"
#include "reports/report_data.h"
#include "study/annual_glare.h"
#include "study/annual_glare_check.h"
#include "study/compliance/compliance_leed.h"
#include "study/sunlight_exposure.h"
#include "study/view_out.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

namespace candela {

namespace {

// "YYYY-MM-DDTHH:MM" (local standard time, the start of the hour) → the index of the weather
// hour that contains it (EPW records are hour-ending: 12:00 falls in hour 13).
int hourIndex(const AnnualSky& sky, const std::string& text, const FileLoc& loc) {
  const LocalTime t = parseLocalTime(text, loc);
  const int ending = std::min(24, static_cast<int>(std::floor(t.hourOfDay())) + 1);
  for (std::size_t h = 0; h < sky.hours.size(); ++h)
    if (sky.hours[h].month == t.month && sky.hours[h].day == t.day && sky.hours[h].hour == ending)
      return static_cast<int>(h);
  throw InputError(loc, "'check_hours': " + text + " is not an hour of the weather file");
}

}  // namespace

ComplianceTallies::ComplianceTallies(const CaseFile& c, std::vector<ComplianceGrid> grids, const AnnualSky& sky)
    : grids_(std::move(grids)) {
  const bool en17037 = std::any_of(c.compliance.begin(), c.compliance.end(),
                                   [](const ComplianceSpec& s) { return s.standard == ComplianceStandard::kEn17037; });
  if (!en17037) return;
  // Each glare view's check hours must be hours of this weather file: refused before any tracing.
  for (const ComplianceSpec& s : c.compliance)
    for (const GlareViewSpec& v : s.glareViews)
      for (const std::string& h : v.checkHours) hourIndex(sky, h, v.checkLoc);
  std::vector<double> diffuse;
  for (const AnnualHour& h : sky.hours) diffuse.push_back(h.diffuseHorizontalLux);
  const std::vector<char> daylight = candela::daylightHours(diffuse);
  daylightCount_ = static_cast<int>(std::count(daylight.begin(), daylight.end(), char{1}));
  medianDiffuseLux_ = medianDiffuseIlluminance(diffuse, daylight);
  for (std::size_t g = 0; g < grids_.size(); ++g) tallies_.emplace_back(daylight, provisionThresholds());
  df_.resize(grids_.size());
  overcast_ = patchMeanLuminance(CieOvercastSky(1.0), sky.subdivision, c.sky.groundReflectance);
}

void ComplianceTallies::addBlock(std::size_t first, std::size_t count, int hours, const float* total,
                                 const float* overcastLux) {
  if (!needsHours()) return;
  for (std::size_t g = 0; g < grids_.size(); ++g) {
    const std::size_t lo = std::max(grids_[g].first, first);
    const std::size_t hi = std::min(grids_[g].first + grids_[g].count, first + count);
    if (hi <= lo) continue;
    tallies_[g].add(total + (lo - first) * static_cast<std::size_t>(hours), static_cast<int>(hi - lo), hours);
    for (std::size_t s = lo; s < hi; ++s) df_[g].push_back(100.0 * overcastLux[s - first]);
  }
}

int ComplianceTallies::gridIndex(const std::string& name) const {
  for (std::size_t g = 0; g < grids_.size(); ++g)
    if (grids_[g].name == name) return static_cast<int>(g);
  return -1;
}

std::vector<int> complianceSpaces(const ComplianceSpec& s, const ComplianceTallies& t) {
  std::vector<int> out;
  if (s.spaces.empty())
    for (int g = 0; g < static_cast<int>(t.grids().size()); ++g) out.push_back(g);
  for (const std::string& name : s.spaces)
    if (const int g = t.gridIndex(name); g >= 0) out.push_back(g);
  return out;
}

namespace {

std::string levelText(En17037Level l) { return std::string(levelWords(l)); }

void provision(const ComplianceInputs& in, const ComplianceSpec& s, En17037Report& r, ComplianceReport& out) {
  const ComplianceTallies& t = *in.tallies;
  r.sensorFirst = s.aggregation == ProvisionAggregation::kSensorFirst;
  r.daylightHours = t.daylightHours();
  r.medianDiffuseLux = t.medianDiffuseLux();
  r.provisionLevel = r.provisionLevelOther = r.daylightFactorLevel = En17037Level::kHigh;
  for (int g : complianceSpaces(s, t)) {
    ProvisionSpaceReport sp;
    sp.space = t.grids()[static_cast<std::size_t>(g)].name;
    sp.illuminance = evaluateProvision(t.tally(g));
    const std::vector<double>& df = t.daylightFactorPct(g);
    if (!df.empty() && t.medianDiffuseLux() > 0.0) {
      sp.daylightFactor = evaluateDaylightFactor(df, t.medianDiffuseLux());
      double sum = 0.0;
      for (double v : df) sum += v;
      sp.meanDaylightFactorPct = sum / static_cast<double>(df.size());
      r.daylightFactorLevel = lowerLevel(r.daylightFactorLevel, sp.daylightFactor->level);
    } else {
      r.daylightFactorLevel = En17037Level::kNone;
    }
    const En17037Level chosen = r.sensorFirst ? sp.illuminance.sensorFirstLevel : sp.illuminance.hourFirstLevel;
    const En17037Level other = r.sensorFirst ? sp.illuminance.hourFirstLevel : sp.illuminance.sensorFirstLevel;
    r.provisionLevel = lowerLevel(r.provisionLevel, chosen);
    r.provisionLevelOther = lowerLevel(r.provisionLevelOther, other);
    r.spaces.push_back(std::move(sp));
  }
  const char* order = r.sensorFirst ? "sensor first" : "hour first";
  std::string line = "daylight provision (illuminance method, " + std::string(order) + "): " + levelText(r.provisionLevel);
  if (r.provisionLevel != r.provisionLevelOther)
    line += " (the other order, " + std::string(r.sensorFirst ? "hour first" : "sensor first") +
            ", gives " + levelText(r.provisionLevelOther) + ")";
  out.verdictLines.push_back(line + "; daylight-factor method: " + levelText(r.daylightFactorLevel));
  if (r.provisionLevel == En17037Level::kNone) out.verdict = "fail";
}

void sunlight(const ComplianceInputs& in, const Tracer& tracer, const ComplianceSpec& s, En17037Report& r,
              ComplianceReport& out) {
  const CivilDate date = s.sunlightDate ? *s.sunlightDate : CivilDate{in.weatherYear, 3, 21};
  r.sunlightMinAltitudeDefault = !s.sunlightMinAltitudeDeg;
  r.sunlightMinAltitudeDeg = s.sunlightMinAltitudeDeg ? *s.sunlightMinAltitudeDeg : en17037MinSunAltitudeDeg(in.site.latitudeDeg);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", date.year, date.month, date.day);
  r.sunlightDate = buf;
  SunlightOptions options;
  options.threads = in.threads;
  const SunlightExposure e =
      sunlightExposure(tracer, in.site, date, s.sunlightPoints, r.sunlightMinAltitudeDeg, options, s.sunlightDateLoc);
  r.sunAboveMinHours = e.sunAboveMinHours;
  En17037Level lowest = En17037Level::kHigh;
  for (const SunlightPoint& p : e.points) {
    SunlightReportPoint q{p.position, p.hours, {}, p.level};
    for (const SunlitInterval& i : p.intervals) q.intervals.emplace_back(i.startHour, i.endHour);
    r.sunlight.push_back(q);
    lowest = lowerLevel(lowest, p.level);
  }
  const double leastHours =
      std::min_element(e.points.begin(), e.points.end(), [](auto& a, auto& b) { return a.hours < b.hours; })->hours;
  out.verdictLines.push_back("exposure to sunlight on " + dateInWords(r.sunlightDate) + ": " + levelText(lowest) + " (" +
                             countOf(static_cast<long long>(e.points.size()), "reference point", "reference points") +
                             ", the least sunlit " + formatFixed(leastHours, 1) + " h)");
  if (lowest == En17037Level::kNone) out.verdict = "fail";
}

void viewOutPart(const ComplianceInputs& in, const Tracer& tracer, const ComplianceSpec& s, En17037Report& r,
                 ComplianceReport& out) {
  ViewOutOptions options;
  options.threads = in.threads;
  En17037Level lowest = En17037Level::kHigh;
  for (const ViewOut& v : viewOut(tracer, s.viewPoints, options)) {
    r.viewOut.push_back({v.eye, v.sightAngleDeg, v.totalSightAngleDeg, v.outsideDistanceM, v.medianOutsideDistanceM,
                         viewLayersName(v.layers), v.sightLevel, v.distanceLevel, v.layersLevel, v.level});
    lowest = lowerLevel(lowest, v.level);
  }
  out.verdictLines.push_back("view out: " + levelText(lowest) + " (the lowest of " +
                             countOf(static_cast<long long>(r.viewOut.size()), "eye position", "eye positions") + ")");
  if (lowest == En17037Level::kNone) out.verdict = "fail";
}

void glare(const ComplianceInputs& in, const Tracer& tracer, const ComplianceSpec& s, En17037Report& r,
           ComplianceReport& out) {
  r.glareExceedance = s.glareExceedance;
  AnnualGlareThresholds th;
  th.exceedanceShare = s.glareExceedance;
  En17037Level lowest = En17037Level::kHigh;
  std::vector<ViewGlareMetrics> all;
  // The views' blinds: LM-83's, operated as the entry's first space's (its hours of closed blinds).
  const std::vector<int> spaces = complianceSpaces(s, *in.tallies);
  const bool blinds = in.closedScene && in.blindsClosed && !spaces.empty();
  const std::vector<char>* closedHours = blinds ? &(*in.blindsClosed)[static_cast<std::size_t>(spaces.front())] : nullptr;
  std::unique_ptr<Tracer> closedTracer;
  if (blinds) closedTracer = std::make_unique<Tracer>(*in.closedScene);
  for (std::size_t i = 0; i < s.glareViews.size(); ++i) {
    const GlareViewSpec& v = s.glareViews[i];
    const GlareView view{"view" + std::to_string(i + 1), v.positionM, v.direction};
    std::vector<int> checkHours;
    for (const std::string& h : v.checkHours) checkHours.push_back(hourIndex(*in.sky, h, v.checkLoc));
    // Open and, with blinds, closed: the same stream, so both states see the same samples.
    const ViewAnnualGlare open = imagelessAnnualGlare(tracer, view, kAnnualGlareStreamBase + i, *in.glareJob);
    std::optional<ViewAnnualGlare> closed;
    std::vector<float> dgp = open.dgp;
    if (blinds) {
      closed = imagelessAnnualGlare(*closedTracer, view, kAnnualGlareStreamBase + i, *in.glareJob);
      dgp = combineByHour(open.dgp, closed->dgp, *closedHours);
    }
    const ViewGlareMetrics m = viewGlareMetrics(dgp, *in.occupied, th);
    all.push_back(m);
    GlareViewReport g;
    g.position = v.positionM;
    g.direction = v.direction;
    g.azimuthDeg = azAltFromDirection(v.direction, in.site.trueNorthDeg()).azimuthDeg;
    g.shareAbove035 = m.aboveHigh, g.shareAbove040 = m.aboveMedium, g.shareAbove045 = m.aboveMinimum;
    g.glareAutonomy = m.glareAutonomy;
    g.level = m.level;
    if (blinds) {
      g.blinds = in.blindsLabel;
      g.blindsSpace = in.tallies->grids()[static_cast<std::size_t>(spaces.front())].name;
      for (std::size_t h = 0; h < closedHours->size(); ++h)
        g.blindsClosedHours += ((*closedHours)[h] && (*in.occupied)[h]) ? 1 : 0;
    }
    // Each check hour rendered in the state its blinds were in.
    RenderedGlareOptions check;
    check.resolutionPx = v.checkResolutionPx;
    for (std::size_t k = 0; k < checkHours.size(); ++k) {
      const bool shut = blinds && (*closedHours)[static_cast<std::size_t>(checkHours[k])];
      const HourSceneInput hs{shut ? in.closedScene : in.scene, in.epw, in.sky, in.glareJob->northDeg,
                              in.caseFile->sky.groundReflectance};
      const GlareHourCheck c =
          checkChosenHours(hs, view, shut ? *closed : open, {checkHours[k]}, in.glareJob->settings, in.threads, {}, check)
              .at(0);
      g.checks.push_back({v.checkHours[k], shut, c.imagelessDgp, c.renderedDgp, c.imagelessEvLux, c.renderedEvLux});
    }
    r.glare.push_back(std::move(g));
    lowest = lowerLevel(lowest, m.level);
  }
  out.verdictLines.push_back("protection from glare: " + levelText(lowest) + " (the lowest of " +
                             countOf(static_cast<long long>(all.size()), "view", "views") +
                             ", imageless DGP every occupied hour; spatial disturbing glare " +
                             formatFixed(100.0 * spatialDisturbingGlare(all), 0) + " % of the views)");
  if (lowest == En17037Level::kNone) out.verdict = "fail";
}

ComplianceReport en17037(const ComplianceInputs& in, const ComplianceSpec& s) {
  ComplianceReport out;
  out.verdict = "pass";
  En17037Report r;
  const std::size_t parts = (in.tallies->needsHours() ? 1 : 0) + (s.sunlightPoints.empty() ? 0 : 1) +
                            (s.viewPoints.empty() ? 0 : 1) + (s.glareViews.empty() ? 0 : 1);
  const ObservedStep step(in.observer ? *in.observer : silentObserver(), "compliance " + s.name, parts);
  const auto timed = [&](const char* part, auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    out.timesS.emplace_back(part, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    (in.observer ? *in.observer : silentObserver()).progress(out.timesS.size());
  };
  if (in.tallies->needsHours()) timed("daylight_provision", [&] { provision(in, s, r, out); });
  if (!s.sunlightPoints.empty() || !s.viewPoints.empty() || !s.glareViews.empty()) {
    const Tracer tracer(*in.scene);
    if (!s.sunlightPoints.empty()) timed("sunlight_exposure", [&] { sunlight(in, tracer, s, r, out); });
    if (!s.viewPoints.empty()) timed("view_out", [&] { viewOutPart(in, tracer, s, r, out); });
    if (!s.glareViews.empty()) timed("protection_from_glare", [&] { glare(in, tracer, s, r, out); });
  }
  out.en17037 = std::move(r);
  return out;
}

}  // namespace

std::vector<ComplianceReport> evaluateCompliance(const ComplianceInputs& in) {
  std::vector<ComplianceReport> reports;
  for (const ComplianceSpec& s : in.caseFile->compliance) {
    ComplianceReport r;
    const auto t0 = std::chrono::steady_clock::now();
    if (s.standard == ComplianceStandard::kEn17037) {
      r = en17037(in, s);
    } else if (s.standard == ComplianceStandard::kLeedV41Option1) {
      const ObservedStep step(in.observer ? *in.observer : silentObserver(), "compliance " + s.name, 1);
      r = leedOption1(in, s);
      step(1);
    } else {
      r = leedOption2(in, s);  // its own step: the points at every time
    }
    if (s.standard != ComplianceStandard::kEn17037)
      r.timesS.emplace_back("total", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    r.name = s.name;
    r.standard = std::string(standardKey(s.standard));
    reports.push_back(std::move(r));
  }
  return reports;
}

}  // namespace candela
