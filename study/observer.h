// What a study tells its caller while it runs. Libraries never print: the command line turns
// these calls into progress bars, a script into whatever it likes.
#pragma once

#include "study/resource_estimate.h"

#include <cstddef>
#include <string>

namespace candela {

class StudyObserver {
 public:
  virtual ~StudyObserver() = default;
  // What the study will need (memory, rays, seconds), once every input is checked and before
  // any tracing; the memory was checked against the caller's limit already.
  virtual void estimated(const ResourceEstimate& estimate) {}
  // A step of `total` items begins ("tracing", "rendering desk", "sky coefficients", ...).
  virtual void begin(const std::string& label, std::size_t total) {}
  // `done` items of the current step are finished. Called from several threads at once: must be
  // thread-safe and cheap.
  virtual void progress(std::size_t done) {}
  // The current step is finished.
  virtual void end() {}
};

// An observer that ignores everything.
inline StudyObserver& silentObserver() {
  static StudyObserver silent;  // stateless: no result depends on it
  return silent;
}

// begin() on construction, end() on destruction (also when the step throws).
class ObservedStep {
 public:
  ObservedStep(StudyObserver& o, const std::string& label, std::size_t total) : o_(o) { o_.begin(label, total); }
  ~ObservedStep() { o_.end(); }
  ObservedStep(const ObservedStep&) = delete;
  ObservedStep& operator=(const ObservedStep&) = delete;
  void operator()(std::size_t done) const { o_.progress(done); }

 private:
  StudyObserver& o_;
};

}  // namespace candela
