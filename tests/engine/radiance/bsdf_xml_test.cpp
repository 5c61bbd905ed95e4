// The LBNL BSDF XML reader (engine/radiance/bsdf_xml.h): genBSDF's sawtooth (Klems full, back
// reflection only) against a sum over its matrix done here, and one fixture per error with its
// line.
#include "engine/radiance/bsdf_xml.h"
#include "base/error.h"
#include "tests/engine/bsdf_test_xml.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace candela {
namespace {

using namespace test_support;
constexpr int kFull = 145;

std::filesystem::path sawtooth() { return std::filesystem::path(CANDELA_TEST_DATA) / "bsdf" / "sawtooth.xml"; }

// The numbers between <ScatteringData> and </ScatteringData>, read here with a stream.
std::vector<double> scatteringData(const std::string& text) {
  const size_t a = text.find("<ScatteringData>") + 16, b = text.find("</ScatteringData>");
  std::string body = text.substr(a, b - a);
  for (char& c : body)
    if (c == ',') c = ' ';
  std::istringstream in(body);
  std::vector<double> v;
  double x;
  while (in >> x) v.push_back(x);
  return v;
}

// The 1-based line of the first occurrence of `needle` (after `from`).
int lineOf(const std::string& text, const std::string& needle, size_t from = 0) {
  const size_t at = text.find(needle, from);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(BsdfXml, SawtoothReflectsOnItsBackOnly) {
  const auto b = readBsdfXml(sawtooth());
  EXPECT_EQ(b->kind(), "Klems full");
  EXPECT_TRUE(b->reflects(true));  // XML "Reflection Back": the +z side
  EXPECT_FALSE(b->reflects(false));
  EXPECT_FALSE(b->transmits());
  std::ifstream f(sawtooth());
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const std::vector<double> m = scatteringData(text);
  ASSERT_EQ(m.size(), size_t(kFull * kFull));
  // "Columns": each line of numbers is one outgoing patch, incident patches along it.
  for (int k : {0, 1, 5, 12, 40, 77, 110, 144}) {
    double sum = 0.0;
    for (int o = 0; o < kFull; ++o) sum += m[o * kFull + k] * klemsFullLambda(o);
    // Incident patch k on the +z side is the direction (−x, −y, z) of its centre.
    const Vec3 c = klemsFullCentre(k), in(-c.x, -c.y, c.z);
    EXPECT_NEAR(b->hemispherical(in, false).y, sum, 1e-9 * sum) << k;
    EXPECT_EQ(b->hemispherical(in, true), Rgb(0.0));
    EXPECT_EQ(b->hemispherical(-in, false), Rgb(0.0));  // nothing on the front
    EXPECT_NEAR(b->eval(in, klemsFullCentre(3)).y, m[3 * kFull + k], 1e-12);
  }
}

std::string lambertian() { return bsdfXml({{"Transmission Front", std::vector<double>(kFull * kFull, 0.5 / kPi)}}); }

// The error's line, and that the message says `what`.
void expectError(const std::string& text, int line, const std::string& what) {
  try {
    parseBsdfXml(text, "bad.xml");
    ADD_FAILURE() << "accepted; expected " << what;
  } catch (const InputError& e) {
    EXPECT_EQ(e.loc().file, "bad.xml");
    EXPECT_EQ(e.loc().line, line) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
    EXPECT_LT(std::string(e.what()).size(), 200u) << "quotes too much";
  }
}

TEST(BsdfXml, TruncatedFile) {
  const std::string full = lambertian();
  // Cut in the middle of the numbers: expat reports the unclosed elements at the end, on the
  // last line.
  const std::string cut = full.substr(0, full.find("</ScatteringData>") - 500);
  expectError(cut, 1 + static_cast<int>(std::count(cut.begin(), cut.end(), '\n')), "XML: ");
  expectError("", 1, "XML: no element found");
}

TEST(BsdfXml, WrongCountOfNumbers) {
  std::vector<double> v(kFull * kFull - 1, 0.1);
  const std::string few = bsdfXml({{"Transmission Front", v}});
  expectError(few, lineOf(few, "<ScatteringData>"), "has 21024 numbers, the bases need 145 × 145 = 21025");
  v.resize(kFull * kFull + 1, 0.1);
  const std::string many = bsdfXml({{"Transmission Front", v}});
  // 145 to a line: the extra number is alone on the last line, before </ScatteringData>.
  expectError(many, lineOf(many, "</ScatteringData>"), "more than the 21025 numbers");
}

TEST(BsdfXml, UnknownBasis) {
  XmlBlock b{"Transmission Front", std::vector<double>(kFull * kFull, 0.1)};
  b.rowBasis = "LBNL/Klems Fancy";
  const std::string text = bsdfXml({b});
  expectError(text, lineOf(text, "<RowAngleBasis>"), "unknown angle basis 'LBNL/Klems Fancy'");
}

TEST(BsdfXml, NegativeNanAndInfiniteValues) {
  std::vector<double> v(kFull * kFull, 0.1);
  v[3 * kFull + 7] = -0.25;  // on the fourth line of numbers
  const std::string text = bsdfXml({{"Transmission Front", v}});
  expectError(text, lineOf(text, "<ScatteringData>") + 4, "negative scattering value -0.25");
  std::string nan = lambertian();
  const size_t at = nan.find("<ScatteringData>") + 17;
  nan.replace(at, 0, "nan, ");
  expectError(nan, lineOf(nan, "<ScatteringData>") + 1, "not a finite number: 'nan'");
  std::string word = lambertian();
  word.replace(word.find("<ScatteringData>") + 17, 0, "0.1x, ");
  expectError(word, lineOf(word, "<ScatteringData>") + 1, "not a number: '0.1x'");
}

TEST(BsdfXml, TooManyPatches) {
  const std::string bases =
      "\t\t<AngleBasis>\n\t\t\t<AngleBasisName>Fine</AngleBasisName>\n"
      "\t\t\t<AngleBasisBlock>\n\t\t\t\t<nPhis>1</nPhis>\n\t\t\t\t<ThetaBounds><LowerTheta>0</LowerTheta>"
      "<UpperTheta>10</UpperTheta></ThetaBounds>\n\t\t\t</AngleBasisBlock>\n"
      "\t\t\t<AngleBasisBlock>\n\t\t\t\t<nPhis>2000</nPhis>\n\t\t\t\t<ThetaBounds><LowerTheta>10</LowerTheta>"
      "<UpperTheta>90</UpperTheta></ThetaBounds>\n\t\t\t</AngleBasisBlock>\n\t\t</AngleBasis>\n";
  XmlBlock b{"Transmission Front", {0.1}};
  b.columnBasis = b.rowBasis = "Fine";
  const std::string text = bsdfXml({b}, "Columns", bases);
  expectError(text, lineOf(text, "<AngleBasisBlock>", text.find("<nPhis>1<")), "has more than 1000 patches");
}

// A custom basis is read and used (a two-ring basis: 1 + 4 patches).
TEST(BsdfXml, CustomBasis) {
  const std::string bases =
      "<AngleBasis><AngleBasisName>Coarse</AngleBasisName>\n"
      "<AngleBasisBlock><nPhis>1</nPhis><ThetaBounds><LowerTheta>0</LowerTheta><UpperTheta>30</UpperTheta>"
      "</ThetaBounds></AngleBasisBlock>\n"
      "<AngleBasisBlock><nPhis>4</nPhis><ThetaBounds><LowerTheta>30</LowerTheta><UpperTheta>90</UpperTheta>"
      "</ThetaBounds></AngleBasisBlock></AngleBasis>\n";
  XmlBlock b{"Transmission Front", std::vector<double>(25, 0.3 / kPi)};
  b.columnBasis = b.rowBasis = "Coarse";
  const auto bsdf = parseBsdfXml(bsdfXml({b}, "Columns", bases), "coarse.xml");
  EXPECT_EQ(bsdf->kind(), "Klems Coarse");
  EXPECT_NEAR(bsdf->hemispherical(Vec3(0.3, 0.2, -0.9), true).y, 0.3, 1e-12);
  const std::string gap = std::string(bases).replace(bases.find("<LowerTheta>30"), 14, "<LowerTheta>35");
  const std::string gapText = bsdfXml({b}, "Columns", gap);
  expectError(gapText, lineOf(gapText, "<LowerTheta>35"), "does not start where the previous ends");
}

TEST(BsdfXml, StructureAndDirectionErrors) {
  std::string text = lambertian();
  text.replace(text.find("Columns"), 7, "Diagonal");
  expectError(text, lineOf(text, "<IncidentDataStructure>"), "unsupported <IncidentDataStructure> 'Diagonal'");
  text = lambertian();
  text.replace(text.find("Transmission Front"), 18, "Transmission Sideways");
  expectError(text, lineOf(text, "<WavelengthDataDirection>"), "unknown <WavelengthDataDirection>");
  expectError("<?xml version=\"1.0\"?>\n<Window/>\n", 2, "the top element is 'Window'");
  expectError("<!DOCTYPE x [<!ENTITY a \"aaaa\">]>\n<WindowElement/>", 1, "DOCTYPE");
  // Solar data only: nothing visible.
  text = lambertian();
  text.replace(text.find(">Visible<"), 9, ">Solar<");
  expectError(text, lineOf(text, "<Layer>"), "no visible scattering");
}

TEST(BsdfXml, TensorTreeErrors) {
  XmlBlock b{"Transmission Front", {}};
  b.rawData = "{ 0.1 0.2 0.3 }";  // 3 values: not 2^(4k)
  std::string text = bsdfXml({b}, "TensorTree4", "");
  expectError(text, lineOf(text, "{ 0.1"), "a leaf of 3 values");
  b.rawData = "{ {0.1} {0.1} }";  // 2 children of 16
  text = bsdfXml({b}, "TensorTree4", "");
  expectError(text, lineOf(text, "{ {0.1}"), "expected '{'");
  std::string deep = "{ 0.1 }";
  for (int d = 0; d < 17; ++d) {
    std::string s = "{ ";
    for (int c = 0; c < 16; ++c) s += c == 0 ? deep : std::string("{0}");
    deep = s + " }";
  }
  b.rawData = deep;
  text = bsdfXml({b}, "TensorTree4", "");
  expectError(text, lineOf(text, "{ { {"), "deeper than 16 levels");
  b.rawData = "{ 0.1 } 7";
  text = bsdfXml({b}, "TensorTree4", "");
  expectError(text, lineOf(text, "{ 0.1 } 7"), "text after the tree");
}

}  // namespace
}  // namespace candela
