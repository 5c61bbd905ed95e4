// Progress on stderr for long runs. On a terminal: a bar redrawn in place ("points done / total,
// percent, elapsed, ETA"). Without one (a log, a pipe): a plain line at most every 10 s, and only
// for work that lasts longer than that (docs/reliability.md, "Progress for logs"). Only the command
// line prints; engine loops report through a callback that calls update().
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "study/observer.h"

namespace candela::cli {

enum class ProgressMode {
  kOff,    // --quiet
  kBar,    // stderr is a terminal
  kLines,  // stderr is a file or a pipe
};

class ProgressBar {
 public:
  // Seconds on a monotonic clock; injectable for tests.
  using Clock = std::function<double()>;
  static double steadySeconds();

  struct Options {
    std::FILE* out = stderr;
    Clock clock = steadySeconds;
    double lineIntervalS = 10.0;  // kLines: seconds between lines, and the work that gets none
    double expectedS = -1.0;      // the step's estimated duration (< 0: none), shown from the start
  };

  // `label` precedes the bar, e.g. "tracing".
  ProgressBar(std::string label, std::size_t total, ProgressMode mode, Options options);
  ProgressBar(std::string label, std::size_t total, ProgressMode mode)
      : ProgressBar(std::move(label), total, mode, Options{}) {}
  ~ProgressBar();

  // Safe to call from many threads at once: `done` points finished so far. Redraws the bar at
  // most every kRedrawInterval, prints a line at most every lineIntervalS; calls in between
  // cost one atomic load and a clock read.
  void update(std::size_t done);

  // Draws the final state and ends the line (idempotent). kLines: a last line only when the
  // work lasted at least lineIntervalS and the last line printed did not already say it.
  void finish();

  // The mode for stderr: kOff when quiet, kBar on a terminal, else kLines.
  static ProgressMode modeFor(bool quiet);

  // The bar's text for `done` of `total` after `elapsedS` seconds (no carriage return), e.g.
  // "tracing [#########...........]  412/1200  34%  0:12 elapsed, ETA 0:23". With an estimate
  // (expectedS >= 0): ", estimated 0:40" follows, and stands for the ETA while nothing is done.
  // The ETA is (total − done) × countingS / done, countingS the seconds since the step last
  // reported 0 done (< 0 or more than elapsedS: elapsedS), so that a step's setup (the cache)
  // is not charged to its first points.
  static std::string format(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                            int width = 30, double expectedS = -1.0, double countingS = -1.0);
  // The plain line for logs, e.g. "tracing: 412/1200 (34%), 0:12 elapsed, ETA 0:23, estimated 0:40".
  static std::string formatLine(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                                double expectedS = -1.0, double countingS = -1.0);

  static constexpr std::chrono::milliseconds kRedrawInterval{200};

 private:
  void draw(std::size_t done);
  double elapsed() const { return clock_() - start_; }

  std::string label_;
  std::size_t total_;
  ProgressMode mode_;
  std::FILE* out_;
  Clock clock_;
  double lineIntervalS_;
  double expectedS_;
  double start_;
  std::atomic<int64_t> nextDrawNs_{0};  // time (ns since start_) of the next redraw or line
  std::atomic<int64_t> countingFromNs_{0};  // time (ns since start_) of the last update(0)
  std::mutex drawMutex_;
  bool finished_ = false;
  std::size_t lastDrawn_ = static_cast<std::size_t>(-1);  // `done` of the last line or bar drawn
};

// "estimate: about 1:23:45 (3.2e11 rays on 2 threads at 2.0 M rays/s each), memory about 1.2 GiB
// of 22.0 GiB allowed"; `limitBytes` 0: no limit shown.
std::string estimateLine(const ResourceEstimate& e, uint64_t limitBytes);

// A study's steps as progress bars or log lines (none when quiet). The estimate is printed
// before tracing when the work is expected to take at least kEstimateShownS (short runs stay
// quiet), and each step's bar shows its estimated duration.
class ProgressObserver : public StudyObserver {
 public:
  static constexpr double kEstimateShownS = 10.0;
  explicit ProgressObserver(bool quiet, uint64_t limitBytes = 0, std::FILE* out = stderr)
      : mode_(ProgressBar::modeFor(quiet)), limitBytes_(limitBytes), out_(out) {}
  ProgressObserver(ProgressMode mode, ProgressBar::Options options, uint64_t limitBytes = 0)
      : mode_(mode), limitBytes_(limitBytes), out_(options.out), options_(std::move(options)) {}
  void estimated(const ResourceEstimate& e) override;
  void begin(const std::string& label, std::size_t total) override;
  void progress(std::size_t done) override {
    if (bar_) bar_->update(done);
  }
  void end() override {
    if (bar_) bar_->finish();
    bar_.reset();
  }

 private:
  ProgressMode mode_;
  uint64_t limitBytes_;
  std::FILE* out_;
  ProgressBar::Options options_;
  std::unique_ptr<ResourceEstimate> estimate_;
  std::unique_ptr<ProgressBar> bar_;
};

}  // namespace candela::cli
