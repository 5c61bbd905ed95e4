// IES LM-83-12 2.2.6's operable blinds with several window groups: in every occupied hour the
// blinds of the groups close "in any combination, until the criterion value for each hour is
// achieved", the criterion being that no more than 2 % of the analysis points receive direct
// sun (>= 1000 lx of direct beam sunlight). docs/annual.md "Window groups" has the reading.
//
// Pure functions over hourly direct sun split by the group whose glass each beam crossed; the
// closed state of a group passes no beam (study/blinds.h), so closing the groups of a set C
// leaves at a sensor the direct sun D − Σ_{g∈C} D_g.
#pragma once

#include <cstdint>
#include <vector>

namespace candela {

// At most this many groups per study: the rule counts every combination (2^groups per hour).
inline constexpr int kMaxWindowGroups = 8;

// For every hour h and every set of closed groups m (a bit mask, bit g: group g closed), adds to
// counts[h * 2^groups + m] the sensors of the block whose remaining direct sun
// directSun − Σ_{g∈m} groupDirect[g] is >= aseLux. All arrays sensor-major [s * nHours + h], lux;
// directSun is all the direct sun (through any glass or none), groupDirect[g] its part through
// group g's glass. counts has nHours × 2^groups entries (zero before the first block).
// Throws std::invalid_argument on null arrays, more than kMaxWindowGroups groups or a wrong size.
void countSunlitByClosure(const float* directSun, const std::vector<const float*>& groupDirect, int nSensors,
                          int nHours, double aseLux, std::vector<int>& counts);

// The closed groups of every hour (a bit mask per hour; 0 when unoccupied or when no more than
// `fraction` of the grid's nSensors are sunlit with every blind open): the combination with the
// fewest closed groups that leaves no more than fraction × nSensors sensors sunlit, the fewest
// sunlit sensors among those, then the lowest mask. When no combination achieves it (sun through
// openings without glass), every group closes. Every group whose own beam alone sunlights more
// than the fraction is closed by any such choice (beams add). Throws std::invalid_argument when
// counts has not occupied.size() × 2^groups entries.
// LM-83's share of a grid's sensors that may be sunlit (direct sun ≥ 1000 lx) in an hour before
// the shading is operated: 2 %.
inline constexpr double kLm83SunlitFraction = 0.02;
std::vector<uint32_t> blindsClosureFromCounts(const std::vector<int>& counts, int groups, int nSensors,
                                              const std::vector<char>& occupied,
                                              double fraction = kLm83SunlitFraction);

// The illuminance with the hour's groups closed, folded in one group at a time: `combined`
// starts as the open year, and group g's closed year (all other glazing open) is folded in as
//   E(h) = E_open(h) + Σ_{g closed at h} (E_g(h) − E_open(h)),
// taking E_g itself in the hours g alone is closed. Exact when no light path crosses two groups'
// glass (light is linear in each window's transmission; docs/annual.md "Window groups").
// Arrays sensor-major [s * closure.size() + h] over `sensors` sensors, lux.
void foldClosedGroup(const float* closed, const float* open, const std::vector<uint32_t>& closure, int group,
                     std::size_t sensors, float* combined);

// Hours in which group g is closed, from blindsClosureFromCounts' masks.
int closedHoursOfGroup(const std::vector<uint32_t>& closure, int group);

}  // namespace candela
