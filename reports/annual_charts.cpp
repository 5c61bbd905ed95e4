#include "reports/annual_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace candela {

namespace {

std::string px(double v) { return svgNumber(v); }

constexpr int kDaysInMonth[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};

int daysIn(int month, bool leap) { return month == 2 && leap ? 29 : kDaysInMonth[month - 1]; }

// 0-based day of the year.
int dayOfYear(const HourStamp& s, bool leap) {
  int d = s.day - 1;
  for (int m = 1; m < s.month; ++m) d += daysIn(m, leap);
  return d;
}

}  // namespace

std::vector<bool> sdaPassPerSensor(const AnnualGridReport& a) {
  std::vector<bool> out;
  for (const SensorAnnualMetrics& s : a.sensors) out.push_back(s.sdaPass);
  return out;
}

std::vector<bool> aseExceededPerSensor(const AnnualGridReport& a) {
  std::vector<bool> out;
  for (const SensorAnnualMetrics& s : a.sensors) out.push_back(s.aseExceeded);
  return out;
}

TemporalMap temporalMap(const std::vector<double>& lux, const std::vector<HourStamp>& hours,
                        const TemporalMapOptions& opt) {
  if (lux.size() != hours.size())
    throw std::invalid_argument("temporalMap: " + std::to_string(lux.size()) + " values for " +
                                std::to_string(hours.size()) + " hour stamps");
  bool leap = false;
  for (const HourStamp& s : hours) leap = leap || (s.month == 2 && s.day == 29);
  for (const HourStamp& s : hours)
    if (s.month < 1 || s.month > 12 || s.day < 1 || s.day > daysIn(s.month, leap) || s.hourEnding < 1 ||
        s.hourEnding > 24)
      throw std::invalid_argument("temporalMap: invalid hour stamp " + std::to_string(s.month) + "/" +
                                  std::to_string(s.day) + " hour " + std::to_string(s.hourEnding));

  TemporalMap m;
  m.days = leap ? 366 : 365;
  m.dayPx = std::max(1, opt.dayPx);
  m.hourPx = std::max(1, opt.hourPx);
  const int fs = 2;  // font scale of the labels: 10 × 14 px digits
  const Rgb8 ink{40, 40, 40}, missing{225, 225, 225};
  const int mapW = m.days * m.dayPx, mapH = 24 * m.hourPx;
  m.mapLeft = textWidth("24", fs) + 6 * fs;
  m.mapTop = 4 * fs + 7 * fs / 2;  // room for the top label's upper half
  const int bottom = 4 * fs + 7 * fs + 4 * fs;
  const std::vector<double> ticks = scaleTicks(opt.scale, 6);
  int labelW = textWidth("lx", fs);
  for (double t : ticks) labelW = std::max(labelW, textWidth(formatNumber(t, 6), fs));
  const int barGap = 8 * fs, barW = 10 * fs;
  const int width = m.mapLeft + mapW + barGap + barW + 3 * fs + labelW + 4 * fs;
  const int height = m.mapTop + mapH + bottom;
  m.image = Image8(width, height, Rgb8{255, 255, 255});
  Image8& img = m.image;

  img.fillRect(m.mapLeft, m.mapTop, mapW, mapH, missing);
  for (std::size_t i = 0; i < hours.size(); ++i) {
    const int d = dayOfYear(hours[i], leap), h = hours[i].hourEnding - 1;
    img.fillRect(m.mapLeft + d * m.dayPx, m.mapTop + h * m.hourPx, m.dayPx, m.hourPx, falseColor(lux[i], opt.scale));
  }

  // Hours of the day at the left (0 at the top: the map reads like a calendar page).
  for (int h = 0; h <= 24; h += 6) {
    const int y = m.mapTop + h * m.hourPx;
    img.fillRect(m.mapLeft - 3 * fs, y, 2 * fs, 1, ink);
    const std::string t = std::to_string(h);
    drawText(img, m.mapLeft - 4 * fs - textWidth(t, fs), y - 7 * fs / 2, t, ink, fs);
  }
  // Month boundaries as ticks, month numbers centred under each month.
  int first = 0;
  for (int month = 1; month <= 12; ++month) {
    const int x0 = m.mapLeft + first * m.dayPx, w = daysIn(month, leap) * m.dayPx;
    img.fillRect(x0, m.mapTop + mapH, 1, 3 * fs, ink);
    const std::string t = std::to_string(month);
    drawText(img, x0 + (w - textWidth(t, fs)) / 2, m.mapTop + mapH + 4 * fs, t, ink, fs);
    first += daysIn(month, leap);
  }
  img.fillRect(m.mapLeft + mapW - 1, m.mapTop + mapH, 1, 3 * fs, ink);

  // Colour bar: the scale's minimum at the bottom of the map, its maximum at the top.
  const int barX = m.mapLeft + mapW + barGap, barTop = m.mapTop, barBottom = m.mapTop + mapH - 1;
  for (int y = barTop; y <= barBottom; ++y)
    img.fillRect(barX, y, barW, 1, viridis(static_cast<double>(barBottom - y) / (barBottom - barTop)));
  for (double v : ticks) {
    const int y = barBottom - static_cast<int>(std::lround(scalePosition(v, opt.scale) * (barBottom - barTop)));
    img.fillRect(barX + barW, y, 2 * fs, fs, ink);
    drawText(img, barX + barW + 3 * fs, y - 7 * fs / 2, formatNumber(v, 6), ink, fs);
  }
  drawText(img, barX, m.mapTop + mapH + 4 * fs, "lx", ink, fs);
  return m;
}

std::string sdaAsePlanSvg(const PlanLayout& L, const std::vector<bool>& sdaPass, const std::vector<bool>& aseExceeded,
                          const PlanOptions& opt) {
  // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
  const PlanExtent extent = planExtent(L);
  const Vec2 lo = extent.lo, hi = extent.hi;
  const Vec2 ext = hi - lo;
  const double k = std::min(opt.maxPlanWidthPx / ext.x, opt.maxPlanHeightPx / ext.y);  // px per m
  const double planW = ext.x * k, planH = ext.y * k, left = 10, top = 10;
  const double width = std::max(left + planW + 10, 300.0), height = top + planH + 70;
  auto X = [&](double u) { return left + (u - lo.x) * k; };
  auto Y = [&](double v) { return top + (hi.y - v) * k; };

  const std::size_t n = std::max(sdaPass.size(), aseExceeded.size());
  std::size_t passCount = 0, aseCount = 0;
  for (bool b : sdaPass) passCount += b;
  for (bool b : aseExceeded) aseCount += b;

  std::ostringstream s;
  s << "<svg " << (opt.standalone ? "xmlns=\"http://www.w3.org/2000/svg\" " : "") << "class=\"plan sda-ase\" width=\""
    << px(width) << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(width) << " " << px(height)
    << "\" role=\"img\" aria-label=\"sDA and ASE plan\" font-family=\"Helvetica Neue,Helvetica,Arial,sans-serif\">\n";
  s << "<rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(planW) << "\" height=\"" << px(planH)
    << "\" fill=\"#f4f4f2\"/>\n<g shape-rendering=\"crispEdges\">\n";
  // Cell (regular grid) or dot (points file) centre and half size of sensor i, in px.
  auto place = [&](std::size_t i, double& cx, double& cy, double& hx, double& hy) {
    if (L.regular && i < L.cells.size()) {
      const Vec2 c = L.originM + (Vec2(L.cells[i]) + 0.5) * L.spacingM;
      cx = X(c.x), cy = Y(c.y), hx = 0.5 * L.spacingM.x * k, hy = 0.5 * L.spacingM.y * k;
      return true;
    }
    if (i < L.planPositions.size()) {
      cx = X(L.planPositions[i].x), cy = Y(L.planPositions[i].y), hx = hy = 6.0;
      return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < sdaPass.size(); ++i) {
    double cx, cy, hx, hy;
    if (!place(i, cx, cy, hx, hy)) continue;
    const char* fill = sdaPass[i] ? kSdaPassColor : kSdaFailColor;
    if (L.regular)
      s << "<rect x=\"" << px(cx - hx) << "\" y=\"" << px(cy - hy) << "\" width=\"" << px(2 * hx + 0.5)
        << "\" height=\"" << px(2 * hy + 0.5) << "\" fill=\"" << fill << "\"/>\n";
    else
      s << "<circle cx=\"" << px(cx) << "\" cy=\"" << px(cy) << "\" r=\"6\" fill=\"" << fill
        << "\" stroke=\"#333\" stroke-width=\"0.8\"/>\n";
  }
  s << "</g>\n";
  // ASE crosses, drawn inset so neighbouring crosses stay apart.
  for (std::size_t i = 0; i < aseExceeded.size(); ++i) {
    double cx, cy, hx, hy;
    if (!aseExceeded[i] || !place(i, cx, cy, hx, hy)) continue;
    const double a = 0.6 * std::min(hx, hy);
    s << "<path class=\"ase\" d=\"M" << px(cx - a) << "," << px(cy - a) << " L" << px(cx + a) << "," << px(cy + a)
      << " M" << px(cx - a) << "," << px(cy + a) << " L" << px(cx + a) << "," << px(cy - a) << "\" stroke=\""
      << kAseColor << "\" stroke-width=\"" << px(std::clamp(0.25 * a, 1.0, 2.5)) << "\" stroke-linecap=\"round\"/>\n";
  }
  if (L.outline.size() >= 3) {
    s << "<polygon points=\"";
    for (const Vec2& p : L.outline) s << px(X(p.x)) << "," << px(Y(p.y)) << " ";
    s << "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\"/>\n";
  }
  s << "<rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(planW) << "\" height=\"" << px(planH)
    << "\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.8\"/>\n";

  // Legend with counts.
  const double ly = top + planH + 14;
  s << "<g font-size=\"11\" fill=\"#333\">\n";
  s << "<rect x=\"" << px(left) << "\" y=\"" << px(ly) << "\" width=\"12\" height=\"12\" fill=\"" << kSdaPassColor
    << "\"/><text x=\"" << px(left + 18) << "\" y=\"" << px(ly + 10) << "\">DA300 ≥ 50 %: " << passCount << " of "
    << n << " sensors</text>\n";
  s << "<rect x=\"" << px(left) << "\" y=\"" << px(ly + 18) << "\" width=\"12\" height=\"12\" fill=\""
    << kSdaFailColor << "\"/><text x=\"" << px(left + 18) << "\" y=\"" << px(ly + 28) << "\">DA300 &lt; 50 %: "
    << sdaPass.size() - passCount << "</text>\n";
  s << "<path d=\"M" << px(left + 1) << "," << px(ly + 37) << " L" << px(left + 11) << "," << px(ly + 47) << " M"
    << px(left + 1) << "," << px(ly + 47) << " L" << px(left + 11) << "," << px(ly + 37) << "\" stroke=\"" << kAseColor
    << "\" stroke-width=\"2\"/><text x=\"" << px(left + 18) << "\" y=\"" << px(ly + 46)
    << "\">more than 250 h of direct sun ≥ 1000 lx (ASE): " << aseCount << "</text>\n";
  s << "</g>\n</svg>\n";
  return s.str();
}

}  // namespace candela
