// The luminaire schedule, the surfaces' reflectances and the energy figures of a point-in-time
// run (docs/en12464.md, "Energy and the luminaire schedule"), from whole cases run in-process
// with real photometric files (cases/luminaires and the shared reference files). Every expected
// value is recomputed here from its own source: the photometric file read by the photometry
// reader and summarised, the scene's colours as written below, summary.json's own numbers.
#include "study/luminaire_schedule.h"

#include "base/units.h"
#include "photometry/luminaire_summary.h"
#include "photometry/photometric_file.h"
#include "study/run_case.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace candela {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kReference = fs::path(CANDELA_REFERENCE) / "photometry";
const fs::path kCaseLuminaires = fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "luminaires";
const fs::path kBollard = kReference / "renderpipeline" / "bollard.ies";         // relative, 100 W
const fs::path kFluorescent = kReference / "eulumdat-rs" / "fluorescent_luminaire.ldt";  // 120 W
const fs::path kNoWatts = kReference / "renderpipeline" / "defined.ies";         // input watts 0
const fs::path kPanel = kCaseLuminaires / "led_panel_600.ies";                   // absolute, 36 W

// A 6 m × 4 m × 3 m room: coloured walls, a floor, a ceiling, a glass pane and a translucent
// screen standing in it, a small glow (an emitter: not a surface reflectance) and one material
// no surface uses.
constexpr const char* kRoom = R"(
void plastic wall_paint
0
0
5 0.7 0.6 0.5 0 0
void plastic floor_vinyl
0
0
5 0.3 0.3 0.25 0.02 0.05
void plastic unused_paint
0
0
5 0.9 0.9 0.9 0 0
void glass pane_glass
0
0
3 0.9 0.9 0.9
void trans screen_fabric
0
0
7 0.6 0.6 0.6 0 0 0.3 0.1
void glow pilot_lamp
0
0
4 1 1 1 0
floor_vinyl polygon floor
0
0
12 0 0 0  0 4 0  6 4 0  6 0 0
wall_paint polygon ceiling
0
0
12 0 0 3  6 0 3  6 4 3  0 4 3
wall_paint polygon south
0
0
12 0 0 0  6 0 0  6 0 3  0 0 3
wall_paint polygon north
0
0
12 0 4 0  0 4 3  6 4 3  6 4 0
wall_paint polygon west
0
0
12 0 0 0  0 0 3  0 4 3  0 4 0
wall_paint polygon east
0
0
12 6 0 0  6 4 0  6 4 3  6 0 3
pane_glass polygon pane
0
0
12 5.5 0.2 0.2  5.5 1.2 0.2  5.5 1.2 1.6  5.5 0.2 1.6
screen_fabric polygon screen
0
0
12 0.5 3.5 0.2  1.5 3.5 0.2  1.5 3.5 1.6  0.5 3.5 1.6
pilot_lamp sphere pilot
0
0
4 0.2 0.2 2.9 0.02
)";

std::string quoted(const fs::path& p) { return "\"" + p.lexically_normal().generic_string() + "\""; }

// The luminaires: a 2 × 3 array "A" and a single "B" of the same file and MF (one type of 7), the
// same file at another MF ("C"), an EULUMDAT file with `power_w` ("D", 2 fittings) and an
// absolute IES file at multiplier 2 ("E"). Grids: a cylindrical one first (not horizontal), then
// the work plane and the floor.
std::string caseText(const std::string& caseKeys = "", const std::string& more = "") {
  std::ostringstream s;
  s << "[case]\nname = \"schedule\"\n" << caseKeys << "\n[[scene]]\nfile = \"room.rad\"\n"
    << "[[luminaire]]\nname = \"A\"\nfile = " << quoted(kBollard)
    << "\nposition = [1, 1, 2.9]\nmaintenance_factor = 0.8\narray = { rows = 2, columns = 3, spacing = [2, 2] }\n"
    << "[[luminaire]]\nname = \"B\"\nfile = " << quoted(kBollard) << "\nposition = [2, 2, 2.9]\nmaintenance_factor = 0.8\n"
    << "[[luminaire]]\nname = \"C\"\nfile = " << quoted(kBollard) << "\nposition = [4, 2, 2.9]\nmaintenance_factor = 0.7\n"
    << "[[luminaire]]\nname = \"D\"\nfile = " << quoted(kFluorescent)
    << "\nposition = [2, 3.5, 2.9]\npower_w = 50\narray = { rows = 1, columns = 2, spacing = [2, 1] }\n"
    << "[[luminaire]]\nname = \"E\"\nfile = " << quoted(kPanel) << "\nposition = [5, 3, 2.9]\nmultiplier = 2\n"
    << more
    << "[[grid]]\nname = \"faces\"\ncorners = [[1, 1], [5, 3]]\nheight = 1.2\nspacing = 1\nquantity = \"cylindrical\"\n"
    << "[[grid]]\nname = \"workplane\"\ncorners = [[0, 0], [6, 4]]\nheight = 0.8\nspacing = 0.5\nborder = 0.5\n"
    << "[[grid]]\nname = \"floor\"\ncorners = [[0, 0], [6, 4]]\nheight = 0.0\nspacing = 0.5\nborder = 0.5\n"
    << "[settings]\nquality = \"draft\"\nseed = 3\n";
  return s.str();
}

struct CaseRun {
  RunResult result;
  json summary;
};

// Writes the room and the case into a fresh folder of this process's own (CTest runs a suite's
// tests as parallel processes, each emptying the folder first) and runs it.
CaseRun runText(const std::string& name, const std::string& text, bool strict = false) {
  const fs::path dir = fs::path(testing::TempDir()) / ("schedule_" + name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "room.rad") << kRoom;
  std::ofstream(dir / "case.toml") << text;
  RunRequest request;
  request.outDir = dir / "out";
  request.strict = strict;
  CaseRun r;
  r.result = runCase(dir / "case.toml", request);
  std::ifstream in(dir / "out" / "summary.json");
  r.summary = json::parse(in);
  return r;
}

const json& gridNamed(const json& summary, const std::string& name) {
  for (const json& g : summary["grids"])
    if (g["name"] == name) return g;
  ADD_FAILURE() << "no grid " << name;
  return summary["grids"][0];
}

class ScheduleCase : public testing::Test {
 protected:
  static void SetUpTestSuite() { run_ = new CaseRun(runText("main", caseText())); }
  static void TearDownTestSuite() { delete run_; }
  static const json& summary() { return run_->summary; }
  static CaseRun* run_;
};
CaseRun* ScheduleCase::run_ = nullptr;

TEST_F(ScheduleCase, OneRowPerTypeCountingEveryPlacedLuminaire) {
  const json& l = summary()["luminaires"];
  ASSERT_EQ(l.size(), 4u);
  // A's 2 × 3 array and B: the same file and maintenance factor.
  EXPECT_EQ(l[0]["count"], 7);
  EXPECT_EQ(l[0]["entries"], json({"A", "B"}));
  EXPECT_EQ(l[0]["maintenance_factor"], 0.8);
  EXPECT_EQ(l[1]["count"], 1);  // C: another maintenance factor, another type
  EXPECT_EQ(l[1]["entries"], json({"C"}));
  EXPECT_EQ(l[1]["maintenance_factor"], 0.7);
  EXPECT_EQ(l[2]["count"], 2);  // D: a 1 × 2 array
  EXPECT_EQ(l[3]["count"], 1);
  // Every placement of the case (arrays expanded by the case reader) is in one row.
  int placed = 0;
  for (const json& t : l) placed += t["count"].get<int>();
  EXPECT_EQ(placed, static_cast<int>(readCaseFile(run_->result.outDir.parent_path() / "case.toml").luminaires.size()));
  // The file as the case names it.
  EXPECT_EQ(l[0]["file"], kBollard.lexically_normal().generic_string());
  EXPECT_EQ(l[2]["file"], kFluorescent.lexically_normal().generic_string());
}

TEST_F(ScheduleCase, FluxPowerAndLorAreTheFilesOwn) {
  const json& l = summary()["luminaires"];
  ASSERT_EQ(l.size(), 4u);
  const LuminaireSummary bollard = summarizeLuminaire(readPhotometricFile(kBollard));
  const LuminaireSummary fluorescent = summarizeLuminaire(readPhotometricFile(kFluorescent));
  const LuminaireSummary panel = summarizeLuminaire(readPhotometricFile(kPanel));
  for (int i : {0, 1}) {
    EXPECT_DOUBLE_EQ(l[i]["flux_lm"].get<double>(), bollard.totalLumens);
    EXPECT_DOUBLE_EQ(l[i]["lamp_flux_lm"].get<double>(), bollard.lampLumens);
    EXPECT_DOUBLE_EQ(l[i]["light_output_ratio"].get<double>(), bollard.lightOutputRatio);
    EXPECT_DOUBLE_EQ(l[i]["power_w"].get<double>(), bollard.inputWatts);
    EXPECT_EQ(l[i]["power_source"], "file");
    EXPECT_DOUBLE_EQ(l[i]["efficacy_lm_per_w"].get<double>(), bollard.totalLumens / bollard.inputWatts);
  }
  // The file's texts: [MANUFAC], [LUMINAIRE] with its [MORE] lines, [LUMCAT], [LAMPCAT].
  EXPECT_EQ(l[0]["manufacturer"], "H.E. WILLIAMS, INC - CARTHAGE, MISSOURI");
  EXPECT_EQ(l[0]["luminaire"].get<std::string>().rfind("1/100W CLEAR ED17 LAMP", 0), 0u);
  EXPECT_NE(l[0]["luminaire"].get<std::string>().find("CYLINDER LENS"), std::string::npos);
  EXPECT_EQ(l[0]["catalogue_number"], "OSA6R-100PSMH120-AC");
  EXPECT_NE(l[0]["lamp"].get<std::string>().find("M90 MH100W/U/PS"), std::string::npos);
  EXPECT_NE(l[0]["lamp"].get<std::string>().find("1 × 9000 lm"), std::string::npos);

  // EULUMDAT: lamp set 1; `power_w` replaces the file's 120 W.
  EXPECT_DOUBLE_EQ(l[2]["flux_lm"].get<double>(), fluorescent.totalLumens);
  EXPECT_DOUBLE_EQ(l[2]["lamp_flux_lm"].get<double>(), fluorescent.lampLumens);
  EXPECT_DOUBLE_EQ(l[2]["light_output_ratio"].get<double>(), fluorescent.lightOutputRatio);
  EXPECT_NE(fluorescent.inputWatts, 50.0);
  EXPECT_EQ(l[2]["power_w"], 50.0);
  EXPECT_EQ(l[2]["power_source"], "case");
  EXPECT_DOUBLE_EQ(l[2]["efficacy_lm_per_w"].get<double>(), fluorescent.totalLumens / 50.0);
  EXPECT_EQ(l[2]["manufacturer"], "Osram GmbH");
  EXPECT_EQ(l[2]["luminaire"], "T16 G5 54W Fluorescent");
  EXPECT_EQ(l[2]["catalogue_number"], "FL-T16-54W");
  // Its colour rendering as lamp set 1 states it, and the least Ra that promises; IES: none.
  const std::string cr = readPhotometricFile(kFluorescent).info().lampSets.at(0).colourRendering;
  EXPECT_EQ(l[2]["colour_rendering"], cr);
  const std::optional<double> ra = leastColourRendering(cr);
  if (ra) EXPECT_EQ(l[2]["ra_least"], *ra);
  else EXPECT_TRUE(l[2]["ra_least"].is_null());
  EXPECT_TRUE(l[0]["ra_least"].is_null());

  // Absolute photometry: no lamp flux and no LOR; the multiplier scales the flux, not the power.
  EXPECT_TRUE(l[3]["lamp_flux_lm"].is_null());
  EXPECT_TRUE(l[3]["light_output_ratio"].is_null());
  EXPECT_DOUBLE_EQ(l[3]["flux_lm"].get<double>(), 2.0 * panel.totalLumens);
  EXPECT_DOUBLE_EQ(l[3]["power_w"].get<double>(), panel.inputWatts);
  EXPECT_EQ(l[3]["multiplier"], 2.0);
  EXPECT_EQ(l[3]["luminaire"], "LED panel 600 x 600 mm, opal diffuser, recessed");
}

TEST_F(ScheduleCase, PowerDensityIsTheInstalledPowerOverThePlanExtent) {
  const json& e = summary()["energy"];
  double installed = 0.0;
  for (const json& t : summary()["luminaires"]) installed += t["count"].get<double>() * t["power_w"].get<double>();
  EXPECT_EQ(e["installed_power_w"].get<double>(), installed);
  EXPECT_EQ(installed, 8 * 100.0 + 2 * 50.0 + 36.0);  // the files' watts and D's power_w
  EXPECT_EQ(e["installed_power_is_lower_bound"], false);
  EXPECT_TRUE(e["luminaires_without_power"].empty());
  EXPECT_EQ(e["floor_area_m2"], 24.0);  // the room's 6 m × 4 m
  EXPECT_EQ(e["floor_area_source"], "scene plan extent");
  EXPECT_EQ(e["power_density_w_m2"].get<double>(), installed / 24.0);
  // The cylindrical grid comes first but is not horizontal illuminance: the work plane is taken.
  EXPECT_EQ(e["reference_grid"], "workplane");
  const double average = gridNamed(summary(), "workplane")["average"].get<double>();
  EXPECT_GT(average, 0.0);
  EXPECT_EQ(e["reference_grid_average_lux"].get<double>(), average);
  EXPECT_DOUBLE_EQ(e["power_density_w_m2_per_100lx"].get<double>(),
                   e["power_density_w_m2"].get<double>() * 100.0 / average);
  EXPECT_TRUE(summary()["warnings"].empty()) << summary()["warnings"].dump();
}

// The materials the surfaces use, with the photopic reflectance of their colours as written in
// kRoom (Radiance's definitions: plastic ρ = (1 − s)·colour + s; trans ρ = (1 − s)(1 − t)·colour
// + s, τ = (1 − s)·t·colour; thin glass at normal incidence with its inter-reflections).
TEST_F(ScheduleCase, SurfacesListTheReflectancesOfTheMaterialsInUse) {
  const json& s = summary()["surfaces"];
  std::map<std::string, json> byName;
  for (const json& m : s) byName[m["material"].get<std::string>()] = m;
  EXPECT_EQ(byName.size(), 4u) << s.dump();  // not the unused paint, not the glow
  EXPECT_FALSE(byName.count("unused_paint"));
  EXPECT_FALSE(byName.count("pilot_lamp"));
  auto y = [](double r, double g, double b) { return 0.265 * r + 0.670 * g + 0.065 * b; };
  EXPECT_NEAR(byName["wall_paint"]["reflectance"].get<double>(), y(0.7, 0.6, 0.5), 1e-12);
  EXPECT_EQ(byName["wall_paint"]["surfaces"], 5);
  EXPECT_EQ(byName["wall_paint"]["type"], "plastic");
  EXPECT_TRUE(byName["wall_paint"]["transmittance"].is_null());
  EXPECT_NEAR(byName["floor_vinyl"]["reflectance"].get<double>(), 0.98 * y(0.3, 0.3, 0.25) + 0.02, 1e-12);
  EXPECT_NEAR(byName["floor_vinyl"]["specular_reflectance"].get<double>(), 0.02, 1e-12);
  EXPECT_NEAR(byName["screen_fabric"]["reflectance"].get<double>(), 0.7 * 0.6, 1e-12);
  EXPECT_NEAR(byName["screen_fabric"]["transmittance"].get<double>(), 0.3 * 0.6, 1e-12);
  // Thin glass, normal incidence: R = ((n − 1)/(n + 1))², τ = 0.9 per pass;
  // T = (1 − R)² τ / (1 − R² τ²), ρ = R + (1 − R)² R τ² / (1 − R² τ²).
  const double r = std::pow((1.52 - 1.0) / (1.52 + 1.0), 2), tau = 0.9, d = 1.0 - r * r * tau * tau;
  EXPECT_NEAR(byName["pane_glass"]["transmittance"].get<double>(), (1 - r) * (1 - r) * tau / d, 1e-12);
  EXPECT_NEAR(byName["pane_glass"]["reflectance"].get<double>(), r + (1 - r) * (1 - r) * r * tau * tau / d, 1e-12);
}

TEST_F(ScheduleCase, ReportShowsTheScheduleEnergyAndSurfacesInWords) {
  std::ifstream in(run_->result.outDir / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* s : {"<h2>Luminaire schedule</h2>", "<h2>Energy</h2>", "<h2>Surfaces</h2>", "T16 G5 54W Fluorescent",
                        "Make: Osram GmbH", "Catalogue no.: FL-T16-54W", ">wall paint<", ">screen fabric<",
                        "Glass (thin pane)", "Translucent", "on grid workplane, the case&#39;s first grid of horizontal",
                        "the plan extent of the scene's bounding box, 6.00 m × 4.00 m", "W/m²/100 lx",
                        "from the case"})
    EXPECT_NE(html.find(s), std::string::npos) << s;
  // One small polar plot per type (the schedule's, titled with its entries).
  std::size_t plots = 0;
  for (std::size_t at = html.find("<td class=\"polar\"><svg"); at != std::string::npos;
       at = html.find("<td class=\"polar\"><svg", at + 1))
    ++plots;
  EXPECT_EQ(plots, 4u);
  EXPECT_NE(html.find(">A, B</text>"), std::string::npos);
}

// EULUMDAT colour rendering fields as manufacturers write them (the shared reference's files:
// "1B/80", "70", "25", "1B", "1A", "1A/90", "1B/86"), CIE 29.2's groups' least Ra otherwise.
TEST(ColourRendering, NumberElseGroupElseNothing) {
  const std::pair<const char*, double> promised[] = {{"1B/80", 80}, {"1B/86", 86}, {"1A/90", 90}, {"70", 70},
                                                     {"25", 25},    {"Ra>80", 80}, {"1A", 90},   {"1b", 80},
                                                     {"2A", 70},    {"2B", 60},    {" 3 ", 40},  {"4", 20}};
  for (const auto& [field, ra] : promised) EXPECT_EQ(leastColourRendering(field), ra) << field;
  for (const char* field : {"", "n/a", "5", "1000"}) EXPECT_FALSE(leastColourRendering(field).has_value()) << field;
}

TEST(Energy, FloorAreaAndReferenceGridFromTheCase) {
  const CaseRun r = runText("keys", caseText("floor_area = 20\nreference_grid = \"floor\"\n"));
  const json& e = r.summary["energy"];
  EXPECT_EQ(e["floor_area_m2"], 20.0);
  EXPECT_EQ(e["floor_area_source"], "case");
  EXPECT_EQ(e["power_density_w_m2"].get<double>(), e["installed_power_w"].get<double>() / 20.0);
  EXPECT_EQ(e["reference_grid"], "floor");
  const double average = gridNamed(r.summary, "floor")["average"].get<double>();
  EXPECT_DOUBLE_EQ(e["power_density_w_m2_per_100lx"].get<double>(),
                   e["power_density_w_m2"].get<double>() * 100.0 / average);
}

// A file that gives 0 W and an entry without power_w: the installed power leaves it out (a lower
// bound), the entry is listed, and the warning points at its line; strict runs stop on it.
TEST(Energy, UnknownPowerIsALowerBoundWithAWarning) {
  const std::string unknown = "[[luminaire]]\nname = \"X\"\nfile = " + quoted(kNoWatts) +
                              "\nposition = [3, 2, 2.9]\narray = { rows = 1, columns = 2, spacing = [1, 1] }\n";
  const std::string text = caseText("", unknown);
  ASSERT_EQ(readPhotometricFile(kNoWatts).inputWatts(), 0.0);
  const CaseRun r = runText("unknown", text);
  const json& e = r.summary["energy"];
  EXPECT_EQ(e["installed_power_w"], 8 * 100.0 + 2 * 50.0 + 36.0);
  EXPECT_EQ(e["installed_power_is_lower_bound"], true);
  EXPECT_EQ(e["luminaires_without_power"], json({"X"}));
  const json& x = r.summary["luminaires"][4];
  EXPECT_EQ(x["count"], 2);
  EXPECT_TRUE(x["power_w"].is_null());
  EXPECT_TRUE(x["efficacy_lm_per_w"].is_null());
  // The warning, once for the entry, at its [[luminaire]] line.
  int line = 0, n = 0;
  std::istringstream lines(text);
  for (std::string l; std::getline(lines, l);) {
    ++n;
    if (l == "name = \"X\"") line = n - 1;
  }
  int found = 0;
  for (const json& w : r.summary["warnings"]) {
    if (w["code"] != "luminaire_power_unknown") continue;
    ++found;
    EXPECT_EQ(w["line"], line);
    EXPECT_NE(w["message"].get<std::string>().find("luminaire 'X'"), std::string::npos);
  }
  EXPECT_EQ(found, 1);
  std::ifstream in(r.result.outDir / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("<strong>at least</strong> 936 W: the input power of X is not known"), std::string::npos);
  try {
    runText("unknown_strict", text, true);
    ADD_FAILURE() << "a strict run accepted a luminaire of unknown power";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("[luminaire_power_unknown]"), std::string::npos) << err.what();
    EXPECT_EQ(err.loc().line, line);
  }
  // power_w gives it: no warning, the full power.
  const CaseRun given = runText("given", caseText("", unknown + "power_w = 12.5\n"));
  EXPECT_EQ(given.summary["energy"]["installed_power_w"], 8 * 100.0 + 2 * 50.0 + 36.0 + 2 * 12.5);
  EXPECT_TRUE(given.summary["warnings"].empty()) << given.summary["warnings"].dump();
}

// Which grid W/m²/100 lx is taken on, from the prepared grids alone.
TEST(ReferenceGrid, ExplicitElseFirstHorizontalGridElseTheFirstTaskGrid) {
  const fs::path path = fs::path(testing::TempDir()) / ("reference." + std::to_string(::getpid()) + ".toml");
  Box room;
  room.extend(Vec3(0.0));
  room.extend(Vec3(6.0, 4.0, 3.0));
  auto pick = [&](const std::string& text) {
    const CaseFile c = parseCaseFile(text, path);
    const std::vector<PreparedGrid> grids = prepareGrids(c, room);
    const ReferenceGrid r = referenceGrid(c, grids);
    return r.index < 0 ? std::string("none") : grids[static_cast<std::size_t>(r.index)].spec->name + ": " + r.reason;
  };
  const std::string task = "[[task_area]]\nname = \"desk\"\ncorners = [[1, 1], [2, 2]]\nheight = 0.8\n"
                           "maintained_illuminance = 500\n";
  const std::string vertical = "[[grid]]\nname = \"wall\"\ncorners = [[0, 0], [2, 2]]\nheight = 1.2\n"
                               "quantity = \"vertical\"\nfacing = [1, 0]\n";
  const std::string plane = "[[grid]]\nname = \"plane\"\ncorners = [[0, 0], [2, 2]]\nheight = 0.8\n";
  EXPECT_EQ(pick(task + vertical + plane), "plane: the case's first grid of horizontal illuminance");
  EXPECT_EQ(pick(task + vertical), "desk: the task grid of the first task area");
  EXPECT_EQ(pick("[case]\nreference_grid = \"desk surrounding\"\n" + task + plane),
            "desk surrounding: the case's reference grid");
  EXPECT_EQ(pick(vertical), "none");
  // A plane tilted by its normal measures no horizontal illuminance: refused at the key's line.
  const std::string tilted = "[case]\nreference_grid = \"tilted\"\n[[grid]]\nname = \"tilted\"\n"
                             "corners = [[0, 0], [2, 2]]\nheight = 0.8\nnormal = [0, 1, 1]\n";
  try {
    pick(tilted);
    ADD_FAILURE() << "a tilted reference grid was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_NE(std::string(e.what()).find("do not all measure horizontal illuminance"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace candela
