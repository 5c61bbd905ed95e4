// Tensor trees (engine/bsdf_tree.h): Shirley and Chiu's map, the tree's layout, lookups of 4-D and
// 3-D trees the tests write against values worked out by hand, and sampling against evaluation.
#include "engine/bsdf_tree.h"
#include "engine/radiance/bsdf_xml.h"
#include "tests/engine/bsdf_test_xml.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace candela {
namespace {

using namespace test_support;

Vec3 randomDir(std::mt19937_64& rng, double side) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = std::sqrt(1.0 - u(rng) * 0.999), phi = kTwoPi * u(rng), s = std::sqrt(1.0 - z * z);
  return Vec3(s * std::cos(phi), s * std::sin(phi), side * z);
}

TEST(ShirleyChiu, RoundTripAndEqualAreas) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 100000;
  int inner = 0;
  for (int t = 0; t < n; ++t) {
    const Vec2 s(u(rng), u(rng));
    const Vec2 d = squareToDisk(s);
    ASSERT_LE(glm::length(d), 1.0 + 1e-12);
    const Vec2 back = diskToSquare(d);
    EXPECT_NEAR(back.x, s.x, 1e-9);
    EXPECT_NEAR(back.y, s.y, 1e-9);
    inner += glm::length(d) < 0.5;
  }
  // Area kept: a quarter of the square lands inside radius ½ (binomial, 4 standard errors).
  EXPECT_NEAR(inner / double(n), 0.25, 4.0 * std::sqrt(0.25 * 0.75 / n));
  // The square's centre column goes to the disc's y axis: sign(x) is kept.
  EXPECT_GT(squareToDisk(Vec2(0.7, 0.95)).x, 0.0);
  EXPECT_LT(squareToDisk(Vec2(0.3, 0.05)).x, 0.0);
}

// A leaf grid's value index: the first coordinate slowest (bsdf_t.c, SDlookupTre).
TEST(TensorTree, LeafGridAndBranches) {
  TensorTree t;
  t.dims = 4;
  t.nodes.resize(1 + 16);
  t.nodes[0].child = 1;
  for (int c = 0; c < 16; ++c) {
    t.nodes[1 + c].first = static_cast<int>(t.values.size());
    if (c == 5) {  // one child a 2×2×2×2 grid: value 100 + its index
      t.nodes[1 + c].log2Grid = 1;
      for (int k = 0; k < 16; ++k) t.values.push_back(100 + k);
    } else {
      t.values.push_back(c);
    }
  }
  // Child c holds the upper half of coordinate d when bit d of c is set.
  double side = 0.0;
  const double p1[4] = {0.7, 0.2, 0.9, 0.1};  // bits 0 and 2: child 5
  const double p2[4] = {0.2, 0.2, 0.9, 0.9};  // bits 2 and 3: child 12
  EXPECT_EQ(t.lookup(p2, &side), 12.0);
  EXPECT_EQ(side, 0.5);
  // Inside child 5 the local coordinates are (0.4, 0.4, 0.8, 0.2): grid index 0b0010 = 2.
  EXPECT_EQ(t.lookup(p1, &side), 102.0);
  EXPECT_EQ(side, 0.25);
  const double p3[4] = {0.9, 0.4, 0.6, 0.3};  // local (0.8, 0.8, 0.2, 0.6): 0b1101 = 13
  EXPECT_EQ(t.lookup(p3), 113.0);
}

// A 4-D tree of one branching: child c is 0.1 + 0.2·bit0 + 0.05·bit2. Bit 0 is the upper half
// of sq(−in.x, …) (in.x < 0), bit 2 that of sq(out.x, …) (out.x > 0), as the map keeps sign(x).
std::string tree4Text() {
  std::string s = "{\n";
  for (int c = 0; c < 16; ++c) s += " { " + std::to_string(0.1 + 0.2 * (c & 1) + 0.05 * ((c >> 2) & 1)) + " },\n";
  return s + "}";
}

double tree4Value(const Vec3& in, const Vec3& out) { return 0.1 + (in.x < 0 ? 0.2 : 0.0) + (out.x > 0 ? 0.05 : 0.0); }

TEST(TreeBsdf, FourDimensionalLookupAndIntegrals) {
  XmlBlock block{"Transmission Front", {}};
  block.rawData = tree4Text();
  const auto b = parseBsdfXml(bsdfXml({block}, "TensorTree4", ""), "t4.xml");
  EXPECT_EQ(b->kind(), "tensor tree 4");
  EXPECT_TRUE(b->transmits());
  EXPECT_FALSE(b->reflects(true));
  std::mt19937_64 rng(2);
  for (int t = 0; t < 300; ++t) {
    const Vec3 in = randomDir(rng, -1.0), out = randomDir(rng, 1.0);  // front: in on −z
    EXPECT_NEAR(b->eval(in, out).y, tree4Value(in, out), 1e-12);
    // From the back by reciprocity: f(in, out) = front(out, in).
    EXPECT_NEAR(b->eval(out, in).y, tree4Value(in, out), 1e-12);
    EXPECT_NEAR(b->hemispherical(in, true).y, kPi * ((in.x < 0 ? 0.3 : 0.1) + 0.025), 1e-9);
    EXPECT_NEAR(b->albedoToward(out, true).y, kPi * (0.2 + (out.x > 0 ? 0.05 : 0.0)), 1e-9);
    EXPECT_EQ(b->eval(in, -out), Rgb(0.0));
  }
}

// A tree's colour (bsdf_t.c): CIE-u and CIE-v trees give each cell's chromaticity u′v′, its Y
// the tree's value. The equal-energy white (u′ 4/19, v′ 9/19) is Radiance's RGB white: grey; a
// reddish x 0.5, y 0.4 keeps its luminance (photopic RGB = Y: the photopic weights are the Y row
// of Radiance's RGB → XYZ) with R > G > B; the integrals take the colour cell by cell.
TEST(TreeBsdf, ChromaticityTreesColourTheValues) {
  auto coloured = [](double up, double vp) {
    XmlBlock y{"Transmission Front", {}}, u{"Transmission Front", {}}, v{"Transmission Front", {}};
    y.rawData = tree4Text();
    u.rawData = "{ " + std::to_string(up) + " }";
    v.rawData = "{ " + std::to_string(vp) + " }";
    u.wavelength = "CIE-u";
    v.wavelength = "CIE-v";
    return parseBsdfXml(bsdfXml({y, u, v}, "TensorTree4", ""), "colour.xml");
  };
  std::mt19937_64 rng(4);
  const auto white = coloured(4.0 / 19.0, 9.0 / 19.0);
  const auto red = coloured(2.0 / 6.8, 3.6 / 6.8);  // x 0.5, y 0.4
  for (int t = 0; t < 50; ++t) {
    const Vec3 in = randomDir(rng, -1.0), out = randomDir(rng, 1.0);
    const double y = tree4Value(in, out);
    const Rgb w = white->eval(in, out);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], y, 2e-3 * y);
    const Rgb r = red->eval(in, out);
    EXPECT_NEAR(photopic(r), y, 2e-3 * y);
    EXPECT_GT(r.x, r.y);
    EXPECT_GT(r.y, r.z);
    // One chromaticity everywhere: the albedo's colour is the value's, its luminance the tree's.
    const Rgb a = red->albedoToward(out, true);
    const double ay = kPi * (0.2 + (out.x > 0 ? 0.05 : 0.0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], ay * r[c] / y, 1e-9);
  }
  // One of the two chromaticity trees alone: grey.
  XmlBlock y{"Transmission Front", {}}, u{"Transmission Front", {}};
  y.rawData = tree4Text();
  u.rawData = "{ 0.3 }";
  u.wavelength = "CIE-u";
  const auto grey = parseBsdfXml(bsdfXml({y, u}, "TensorTree4", ""), "grey.xml");
  const Vec3 in = glm::normalize(Vec3(0.2, 0.1, -0.9)), out = glm::normalize(Vec3(0.1, 0.3, 0.9));
  const Rgb g = grey->eval(in, out);
  EXPECT_EQ(g.x, g.y);
  EXPECT_EQ(g.y, g.z);
}

// Sampling the incident direction of a 4-D tree: in.x < 0 with chance (0.3 + e)/(0.4 + 2e),
// the pdf as pdfIn says, the mean weight the albedo.
TEST(TreeBsdf, SamplingMatchesEvaluation) {
  XmlBlock block{"Transmission Front", {}};
  block.rawData = tree4Text();
  const auto b = parseBsdfXml(bsdfXml({block}, "TensorTree4", ""), "t4.xml");
  for (const Vec3& out : {glm::normalize(Vec3(0.4, 0.3, 0.8)), glm::normalize(Vec3(-0.4, 0.3, 0.5))}) {
    const double e = out.x > 0 ? 0.05 : 0.0, pNeg = (0.3 + e) / (0.4 + 2 * e);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 100000;
    int neg = 0;
    double sum = 0.0, sum2 = 0.0;
    for (int t = 0; t < n; ++t) {
      Bsdf::Sample s;
      ASSERT_TRUE(b->sampleIn(out, Vec2(u(rng), u(rng)), u(rng), s));
      ASSERT_LT(s.in.z, 0.0);
      neg += s.in.x < 0;
      ASSERT_NEAR(b->pdfIn(s.in, out), s.pdf, 1e-9 * s.pdf);
      const double w = photopic(s.weight);
      sum += w, sum2 += w * w;
    }
    EXPECT_NEAR(neg / double(n), pNeg, 4.0 * std::sqrt(pNeg * (1 - pNeg) / n));
    const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, b->albedoToward(out, true).y, 4.0 * se + 1e-9);
  }
}

// An isotropic (3-D) reflection: a for light scattered forwards (rotated out.x > 0: away from
// where it came from, towards the mirror side), b backwards. With in = (sinθ, 0, cosθ):
// forwards is out.x < 0.
TEST(TreeBsdf, ThreeDimensionalIsotropicReflection) {
  const double a = 0.25, bb = 0.05;
  std::string s = "{\n";
  for (int c = 0; c < 8; ++c) s += " { " + std::to_string((c >> 1) & 1 ? a : bb) + " }\n";
  s += "}";
  XmlBlock block{"Reflection Back", {}};
  block.rawData = s;
  const auto b = parseBsdfXml(bsdfXml({block}, "TensorTree3", ""), "t3.xml");
  EXPECT_EQ(b->kind(), "tensor tree 3");
  EXPECT_TRUE(b->reflects(true));
  EXPECT_FALSE(b->reflects(false));
  EXPECT_FALSE(b->transmits());
  std::mt19937_64 rng(4);
  for (int t = 0; t < 300; ++t) {
    const Vec3 out = randomDir(rng, 1.0);
    for (double theta : {0.2, 0.7, 1.2}) {
      const Vec3 in(std::sin(theta), 0.0, std::cos(theta));
      EXPECT_NEAR(b->eval(in, out).y, out.x < 0 ? a : bb, 1e-12);
      // Rotating both about z changes nothing.
      const double r = 1.1;
      const Vec3 in2(std::cos(r) * in.x - std::sin(r) * in.y, std::sin(r) * in.x + std::cos(r) * in.y, in.z);
      const Vec3 out2(std::cos(r) * out.x - std::sin(r) * out.y, std::sin(r) * out.x + std::cos(r) * out.y, out.z);
      EXPECT_NEAR(b->eval(in2, out2).y, out.x < 0 ? a : bb, 1e-12);
      EXPECT_NEAR(b->hemispherical(in, false).y, kPi * (a + bb) / 2, 1e-9);
    }
  }
  // Sampling the incident direction: these data are reciprocal, so the mean weight is the albedo.
  const Vec3 out = glm::normalize(Vec3(0.5, -0.2, 0.6));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 50000;
  double sum = 0.0, sum2 = 0.0;
  for (int t = 0; t < n; ++t) {
    Bsdf::Sample smp;
    ASSERT_TRUE(b->sampleIn(out, Vec2(u(rng), u(rng)), u(rng), smp));
    ASSERT_NEAR(b->pdfIn(smp.in, out), smp.pdf, 1e-9 * smp.pdf);
    const double w = photopic(smp.weight);
    sum += w, sum2 += w * w;
  }
  const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, kPi * (a + bb) / 2, 4.0 * se + 1e-9);
  EXPECT_NEAR(b->albedoToward(out, false).y, kPi * (a + bb) / 2, 1e-9);
}

// A narrow peak straight through: a 4-D tree fine near the centre of both squares (normal
// incidence, normal exit) — the peak of normal incidence is found and its surround is the rest.
TEST(TreeBsdf, PeakOfAFineCentreCell) {
  // Depth 5 at the centre: the root's child 15 (the upper half in every coordinate) is split,
  // then always its child 0 (the corner at the centre), down to a cell of side 1/32 holding
  // 1000; every other cell holds 0.1.
  std::function<std::string(int, int)> node = [&](int depth, int corner) -> std::string {
    if (depth == 0) return "{ 1000 }";
    std::string s = "{ ";
    for (int c = 0; c < 16; ++c) s += (c == corner ? node(depth - 1, 0) : std::string("{ 0.1 }")) + " ";
    return s + "}";
  };
  XmlBlock block{"Transmission Front", {}};
  block.rawData = node(5, 15);
  const auto b = parseBsdfXml(bsdfXml({block}, "TensorTree4", ""), "p.xml");
  // sq(−in.x, −in.y) and sq(out.x, out.y) just above ½: in the fine cell.
  const Vec3 in = glm::normalize(Vec3(-1e-4, -1e-4, -1.0));
  EXPECT_NEAR(b->eval(in, -in).y, 1000.0, 1e-9);
  const Rgb peak = b->peakThrough(glm::normalize(in));
  // The fine cell's side is 1/32: Ω = π/1024 (Radiance's minProjSA); the probes that fall in it
  // repeat its value and count once, the others (0.1, 8000 times less) are the surround.
  EXPECT_NEAR(peak.y, 1000.0 * kPi / 1024.0, 1e-9);
  const auto* tab = dynamic_cast<const TabulatedBsdf*>(b.get());
  ASSERT_TRUE(tab);
  EXPECT_NEAR(tab->peakFor(in).surround.y, 0.1, 1e-12);
  EXPECT_NEAR(b->eval(in, -in, true).y, 0.1, 1e-12);
  // A flat tree has no peak.
  XmlBlock flat{"Transmission Front", {}};
  flat.rawData = "{ 0.2 }";
  EXPECT_EQ(parseBsdfXml(bsdfXml({flat}, "TensorTree4", ""), "f.xml")->peakThrough(in), Rgb(0.0));
}

}  // namespace
}  // namespace candela
