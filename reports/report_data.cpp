#include "reports/report_data.h"

#include <cmath>
#include <cstdio>

namespace candela {

std::string formatNumber(double v, int significant) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string formatFixed(double v, int decimals) {
  if (!std::isfinite(v)) return formatNumber(v);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // "-0.0" → "0.0"
  return s;
}

std::string safeFileName(const std::string& name) {
  std::string s;
  for (char ch : name) {
    const bool ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '-' ||
                    ch == '_';
    s += ok ? ch : '_';
  }
  return s.empty() ? "grid" : s;
}

namespace {

// The kinds of checked line, in the report's order (checkedCategories' words).
enum class LineKind { kGrid, kSurface, kModelling, kColourRendering, kObserverUgr, kCompliance, kStandard, kCount };
constexpr const char* kLineKindWords[] = {"grids",           "walls and ceiling", "modelling",
                                          "colour rendering", "observers' UGR",    "daylight compliance",
                                          "standards"};

// Calls line(verdict, kind) for every line the run's verdict counts, checked or not.
template <class F>
void forEachLine(const ReportData& data, F line) {
  for (const GridReport& g : data.grids) {
    line(g.check.overall, g.surfaceGrid.empty() ? LineKind::kGrid : LineKind::kSurface);
    if (g.modelling) line(g.modelling->verdict, LineKind::kModelling);
  }
  // A task area's and a surface grid's verdicts combine their grids' and observers', counted
  // here each once: a task area's own further line is its Ra.
  for (const TaskAreaReport& a : data.taskAreas) line(a.raVerdict, LineKind::kColourRendering);
  for (const ObserverReport& o : data.observers)
    if (const std::optional<bool> pass = o.pass())
      line(*pass ? Verdict::kPass : Verdict::kFail, LineKind::kObserverUgr);
  // A [[compliance]] entry is one line: its standard's verdict.
  for (const ComplianceReport& r : data.compliance)
    line(r.verdict == "pass" ? Verdict::kPass : Verdict::kFail,
         r.section ? LineKind::kStandard : LineKind::kCompliance);  // a standard of its own unit (EN 1838)
}

}  // namespace

Verdict overallVerdict(const ReportData& data, int* checked, int* failed) {
  int n = 0, bad = 0;
  forEachLine(data, [&](Verdict v, LineKind) {
    if (v == Verdict::kNotChecked) return;
    ++n;
    bad += v == Verdict::kFail;
  });
  if (checked) *checked = n;
  if (failed) *failed = bad;
  return bad > 0 ? Verdict::kFail : n > 0 ? Verdict::kPass : Verdict::kNotChecked;
}

std::vector<std::string> checkedCategories(const ReportData& data) {
  bool seen[static_cast<int>(LineKind::kCount)] = {};
  forEachLine(data, [&](Verdict v, LineKind k) { seen[static_cast<int>(k)] |= v != Verdict::kNotChecked; });
  std::vector<std::string> out;
  for (int k = 0; k < static_cast<int>(LineKind::kCount); ++k)
    if (seen[k]) out.push_back(kLineKindWords[k]);
  return out;
}

std::string dateInWords(const std::string& iso) {
  static constexpr const char* kMonths[12] = {"January", "February", "March",     "April",   "May",      "June",
                                              "July",    "August",   "September", "October", "November", "December"};
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  char sep = 0;
  const int n = std::sscanf(iso.c_str(), "%4d-%2d-%2d%c%2d:%2d", &y, &mo, &d, &sep, &h, &mi);
  if (n < 3 || mo < 1 || mo > 12 || d < 1 || d > 31) return iso;
  std::string out = std::to_string(d) + " " + kMonths[mo - 1] + " " + std::to_string(y);
  if (n == 6 && sep == 'T') {
    char buf[16];
    std::snprintf(buf, sizeof buf, ", %02d:%02d", h, mi);
    out += buf;
  }
  return out;
}

std::string countOf(long long n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace candela
