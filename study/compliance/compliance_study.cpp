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

// The scenes the glare views see hour by hour: the entry's scene (index 0: blinds open, every
// window group in its first state) and, with LM-83's blinds, the closed scene, or with window
// states every combination of the groups' states that the entry's first space's occupied hours
// use (at most kMaxGlareStateScenes).
struct ViewScenes {
  std::vector<uint16_t> sceneOf;               // per hour: the index of its scene
  std::vector<std::vector<int>> choices;       // window states: each scene's state per group
  std::string label, space;                    // as GlareViewReport's blinds and blindsSpace
  std::string note;                            // why the views stay in the first scene, when they do
  std::size_t count() const { return std::max<std::size_t>(1, choices.size()); }
};

ViewScenes viewScenes(const ComplianceInputs& in, const ComplianceSpec& s) {
  ViewScenes v;
  const std::vector<int> spaces = complianceSpaces(s, *in.tallies);
  if (spaces.empty()) return v;
  const std::size_t space = static_cast<std::size_t>(spaces.front());
  const std::size_t hours = in.occupied->size();
  if (in.closedScene && in.blindsClosed) {  // LM-83's blinds, as the entry's first space operates them
    const std::vector<char>& closed = (*in.blindsClosed)[space];
    v.sceneOf.assign(closed.begin(), closed.end());
    v.choices = {{0}, {1}};
    v.label = in.blindsLabel;
  } else if (in.windowStates && in.stateScene) {
    const std::vector<std::vector<uint8_t>>& stateOf = (*in.windowStates)[space];
    v.choices = {std::vector<int>(stateOf.size(), 0)};
    v.sceneOf.assign(hours, 0);
    // The hours judged (occupied) and the views' check hours are in their states; the others are
    // not looked at and stay in the first scene.
    std::vector<char> used(in.occupied->begin(), in.occupied->end());
    for (const GlareViewSpec& g : s.glareViews)
      for (const std::string& h : g.checkHours) used[static_cast<std::size_t>(hourIndex(*in.sky, h, g.checkLoc))] = 1;
    std::vector<int> choice(stateOf.size(), 0);
    for (std::size_t h = 0; h < hours; ++h) {
      if (!used[h]) continue;
      for (std::size_t q = 0; q < stateOf.size(); ++q) choice[q] = stateOf[q][h];
      const auto at = std::find(v.choices.begin(), v.choices.end(), choice);
      if (at == v.choices.end() && v.choices.size() == kMaxGlareStateScenes) {
        v.note = "more than " + std::to_string(kMaxGlareStateScenes) +
                 " combinations of window states or closed groups in the hours judged: the views see the first "
                 "states, blinds open";
        v.sceneOf.assign(hours, 0);
        v.choices.resize(1);
        break;
      }
      v.sceneOf[h] = static_cast<uint16_t>(at - v.choices.begin());
      if (at == v.choices.end()) v.choices.push_back(choice);
    }
    v.label = in.blindsLabel;
  } else {
    return v;
  }
  v.space = in.tallies->grids()[space].name;
  return v;
}

// Scene i of v: the entry's, LM-83's closed one, or a combination of window states (made in keep).
const Scene* viewScene(const ComplianceInputs& in, const ViewScenes& v, std::size_t i, std::unique_ptr<Scene>& keep) {
  if (i == 0) return in.scene;
  if (in.closedScene && in.blindsClosed) return in.closedScene;
  keep = in.stateScene(v.choices[i]);
  return keep.get();
}

void glare(const ComplianceInputs& in, const Tracer& tracer, const ComplianceSpec& s, En17037Report& r,
           ComplianceReport& out) {
  r.glareExceedance = s.glareExceedance;
  AnnualGlareThresholds th;
  th.exceedanceShare = s.glareExceedance;
  En17037Level lowest = En17037Level::kHigh;
  std::vector<ViewGlareMetrics> all;
  // The views' blinds or window states, operated as the entry's first space's.
  const ViewScenes scenes = viewScenes(in, s);
  const bool operated = scenes.count() > 1;
  // Every view in every scene, a scene at a time (the same stream in each, so that every scene
  // sees the same samples).
  std::vector<std::vector<ViewAnnualGlare>> year(s.glareViews.size());
  for (std::size_t i = 0; i < scenes.count(); ++i) {
    std::unique_ptr<Scene> keep;
    std::unique_ptr<Tracer> own;
    const Tracer* t = &tracer;
    if (i > 0) t = (own = std::make_unique<Tracer>(*viewScene(in, scenes, i, keep))).get();
    for (std::size_t vi = 0; vi < s.glareViews.size(); ++vi) {
      const GlareViewSpec& v = s.glareViews[vi];
      const GlareView view{"view" + std::to_string(vi + 1), v.positionM, v.direction};
      year[vi].push_back(imagelessAnnualGlare(*t, view, kAnnualGlareStreamBase + vi, *in.glareJob));
    }
  }
  for (std::size_t i = 0; i < s.glareViews.size(); ++i) {
    const GlareViewSpec& v = s.glareViews[i];
    const GlareView view{"view" + std::to_string(i + 1), v.positionM, v.direction};
    std::vector<int> checkHours;
    for (const std::string& h : v.checkHours) checkHours.push_back(hourIndex(*in.sky, h, v.checkLoc));
    std::vector<float> dgp = year[i][0].dgp;
    for (std::size_t h = 0; h < dgp.size() && operated; ++h) dgp[h] = year[i][scenes.sceneOf[h]].dgp[h];
    const ViewGlareMetrics m = viewGlareMetrics(dgp, *in.occupied, th);
    all.push_back(m);
    GlareViewReport g;
    g.position = v.positionM;
    g.direction = v.direction;
    g.azimuthDeg = azAltFromDirection(v.direction, in.site.trueNorthDeg()).azimuthDeg;
    g.shareAbove035 = m.aboveHigh, g.shareAbove040 = m.aboveMedium, g.shareAbove045 = m.aboveMinimum;
    g.glareAutonomy = m.glareAutonomy;
    g.level = m.level;
    if (operated || !scenes.note.empty()) {
      g.blinds = scenes.label;
      g.blindsSpace = scenes.space;
      g.blindsNote = scenes.note;
      for (std::size_t h = 0; h < scenes.sceneOf.size(); ++h)
        g.blindsClosedHours += (scenes.sceneOf[h] != 0 && (*in.occupied)[h]) ? 1 : 0;
    }
    // Each check hour rendered in the scene of that hour.
    RenderedGlareOptions check;
    check.resolutionPx = v.checkResolutionPx;
    for (std::size_t k = 0; k < checkHours.size(); ++k) {
      const std::size_t at = operated ? scenes.sceneOf[static_cast<std::size_t>(checkHours[k])] : 0;
      std::unique_ptr<Scene> keep;
      const HourSceneInput hs{viewScene(in, scenes, at, keep), in.epw, in.sky, in.glareJob->northDeg,
                              in.caseFile->sky.groundReflectance};
      const GlareHourCheck c =
          checkChosenHours(hs, view, year[i][at], {checkHours[k]}, in.glareJob->settings, in.threads, {}, check).at(0);
      g.checks.push_back({v.checkHours[k], at != 0, c.imagelessDgp, c.renderedDgp, c.imagelessEvLux, c.renderedEvLux});
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
