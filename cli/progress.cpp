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

}  // namespace

ProgressBar::ProgressBar(std::string label, std::size_t total, bool enabled, std::FILE* out)
    : label_(std::move(label)), total_(total), enabled_(enabled), out_(out), start_(std::chrono::steady_clock::now()) {
  if (enabled_) draw(0);
}

ProgressBar::~ProgressBar() {
  // Left without finish() (an exception): end the line without claiming completion.
  if (enabled_ && !finished_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

bool ProgressBar::wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO) == 1; }

std::string ProgressBar::format(const std::string& label, std::size_t done, std::size_t total, double elapsedS,
                                int width) {
  const double fraction = total > 0 ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total)) : 1.0;
  const int filled = static_cast<int>(fraction * width);
  std::string bar = label + " [" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
  char buf[160];
  std::snprintf(buf, sizeof buf, " %zu/%zu %3d%%  %s elapsed", done, total, static_cast<int>(fraction * 100.0),
                clock(elapsedS).c_str());
  bar += buf;
  // The rate so far predicts the rest; with nothing done yet there is no estimate.
  if (done > 0 && done < total) bar += ", ETA " + clock(elapsedS * static_cast<double>(total - done) / done);
  return bar;
}

void ProgressBar::update(std::size_t done) {
  if (!enabled_) return;
  const int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_)
                          .count();
  int64_t next = nextDrawNs_.load(std::memory_order_relaxed);
  if (now < next) return;
  // One thread wins the right to draw this interval; the others return at once.
  const int64_t interval = std::chrono::duration_cast<std::chrono::nanoseconds>(kRedrawInterval).count();
  if (!nextDrawNs_.compare_exchange_strong(next, now + interval, std::memory_order_relaxed)) return;
  std::unique_lock lock(drawMutex_, std::try_to_lock);
  if (lock && !finished_) draw(done);
}

void ProgressBar::draw(std::size_t done) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // "\r" returns to the line start; "\033[K" clears what a longer previous line left behind.
  std::fprintf(out_, "\r%s\033[K", format(label_, done, total_, elapsed).c_str());
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  std::lock_guard lock(drawMutex_);
  if (finished_) return;
  finished_ = true;
  draw(total_);
  std::fputc('\n', out_);
  std::fflush(out_);
}

}  // namespace candela::cli
