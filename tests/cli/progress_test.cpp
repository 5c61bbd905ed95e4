// The log mode of cli/progress (docs/reliability.md, "Progress for logs"): lines at most every
// interval, none for work shorter than one, and their text; the bar's estimate from the start.
#include "cli/progress.h"
#include "cli/resource_options.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace candela::cli {
namespace {

// What was written to a temporary FILE*, as lines.
std::vector<std::string> linesOf(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::vector<std::string> out;
  std::string line;
  for (int c; (c = std::fgetc(f)) != EOF;) {
    if (c == '\n') {
      out.push_back(line);
      line.clear();
    } else {
      line.push_back(static_cast<char>(c));
    }
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

struct FakeClock {
  double now = 1000.0;
  ProgressBar::Options options(std::FILE* out, double intervalS = 10.0) {
    ProgressBar::Options o;
    o.out = out;
    o.clock = [this] { return now; };
    o.lineIntervalS = intervalS;
    return o;
  }
};

TEST(ProgressLines, NoneForWorkShorterThanTheInterval) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  {
    ProgressBar bar("tracing", 100, ProgressMode::kLines, clock.options(f));
    for (int i = 1; i <= 100; ++i) {
      clock.now += 0.099;  // 9.9 s in all
      bar.update(i);
    }
    bar.finish();
  }
  EXPECT_TRUE(linesOf(f).empty());
  std::fclose(f);
}

TEST(ProgressLines, AtMostOneLinePerIntervalAndAFinalLine) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  std::vector<double> printedAt;
  {
    ProgressBar bar("tracing", 1000, ProgressMode::kLines, clock.options(f));
    std::size_t lines = 0;
    for (int i = 1; i <= 1000; ++i) {
      clock.now += 0.047;  // 47 s in all, an update every 47 ms
      bar.update(i);
      const std::size_t n = linesOf(f).size();
      std::fseek(f, 0, SEEK_END);
      if (n > lines) printedAt.push_back(clock.now - 1000.0);
      lines = n;
    }
    bar.finish();
  }
  const std::vector<std::string> lines = linesOf(f);
  // Lines at 10, 20, 30 and 40 s (the first update past each mark), then the final one.
  ASSERT_EQ(printedAt.size(), 4u);
  EXPECT_GE(printedAt[0], 10.0);
  for (std::size_t k = 1; k < printedAt.size(); ++k) EXPECT_GE(printedAt[k] - printedAt[k - 1], 10.0);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines.back(), "tracing: 1000/1000 (100%), 0:47 elapsed");
  EXPECT_EQ(lines[0].rfind("tracing: 213/1000 (21%), 0:10 elapsed, ETA 0:37", 0), 0u) << lines[0];
  std::fclose(f);
}

TEST(ProgressLines, InjectedInterval) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  {
    ProgressBar bar("sky coefficients", 10, ProgressMode::kLines, clock.options(f, 1.0));
    for (int i = 1; i <= 9; ++i) {
      clock.now += 0.5;
      bar.update(i);
    }
    bar.finish();
  }
  // Updates at 0.5 s steps, a line at most every second: at 1, 2, 3, 4 s and the final one at 4.5 s.
  EXPECT_EQ(linesOf(f).size(), 5u);
  std::fclose(f);
}

// A step whose last update already printed its end (a compliance part: 4/4 after 12 s) gets no
// second, identical final line.
TEST(ProgressLines, NoRepeatedFinalLine) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  {
    ProgressBar bar("compliance en17037", 4, ProgressMode::kLines, clock.options(f));
    for (int i = 1; i <= 4; ++i) {
      clock.now += 12.0;
      bar.update(i);
    }
    bar.finish();
  }
  const std::vector<std::string> lines = linesOf(f);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines.back(), "compliance en17037: 4/4 (100%), 0:48 elapsed");
  std::fclose(f);
}

TEST(ProgressLines, OffPrintsNothing) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  {
    ProgressBar bar("tracing", 10, ProgressMode::kOff, clock.options(f));
    clock.now += 100.0;
    bar.update(5);
    bar.finish();
  }
  EXPECT_TRUE(linesOf(f).empty());
  std::fclose(f);
}

TEST(ProgressFormat, LineText) {
  EXPECT_EQ(ProgressBar::formatLine("tracing", 412, 1200, 12.0), "tracing: 412/1200 (34%), 0:12 elapsed, ETA 0:23");
  EXPECT_EQ(ProgressBar::formatLine("tracing", 412, 1200, 12.0, 40.0),
            "tracing: 412/1200 (34%), 0:12 elapsed, ETA 0:23, estimated 0:40");
  // Nothing done yet: the estimate is the ETA.
  EXPECT_EQ(ProgressBar::formatLine("rendering desk", 0, 5000, 3.0, 3725.0),
            "rendering desk: 0/5000 (0%), 0:03 elapsed, ETA 1:02:02, estimated 1:02:05");
}

// A step that reports 0 done while it builds its cache (60 s), then its points: the rate counts
// from the last 0, so one point 0.4 s later leaves 569 × 0.4 s = 3:48, not 569 × 60.4 s (the
// 9:32:48 a rate over the whole elapsed time gave).
TEST(ProgressFormat, TheEtaCountsFromTheLastZero) {
  EXPECT_EQ(ProgressBar::formatLine("tracing", 1, 570, 60.4, -1.0, 0.4), "tracing: 1/570 (0%), 1:00 elapsed, ETA 3:48");
  // No count start given, or one beyond the elapsed time: the whole elapsed time.
  EXPECT_EQ(ProgressBar::formatLine("tracing", 1, 570, 60.4), "tracing: 1/570 (0%), 1:00 elapsed, ETA 9:32:48");
  EXPECT_EQ(ProgressBar::formatLine("tracing", 1, 570, 60.4, -1.0, 99.0),
            "tracing: 1/570 (0%), 1:00 elapsed, ETA 9:32:48");
}

TEST(ProgressLines, TheEtaAfterASetupThatReportedZero) {
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  {
    ProgressBar bar("tracing", 570, ProgressMode::kLines, clock.options(f, 1.0));
    for (int i = 0; i < 60; ++i) {  // the cache: 0 done, once a second
      clock.now += 1.0;
      bar.update(0);
    }
    for (int i = 1; i <= 4; ++i) {  // then a point every 0.5 s
      clock.now += 0.5;
      bar.update(static_cast<std::size_t>(i));
    }
  }
  const std::vector<std::string> lines = linesOf(f);
  ASSERT_FALSE(lines.empty());
  // The last line: 4 points in the 2 s since the last 0 → 566 × 0.5 s = 4:43.
  EXPECT_EQ(lines.back(), "tracing: 4/570 (0%), 1:02 elapsed, ETA 4:43") << lines.back();
  std::fclose(f);
}

TEST(ProgressFormat, BarShowsTheEstimateFromTheStart) {
  const std::string bar = ProgressBar::format("tracing", 0, 100, 0.0, 10, 90.0);
  EXPECT_EQ(bar, "tracing [..........] 0/100   0%  0:00 elapsed, ETA 1:30, estimated 1:30");
}

TEST(ProgressObserverTest, EstimatePrintedOnlyForLongWork) {
  ResourceEstimate e;
  e.threads = 2;
  e.raysPerSecondPerThread = 1e6;
  e.baseBytes = 3ull << 30;
  e.work.push_back({"tracing", 2e6 * 5});  // 5 s
  {
    std::FILE* f = std::tmpfile();
    FakeClock clock;
    ProgressObserver o(ProgressMode::kLines, clock.options(f));
    o.estimated(e);
    EXPECT_TRUE(linesOf(f).empty());
    std::fclose(f);
  }
  e.work.back().rays = 2e6 * 100;  // 100 s
  std::FILE* f = std::tmpfile();
  FakeClock clock;
  ProgressObserver o(ProgressMode::kLines, clock.options(f), 8ull << 30);
  o.estimated(e);
  const std::vector<std::string> lines = linesOf(f);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "estimate: about 1:40 (2e+08 rays on 2 threads at 1.0 M rays/s each), memory about 3.0 GiB of "
                      "8.0 GiB allowed");
  std::fclose(f);
}

TEST(MaxMemory, Units) {
  EXPECT_EQ(parseMemorySize("8G"), 8ull << 30);
  EXPECT_EQ(parseMemorySize("512M"), 512ull << 20);
  EXPECT_EQ(parseMemorySize("512m"), 512ull << 20);
  EXPECT_EQ(parseMemorySize("1.5GiB"), 3ull << 29);
  EXPECT_EQ(parseMemorySize("100MB"), 100ull << 20);
  EXPECT_EQ(parseMemorySize("2048K"), 2ull << 20);
  EXPECT_EQ(parseMemorySize("1T"), 1ull << 40);
  EXPECT_EQ(parseMemorySize("4"), 4ull << 30);  // a plain number: GiB
  EXPECT_EQ(parseMemorySize("0.5"), 1ull << 29);
  for (const char* bad : {"", "G", "-1G", "0", "8X", "8GG", "eight", "nan", "1e30G"})
    EXPECT_THROW(parseMemorySize(bad), std::invalid_argument) << bad;
}

TEST(MaxMemory, AvailableIsKnownOnLinux) { EXPECT_GT(availableMemoryBytes(), 0u); }

}  // namespace
}  // namespace candela::cli
