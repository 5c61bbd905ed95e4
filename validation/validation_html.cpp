#include "validation/validation_html.h"

#include "reports/plan_svg.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela::validation {

namespace {

std::string num(const char* fmt, double v) {
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

std::string badge(bool pass) {
  return pass ? "<span class=\"b pass\">PASS</span>" : "<span class=\"b fail\">FAIL</span>";
}

}  // namespace

std::string validationHtml(const std::vector<CaseResult>& results, const ValidationPage& page) {
  std::ostringstream h;
  size_t failed = 0;
  for (const CaseResult& r : results) failed += !r.pass();
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>candela validation</title>\n<style>\n"
       "body{font-family:system-ui,-apple-system,'Segoe UI',sans-serif;margin:0;background:#eef1f4;color:#1d2733}\n"
       "main{max-width:1100px;margin:0 auto;background:#fff;padding:28px 36px}\n"
       "h1{margin:0 0 4px;font-size:26px} h2{font-size:18px;margin:28px 0 8px} .sub{color:#5a6572;font-size:13px}\n"
       "table{border-collapse:collapse;width:100%;font-size:13px;margin:8px 0}\n"
       "th,td{border-bottom:1px solid #dde3ea;padding:5px 8px;text-align:left} th{background:#f4f6f8}\n"
       "td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\n"
       ".b{border-radius:9px;padding:1px 8px;font-size:11px;font-weight:600}\n"
       ".pass{background:#e3f4e6;color:#1e6b2e} .fail{background:#fbe3e3;color:#9b1c1c}\n"
       "details{margin:4px 0} summary{cursor:pointer;font-size:13px}\n"
       "</style></head><body><main>\n";
  h << "<h1>candela validation</h1>\n<p class=\"sub\">candela " << xmlEscape(page.version) << " · quality "
    << xmlEscape(page.quality) << " · seed " << page.seed << " · " << results.size() << " cases: "
    << results.size() - failed << " passed, " << failed << " failed. Errors are relative to the reference; the "
    << "time is candela's computation only.</p>\n";
  h << "<h2>Cases</h2>\n<table><thead><tr><th>Group</th><th>Case</th><th>Reference</th><th class=\"num\">Max error"
       "</th><th class=\"num\">RMS error</th><th class=\"num\">Tolerance</th><th>Verdict</th><th class=\"num\">Time"
       "</th></tr></thead><tbody>\n";
  for (const CaseResult& r : results)
    h << "<tr><td>" << xmlEscape(r.group) << "</td><td><a href=\"#" << xmlEscape(r.name) << "\">" << xmlEscape(r.name)
      << "</a></td><td>" << xmlEscape(r.reference) << "</td><td class=\"num\">" << num("%.3f %%", 100 * r.maxRelativeError())
      << "</td><td class=\"num\">" << num("%.3f %%", 100 * r.rmsRelativeError()) << "</td><td class=\"num\">"
      << num("%.1f %%", 100 * r.tolerance) << "</td><td>" << badge(r.pass()) << "</td><td class=\"num\">"
      << num("%.3f s", r.seconds) << "</td></tr>\n";
  h << "</tbody></table>\n";
  if (!page.chartSvg.empty()) h << "<h2>Speed and accuracy</h2>\n" << page.chartSvg << "\n";
  h << "<h2>Points</h2>\n";
  for (const CaseResult& r : results) {
    h << "<details id=\"" << xmlEscape(r.name) << "\"" << (r.pass() ? "" : " open") << "><summary>" << badge(r.pass())
      << " " << xmlEscape(r.name) << " — " << r.points.size() << " points</summary>\n<table><thead><tr><th>Point</th>"
      << "<th class=\"num\">Reference (" << xmlEscape(r.unit) << ")</th><th class=\"num\">Result (" << xmlEscape(r.unit)
      << ")</th><th class=\"num\">Std. error (" << xmlEscape(r.unit) << ")"
      << "</th><th class=\"num\">Error</th></tr></thead><tbody>\n";
    for (const PointResult& p : r.points)
      h << "<tr><td>" << xmlEscape(p.label) << "</td><td class=\"num\">" << num("%.5g", p.referenceLux)
        << "</td><td class=\"num\">" << num("%.5g", p.resultLux) << "</td><td class=\"num\">"
        << num("%.3g", p.standardErrorLux) << "</td><td class=\"num\">" << num("%+.3f %%", 100 * p.relativeError())
        << "</td></tr>\n";
    h << "</tbody></table></details>\n";
  }
  h << "</main></body></html>\n";
  return h.str();
}

}  // namespace candela::validation
