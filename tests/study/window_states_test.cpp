// Window states (docs/annual.md "Window states"): the [[window_group]] states, schedule and
// sun_grid keys and their errors, the schedule file, the states' scenes, and the annual study of
// a side-lit room with a "clear" and a "dim" state against single-state runs of the same scenes:
// each state's year equals its single run float for float (the same scene, sensors and random
// streams), and the switched year is, hour by hour, exactly the chosen state's year. The
// Honeybee radiance folder read into the case its hand-written equivalent gives.
#include "study/window_states.h"

#include "base/error.h"
#include "metrics/annual.h"
#include "reports/annual_results.h"
#include "study/annual_study.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/compliance/compliance_spec.h"
#include "study/run_case.h"
#include "study/trace_options.h"

#include "tests/engine/bsdf_test_xml.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(CANDELA_TEST_DATA) / "study" / "annual_window_states";
const std::string kAnnual =
    "[[scene]]\nfile = \"walls.rad\"\n[sky]\ntype = \"annual\"\nweather = \"../../epw/synthetic_golden_2026.epw\"\n"
    "[[grid]]\nname = \"room\"\ncorners = [[0, 0], [4, 4]]\nheight = 0.8\n";
const std::string kStates =
    "[[window_group]]\nname = \"south\"\nsurfaces = [\"south_pane\"]\n"
    "states = [{ name = \"clear\", scene = \"clear.rad\" }, { name = \"dim\", scene = \"dim.rad\" }]\n";

// The same sky and grid with the weather file's absolute path (cases written in scratch folders).
const std::string kSkyGrid = "[sky]\ntype = \"annual\"\nweather = \"" +
                             (fs::path(CANDELA_TEST_DATA) / "epw" / "synthetic_golden_2026.epw").string() +
                             "\"\n[[grid]]\nname = \"room\"\ncorners = [[0, 0], [4, 4]]\nheight = 0.8\n";

std::string parseError(const std::string& text, const fs::path& where = kDir / "case.toml") {
  try {
    parseCaseFile(text, where);
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

TEST(WindowStateCase, ReadsTheStates) {
  const CaseFile c = parseCaseFile(kAnnual + kStates + "sun_grid = \"room\"\n", kDir / "case.toml");
  ASSERT_EQ(c.windowGroups.size(), 1u);
  const WindowGroupSpec& g = c.windowGroups[0];
  ASSERT_EQ(g.states.size(), 2u);
  EXPECT_EQ(g.states[0].name, "clear");
  EXPECT_EQ(g.states[1].scene, (kDir / "dim.rad").lexically_normal());
  EXPECT_EQ(g.patterns, std::vector<std::string>{"south_pane"});
  EXPECT_EQ(g.sunGrid, "room");
  // `surfaces` is optional with states.
  EXPECT_EQ(parseError(kAnnual + "[[window_group]]\nstates = [{ name = \"a\", scene = \"clear.rad\" }]\n"), "accepted");
}

TEST(WindowStateCase, ErrorsNameTheirLine) {
  const std::string g = "[[window_group]]\nname = \"s\"\n";
  EXPECT_NE(parseError(kAnnual + g + "states = []\n").find("12: 'states' needs at least one entry { name"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + g + "states = [{ name = \"a\", scene = \"nowhere.rad\" }]\n")
                .find("12: state scene file 'nowhere.rad' not found"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + g + "states = [{ name = \"a\", scene = \"clear.rad\", colour = 1 }]\n")
                .find("12: unknown key 'colour'"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + g +
                       "states = [{ name = \"a\", scene = \"clear.rad\" }, { name = \"a\", scene = \"dim.rad\" }]\n")
                .find("12: window group 's' has two states named 'a'"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + g + "surfaces = [\"x\"]\nschedule = \"clear.rad\"\n").find("13: 'schedule' and"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + kStates + "schedule = \"clear.rad\"\nsun_grid = \"room\"\n").find("15: give either"),
            std::string::npos);
  // Three states under the direct-sun rule: it escalates from state to state (docs/annual.md).
  EXPECT_EQ(parseError(kAnnual + g +
                       "states = [{ name = \"a\", scene = \"clear.rad\" }, { name = \"b\", scene = \"dim.rad\" }, "
                       "{ name = \"c\", scene = \"pane.rad\" }]\n"),
            "accepted");
}

// A schedule file of `lines` lines in `dir`, state "dim" in the hours where dimHour(h), else "clear".
fs::path writeSchedule(const fs::path& dir, std::size_t lines, const std::function<bool(std::size_t)>& dimHour) {
  const fs::path p = dir / "schedule.txt";
  std::ofstream out(p);
  for (std::size_t h = 0; h < lines; ++h) out << (dimHour(h) ? "dim" : "clear") << "\n";
  return p;
}

std::string scheduleError(const fs::path& p, std::size_t hours) {
  try {
    readStateSchedule(p, {"clear", "dim"}, hours);
  } catch (const InputError& e) {
    return e.loc().file.substr(e.loc().file.rfind('/') + 1) + ":" + std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

TEST(WindowStateSchedule, ReadsOneStatePerHourAndNamesBadLines) {
  const fs::path dir = test_support::scratchDir("window_states", "schedule." + std::to_string(::getpid()));
  const fs::path p = writeSchedule(dir, 8760, [](std::size_t h) { return h % 7 == 3; });
  const std::vector<uint8_t> s = readStateSchedule(p, {"clear", "dim"}, 8760);
  ASSERT_EQ(s.size(), 8760u);
  EXPECT_EQ(s[3], 1);
  EXPECT_EQ(s[4], 0);
  // A leap year's weather file has 8784 hours: 8760 lines end short, at the last line.
  EXPECT_NE(scheduleError(p, 8784).find("schedule.txt:8760: the schedule ends after 8760 lines; the weather file's "
                                        "year has 8784 hours"),
            std::string::npos);
  writeSchedule(dir, 8761, [](std::size_t) { return false; });
  EXPECT_NE(scheduleError(p, 8760).find("schedule.txt:8761: the schedule has more than 8760 lines"), std::string::npos);
  writeSchedule(dir, 8784, [](std::size_t) { return false; });
  EXPECT_EQ(scheduleError(p, 8784), "accepted");
  {
    std::ofstream out(p);
    out << "clear\n  dim \r\nopen\n";
  }
  EXPECT_NE(scheduleError(p, 3).find("schedule.txt:3: unknown state 'open' (the group's states: 'clear', 'dim')"),
            std::string::npos);
  {
    std::ofstream out(p);
    out << "clear\n\ndim\n";
  }
  EXPECT_NE(scheduleError(p, 3).find("schedule.txt:2: empty line"), std::string::npos);
  fs::remove_all(dir);
}

TEST(WindowStateFold, TakesTheStateAloneOrAddsItsDifference) {
  // 1 sensor, 3 hours: hour 0 reference, hour 1 this group alone in state 1, hour 2 two groups.
  const float stateYear[] = {10.0f, 0.3f, 5.0f}, reference[] = {1.0f, 0.7f, 2.0f};
  float combined[] = {1.0f, 0.7f, 4.0f};  // hour 2: another group's fold already in
  foldWindowState(stateYear, reference, {0, 1, 1}, 1, {0, 1, 2}, 1, combined);
  EXPECT_EQ(combined[0], 1.0f);
  EXPECT_EQ(combined[1], 0.3f);  // the state's own value, not 0.7 + (0.3 − 0.7)
  EXPECT_EQ(combined[2], 7.0f);  // 4 + (5 − 2)
}

CaseFile roomCase() { return readCaseFile(kDir / "case.toml"); }

WindowGroupSpec southStates() {
  WindowGroupSpec g;
  g.name = "south";
  g.patterns = {"south_pane"};
  g.loc = g.patternsLoc = FileLoc{"case.toml", 30, 1};
  g.states = {{"clear", kDir / "clear.rad", g.loc}, {"dim", kDir / "dim.rad", g.loc}};
  return g;
}

TEST(WindowStateScene, ReplacesTheGroupsSurfaces) {
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / "pane.rad", {}});
  c.windowGroups = {southStates()};
  const WindowStates ws = resolveWindowStates(c, 8760);
  SurfaceLabels labels;
  const auto scene = loadStateScene(c, 0.0, ws, {1}, &labels);
  int panes = 0;
  for (uint32_t id = 0; id < scene->surfaceCount(); ++id)
    if (scene->surfaceName(id) == "south_pane") {
      ++panes;
      EXPECT_EQ(scene->materials[scene->surfaceMaterial(id)].type, MaterialType::kTrans);
      EXPECT_EQ(labels.ofSurface[id], 0);
    } else {
      EXPECT_EQ(labels.ofSurface[id], -1);
    }
  EXPECT_EQ(panes, 1);  // the base's pane removed, the state's added
  // Point-in-time studies see the first state, the base's pane removed.
  const auto first = loadCaseScene(c, false);
  panes = 0;
  for (uint32_t id = 0; id < first->surfaceCount(); ++id)
    if (first->surfaceName(id) == "south_pane") {
      ++panes;
      EXPECT_EQ(first->materials[first->surfaceMaterial(id)].name, "clear_glass");
    }
  EXPECT_EQ(panes, 1);
  c.windowGroups[0].patterns = {"nowhere_*"};
  try {
    loadStateScene(c, 0.0, ws, {0});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 30);
    EXPECT_NE(std::string(e.what()).find("no surface of the scene is named 'nowhere_*'"), std::string::npos);
  }
}

std::string resolveError(const CaseFile& c) {
  try {
    resolveWindowStates(c, 8760);
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

TEST(WindowStateScene, ResolveErrorsNameTheEntry) {
  CaseFile c = roomCase();
  c.windowGroups = {southStates()};
  EXPECT_EQ(resolveError(c), "accepted");
  c.windowGroups[0].sunGrid = "hall";
  c.windowGroups[0].sunGridLoc = FileLoc{"case.toml", 33, 1};
  EXPECT_NE(resolveError(c).find("33: 'sun_grid': no [[grid]] is named 'hall'"), std::string::npos);
  c.windowGroups = {southStates(), southStates()};
  c.windowGroups[1].name = "blinds";
  c.windowGroups[1].states.clear();
  c.windowGroups[1].loc.line = 40;
  EXPECT_NE(resolveError(c).find("40: window group 'blinds' has no 'states' while others have"), std::string::npos);
  c.windowGroups = {southStates()};
  c.windowGroups[0].states.pop_back();  // one state, no schedule
  EXPECT_NE(resolveError(c).find("30: window group 'south': the direct-sun rule chooses among at least two states"),
            std::string::npos);
}

RunResult runRoom(CaseFile c, const fs::path& out) {
  RunContext run;
  run.request.outDir = out;
  c.settings.scene = sceneReadOptions(&c.settings, run.request.trace);
  run.outDir = out;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = "2026-01-01 00:00";
  return runAnnualStudy(c, run, silentObserver());
}

// One state alone: the walls and the state's file as the case's scene, no blinds.
RunResult runSingle(const std::string& state, const fs::path& out) {
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / (state + ".rad"), {}});
  c.annual.blinds = false;
  return runRoom(c, out);
}

// EN 17037 with one glare view, from the room's middle towards the south window.
ComplianceSpec glareEntry() {
  ComplianceSpec e;
  e.name = "en17037";
  e.standard = ComplianceStandard::kEn17037;
  GlareViewSpec v;
  v.positionM = Vec3(2.0, 2.5, 1.2);
  v.direction = Vec3(0.0, -1.0, 0.0);
  e.glareViews = {v};
  return e;
}

// One state alone with the glare view: the view's year in that state all year.
RunResult runSingleWithGlare(const std::string& state, const fs::path& out) {
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / (state + ".rad"), {}});
  c.annual.blinds = false;
  c.compliance = {glareEntry()};
  return runRoom(c, out);
}

// The glare view of a run's EN 17037 entry (the `entry`-th compliance entry).
const GlareViewReport& glareView(const RunResult& r, std::size_t entry = 0) {
  return r.data.compliance.at(entry).en17037->glare.at(0);
}

// Two views' yearly figures, to the last bit.
void expectSameGlare(const GlareViewReport& got, const GlareViewReport& want) {
  EXPECT_EQ(got.shareAbove035, want.shareAbove035);
  EXPECT_EQ(got.shareAbove045, want.shareAbove045);
  EXPECT_EQ(got.glareAutonomy, want.glareAutonomy);
}

class WindowStateStudy : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test_support::scratchDir("window_states", "study." + std::to_string(::getpid()));
    clear_ = new RunResult(runSingle("clear", dir_ / "clear"));
    dim_ = new RunResult(runSingle("dim", dir_ / "dim"));
    CaseFile c = roomCase();
    c.scenes.push_back({kDir / "pane.rad", {}});  // the base's pane, which the states replace
    c.windowGroups = {southStates()};
    ComplianceSpec leed;
    leed.name = "leed";
    leed.standard = ComplianceStandard::kLeedV41Option1;
    c.compliance = {leed, glareEntry()};
    sun_ = new RunResult(runRoom(c, dir_ / "sun"));
    c.compliance.clear();
    c.windowGroups[0].schedule = writeSchedule(dir_, 8760, [](std::size_t h) { return h % 3 == 1 || h / 24 % 10 == 0; });
    scheduled_ = new RunResult(runRoom(c, dir_ / "schedule"));
  }
  static void TearDownTestSuite() {
    for (RunResult* r : {clear_, dim_, sun_, scheduled_}) delete r;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static AnnualResults hourly(const RunResult* r, const std::string& name) {
    return readAnnualResults(r->outDir / annualResultsFileName(name));
  }
  static const AnnualGridReport& annual(const RunResult* r) { return *r->data.grids.at(0).annual; }
  static RunResult *clear_, *dim_, *sun_, *scheduled_;
  static fs::path dir_;
};
RunResult *WindowStateStudy::clear_ = nullptr, *WindowStateStudy::dim_ = nullptr, *WindowStateStudy::sun_ = nullptr,
          *WindowStateStudy::scheduled_ = nullptr;
fs::path WindowStateStudy::dir_;

// Each state's year is its single-state run's, float for float: the same scene (the base's pane
// removed, the state's file added), the same sensors and random streams.
TEST_F(WindowStateStudy, EachStateIsItsSingleRun) {
  for (const RunResult* r : {sun_, scheduled_}) {
    EXPECT_EQ(hourly(r, "room_south_clear").lux, hourly(clear_, "room").lux);
    EXPECT_EQ(hourly(r, "room_south_dim").lux, hourly(dim_, "room").lux);
    EXPECT_EQ(hourly(r, "room_south_clear_direct_sun").lux, hourly(clear_, "room_direct_sun").lux);
    EXPECT_EQ(hourly(r, "room_south_dim_direct_sun").lux, hourly(dim_, "room_direct_sun").lux);
  }
  // Per-state metrics: the single runs' (no blinds), to the last bit.
  const auto& states = annual(sun_).windowStates;
  ASSERT_EQ(states.size(), 2u);
  EXPECT_EQ(states[0].state, "clear");
  EXPECT_EQ(states[0].summary.DA300, annual(clear_).summary.DA300);
  EXPECT_EQ(states[0].summary.ASE1000_250, annual(clear_).summary.ASE1000_250);
  EXPECT_EQ(states[1].summary.DA300, annual(dim_).summary.DA300);
  EXPECT_EQ(states[1].summary.sDA300_50, annual(dim_).summary.sDA300_50);
  EXPECT_GT(annual(clear_).summary.DA300, annual(dim_).summary.DA300);  // the dim state is dimmer
  EXPECT_GT(annual(clear_).summary.ASE1000_250, 0.0);
  EXPECT_EQ(annual(dim_).summary.ASE1000_250, 0.0);  // no beam through the trans
}

// The switched year is, in every hour, exactly the chosen state's year; `chosen(h)` says whether
// hour h is in the dim state. Returns the occupied hours in the dim state.
int expectSwitched(const AnnualResults& switched, const AnnualResults& clear, const AnnualResults& dim,
                   const std::function<bool(std::size_t)>& chosen, const std::vector<char>& occupied) {
  int dimHours = 0, mismatches = 0;
  const std::size_t nh = switched.hours.size();
  for (std::size_t h = 0; h < nh; ++h) {
    const bool d = chosen(h);
    dimHours += d && occupied[h];
    for (int s = 0; s < switched.sensors; ++s)
      mismatches += switched.lux[s * nh + h] != (d ? dim : clear).lux[s * nh + h];
  }
  EXPECT_EQ(mismatches, 0);
  return dimHours;
}

std::vector<char> occupiedOf(const AnnualResults& r) {
  std::vector<int> hourEnding;
  for (const HourStamp& h : r.hours) hourEnding.push_back(h.hourEnding);
  return occupiedHours(hourEnding, 8.0, 18.0);
}

TEST_F(WindowStateStudy, TheScheduleChoosesEveryHour) {
  const AnnualResults clear = hourly(clear_, "room"), dim = hourly(dim_, "room");
  const std::vector<char> occupied = occupiedOf(clear);
  auto dimHour = [](std::size_t h) { return h % 3 == 1 || h / 24 % 10 == 0; };
  const int dimHours = expectSwitched(hourly(scheduled_, "room"), clear, dim, dimHour, occupied);
  EXPECT_EQ(annual(scheduled_).windowStates.at(1).occupiedHours, dimHours);
  EXPECT_EQ(annual(scheduled_).windowStates.at(0).occupiedHours, countHours(occupied) - dimHours);
  // The direct sun of the switched year too (none through the dim state).
  const AnnualResults direct = hourly(scheduled_, "room_direct_sun"), clearDirect = hourly(clear_, "room_direct_sun");
  const std::size_t nh = direct.hours.size();
  int mismatches = 0;
  for (std::size_t h = 0; h < nh; ++h)
    for (int s = 0; s < direct.sensors; ++s)
      mismatches += direct.lux[s * nh + h] != (dimHour(h) ? 0.0f : clearDirect.lux[s * nh + h]);
  EXPECT_EQ(mismatches, 0);
}

// The direct-sun rule, computed directly from the clear run's direct sun: dim in the occupied
// hours in which more than 2 % of the grid's sensors get ≥ 1000 lx of direct sun.
TEST_F(WindowStateStudy, TheSunRuleIsLm83sThreshold) {
  const AnnualResults clear = hourly(clear_, "room"), dim = hourly(dim_, "room");
  const AnnualResults direct = hourly(clear_, "room_direct_sun");
  const std::vector<char> occupied = occupiedOf(clear);
  const std::size_t nh = direct.hours.size();
  auto dimHour = [&](std::size_t h) {
    int sunlit = 0;
    for (int s = 0; s < direct.sensors; ++s) sunlit += direct.lux[s * nh + h] >= 1000.0f;
    return occupied[h] && sunlit > 0.02 * direct.sensors;
  };
  const int dimHours = expectSwitched(hourly(sun_, "room"), clear, dim, dimHour, occupied);
  EXPECT_GT(dimHours, 100);
  EXPECT_LT(dimHours, countHours(occupied) - 100);
  EXPECT_EQ(annual(sun_).windowStates.at(1).occupiedHours, dimHours);
}

// More than two states under the direct-sun rule: clear, a tinted glass whose beam is weak, and
// the dim trans. In an hour the clear state leaves more than 2 % of the grid sunlit, the rule
// takes the tinted state when its own direct sun leaves no more than 2 % sunlit, else the dim
// one; computed here from the three single runs' direct sun, and the switched year is the chosen
// state's year in every hour. Both escalations occur (the tint's beam of 3 % crosses 1000 lx at
// some sensors in some hours only).
TEST_F(WindowStateStudy, TheSunRuleEscalatesThroughMoreStates) {
  const fs::path dir = dir_ / "three";
  const RunResult tint = runSingle("tint", dir / "tint");
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / "pane.rad", {}});
  WindowGroupSpec g = southStates();
  g.states = {{"clear", kDir / "clear.rad", g.loc}, {"tint", kDir / "tint.rad", g.loc}, {"dim", kDir / "dim.rad", g.loc}};
  c.windowGroups = {g};
  const RunResult three = runRoom(c, dir / "run");
  const AnnualResults clear = hourly(clear_, "room"), dim = hourly(dim_, "room"), tinted = hourly(&tint, "room");
  const AnnualResults clearDirect = hourly(clear_, "room_direct_sun"), tintDirect = hourly(&tint, "room_direct_sun");
  const std::vector<char> occupied = occupiedOf(clear);
  const std::size_t nh = clear.hours.size();
  auto sunlit = [&](const AnnualResults& d, std::size_t h) {
    int n = 0;
    for (int s = 0; s < d.sensors; ++s) n += d.lux[s * nh + h] >= 1000.0f;
    return n > 0.02 * d.sensors;
  };
  std::vector<int> want(nh, 0);
  int tintHours = 0, dimHours = 0, mismatches = 0;
  for (std::size_t h = 0; h < nh; ++h) {
    if (occupied[h] && sunlit(clearDirect, h)) want[h] = sunlit(tintDirect, h) ? 2 : 1;
    tintHours += want[h] == 1;
    dimHours += want[h] == 2;
  }
  EXPECT_GT(tintHours, 20);
  EXPECT_GT(dimHours, 20);
  const AnnualResults switched = hourly(&three, "room");
  for (std::size_t h = 0; h < nh; ++h) {
    const AnnualResults& chosen = want[h] == 0 ? clear : want[h] == 1 ? tinted : dim;
    for (int s = 0; s < switched.sensors; ++s) mismatches += switched.lux[s * nh + h] != chosen.lux[s * nh + h];
  }
  EXPECT_EQ(mismatches, 0);
  const auto& states = annual(&three).windowStates;
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states[1].occupiedHours, tintHours);
  EXPECT_EQ(states[2].occupiedHours, dimHours);
  // Each state's own year is still its single run's.
  EXPECT_EQ(hourly(&three, "room_south_tint").lux, tinted.lux);
}

// LEED v4.1 option 1 with window states: sDA of the switched year (the shading operated, LM-83),
// ASE of the reference year (every group in its first state: no operable shading), which here is
// the clear state's single run; the switched year's own ASE is lower (the dim state stops the beam).
TEST_F(WindowStateStudy, LeedTakesTheSwitchedSdaAndTheReferenceAse) {
  ASSERT_EQ(sun_->data.compliance.size(), 2u);  // LEED, then EN 17037 (GlareViewsFollowTheStates)
  ASSERT_TRUE(sun_->data.compliance[0].leed.has_value());
  const LeedSpaceReport& space = sun_->data.compliance[0].leed->spaces.at(0);
  EXPECT_EQ(space.sdaPct, annual(sun_).summary.sDA300_50);
  EXPECT_EQ(space.asePct, annual(clear_).summary.ASE1000_250);
  EXPECT_LT(annual(sun_).summary.ASE1000_250, annual(clear_).summary.ASE1000_250);
}

// EN 17037's glare view follows a group of two states as it follows LM-83's blinds: each occupied
// hour's DGP is the state's of that hour (the clear state's single run and the dim one's, chosen
// by the switched year's hours), the hours in the second state reported.
TEST_F(WindowStateStudy, GlareViewsFollowTheStates) {
  const GlareViewReport& g = glareView(*sun_, 1);
  EXPECT_EQ(g.blinds, "window_states");
  EXPECT_EQ(g.blindsSpace, "room");
  EXPECT_EQ(g.blindsClosedHours, annual(sun_).windowStates.at(1).occupiedHours);
  const fs::path dir = dir_ / "glare";
  const RunResult clear = runSingleWithGlare("clear", dir / "clear");
  const RunResult dim = runSingleWithGlare("dim", dir / "dim");
  const GlareViewReport& c = glareView(clear);
  const GlareViewReport& d = glareView(dim);
  EXPECT_EQ(c.blinds, "open");
  // The switched year lies between its states' years, and the dim state cuts the clear's glare.
  EXPECT_LT(d.shareAbove035, c.shareAbove035);
  EXPECT_LE(g.shareAbove035, c.shareAbove035);
  EXPECT_GE(g.shareAbove035, d.shareAbove035);
  EXPECT_LT(g.shareAbove035, c.shareAbove035);
}

// The glare view follows any state, not only a second one: a group of three states scheduled in
// its third all year sees exactly the third state's single run (the same view stream), and every
// occupied hour is reported switched.
TEST_F(WindowStateStudy, GlareViewsFollowAThirdState) {
  const fs::path dir = dir_ / "glare3";
  fs::create_directories(dir);
  const fs::path schedule = dir / "tint.txt";
  {
    std::ofstream out(schedule);
    for (int h = 0; h < 8760; ++h) out << "tint\n";
  }
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / "pane.rad", {}});
  WindowGroupSpec g = southStates();
  g.states = {{"clear", kDir / "clear.rad", g.loc}, {"dim", kDir / "dim.rad", g.loc}, {"tint", kDir / "tint.rad", g.loc}};
  g.schedule = schedule;
  c.windowGroups = {g};
  c.compliance = {glareEntry()};
  const RunResult three = runRoom(c, dir / "run");
  const RunResult tint = runSingleWithGlare("tint", dir / "tint");
  const GlareViewReport& got = glareView(three);
  const GlareViewReport& want = glareView(tint);
  EXPECT_EQ(got.blinds, "window_states");
  expectSameGlare(got, want);
  EXPECT_EQ(got.blindsClosedHours, countHours(occupiedOf(hourly(clear_, "room"))));
  // The first state glares where the tint does not: following the wrong state would show.
  const RunResult clear = runSingleWithGlare("clear", dir / "clear");
  EXPECT_GT(glareView(clear).shareAbove035, want.shareAbove035);
}

// LM-83's blinds of a [[window_group]] (not states) are followed by the glare view too: one group
// holding the room's only glazing closes in the hours the whole glazing's blinds close, so the
// view's shares and closed hours equal the run without groups (the same rule, the same closed
// scene, the same view stream); before, the view saw the group's blinds open all year.
TEST_F(WindowStateStudy, GlareViewsFollowTheBlindsOfAWindowGroup) {
  const fs::path dir = dir_ / "groups";
  CaseFile c = roomCase();
  c.scenes.push_back({kDir / "clear.rad", {}});
  c.compliance = {glareEntry()};
  const RunResult whole = runRoom(c, dir / "whole");
  WindowGroupSpec g;
  g.name = "south";
  g.patterns = {"south_pane"};
  g.loc = g.patternsLoc = FileLoc{"case.toml", 30, 1};
  c.windowGroups = {g};
  const RunResult grouped = runRoom(c, dir / "grouped");
  const GlareViewReport& a = glareView(whole);
  const GlareViewReport& b = glareView(grouped);
  EXPECT_EQ(a.blinds, "lm83");
  EXPECT_EQ(b.blinds, "lm83");
  EXPECT_GT(a.blindsClosedHours, 100);
  EXPECT_EQ(b.blindsClosedHours, a.blindsClosedHours);
  expectSameGlare(b, a);
}

// Two groups under the direct-sun rule, one of three states and one of two: the opening split
// into a west and an east pane. Each group's states cover its occupied hours; the west group's
// middle state is used; the glare view follows the combinations (its hours off the first
// states at least each group's, at most their sum).
TEST_F(WindowStateStudy, TwoGroupsEscalateAndTheGlareViewFollowsTheirCombinations) {
  const fs::path dir = dir_ / "two";
  fs::create_directories(dir);
  auto pane = [](const std::string& mat, const std::string& name, double x0, double x1) {
    const std::string a = std::to_string(x0), b = std::to_string(x1);
    return mat + " polygon " + name + " 0 0 12  " + a + " 0 0.8  " + b + " 0 0.8  " + b + " 0 2.2  " + a + " 0 2.2\n";
  };
  const std::string glass = "void glass g_clear 0 0 3 0.9 0.9 0.9\nvoid glass g_tint 0 0 3 0.03 0.03 0.03\n"
                            "void trans g_dim 0 0 7 0.5 0.5 0.5 0 0 0.4 0\n";
  std::ofstream(dir / "panes.rad") << glass << pane("g_clear", "pane_w", 0.8, 2.0) << pane("g_clear", "pane_e", 2.0, 3.2);
  for (const char* m : {"clear", "tint", "dim"}) {
    std::ofstream(dir / (std::string("w_") + m + ".rad")) << glass << pane(std::string("g_") + m, "pane_w", 0.8, 2.0);
    std::ofstream(dir / (std::string("e_") + m + ".rad")) << glass << pane(std::string("g_") + m, "pane_e", 2.0, 3.2);
  }
  CaseFile c = roomCase();
  c.scenes.push_back({dir / "panes.rad", {}});
  WindowGroupSpec west = southStates(), east = southStates();
  west.name = "west";
  west.patterns = {"pane_w"};
  west.states = {{"clear", dir / "w_clear.rad", west.loc}, {"tint", dir / "w_tint.rad", west.loc},
                 {"dim", dir / "w_dim.rad", west.loc}};
  east.name = "east";
  east.patterns = {"pane_e"};
  east.states = {{"clear", dir / "e_clear.rad", east.loc}, {"dim", dir / "e_dim.rad", east.loc}};
  c.windowGroups = {west, east};
  c.compliance = {glareEntry()};
  const RunResult r = runRoom(c, dir / "run");
  const auto& states = annual(&r).windowStates;
  ASSERT_EQ(states.size(), 5u);  // west clear, tint, dim; east clear, dim
  const int occupied = countHours(occupiedOf(hourly(clear_, "room")));
  EXPECT_EQ(states[0].occupiedHours + states[1].occupiedHours + states[2].occupiedHours, occupied);
  EXPECT_EQ(states[3].occupiedHours + states[4].occupiedHours, occupied);
  EXPECT_GT(states[1].occupiedHours, 0);  // the west pane's tint is chosen in some hours
  const int westOff = states[1].occupiedHours + states[2].occupiedHours, eastOff = states[4].occupiedHours;
  EXPECT_GT(westOff + eastOff, 0);
  const GlareViewReport& g = glareView(r);
  EXPECT_EQ(g.blinds, "window_states");
  EXPECT_TRUE(g.blindsNote.empty());
  EXPECT_GE(g.blindsClosedHours, std::max(westOff, eastOff));
  EXPECT_LE(g.blindsClosedHours, westOff + eastOff);
}

// A Honeybee radiance folder (honeybee-radiance-folder's layout) written here, read into the case
// the hand-written [[scene]] and [[window_group]] entries give.
TEST(HoneybeeFolder, ReadsIntoItsHandWrittenCase) {
  const fs::path dir = test_support::scratchDir("window_states", "honeybee." + std::to_string(::getpid()));
  const fs::path m = dir / "folder" / "model";
  for (const char* sub : {"scene", "aperture", "aperture_group"}) fs::create_directories(m / sub);
  auto write = [](const fs::path& p, const std::string& text) { std::ofstream(p) << text; };
  write(m / "scene" / "envelope.mat", "void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n");
  write(m / "scene" / "envelope.rad", "wall polygon floor 0 0 12 0 0 0 0 4 0 4 4 0 4 0 0\n");
  write(m / "scene" / "envelope.blk", "void glow black 0 0 4 0 0 0 0\n");
  write(m / "aperture" / "aperture.mat", "void glass g 0 0 3 0.8 0.8 0.8\n");
  write(m / "aperture" / "aperture.rad", "g polygon north_pane 0 0 12 0 4 1 1 4 1 1 4 2 0 4 2\n");
  write(m / "aperture_group" / "south..default..0.rad", "void glass c 0 0 3 0.9 0.9 0.9\n");
  write(m / "aperture_group" / "south..default..1.rad", "void glass t 0 0 3 0.2 0.2 0.2\n");
  write(m / "aperture_group" / "states.json",
        R"({"south": [{"identifier": "0_south", "default": "./south..default..0.rad", "black": "./south..black.rad"},
                      {"identifier": "1_south", "default": "./south..default..1.rad"}]})");
  const CaseFile hb = parseCaseFile(kSkyGrid +
                                        "[[scene]]\nhoneybee_folder = \"folder\"\n",
                                    dir / "case.toml");
  const std::string a = "folder/model/aperture/", s = "folder/model/scene/", g = "folder/model/aperture_group/";
  const CaseFile hand = parseCaseFile(
      kSkyGrid + "[[scene]]\nfile = \"" + s + "envelope.mat\"\n[[scene]]\nfile = \"" + a +
          "aperture.mat\"\n[[scene]]\nfile = \"" + s + "envelope.rad\"\n[[scene]]\nfile = \"" + a +
          "aperture.rad\"\n[[window_group]]\nname = \"south\"\nstates = [{ name = \"0_south\", scene = \"" + g +
          "south..default..0.rad\" }, { name = \"1_south\", scene = \"" + g + "south..default..1.rad\" }]\n",
      dir / "case.toml");
  ASSERT_EQ(hb.scenes.size(), hand.scenes.size());
  for (std::size_t i = 0; i < hb.scenes.size(); ++i) EXPECT_EQ(hb.scenes[i].file, hand.scenes[i].file);
  ASSERT_EQ(hb.windowGroups.size(), 1u);
  ASSERT_EQ(hand.windowGroups.size(), 1u);
  EXPECT_EQ(hb.windowGroups[0].name, hand.windowGroups[0].name);
  ASSERT_EQ(hb.windowGroups[0].states.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(hb.windowGroups[0].states[k].name, hand.windowGroups[0].states[k].name);
    EXPECT_EQ(hb.windowGroups[0].states[k].scene, hand.windowGroups[0].states[k].scene);
  }
  EXPECT_TRUE(hb.windowGroups[0].patterns.empty());
  // A [[window_group]] of the folder's group's name sets its rule, nothing else.
  const std::string hbCase = kSkyGrid + "[[scene]]\nhoneybee_folder = \"folder\"\n";
  write(dir / "hours.txt", "0_south\n");
  const CaseFile ruled =
      parseCaseFile(hbCase + "[[window_group]]\nname = \"south\"\nschedule = \"hours.txt\"\n", dir / "case.toml");
  ASSERT_EQ(ruled.windowGroups.size(), 1u);
  EXPECT_EQ(ruled.windowGroups[0].schedule, (dir / "hours.txt").lexically_normal());
  EXPECT_NE(parseError(hbCase + "[[window_group]]\nname = \"south\"\nsurfaces = [\"x\"]\n", dir / "case.toml")
                .find("12: window group 'south' comes from a Honeybee folder"),
            std::string::npos);
  // Errors: no such folder, a states.json that is not JSON (its line), a missing default file.
  EXPECT_NE(parseError(kSkyGrid + "[[scene]]\nhoneybee_folder = \"nowhere\"\n", dir / "case.toml")
                .find("9: Honeybee folder 'nowhere' not found"),
            std::string::npos);
  write(m / "aperture_group" / "states.json", "{\n\"south\": [\n{\"identifier\": }]}");
  EXPECT_NE(parseError(hbCase, dir / "case.toml").find("3: not JSON"), std::string::npos);
  write(m / "aperture_group" / "states.json", R"({"south": [{"identifier": "a", "default": "./gone.rad"}]})");
  EXPECT_NE(parseError(hbCase, dir / "case.toml").find("aperture group 'south', state 1: its default file"),
            std::string::npos);
  fs::remove_all(dir);
}

// Honeybee's scene files name their BSDF files from the folder holding model/ (Honeybee runs
// Radiance there): found wherever candela runs (the tests run in the build folder), and not
// without the folder as the scene's root.
TEST(HoneybeeFolder, FilesNamedFromTheFolderRootAreFound) {
  const fs::path dir = test_support::scratchDir("window_states", "honeybee-bsdf." + std::to_string(::getpid()));
  const fs::path m = dir / "folder" / "model";
  for (const char* sub : {"scene", "aperture_group", "bsdf"}) fs::create_directories(m / sub);
  std::ofstream(m / "scene" / "envelope.mat") << "void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n";
  std::ofstream(m / "scene" / "envelope.rad") << "wall polygon floor 0 0 12 0 0 0 0 4 0 4 4 0 4 0 0\n";
  std::ofstream(m / "bsdf" / "half.xml") << test_support::bsdfXml(
      {{"Transmission Front", std::vector<double>(145 * 145, 0.5 / kPi)}});
  std::ofstream(m / "aperture_group" / "south..default..0.rad")
      << "void BSDF half 6 0.0 ./model/bsdf/half.xml 0.01 0.01 1.0 .\n0\n0\n"
         "half polygon south 0 0 12 0 0 1 0 0 2 4 0 2 4 0 1\n";
  std::ofstream(m / "aperture_group" / "states.json")
      << R"({"south": [{"identifier": "0_south", "default": "./south..default..0.rad"}]})";
  const CaseFile c = parseCaseFile(kSkyGrid + "[[scene]]\nhoneybee_folder = \"folder\"\n", dir / "case.toml");
  EXPECT_EQ(c.settings.scene.rootFolder, (dir / "folder").lexically_normal());
  const auto scene = loadCaseScene(c, false);
  ASSERT_EQ(scene->bsdfs.size(), 1u);
  CaseFile without = c;
  without.settings.scene.rootFolder.clear();
  EXPECT_THROW(loadCaseScene(without, false), InputError);
}

}  // namespace
}  // namespace candela
