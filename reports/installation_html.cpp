#include "reports/installation_html.h"

#include <cmath>
#include <sstream>

#include "reports/plan_svg.h"
#include "reports/polar_plot_svg.h"

namespace candela {

namespace {

// The schedule's polar plots: small, the table's row height.
constexpr double kPolarPlotPx = 200.0;

std::string lm(double v) { return formatFixed(v, 0) + " lm"; }
std::string watts(double v) { return formatFixed(v, std::abs(v) >= 100.0 ? 0 : 1) + " W"; }
std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// The luminaire's name as the file gives it, else the file's name.
std::string luminaireName(const LuminaireTypeReport& t) {
  if (!t.luminaire.empty()) return t.luminaire;
  const std::size_t slash = t.file.find_last_of("/\\");
  return slash == std::string::npos ? t.file : t.file.substr(slash + 1);
}

void scheduleRow(std::ostringstream& h, const LuminaireTypeReport& t) {
  h << "<tr><td class=\"polar\">"
    << polarPlotSvg(t.polar, PolarPlotOptions{joined(t.entries), kPolarPlotPx, false}) << "</td><td class=\"lum\"><strong>"
    << xmlEscape(luminaireName(t)) << "</strong>";
  auto line = [&](const char* label, const std::string& v) {
    if (!v.empty()) h << "<span class=\"f\">" << label << " " << xmlEscape(v) << "</span>";
  };
  line("Make:", t.manufacturer);
  line("Catalogue no.:", t.catalogueNumber);
  line("Lamp:", t.lamp);
  line("Photometric file:", t.file);
  line("Placed as:", joined(t.entries));
  h << "</td><td class=\"num\">" << t.count << "</td><td class=\"num\">" << lm(t.fluxLm);
  if (t.lampFluxLm) h << "<span class=\"f\">lamps " << lm(*t.lampFluxLm) << "</span>";
  if (t.multiplier != 1.0) h << "<span class=\"f\">multiplier " << formatNumber(t.multiplier, 4) << "</span>";
  h << "</td><td class=\"num\">" << (t.powerW ? watts(*t.powerW) : "unknown");
  if (t.powerW) h << "<span class=\"f\">" << (t.powerFromCase ? "from the case" : "from the file") << "</span>";
  h << "</td><td class=\"num\">"
    << (t.lightOutputRatio ? formatFixed(100.0 * *t.lightOutputRatio, 1) + " %"
                           : "—<span class=\"f\">absolute</span>")
    << "</td><td class=\"num\">" << (t.efficacyLmPerW ? formatFixed(*t.efficacyLmPerW, 1) + " lm/W" : "—")
    << "</td><td class=\"num\">" << formatFixed(t.maintenanceFactor, 2) << "</td></tr>\n";
}

}  // namespace

std::string readableName(const std::string& identifier) {
  std::string s = identifier;
  for (char& ch : s)
    if (ch == '_') ch = ' ';
  return s;
}

std::string materialTypeText(const std::string& type) {
  if (type == "plastic") return "Plastic (diffuse, uncoloured highlight)";
  if (type == "metal") return "Metal (diffuse, coloured highlight)";
  if (type == "trans") return "Translucent";
  if (type == "mirror") return "Mirror";
  if (type == "glass") return "Glass (thin pane)";
  if (type == "dielectric") return "Dielectric (solid)";
  return type;
}

std::string luminaireScheduleHtml(const InstallationReport& installation) {
  const std::vector<LuminaireTypeReport>& types = installation.luminaires;
  if (types.empty()) return "";
  std::ostringstream h;
  h << "<section class=\"grid\" id=\"luminaires\">\n<h2>Luminaire schedule</h2>\n<p class=\"sub\">One row per type "
       "of luminaire (the same photometric file, multiplier, maintenance factor and power), with the data its "
       "photometric file gives, the number placed, and its intensity in the C0–C180 (solid) and C90–C270 "
       "(dashed) planes. Luminaire flux as installed before the maintenance factor; LOR = luminaire flux / lamp "
       "flux; efficacy = luminaire flux / input power.</p>\n"
       "<table class=\"schedule\">\n<thead><tr><th>Distribution</th><th>Luminaire</th><th class=\"num\">Number"
       "</th><th class=\"num\">Luminaire flux</th><th class=\"num\">Input power</th><th class=\"num\">LOR</th>"
       "<th class=\"num\">Efficacy</th><th class=\"num\">MF</th></tr></thead>\n<tbody>\n";
  std::size_t count = 0;
  double flux = 0.0;
  for (const LuminaireTypeReport& t : types) {
    scheduleRow(h, t);
    count += t.count;
    flux += static_cast<double>(t.count) * t.fluxLm;
  }
  const EnergyReport& e = installation.energy;
  h << "<tr><th colspan=\"2\">All luminaires</th><th class=\"num\">" << count << "</th><th class=\"num\">" << lm(flux)
    << "</th><th class=\"num\">" << (e.luminairesWithoutPower.empty() ? "" : "at least ") << watts(e.installedPowerW)
    << "</th><th></th><th></th><th></th></tr>\n</tbody>\n</table>\n</section>\n";
  return h.str();
}

std::string energyHtml(const InstallationReport& installation) {
  if (installation.luminaires.empty()) return "";
  const EnergyReport& e = installation.energy;
  std::ostringstream h;
  h << "<section class=\"grid\" id=\"energy\">\n<h2>Energy</h2>\n<p class=\"sub\">The installed power of the "
       "luminaires (number × input power of each type) over the floor area, and normalised to 100 lx of the "
       "reference grid's average illuminance Ē.</p>\n<table class=\"kv energy\">\n<tbody>\n";
  h << "<tr><td>Installed power</td><td>";
  if (e.luminairesWithoutPower.empty())
    h << watts(e.installedPowerW);
  else
    h << "<strong>at least</strong> " << watts(e.installedPowerW) << ": the input power of "
      << xmlEscape(joined(e.luminairesWithoutPower))
      << " is not known (neither the photometric file nor the case gives it), so it is left out";
  h << "</td></tr>\n<tr><td>Floor area</td><td>";
  if (e.floorAreaM2) {
    h << formatFixed(*e.floorAreaM2, 2) << " m²";
    if (e.floorAreaFromCase)
      h << ", as the case gives it";
    else
      h << ": the plan extent of the scene's bounding box, " << formatFixed(e.planExtentM.x, 2) << " m × "
        << formatFixed(e.planExtentM.y, 2) << " m (the case may give the floor area instead)";
  } else {
    h << "unknown: the scene has no geometry and the case gives no floor area";
  }
  h << "</td></tr>\n<tr><td>Power density</td><td>"
    << (e.powerDensityWm2 ? formatFixed(*e.powerDensityWm2, 2) + " W/m²" : std::string("—")) << "</td></tr>\n";
  h << "<tr><td>Power density per 100 lx</td><td>";
  if (e.powerDensityWm2Per100Lux)
    h << formatFixed(*e.powerDensityWm2Per100Lux, 2) << " W/m²/100 lx";
  else
    h << "—";
  if (!e.referenceGrid.empty())
    h << " (Ē = " << formatFixed(e.referenceAverageLux, 0) << " lx on grid " << xmlEscape(e.referenceGrid) << ", "
      << xmlEscape(e.referenceGridReason) << ")";
  else
    h << ": no grid of horizontal illuminance to take Ē on";
  h << "</td></tr>\n</tbody>\n</table>\n</section>\n";
  return h.str();
}

std::string surfacesHtml(const InstallationReport& installation) {
  const std::vector<SurfaceMaterialReport>& surfaces = installation.surfaces;
  if (surfaces.empty()) return "";
  std::ostringstream h;
  h << "<section class=\"grid\" id=\"surfaces\">\n<h2>Surfaces</h2>\n<p class=\"sub\">The materials of the "
       "scene's surfaces with their photopic reflectance ρ (diffuse and specular together, at normal incidence) "
       "and, for materials that pass light, their transmittance τ.</p>\n<table class=\"surfaces\">\n<thead><tr>"
       "<th>Material</th><th>Type</th><th class=\"num\">Reflectance ρ</th><th class=\"num\">Transmittance τ</th>"
       "<th class=\"num\">Surfaces</th></tr></thead>\n<tbody>\n";
  for (const SurfaceMaterialReport& s : surfaces) {
    h << "<tr><td title=\"" << xmlEscape(s.material) << "\">" << xmlEscape(readableName(s.material)) << "</td><td>"
      << xmlEscape(materialTypeText(s.type)) << "</td><td class=\"num\">" << formatFixed(s.reflectance, 2);
    if (s.specularReflectance > 0.0 && s.specularReflectance < s.reflectance)
      h << "<span class=\"f\">specular " << formatFixed(s.specularReflectance, 2) << "</span>";
    h << "</td><td class=\"num\">" << (s.transmittance ? formatFixed(*s.transmittance, 2) : "—")
      << "</td><td class=\"num\">" << s.surfaces << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n</section>\n";
  return h.str();
}

}  // namespace candela
