// A progress bar on stderr for long runs: "points done / total, percent, elapsed, ETA". Only the
// command line prints; engine loops report through a callback that calls update().
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

#include "study/observer.h"

namespace candela::cli {

class ProgressBar {
 public:
  // `enabled` false makes every call a no-op (not a terminal, or --quiet). `label` precedes
  // the bar, e.g. "tracing".
  ProgressBar(std::string label, std::size_t total, bool enabled, std::FILE* out = stderr);
  ~ProgressBar();

  // Safe to call from many threads at once: `done` points finished so far. Redraws at most
  // every kRedrawInterval; calls in between cost one atomic load and a clock read.
  void update(std::size_t done);

  // Draws the final state and ends the line (idempotent).
  void finish();

  // True when stderr is a terminal and the user did not ask for quiet.
  static bool wanted(bool quiet);

  // The bar's text for `done` of `total` after `elapsedS` seconds (no carriage return), e.g.
  // "tracing [#########...........]  412/1200  34%  0:12 elapsed, ETA 0:23". Pure, for tests.
  static std::string format(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                            int width = 30);

  static constexpr std::chrono::milliseconds kRedrawInterval{200};

 private:
  void draw(std::size_t done);

  std::string label_;
  std::size_t total_;
  bool enabled_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<int64_t> nextDrawNs_{0};  // steady-clock time (ns since start_) of the next redraw
  std::mutex drawMutex_;
  bool finished_ = false;
};

// A study's steps as progress bars (none when not wanted).
class ProgressObserver : public StudyObserver {
 public:
  explicit ProgressObserver(bool quiet) : enabled_(ProgressBar::wanted(quiet)) {}
  void begin(const std::string& label, std::size_t total) override {
    bar_ = std::make_unique<ProgressBar>(label, total, enabled_);
  }
  void progress(std::size_t done) override {
    if (bar_) bar_->update(done);
  }
  void end() override {
    if (bar_) bar_->finish();
    bar_.reset();
  }

 private:
  bool enabled_;
  std::unique_ptr<ProgressBar> bar_;
};

}  // namespace candela::cli
