// Window states in the annual study (docs/bsdf.md, "Window states"): the states chosen per hour
// (a schedule or LM-83's direct-sun rule), one coefficient pass per group and state beyond its
// first, the switched year folded from them, and each state's results and hourly files.
#include "study/annual_year.h"

#include "metrics/window_groups.h"
#include "study/finite_results.h"

#include <cstdint>

namespace candela::annual_detail {

namespace {

// A traced window state: group `group` in state `state` (≥ 1), the other groups in their first.
// For a direct-sun-rule group of more than two states, each state but the last also has, per
// grid and hour, the grid's sensors it leaves sunlit (direct sun ≥ the ASE threshold): the rule
// escalates to the first state that leaves no more than LM-83's 2 % (chooseWindowStates).
struct StateTrace {
  int group = 0, state = 0;
  std::unique_ptr<Scene> scene;
  std::unique_ptr<YearTracer> tracer;
  std::vector<std::vector<int>> sunlit;  // [grid][hour]; empty when the rule does not ask
};

// Whether the direct-sun rule needs state k of group g's sunlit counts: g has more than two
// states, k is neither its first nor its last (the last is where the rule ends).
bool escalationState(const WindowStateGroup& g, int k) {
  return g.scheduled.empty() && g.states.size() > 2 && k >= 1 && k + 1 < static_cast<int>(g.states.size());
}

// Each traced state's sunlit counts that the rule asks (escalationState), block by block from
// the state's direct sun alone (the other groups in their first states).
void countStatesSunlit(const AnnualPass& p, std::vector<StateTrace>& traced, StudyObserver& observer) {
  const WindowStates& ws = p.in.states;
  const std::size_t sensors = p.in.positions.size(), nh = p.y.stamps.size();
  std::size_t asked = 0;
  for (const StateTrace& st : traced) asked += escalationState(ws.groups[static_cast<std::size_t>(st.group)], st.state);
  if (asked == 0) return;
  const ObservedStep step(observer, "window states: direct sun", sensors * asked);
  std::size_t done = 0;
  for (StateTrace& st : traced) {
    if (!escalationState(ws.groups[static_cast<std::size_t>(st.group)], st.state)) continue;
    st.sunlit.assign(p.grids.size(), std::vector<int>(nh, 0));
    for (std::size_t b0 = 0; b0 < sensors; b0 += p.block) {
      const std::size_t n = std::min(p.block, sensors - b0);
      const std::vector<float> direct = st.tracer->directSun(b0, n);
      for (std::size_t gi = 0; gi < p.grids.size(); ++gi) {
        const GridYear& g = p.grids[gi];
        const std::size_t lo = std::max(g.first, b0), hi = std::min(g.first + g.count, b0 + n);
        for (std::size_t s = lo; s < hi; ++s)
          for (std::size_t h = 0; h < nh; ++h) st.sunlit[gi][h] += direct[(s - b0) * nh + h] >= p.th.aseLux;
      }
      done += n;
      step(done);
    }
  }
}

// The hourly stream of grid g's year in one window state, opened beside the run's folder.
std::unique_ptr<AnnualResultsStream> stateStream(const AnnualPass& p, const GridYear& g) {
  std::unique_ptr<AnnualResultsStream> out;
  p.folder.guard([&] {
    static int serial = 0;  // unique temporary names; the files are renamed at the end
    out = std::make_unique<AnnualResultsStream>(p.folder.beside() / ("window_state_" + std::to_string(serial++)),
                                                static_cast<int>(g.count), p.y.stamps);
  });
  return out;
}

// Pass 2 with window states: each block's reference year (every group in its first state) read
// back, each traced state's year beside it (its own stream and metrics), folded into the switched
// year by the hours' states (foldWindowState), which goes to the grid's switched streams.
void statesPass(const AnnualPass& p, std::vector<StateTrace>& traced, StudyObserver& observer) {
  const std::size_t sensors = p.in.positions.size(), nh = p.y.stamps.size(), nq = traced.size();
  const ObservedStep step(observer, "window states: coefficients", 2 * sensors * nq);
  struct Slice {
    BlockPart ref;                     // the reference year (every group in its first state)
    std::vector<float> total, direct;  // the switched year, folded state by state
  };
  auto metrics = [&](const float* e, const float* d, std::size_t k) {
    return sensorAnnualMetrics(e, d, static_cast<int>(k), static_cast<int>(nh), p.y.occupied, p.th);
  };
  auto addTo = [](std::vector<SensorAnnualMetrics>& to, const std::vector<SensorAnnualMetrics>& m) {
    to.insert(to.end(), m.begin(), m.end());
  };
  for (std::size_t b0 = 0; b0 < sensors; b0 += p.block) {
    const std::size_t n = std::min(p.block, sensors - b0);
    std::vector<Slice> slices;
    for (BlockPart& part : readBlockParts(p, b0, n)) {
      addTo(part.g->stateSensors[0], metrics(part.total.data(), part.direct.data(), part.k));
      Slice sl{std::move(part), {}, {}};
      sl.total = sl.ref.total;
      sl.direct = sl.ref.direct;
      slices.push_back(std::move(sl));
    }
    for (std::size_t q = 0; q < nq; ++q) {
      const StateTrace& st = traced[q];
      const AnnualIlluminance year = st.tracer->block(b0, n, 2 * (b0 * nq + q * n), step);
      checkFinite(year.total, "the hourly illuminance of a window state", b0 * nh);
      for (Slice& sl : slices) {
        GridYear& g = *sl.ref.g;
        const float* e = year.total.data() + (sl.ref.lo - b0) * nh;
        const float* d = year.directSun.data() + (sl.ref.lo - b0) * nh;
        const std::vector<uint8_t>& state = g.stateOf[static_cast<std::size_t>(st.group)];
        foldWindowState(e, sl.ref.total.data(), state, st.state, g.switched, sl.ref.k, sl.total.data());
        foldWindowState(d, sl.ref.direct.data(), state, st.state, g.switched, sl.ref.k, sl.direct.data());
        p.folder.guard([&] {
          g.stateTotal[q]->append(e, static_cast<int>(sl.ref.k));
          g.stateDirect[q]->append(d, static_cast<int>(sl.ref.k));
        });
        addTo(g.stateSensors[q + 1], metrics(e, d, sl.ref.k));
      }
    }
    for (Slice& sl : slices) {
      GridYear& g = *sl.ref.g;
      p.folder.guard([&] {
        g.switchedTotal->append(sl.total.data(), static_cast<int>(sl.ref.k));
        g.switchedDirect->append(sl.direct.data(), static_cast<int>(sl.ref.k));
      });
      const std::size_t chosen = g.first + static_cast<std::size_t>(g.chosenSensor);
      if (chosen >= sl.ref.lo && chosen < sl.ref.lo + sl.ref.k)
        g.chosenSensorLux.assign(sl.total.begin() + (chosen - sl.ref.lo) * nh, sl.total.begin() + (chosen - sl.ref.lo + 1) * nh);
      addTo(g.sensors, metrics(sl.total.data(), sl.direct.data(), sl.ref.k));
    }
  }
}

// Each grid's state per group and hour: the schedule's, or LM-83's direct-sun rule over the
// sun-rule groups (blindsClosureFromCounts) on the group's sun_grid or on the grid itself: a
// group the rule closes goes to its second state, or with more than two states to the first
// state after its first that leaves no more than 2 % of that grid's sensors sunlit (its own
// direct sun, the other groups in their first states: countStatesSunlit), else to its last.
void chooseWindowStates(const AnnualInputs& in, const AnnualPass& p, const std::vector<StateTrace>& traced) {
  const WindowStates& ws = in.states;
  const std::size_t nh = p.y.stamps.size();
  std::vector<std::vector<uint32_t>> closure(p.grids.size());
  for (std::size_t gi = 0; gi < p.grids.size() && ws.sunGroups > 0; ++gi)
    closure[gi] = blindsClosureFromCounts(p.grids[gi].closureCounts, ws.sunGroups,
                                          static_cast<int>(p.grids[gi].count), p.y.occupied);
  for (std::size_t gi = 0; gi < p.grids.size(); ++gi) {
    GridYear& g = p.grids[gi];
    std::vector<int>().swap(g.closureCounts);
    g.stateOf.clear();
    g.switched.assign(nh, 0);
    for (std::size_t q = 0; q < ws.groups.size(); ++q) {
      const WindowStateGroup& wg = ws.groups[q];
      std::vector<uint8_t> state = wg.scheduled;
      if (state.empty()) {
        const std::size_t decides = wg.sunGrid >= 0 ? static_cast<std::size_t>(wg.sunGrid) : gi;
        const std::vector<uint32_t>& mask = closure[decides];
        const double allowed = kLm83SunlitFraction * static_cast<double>(p.grids[decides].count);
        const uint8_t last = static_cast<uint8_t>(wg.states.size() - 1);
        state.resize(nh);
        for (std::size_t h = 0; h < nh; ++h) {
          if (!((mask[h] >> wg.sunIndex) & 1u)) continue;  // the first state leaves the grid shaded enough
          state[h] = last;
          for (const StateTrace& st : traced)
            if (st.group == static_cast<int>(q) && !st.sunlit.empty() && st.sunlit[decides][h] <= allowed) {
              state[h] = static_cast<uint8_t>(st.state);
              break;
            }
        }
      }
      for (std::size_t h = 0; h < nh; ++h) g.switched[h] += state[h] != 0;
      g.stateOf.push_back(std::move(state));
    }
  }
}

}  // namespace

// With window states: the reference year (every group in its first state; the direct sun split
// by the sun-rule groups), each grid's states per hour, then one coefficient pass per group and
// state other than its first (every state is traced, used or not: its results are reported).
void traceWindowStates(const CaseFile& c, const AnnualInputs& in, const YearJob& job, const AnnualPass& p,
                       AnnualTraces& t, StudyObserver& observer) {
  tracedOpenPass(in, job, p, false, t, observer);  // the reference: every group in its first state
  YearJob stateJob = job;
  stateJob.windows = nullptr;
  const WindowStates& ws = in.states;
  std::vector<StateTrace> traced;
  for (std::size_t q = 0; q < ws.groups.size(); ++q)
    for (std::size_t k = 1; k < ws.groups[q].states.size(); ++k) {
      StateTrace st{static_cast<int>(q), static_cast<int>(k), nullptr, nullptr, {}};
      std::vector<int> choice(ws.groups.size(), 0);
      choice[q] = static_cast<int>(k);
      st.scene = loadStateScene(c, in.north, ws, choice);
      st.scene->sky->model = in.scene->sky->model;
      st.tracer = std::make_unique<YearTracer>(*st.scene, stateJob, true);
      traced.push_back(std::move(st));
    }
  countStatesSunlit(p, traced, observer);
  chooseWindowStates(in, p, traced);
  for (GridYear& g : p.grids) {
    g.stateSensors.assign(traced.size() + 1, {});
    for (std::size_t q = 0; q < traced.size(); ++q) {
      g.stateTotal.push_back(stateStream(p, g));
      g.stateDirect.push_back(stateStream(p, g));
    }
    g.switchedTotal = stateStream(p, g);
    g.switchedDirect = stateStream(p, g);
  }
  statesPass(p, traced, observer);
  for (const StateTrace& st : traced) {
    t.coefficientsClosedS += st.tracer->coefficientsS();
    t.productClosedS += st.tracer->productS();
    t.raysClosed += st.tracer->rays();
  }
  // The [[compliance]] glare views follow the states (every combination the hours use is traced
  // for them: study/compliance/compliance_study.cpp), each grid's states kept for them.
  for (GridYear& g : p.grids) t.stateOf.push_back(g.stateOf);
}

// Per group and state: the occupied hours in it and the metrics of its year (statesPass's order:
// the reference year, then each group's states after its first).
void windowStateResults(const WindowStates& ws, const YearHours& y, GridYear& gy, AnnualGridReport& ar) {
  std::size_t traced = 0;
  for (std::size_t q = 0; q < ws.groups.size() && !gy.stateSensors.empty(); ++q)
    for (std::size_t k = 0; k < ws.groups[q].states.size(); ++k) {
      int hours = 0;
      for (std::size_t h = 0; h < y.occupied.size(); ++h) hours += y.occupied[h] && gy.stateOf[q][h] == static_cast<uint8_t>(k);
      const std::vector<SensorAnnualMetrics>& m = gy.stateSensors[k == 0 ? 0 : ++traced];
      ar.windowStates.push_back({ws.groups[q].name, ws.groups[q].states[k], hours, summarizeAnnual(m, y.occupiedCount)});
    }
}

// With window states: the switched year as the grid's hourly files, and each state's year (all
// light and direct sun) as <grid>_<group>_<state> and <grid>_<group>_<state>_direct_sun (the
// reference year for every group's first state).
void writeWindowStateFiles(const std::filesystem::path& outDir, const WindowStates& ws, const std::string& grid,
                           GridYear& gy) {
  gy.switchedTotal->commitAs(outDir / annualResultsFileName(grid));
  gy.switchedDirect->commitAs(outDir / annualResultsFileName(grid + "_direct_sun"));
  std::size_t traced = 0;
  std::filesystem::path reference, referenceDirect;
  for (const WindowStateGroup& g : ws.groups)
    for (std::size_t k = 0; k < g.states.size(); ++k) {
      const std::string name = grid + "_" + g.name + "_" + g.states[k];
      const std::filesystem::path total = outDir / annualResultsFileName(name),
                                  direct = outDir / annualResultsFileName(name + "_direct_sun");
      if (k > 0) {
        gy.stateTotal[traced]->commitAs(total);
        gy.stateDirect[traced++]->commitAs(direct);
      } else if (reference.empty()) {
        gy.total->commitAs(total);
        gy.directSun->commitAs(direct);
        reference = total;
        referenceDirect = direct;
      } else {
        std::filesystem::copy_file(reference, total, std::filesystem::copy_options::overwrite_existing);
        std::filesystem::copy_file(referenceDirect, direct, std::filesystem::copy_options::overwrite_existing);
      }
    }
}

}  // namespace candela::annual_detail
