// BSDF XML written by the tests themselves (LBNL's layout, as WINDOW and genBSDF write it), and
// the Klems geometry computed independently of engine/bsdf_klems.cpp for the checks.
#pragma once

#include "base/math.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace candela::test_support {

struct XmlBlock {
  XmlBlock(std::string direction, std::vector<double> values, std::string detector = "ASTM E308 1931 Y.dsp")
      : direction(std::move(direction)), values(std::move(values)), detector(std::move(detector)) {}
  std::string direction;  // "Transmission Front", ...
  std::vector<double> values;
  std::string detector;
  std::string columnBasis = "LBNL/Klems Full", rowBasis = "LBNL/Klems Full";
  std::string rawData;  // used instead of values when not empty
  std::string wavelength = "Visible";  // a tensor tree's chromaticity: "CIE-u", "CIE-v"
};

// Klems full rings: lower θ (degrees) and nPhis (LBNL's basis, as published with WINDOW).
struct TestRing {
  double lo, hi;
  int n;
};
inline const std::vector<TestRing>& klemsFullRings() {
  static const std::vector<TestRing> r = {{0, 5, 1},   {5, 15, 8},  {15, 25, 16}, {25, 35, 20}, {35, 45, 24},
                                          {45, 55, 24}, {55, 65, 24}, {65, 75, 16}, {75, 90, 12}};
  return r;
}
// Patch k's projected solid angle: π (cos²θ_lo − cos²θ_hi) / nPhis.
inline double klemsFullLambda(int k) {
  for (const TestRing& r : klemsFullRings()) {
    if (k < r.n) {
      const double a = std::cos(degToRad(r.lo)), b = std::cos(degToRad(r.hi));
      return kPi * (a * a - b * b) / r.n;
    }
    k -= r.n;
  }
  return 0.0;
}
// The centre direction (outgoing convention, z > 0) of patch k: mid cos²θ, sector centre.
inline Vec3 klemsFullCentre(int k) {
  for (const TestRing& r : klemsFullRings()) {
    if (k < r.n) {
      const double a = std::cos(degToRad(r.lo)), b = std::cos(degToRad(r.hi));
      const double c2 = 0.5 * (a * a + b * b);
      const double phi = kTwoPi * k / r.n;
      const double s = std::sqrt(1.0 - c2);
      return Vec3(s * std::cos(phi), s * std::sin(phi), std::sqrt(c2));
    }
    k -= r.n;
  }
  return Vec3(0.0, 0.0, 1.0);
}
// The patch of the same ring half a turn away (azimuth + 180°).
inline int klemsFullOpposite(int k) {
  int first = 0;
  for (const TestRing& r : klemsFullRings()) {
    if (k < first + r.n) return first + (k - first + r.n / 2) % r.n;
    first += r.n;
  }
  return k;
}

inline std::string klemsFullBasisXml() {
  std::ostringstream s;
  s << "\t\t<AngleBasis>\n\t\t\t<AngleBasisName>LBNL/Klems Full</AngleBasisName>\n";
  for (const TestRing& r : klemsFullRings())
    s << "\t\t\t<AngleBasisBlock>\n\t\t\t\t<Theta>" << 0.5 * (r.lo + r.hi) << "</Theta>\n\t\t\t\t<nPhis>" << r.n
      << "</nPhis>\n\t\t\t\t<ThetaBounds>\n\t\t\t\t\t<LowerTheta>" << r.lo << "</LowerTheta>\n\t\t\t\t\t<UpperTheta>"
      << r.hi << "</UpperTheta>\n\t\t\t\t</ThetaBounds>\n\t\t\t</AngleBasisBlock>\n";
  s << "\t\t</AngleBasis>\n";
  return s.str();
}

// A whole file: `structure` Columns/Rows/TensorTree3/TensorTree4, `bases` the AngleBasis
// elements, one <WavelengthData> per block. Numbers are written `perLine` to a line.
inline std::string bsdfXml(const std::vector<XmlBlock>& blocks, const std::string& structure = "Columns",
                           const std::string& bases = klemsFullBasisXml(), int perLine = 145) {
  std::ostringstream s;
  s.precision(17);
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
       "<WindowElement xmlns=\"http://windows.lbl.gov\">\n"
       "<WindowElementType>System</WindowElementType>\n<FileType>BSDF</FileType>\n<Optical>\n<Layer>\n"
       "\t<DataDefinition>\n\t\t<IncidentDataStructure>"
    << structure << "</IncidentDataStructure>\n"
    << bases << "\t</DataDefinition>\n";
  for (const XmlBlock& b : blocks) {
    s << "\t<WavelengthData>\n\t\t<LayerNumber>System</LayerNumber>\n"
         "\t\t<Wavelength unit=\"Integral\">"
      << b.wavelength
      << "</Wavelength>\n"
         "\t\t<SourceSpectrum>CIE Illuminant D65 1nm.ssp</SourceSpectrum>\n"
         "\t\t<DetectorSpectrum>"
      << b.detector << "</DetectorSpectrum>\n\t\t<WavelengthDataBlock>\n\t\t\t<WavelengthDataDirection>" << b.direction
      << "</WavelengthDataDirection>\n";
    if (structure == "TensorTree3" || structure == "TensorTree4")
      s << "\t\t\t<AngleBasis>LBNL/Shirley-Chiu</AngleBasis>\n";
    else
      s << "\t\t\t<ColumnAngleBasis>" << b.columnBasis << "</ColumnAngleBasis>\n\t\t\t<RowAngleBasis>" << b.rowBasis
        << "</RowAngleBasis>\n";
    s << "\t\t\t<ScatteringDataType>BTDF</ScatteringDataType>\n\t\t\t<ScatteringData>\n";
    if (!b.rawData.empty()) {
      s << b.rawData << "\n";
    } else {
      for (size_t k = 0; k < b.values.size(); ++k) s << b.values[k] << ((k + 1) % perLine == 0 ? ",\n" : ", ");
    }
    s << "</ScatteringData>\n\t\t</WavelengthDataBlock>\n\t</WavelengthData>\n";
  }
  s << "</Layer>\n</Optical>\n</WindowElement>\n";
  return s.str();
}

}  // namespace candela::test_support
