#include "metrics/window_groups.h"

#include <bit>
#include <stdexcept>

namespace candela {

void countSunlitByClosure(const float* directSun, const std::vector<const float*>& groupDirect, int nSensors,
                          int nHours, double aseLux, std::vector<int>& counts) {
  const int groups = static_cast<int>(groupDirect.size());
  if (!directSun || nSensors < 0 || nHours < 0) throw std::invalid_argument("countSunlitByClosure: bad arrays");
  if (groups > kMaxWindowGroups) throw std::invalid_argument("countSunlitByClosure: too many window groups");
  for (const float* g : groupDirect)
    if (!g) throw std::invalid_argument("countSunlitByClosure: null group array");
  const std::size_t masks = std::size_t{1} << groups;
  if (counts.size() != static_cast<std::size_t>(nHours) * masks)
    throw std::invalid_argument("countSunlitByClosure: counts must have nHours × 2^groups entries");
  double remaining[std::size_t{1} << kMaxWindowGroups];
  for (int s = 0; s < nSensors; ++s)
    for (int h = 0; h < nHours; ++h) {
      const std::size_t i = static_cast<std::size_t>(s) * nHours + h;
      remaining[0] = directSun[i];
      // Closing groups only removes light: nothing left to count below the threshold.
      if (remaining[0] < aseLux) continue;
      int* c = counts.data() + static_cast<std::size_t>(h) * masks;
      ++c[0];
      for (std::size_t m = 1; m < masks; ++m) {
        const int low = std::countr_zero(m);
        remaining[m] = remaining[m & (m - 1)] - groupDirect[low][i];
        c[m] += remaining[m] >= aseLux;
      }
    }
}

std::vector<uint32_t> blindsClosureFromCounts(const std::vector<int>& counts, int groups, int nSensors,
                                              const std::vector<char>& occupied, double fraction) {
  if (groups < 0 || groups > kMaxWindowGroups) throw std::invalid_argument("blindsClosureFromCounts: bad group count");
  const std::size_t masks = std::size_t{1} << groups, nh = occupied.size();
  if (counts.size() != nh * masks) throw std::invalid_argument("blindsClosureFromCounts: counts of the wrong size");
  const double allowed = fraction * nSensors;  // "more than 2 %" closes: a count equal to it stays
  std::vector<uint32_t> closure(nh, 0);
  for (std::size_t h = 0; h < nh; ++h) {
    const int* c = counts.data() + h * masks;
    if (!occupied[h] || c[0] <= allowed) continue;
    uint32_t best = static_cast<uint32_t>(masks - 1);  // none achieves it: all close
    bool found = false;
    for (uint32_t m = 1; m < masks; ++m) {
      if (c[m] > allowed) continue;
      const int closed = std::popcount(m), bestClosed = std::popcount(best);
      if (!found || closed < bestClosed || (closed == bestClosed && c[m] < c[best])) best = m;
      found = true;
    }
    closure[h] = best;
  }
  return closure;
}

void foldClosedGroup(const float* closed, const float* open, const std::vector<uint32_t>& closure, int group,
                     std::size_t sensors, float* combined) {
  const std::size_t nh = closure.size();
  const uint32_t bit = 1u << group;
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t h = 0; h < nh; ++h) {
      const uint32_t m = closure[h];
      if (!(m & bit)) continue;
      const std::size_t i = s * nh + h;
      combined[i] = m == bit ? closed[i] : combined[i] + (closed[i] - open[i]);
    }
}

int closedHoursOfGroup(const std::vector<uint32_t>& closure, int group) {
  int n = 0;
  for (uint32_t m : closure) n += (m >> group) & 1u;
  return n;
}

}  // namespace candela
