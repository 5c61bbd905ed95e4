// [[window_group]] (docs/annual.md "Window groups"): the case-file entry and its errors, the
// groups resolved against a scene, and the annual study of a room with a south and a west window
// run three ways: no groups, one group of both panes (the same numbers, float for float), and
// two groups (each closing on its own; together exactly when the one group would).
#include "study/window_groups.h"

#include "base/error.h"
#include "metrics/annual.h"
#include "reports/annual_results.h"
#include "study/annual_study.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/run_case.h"
#include "study/trace_options.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(CANDELA_TEST_DATA) / "study" / "annual_window_groups";

std::string parseError(const std::string& text) {
  try {
    parseCaseFile(text, kDir / "case.toml");
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

const std::string kAnnual =
    "[[scene]]\nfile = \"room.rad\"\n[sky]\ntype = \"annual\"\nweather = \"../../epw/synthetic_golden_2026.epw\"\n";

TEST(WindowGroupCase, ReadsTheEntries) {
  const CaseFile c = parseCaseFile(kAnnual +
                                       "[[window_group]]\nname = \"south\"\nsurfaces = [\"south_*\"]\n"
                                       "blinds_transmittance = 0.05\n[[window_group]]\nsurfaces = [\"west_pane\"]\n",
                                   kDir / "case.toml");
  ASSERT_EQ(c.windowGroups.size(), 2u);
  EXPECT_EQ(c.windowGroups[0].name, "south");
  EXPECT_EQ(c.windowGroups[0].patterns, std::vector<std::string>{"south_*"});
  EXPECT_EQ(c.windowGroups[0].blindsTransmittance, 0.05);
  EXPECT_EQ(c.windowGroups[0].loc.line, 6);
  EXPECT_EQ(c.windowGroups[1].name, "group 2");
  EXPECT_FALSE(c.windowGroups[1].blindsTransmittance);
}

TEST(WindowGroupCase, ErrorsNameTheirLine) {
  const std::string g = "[[window_group]]\nname = \"a\"\nsurfaces = [\"south_pane\"]\n";
  EXPECT_EQ(parseError(kAnnual + g + "colour = 1\n").substr(0, 2), "9:");
  EXPECT_NE(parseError(kAnnual + g + "colour = 1\n").find("unknown key 'colour'"), std::string::npos);
  EXPECT_NE(parseError(kAnnual + g + "blinds_transmittance = 0\n").find("9: 'blinds_transmittance' must be greater than 0"),
            std::string::npos);
  EXPECT_NE(parseError(kAnnual + g + "blinds_transmittance = 1.5\n").find("9:"), std::string::npos);
  EXPECT_EQ(parseError(kAnnual + g + "blinds_transmittance = 1\n"), "accepted");
  EXPECT_NE(parseError(kAnnual + g + g).find("9: two window groups are named 'a'"), std::string::npos);
  EXPECT_NE(parseError(kAnnual + "[[window_group]]\nsurfaces = []\n").find("7: 'surfaces' must name"), std::string::npos);
  // Without an annual sky.
  EXPECT_NE(parseError("[sky]\ntype = \"uniform\"\n" + g).find("3: [[window_group]] needs [sky] type = \"annual\""),
            std::string::npos);
}

CaseFile roomCase() { return readCaseFile(kDir / "case.toml"); }

WindowGroupSpec group(const std::string& name, std::vector<std::string> patterns, int line) {
  WindowGroupSpec g;
  g.name = name;
  g.patterns = std::move(patterns);
  g.loc = g.patternsLoc = FileLoc{"case.toml", line, 1};
  return g;
}

TEST(WindowGroups, ResolvesGlazingAndTheImplicitOther) {
  CaseFile c = roomCase();
  const auto scene = loadAnnualScene(c, 0.0);
  EXPECT_TRUE(resolveWindowGroups(c, *scene).groups.empty());
  c.windowGroups = {group("south", {"south_*"}, 30)};  // south_low etc. are walls: glazing only
  const WindowGroups w = resolveWindowGroups(c, *scene);
  ASSERT_EQ(w.groups.size(), 2u);
  EXPECT_EQ(w.groups[0].surfaces, std::vector<std::string>{"south_pane"});
  EXPECT_EQ(w.groups[1].name, "other");
  EXPECT_EQ(w.groups[1].surfaces, std::vector<std::string>{"west_pane"});
  EXPECT_EQ(w.labels.count, 2);
  int labelled = 0;
  for (int l : w.labels.ofSurface) labelled += l >= 0;
  EXPECT_EQ(labelled, 2);
  // Closing the south group turns only its pane into the blinds.
  Scene closed = *scene;
  EXPECT_EQ(closeWindowGroup(closed, w, 0), 1);
  for (uint32_t id = 0; id < closed.surfaceCount(); ++id) {
    const MaterialType t = closed.materials[closed.surfaceMaterial(id)].type;
    if (closed.surfaceName(id) == "south_pane") EXPECT_EQ(t, MaterialType::kTrans);
    if (closed.surfaceName(id) == "west_pane") EXPECT_EQ(t, MaterialType::kGlass);
  }
}

std::string resolveError(const std::vector<WindowGroupSpec>& groups) {
  CaseFile c = roomCase();
  c.windowGroups = groups;
  try {
    resolveWindowGroups(c, *loadAnnualScene(c, 0.0));
  } catch (const InputError& e) {
    return std::to_string(e.loc().line) + ": " + e.what();
  }
  return "accepted";
}

TEST(WindowGroups, SceneErrorsNameTheEntry) {
  EXPECT_NE(resolveError({group("a", {"north"}, 31)}).find("31: window group 'a': no glazing surface"),
            std::string::npos);  // a wall, not glazing
  EXPECT_NE(resolveError({group("a", {"*_pane"}, 31), group("b", {"west_pane"}, 35)})
                .find("35: glazing surface 'west_pane' is in window groups 'a' and 'b'"),
            std::string::npos);
  EXPECT_NE(resolveError({group("other", {"south_pane"}, 31)}).find("31: window group 'other'"), std::string::npos);
  EXPECT_EQ(resolveError({group("other", {"*_pane"}, 31)}), "accepted");  // nothing left over
}

RunResult runRoom(const std::vector<WindowGroupSpec>& groups, const fs::path& out) {
  CaseFile c = roomCase();
  c.windowGroups = groups;
  RunContext run;
  run.request.outDir = out;
  c.settings.scene = sceneReadOptions(&c.settings, run.request.trace);
  run.outDir = out;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = "2026-01-01 00:00";
  return runAnnualStudy(c, run, silentObserver());
}

class WindowGroupStudy : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test_support::scratchDir("window_groups", "study." + std::to_string(::getpid()));
    none_ = new RunResult(runRoom({}, dir_ / "none"));
    one_ = new RunResult(runRoom({group("all", {"*_pane"}, 30)}, dir_ / "one"));
    two_ = new RunResult(runRoom({group("south", {"south_pane"}, 30), group("west", {"west_pane"}, 34)}, dir_ / "two"));
  }
  static void TearDownTestSuite() {
    delete none_;
    delete one_;
    delete two_;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static const AnnualGridReport& annual(const RunResult* r) { return *r->data.grids.at(0).annual; }
  static RunResult *none_, *one_, *two_;
  static fs::path dir_;
};
RunResult *WindowGroupStudy::none_ = nullptr, *WindowGroupStudy::one_ = nullptr, *WindowGroupStudy::two_ = nullptr;
fs::path WindowGroupStudy::dir_;

// One group of all the glazing is the study without groups: the same closed hours, the same
// metrics, float for float (the group path's direct sun and closed scene are the same numbers).
TEST_F(WindowGroupStudy, OneGroupOfAllTheGlazingIsTheStudyWithout) {
  const auto& a = annual(none_).sensors;
  const auto& b = annual(one_).sensors;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t s = 0; s < a.size(); ++s) {
    EXPECT_EQ(a[s].da, b[s].da);
    EXPECT_EQ(a[s].cda, b[s].cda);
    EXPECT_EQ(a[s].udiExceeded, b[s].udiExceeded);
    EXPECT_EQ(a[s].aseHours, b[s].aseHours);
  }
  EXPECT_TRUE(annual(none_).windowGroups.empty());
  ASSERT_EQ(annual(one_).windowGroups.size(), 1u);
  // The closed hours against the whole-grid rule on the written direct-sun file.
  const AnnualResults direct = readAnnualResults(none_->outDir / annualResultsFileName("room_direct_sun"));
  std::vector<int> hourEnding;
  for (const HourStamp& h : direct.hours) hourEnding.push_back(h.hourEnding);
  const std::vector<char> occupied = occupiedHours(hourEnding, 8.0, 18.0);
  const int closed = countHours(blindsClosedHours(direct.lux.data(), direct.sensors, direct.hours.size(), occupied));
  EXPECT_GT(closed, 0);
  EXPECT_EQ(annual(one_).windowGroups[0].blindsClosedHours, closed);
}

// Two groups on two facades: each group closes in some hours, never more than the one group of
// both panes (a group closes only in hours the whole grid has more than 2 % of its sensors in the
// sun), and not always together; ASE (blinds open) is unchanged; and DA is higher than with every
// pane closing together (in the hours only one group closes, the other pane lets its light in).
TEST_F(WindowGroupStudy, TwoGroupsCloseSeparately) {
  const auto& groups = annual(two_).windowGroups;
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].name, "south");
  EXPECT_EQ(groups[1].name, "west");
  const int all = annual(one_).windowGroups[0].blindsClosedHours;
  EXPECT_GT(groups[0].blindsClosedHours, 0);
  EXPECT_GT(groups[1].blindsClosedHours, 0);
  EXPECT_LE(groups[0].blindsClosedHours, all);
  EXPECT_LE(groups[1].blindsClosedHours, all);
  EXPECT_LT(groups[0].blindsClosedHours + groups[1].blindsClosedHours, 2 * all);  // not always together
  const auto& a = annual(one_).sensors;
  const auto& b = annual(two_).sensors;
  double daOne = 0.0, daTwo = 0.0;
  for (std::size_t s = 0; s < a.size(); ++s) {
    EXPECT_EQ(a[s].aseHours, b[s].aseHours);
    daOne += a[s].da;
    daTwo += b[s].da;
  }
  EXPECT_GT(daTwo, daOne);  // fewer panes closed, more daylight
}

}  // namespace
}  // namespace candela
