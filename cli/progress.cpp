#include "cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace candela::cli {

namespace {

std::string clock(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

double fractionOf(std::size_t done, std::size_t total) {
  return total > 0 ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total)) : 1.0;
}

// ", ETA 0:23" from the rate so far; while nothing is done, the estimate stands in for it.
// ", estimated 0:40" when there is an estimate. The rate is done / countingS, the seconds since
// the step last reported nothing done: a step that first builds something (the irradiance
// cache, reporting 0 done meanwhile) would otherwise charge that time to its first points, and
// one point after a minute's cache read as an ETA of hours.
std::string timeLeft(std::size_t done, std::size_t total, double elapsedS, double expectedS, double countingS) {
  std::string s;
  if (countingS < 0.0 || countingS > elapsedS) countingS = elapsedS;
  if (done > 0 && done < total)
    s += ", ETA " + clock(countingS * static_cast<double>(total - done) / static_cast<double>(done));
  else if (done == 0 && total > 0 && expectedS >= 0.0)
    s += ", ETA " + clock(std::max(0.0, expectedS - elapsedS));
  if (expectedS >= 0.0) s += ", estimated " + clock(expectedS);
  return s;
}

}  // namespace

double ProgressBar::steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressBar::ProgressBar(std::string label, std::size_t total, ProgressMode mode, Options options)
    : label_(std::move(label)),
      total_(total),
      mode_(mode),
      out_(options.out),
      clock_(options.clock ? std::move(options.clock) : Clock(steadySeconds)),
      lineIntervalS_(options.lineIntervalS),
      expectedS_(options.expectedS),
      start_(clock_()) {
  if (mode_ == ProgressMode::kBar) draw(0);
  // A log's first line comes after one interval: work shorter than that prints nothing.
  if (mode_ == ProgressMode::kLines) nextDrawNs_.store(static_cast<int64_t>(lineIntervalS_ * 1e9));
}

ProgressBar::~ProgressBar() {
  // Left without finish() (an exception): end the bar's line without claiming completion.
  if (mode_ == ProgressMode::kBar && !finished_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

ProgressMode ProgressBar::modeFor(bool quiet) {
  if (quiet) return ProgressMode::kOff;
  return isatty(STDERR_FILENO) == 1 ? ProgressMode::kBar : ProgressMode::kLines;
}

std::string ProgressBar::format(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                                int width, double expectedS, double countingS) {
  const double fraction = fractionOf(done, total);
  const int filled = static_cast<int>(fraction * width);
  std::string bar = label + " [" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
  char buf[160];
  std::snprintf(buf, sizeof buf, " %zu/%zu %3d%%  %s elapsed", done, total, static_cast<int>(fraction * 100.0),
                clock(elapsedS).c_str());
  return bar + buf + timeLeft(done, total, elapsedS, expectedS, countingS);
}

std::string ProgressBar::formatLine(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                                    double expectedS, double countingS) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s: %zu/%zu (%d%%), %s elapsed", label.c_str(), done, total,
                static_cast<int>(fractionOf(done, total) * 100.0), clock(elapsedS).c_str());
  return buf + timeLeft(done, total, elapsedS, expectedS, countingS);
}

void ProgressBar::update(std::size_t done) {
  if (mode_ == ProgressMode::kOff) return;
  const int64_t now = static_cast<int64_t>(elapsed() * 1e9);
  if (done == 0) countingFromNs_.store(now, std::memory_order_relaxed);
  int64_t next = nextDrawNs_.load(std::memory_order_relaxed);
  if (now < next) return;
  // One thread wins the right to draw this interval; the others return at once.
  const int64_t interval = mode_ == ProgressMode::kBar
                               ? std::chrono::duration_cast<std::chrono::nanoseconds>(kRedrawInterval).count()
                               : static_cast<int64_t>(lineIntervalS_ * 1e9);
  if (!nextDrawNs_.compare_exchange_strong(next, now + interval, std::memory_order_relaxed)) return;
  std::unique_lock lock(drawMutex_, std::try_to_lock);
  if (lock && !finished_) draw(done);
}

void ProgressBar::draw(std::size_t done) {
  const double t = elapsed();
  const double counting = t - static_cast<double>(countingFromNs_.load(std::memory_order_relaxed)) * 1e-9;
  lastDrawn_ = done;
  if (mode_ == ProgressMode::kBar) {
    // "\r" returns to the line start; "\033[K" clears what a longer previous line left behind.
    std::fprintf(out_, "\r%s\033[K", format(label_, done, total_, t, 30, expectedS_, counting).c_str());
  } else {
    std::fprintf(out_, "%s\n", formatLine(label_, done, total_, t, expectedS_, counting).c_str());
  }
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (mode_ == ProgressMode::kOff) return;
  std::lock_guard lock(drawMutex_);
  if (finished_) return;
  finished_ = true;
  if (mode_ == ProgressMode::kLines) {
    if (elapsed() >= lineIntervalS_ && lastDrawn_ != total_) draw(total_);
    return;
  }
  draw(total_);
  std::fputc('\n', out_);
  std::fflush(out_);
}

std::string estimateLine(const ResourceEstimate& e, uint64_t limitBytes) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "estimate: about %s (%.2g rays on %d thread%s at %.1f M rays/s each), memory about %s",
                clock(e.seconds()).c_str(), e.rays(), e.threads, e.threads == 1 ? "" : "s",
                e.raysPerSecondPerThread / 1e6, formatBytes(e.bytes()).c_str());
  std::string s = buf;
  if (limitBytes > 0) s += " of " + formatBytes(limitBytes) + " allowed";
  return s;
}

void ProgressObserver::estimated(const ResourceEstimate& e) {
  estimate_ = std::make_unique<ResourceEstimate>(e);
  if (mode_ == ProgressMode::kOff || e.seconds() < kEstimateShownS) return;
  std::fprintf(out_, "%s\n", estimateLine(e, limitBytes_).c_str());
  std::fflush(out_);
}

void ProgressObserver::begin(const std::string& label, std::size_t total) {
  ProgressBar::Options o = options_;
  o.out = out_;
  o.expectedS = estimate_ ? estimate_->seconds(label) : -1.0;
  bar_ = std::make_unique<ProgressBar>(label, total, mode_, std::move(o));
}

}  // namespace candela::cli
