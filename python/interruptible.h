// A study run from Python: the work runs on a thread of its own while the calling thread waits
// without the GIL, waking every 100 ms to hand progress to a Python callback and to notice
// Ctrl-C. On an interruption (or an exception from the callback) the observer makes the study's
// next progress call throw, the work unwinds (its unnamed temporaries vanish, nothing is
// committed: docs/reliability.md) and the Python exception is raised once the thread has ended.
#pragma once

#include "study/observer.h"

#include <pybind11/pybind11.h>

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace candela::python {

// Thrown inside the study when the caller cancels. Not a std::exception, so that no library
// code that turns write failures into InputError takes it for one.
struct Cancelled {};

class CancellableObserver : public StudyObserver {
 public:
  void estimated(const ResourceEstimate&) override { check(); }
  void begin(const std::string& label, std::size_t total) override;
  void progress(std::size_t done) override;
  // end() never throws: ObservedStep calls it from its destructor.
  void end() override {}

  void cancel() { cancelled_.store(true); }

  struct Snapshot {
    std::string label;
    std::size_t done = 0, total = 0;
    int step = 0;  // 0 before the first step; changes when a step begins
  };
  Snapshot snapshot() const;

 private:
  void check() const {
    if (cancelled_.load(std::memory_order_relaxed)) throw Cancelled{};
  }
  std::atomic<bool> cancelled_{false};
  std::atomic<std::size_t> done_{0};
  mutable std::mutex labelMutex_;
  std::string label_;
  std::size_t total_ = 0;
  int step_ = 0;
};

// Calls progress(label, done, total) with the observer's latest state when it changed since
// `last` (None: nothing). Throws what the callback throws.
void reportProgress(const pybind11::object& progress, const CancellableObserver& observer,
                    CancellableObserver::Snapshot& last);

// Runs work(observer) as described above; returns its result or rethrows its exception (a
// KeyboardInterrupt, or the callback's exception, when the caller stopped it). Call with the GIL.
template <class Result>
Result runInterruptible(const std::function<Result(StudyObserver&)>& work, const pybind11::object& progress) {
  CancellableObserver observer;
  std::optional<Result> result;
  std::exception_ptr error;
  std::mutex m;
  std::condition_variable cv;
  bool finished = false;
  std::thread worker([&] {
    try {
      result.emplace(work(observer));
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(m);
    finished = true;
    cv.notify_all();
  });
  const auto stop = [&] {
    observer.cancel();
    pybind11::gil_scoped_release release;
    worker.join();
  };
  CancellableObserver::Snapshot last;
  for (;;) {
    bool done = false;
    {
      pybind11::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(m);
      done = cv.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
    }
    if (done) break;
    if (PyErr_CheckSignals() != 0) {
      pybind11::error_already_set interrupt;  // takes the pending KeyboardInterrupt
      stop();
      throw interrupt;
    }
    try {
      reportProgress(progress, observer, last);
    } catch (...) {
      stop();
      throw;
    }
  }
  worker.join();
  if (error) std::rethrow_exception(error);
  reportProgress(progress, observer, last);
  return std::move(*result);
}

}  // namespace candela::python
