#include "reports/ugr_table_report.h"

#include "reports/plan_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace candela {

namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// "2H", "12H", "0.5H".
std::string roomSize(double multipleOfH) { return fmt("%gH", multipleOfH); }

int percent(double reflectance) { return int(std::lround(100.0 * reflectance)); }

const std::vector<double>& rowOf(const UgrTable& t, size_t room, bool endwise) {
  return endwise ? t.endwise[room] : t.crosswise[room];
}

// The conditions of the table in two lines.
std::vector<std::string> conditions(const UgrTable& t, const UgrTableLabels& labels) {
  return {"Uncorrected: luminaires whose lamps give " + fmt("%.0f", labels.referenceLumens) +
              " lm, in an array at spacing S = " + fmt("%g", t.settings.spacingToHeight) + " H,",
          "H the height of the luminaire plane above the eye; reflectances ceiling / walls / floor in %."};
}

std::string correction(const UgrTableLabels& labels) {
  std::string s = "For lamps of F lm add 8 log10(F / " + fmt("%.0f", labels.referenceLumens) + " lm)";
  if (labels.lampLumens > 0.0)
    s += std::string(": this file's ") + fmt("%.0f", labels.lampLumens) + " lm" +
         (labels.absolutePhotometry ? " (luminaire flux, absolute photometry)" : "") + " add " +
         fmt("%+.1f", 8.0 * std::log10(labels.lampLumens / labels.referenceLumens));
  return s + ".";
}

const char* kViewing[2] = {"Crosswise: the line of sight crosses the luminaires (their C0 plane faces the observer);",
                           "endwise: it runs along them (C90 faces the observer)."};

}  // namespace

std::string ugrCell(double ugr) { return std::isfinite(ugr) ? fmt("%.1f", ugr) : "-"; }

std::string ugrTableText(const UgrTable& t, const UgrTableLabels& labels) {
  const size_t nr = t.settings.reflectances.size();
  const auto pad = [](const std::string& s, size_t w) { return std::string(w > s.size() ? w - s.size() : 0, ' ') + s; };
  const size_t cell = 6, block = cell * nr;
  std::string out = "UGR table (CIE 117 tabular method, CIE 190 presentation)";
  if (!labels.title.empty()) out += ": " + labels.title;
  out += "\n";
  for (const std::string& line : conditions(t, labels)) out += line + "\n";
  out += "\n";
  const std::string cross = "Viewed crosswise", end = "Viewed endwise";
  out += std::string("Room size ") + " " + cross + std::string(block - cross.size(), ' ') + "  " + end + "\n";
  const auto header = [&](const std::string& lead, auto part) {
    std::string line = lead;
    for (int b = 0; b < 2; ++b) {
      if (b) line += "  ";
      for (const RoomReflectances& r : t.settings.reflectances) line += pad(std::to_string(part(r)), cell);
    }
    return line + "\n";
  };
  out += header("  X    Y  ", [](const RoomReflectances& r) { return percent(r.ceiling); });
  out += header("          ", [](const RoomReflectances& r) { return percent(r.walls); });
  out += header("          ", [](const RoomReflectances& r) { return percent(r.floor); });
  for (size_t i = 0; i < t.settings.rooms.size(); ++i) {
    std::string line = pad(roomSize(t.settings.rooms[i].xH), 4) + pad(roomSize(t.settings.rooms[i].yH), 5) + " ";
    for (int b = 0; b < 2; ++b) {
      if (b) line += "  ";
      for (double v : rowOf(t, i, b == 1)) line += pad(ugrCell(v), cell);
    }
    out += line + "\n";
  }
  out += "\n" + std::string(kViewing[0]) + "\n" + kViewing[1] + "\n" + correction(labels) + "\n";
  out += "Luminaires counted: " + fmt("%.2g", t.minSolidAngleSr) + " to " + fmt("%.2g", t.maxSolidAngleSr) +
         " sr, projected areas " + fmt("%.3g", t.minProjectedAreaM2) + " to " + fmt("%.3g", t.maxProjectedAreaM2) +
         " m² (CIE 147's small- and large-source forms not applied).\n";
  return out;
}

std::string ugrTableCsv(const UgrTable& t) {
  std::string out = "room_x_H,room_y_H,luminaires";
  for (const char* side : {"crosswise", "endwise"})
    for (const RoomReflectances& r : t.settings.reflectances)
      out += std::string(",") + side + "_" + std::to_string(percent(r.ceiling)) + "_" +
             std::to_string(percent(r.walls)) + "_" + std::to_string(percent(r.floor));
  out += "\n";
  for (size_t i = 0; i < t.settings.rooms.size(); ++i) {
    out += fmt("%g", t.settings.rooms[i].xH) + "," + fmt("%g", t.settings.rooms[i].yH) + "," +
           std::to_string(t.luminaires[i]);
    for (int b = 0; b < 2; ++b)
      for (double v : rowOf(t, i, b == 1)) out += "," + (std::isfinite(v) ? fmt("%.2f", v) : std::string());
    out += "\n";
  }
  return out;
}

std::string ugrTableSvg(const UgrTable& t, const UgrTableLabels& labels) {
  // Sizes in px for 13 px sans-serif text, whose characters are at most about 0.62 em wide.
  const double margin = 16.0, roomW = 44.0, cellW = 46.0, gap = 24.0, rowH = 20.0, charW = 0.62;
  const size_t nr = t.settings.reflectances.size();
  const double blockW = cellW * double(nr);
  const std::string title = "UGR table" + (labels.title.empty() ? std::string() : " — " + labels.title);
  std::vector<std::string> notes = conditions(t, labels);
  notes.insert(notes.end(), {kViewing[0], kViewing[1], correction(labels)});
  double textW = title.size() * 15.0 * charW;
  for (const std::string& n : notes) textW = std::max(textW, n.size() * 11.0 * charW);
  const double tableW = 2.0 * roomW + 2.0 * blockW + gap;
  const double labelW = 56.0;  // "ceiling", "walls", "floor" right of the header
  const double width = 2.0 * margin + std::max(tableW + labelW, textW);
  const double tableTop = margin + 30.0, headerRows = 4.0;
  const double tableBottom = tableTop + rowH * (headerRows + double(t.settings.rooms.size()));
  const double height = tableBottom + 16.0 + 16.0 * double(notes.size()) + margin;
  const auto x0 = [&](int block) { return margin + 2.0 * roomW + block * (blockW + gap); };
  const auto text = [](double x, double y, const std::string& s, const char* extra = "") {
    return "<text x=\"" + svgNumber(x) + "\" y=\"" + svgNumber(y) + "\"" + extra + ">" + xmlEscape(s) + "</text>\n";
  };
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    svgNumber(width) + "\" height=\"" + svgNumber(height) + "\" viewBox=\"0 0 " + svgNumber(width) +
                    " " + svgNumber(height) + "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += text(margin, margin + 14.0, title, " font-size=\"15\" font-weight=\"bold\"");
  // Header: the two blocks' names, then ceiling, walls and floor reflectances in %.
  const double base = tableTop + rowH - 6.0;
  svg += text(margin, base, "Room", " font-weight=\"bold\"");
  for (int b = 0; b < 2; ++b)
    svg += text(x0(b) + 0.5 * blockW, base, b ? "Viewed endwise" : "Viewed crosswise",
                " text-anchor=\"middle\" font-weight=\"bold\"");
  const char* rowName[3] = {"ceiling", "walls", "floor"};
  for (int k = 0; k < 3; ++k) {
    const double y = base + rowH * (k + 1);
    if (k == 0) svg += text(margin + roomW - 6.0, y, "X", " text-anchor=\"end\" font-weight=\"bold\"");
    if (k == 0) svg += text(margin + 2.0 * roomW - 6.0, y, "Y", " text-anchor=\"end\" font-weight=\"bold\"");
    for (int b = 0; b < 2; ++b)
      for (size_t c = 0; c < nr; ++c) {
        const RoomReflectances& r = t.settings.reflectances[c];
        const double v = k == 0 ? r.ceiling : k == 1 ? r.walls : r.floor;
        svg += text(x0(b) + cellW * (c + 1) - 8.0, y, std::to_string(percent(v)), " text-anchor=\"end\" fill=\"#555\"");
      }
    svg += text(x0(1) + blockW + 4.0, y, rowName[k], " font-size=\"11\" fill=\"#555\"");
  }
  const double bodyTop = tableTop + rowH * headerRows;
  svg += "<line x1=\"" + svgNumber(margin) + "\" y1=\"" + svgNumber(bodyTop) + "\" x2=\"" +
         svgNumber(margin + tableW) + "\" y2=\"" + svgNumber(bodyTop) + "\" stroke=\"#333\"/>\n";
  for (size_t i = 0; i < t.settings.rooms.size(); ++i) {
    const double top = bodyTop + rowH * double(i), y = top + rowH - 6.0;
    if (i % 2 == 1)
      svg += "<rect x=\"" + svgNumber(margin) + "\" y=\"" + svgNumber(top) + "\" width=\"" + svgNumber(tableW) +
             "\" height=\"" + svgNumber(rowH) + "\" fill=\"#eef2f7\"/>\n";
    svg += text(margin + roomW - 6.0, y, roomSize(t.settings.rooms[i].xH), " text-anchor=\"end\"");
    svg += text(margin + 2.0 * roomW - 6.0, y, roomSize(t.settings.rooms[i].yH), " text-anchor=\"end\"");
    for (int b = 0; b < 2; ++b) {
      const std::vector<double>& row = rowOf(t, i, b == 1);
      for (size_t c = 0; c < row.size(); ++c)
        svg += text(x0(b) + cellW * (c + 1) - 8.0, y, ugrCell(row[c]), " text-anchor=\"end\"");
    }
  }
  for (size_t k = 0; k < notes.size(); ++k)
    svg += text(margin, tableBottom + 16.0 * double(k + 1) + 4.0, notes[k], " font-size=\"11\"");
  return svg + "</svg>\n";
}

}  // namespace candela
