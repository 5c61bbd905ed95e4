// The annual study traced block by block (study/annual_study.h AnnualStudyOptions): a small case
// of two grids traced in blocks of 64 sensors, one of which straddles the grids, against the same
// case in one block (the whole-study order of before the blocks); LM-83's blinds rule, whose
// per-hour count spans the blocks, checked against the whole-grid function on the written
// direct-sun file; a run that fails mid-way leaves neither a result nor its temporary folder.
#include "study/annual_study.h"

#include "metrics/annual.h"
#include "reports/annual_results.h"
#include "study/case/case_file.h"
#include "study/run_case.h"
#include "study/run_outputs.h"
#include "study/trace_options.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {
namespace {

namespace fs = std::filesystem;
using test_support::scratchDir;
using test_support::slurp;

const fs::path kCase = fs::path(CANDELA_TEST_DATA) / "study" / "annual_blocks" / "case.toml";

RunResult runInBlocks(const fs::path& outDir, std::size_t sensorsPerBlock, StudyObserver& observer) {
  CaseFile c = readCaseFile(kCase);
  RunContext run;
  run.request.outDir = outDir;
  c.settings.scene = sceneReadOptions(&c.settings, run.request.trace);
  run.outDir = outDir;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = "2026-01-01 00:00";
  return runAnnualStudy(c, run, observer, AnnualStudyOptions{sensorsPerBlock});
}

// Runs the case once in blocks of 64 and once in one block, for every test of this file.
class AnnualBlocks : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    // A folder of this process's own: CTest runs this suite's tests as parallel processes, and
    // scratchDir empties its folder.
    dir_ = scratchDir("annual_study", "blocks." + std::to_string(::getpid()));
    const fs::path& d = dir_;
    blocks_ = new RunResult(runInBlocks(d / "blocks64", 64, silentObserver()));
    whole_ = new RunResult(runInBlocks(d / "whole", 1 << 20, silentObserver()));
  }
  static void TearDownTestSuite() {
    delete blocks_;
    delete whole_;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static RunResult* blocks_;
  static RunResult* whole_;
  static fs::path dir_;
};
RunResult* AnnualBlocks::blocks_ = nullptr;
RunResult* AnnualBlocks::whole_ = nullptr;
fs::path AnnualBlocks::dir_;

TEST_F(AnnualBlocks, TheCaseHasBlocksThatStraddleItsGrids) {
  ASSERT_EQ(whole_->data.grids.size(), 2u);
  const int room = whole_->data.grids[0].annual->summary.sensors, band = whole_->data.grids[1].annual->summary.sensors;
  // Neither grid a multiple of the block, and the second block holds sensors of both.
  EXPECT_GT(room, 64);
  EXPECT_LT(room, 128);
  EXPECT_NE(room % 64, 0);
  EXPECT_GT(room + band, 128);
}

TEST_F(AnnualBlocks, SameFilesAsOneBlock) {
  for (const GridReport& g : whole_->data.grids)
    for (const std::string& name : {annualResultsFileName(g.name), annualResultsFileName(g.name + "_direct_sun"),
                                    safeFileName(g.name) + "_annual.csv"}) {
      const std::string a = slurp(blocks_->outDir / name), b = slurp(whole_->outDir / name);
      EXPECT_FALSE(a.empty()) << name;
      EXPECT_TRUE(a == b) << name << " differs";
    }
}

TEST_F(AnnualBlocks, StreamedFilesAreWholeAndReadable) {
  for (const GridReport& g : blocks_->data.grids) {
    const AnnualResults r = readAnnualResults(blocks_->outDir / annualResultsFileName(g.name));
    EXPECT_EQ(r.sensors, g.annual->summary.sensors);
    EXPECT_EQ(r.hourCount(), 8760);
    EXPECT_EQ(r.hours, g.annual->hours);
    // The temporal map's sensor is that row of the file.
    EXPECT_EQ(r.sensorSeries(g.annual->chosenSensor), g.annual->chosenSensorLux);
  }
  // Nothing but the result: no temporary folder beside it.
  for (const fs::directory_entry& e : fs::directory_iterator(blocks_->outDir.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST_F(AnnualBlocks, BlindsRuleOverTheWholeGridAcrossBlocks) {
  // Independent of the blocks: the whole grid's direct-sun file through blindsClosedHours.
  int closedSomewhere = 0, shadedDiffers = 0;
  for (const GridReport& g : blocks_->data.grids) {
    const AnnualResults direct = readAnnualResults(blocks_->outDir / annualResultsFileName(g.name + "_direct_sun"));
    const AnnualResults total = readAnnualResults(blocks_->outDir / annualResultsFileName(g.name));
    std::vector<int> hourEnding;
    for (const HourStamp& h : direct.hours) hourEnding.push_back(h.hourEnding);
    const std::vector<char> occupied = occupiedHours(hourEnding, 8.0, 18.0);
    const std::vector<char> closed = blindsClosedHours(direct.lux.data(), direct.sensors, 8760, occupied);
    closedSomewhere += countHours(closed);
    // ASE uses the direct sun alone, blinds open: the file's values give the study's hours.
    const AnnualThresholds th;
    const std::vector<SensorAnnualMetrics> open =
        sensorAnnualMetrics(total.lux.data(), direct.lux.data(), total.sensors, 8760, occupied, th);
    const std::vector<SensorAnnualMetrics>& study = g.annual->sensors;
    ASSERT_EQ(study.size(), open.size());
    for (std::size_t s = 0; s < open.size(); ++s) {
      EXPECT_EQ(study[s].aseHours, open[s].aseHours);
      EXPECT_EQ(study[s].sunHours, open[s].sunHours);
      shadedDiffers += study[s].da != open[s].da;
    }
  }
  // Not vacuous: the rule closed the blinds in some hours and that changed DA somewhere.
  EXPECT_GT(closedSomewhere, 0);
  EXPECT_GT(shadedDiffers, 0);
  // And the blocks' metrics are the one block's, number for number.
  for (std::size_t gi = 0; gi < whole_->data.grids.size(); ++gi) {
    const auto& a = blocks_->data.grids[gi].annual->sensors;
    const auto& b = whole_->data.grids[gi].annual->sensors;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t s = 0; s < a.size(); ++s) {
      EXPECT_EQ(a[s].da, b[s].da);
      EXPECT_EQ(a[s].cda, b[s].cda);
      EXPECT_EQ(a[s].udiAutonomous, b[s].udiAutonomous);
    }
  }
}

// Fails as the blinds' pass begins: the hourly files of the open pass are written by then.
class FailAtClosedPass : public StudyObserver {
 public:
  void begin(const std::string& label, std::size_t) override {
    if (label.rfind("blinds closed", 0) == 0) throw std::runtime_error("stopped by the test");
  }
};

TEST(AnnualStudy, AFailedRunLeavesNoResultAndNoTemporaryFolder) {
  const fs::path d = scratchDir("annual_study", "failed");
  FailAtClosedPass observer;
  EXPECT_THROW(runInBlocks(d / "out", 64, observer), std::runtime_error);
  EXPECT_TRUE(fs::is_empty(d)) << "left behind: " << fs::directory_iterator(d)->path();
}

}  // namespace
}  // namespace candela
