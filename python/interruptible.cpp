#include "python/interruptible.h"

namespace candela::python {

void CancellableObserver::begin(const std::string& label, std::size_t total) {
  check();
  std::lock_guard<std::mutex> lock(labelMutex_);
  label_ = label;
  total_ = total;
  done_.store(0);
  ++step_;
}

void CancellableObserver::progress(std::size_t done) {
  check();
  // Several threads report at once, not necessarily in order: keep the largest count.
  std::size_t seen = done_.load(std::memory_order_relaxed);
  while (done > seen && !done_.compare_exchange_weak(seen, done, std::memory_order_relaxed)) {
  }
}

CancellableObserver::Snapshot CancellableObserver::snapshot() const {
  std::lock_guard<std::mutex> lock(labelMutex_);
  return {label_, done_.load(std::memory_order_relaxed), total_, step_};
}

void reportProgress(const pybind11::object& progress, const CancellableObserver& observer,
                    CancellableObserver::Snapshot& last) {
  if (progress.is_none()) return;
  const CancellableObserver::Snapshot now = observer.snapshot();
  if (now.step == 0 || (now.step == last.step && now.done == last.done)) return;
  last = now;
  progress(now.label, now.done, now.total);
}

}  // namespace candela::python
