// The UGR table of a luminaire (metrics/ugr_table.h) as manufacturers print it: rooms down,
// reflectances across, a crosswise and an endwise block, one decimal. Plain text for the
// terminal, CSV and a standalone SVG.
#pragma once

#include "metrics/ugr_table.h"

#include <string>

namespace candela {

struct UgrTableLabels {
  std::string title;                 // e.g. the luminaire's name and file
  double referenceLumens = 1000.0;   // Φ0 the table is for, lm
  double lampLumens = 0.0;           // the file's lamp flux Φ, lm (0: not shown)
  bool absolutePhotometry = false;   // Φ is then the luminaire's flux
};

// A cell: one decimal; "-" when undefined (no luminaire counted, or no background luminance).
std::string ugrCell(double ugr);

// The table and, below it, the conditions and the flux correction 8 log10(Φ/Φ0).
std::string ugrTableText(const UgrTable& table, const UgrTableLabels& labels);

// Header room_x_H,room_y_H,luminaires,crosswise_70_50_20,…,endwise_30_30_20 (reflectances in %
// ceiling_walls_floor) and one row per room; UGR with 2 decimals, empty when undefined.
std::string ugrTableCsv(const UgrTable& table);

// A standalone SVG document (with XML declaration) of the same table, sized to its text.
std::string ugrTableSvg(const UgrTable& table, const UgrTableLabels& labels);

}  // namespace candela
