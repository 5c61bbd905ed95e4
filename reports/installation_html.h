// The report's sections on the installation of a point-in-time run (docs/reports.md): the
// luminaire schedule with a small polar plot per type, the energy figures (installed power,
// W/m², W/m²/100 lx) and the surfaces' reflectances. Part of report.html (reports/html_report.h),
// whose stylesheet styles them.
#pragma once

#include <string>

#include "reports/report_data.h"

namespace candela {

// The three sections, HTML fragments in the order the report shows them; "" for a run
// without luminaires and surfaces.
std::string luminaireScheduleHtml(const InstallationReport& installation);
std::string energyHtml(const InstallationReport& installation);
std::string surfacesHtml(const InstallationReport& installation);

// A name from a scene or a file made readable: '_' becomes a space ("wall_paint" → "wall paint").
std::string readableName(const std::string& identifier);

// What a reader calls a Radiance material type: "plastic" → "Plastic", "trans" → "Translucent
// (trans)", ...; the type itself for one it does not know.
std::string materialTypeText(const std::string& type);

}  // namespace candela
