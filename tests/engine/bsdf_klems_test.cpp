// Klems matrices (engine/bsdf_klems.h) read from XML the tests write: the bases' geometry, a
// Lambertian transmitter, a diagonal clear glass and its peak, the hemispherical sums against
// the matrix, reciprocity for the missing transmission, colour, and sampling against evaluation
// (chi-square over patches, mean weight against albedoToward).
#include "engine/bsdf_klems.h"
#include "engine/radiance/bsdf_xml.h"
#include "tests/engine/bsdf_test_xml.h"

#include <gtest/gtest.h>

#include <random>

namespace candela {
namespace {

using namespace test_support;
constexpr int kFull = 145;

// The Klems full patch of (x, y, z), z > 0, computed here from the ring table (the nearest
// sector centre, centres at 360°·k/n).
int fullIndex(const Vec3& v) {
  const double theta = radToDeg(std::acos(std::min(1.0, v.z)));
  int first = 0;
  for (const TestRing& r : klemsFullRings()) {
    if (theta < r.hi) {
      double az = radToDeg(std::atan2(v.y, v.x));
      if (az < 0) az += 360.0;
      return first + static_cast<int>(std::lround(az / 360.0 * r.n)) % r.n;
    }
    first += r.n;
  }
  return -1;
}

Vec3 randomDir(std::mt19937_64& rng, double side) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = std::sqrt(1.0 - u(rng) * 0.999), phi = kTwoPi * u(rng), s = std::sqrt(1.0 - z * z);
  return Vec3(s * std::cos(phi), s * std::sin(phi), side * z);
}

std::vector<double> randomMatrix(uint64_t seed, double zeroFraction) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> m(kFull * kFull);
  for (double& v : m) v = u(rng) < zeroFraction ? 0.0 : 0.02 * u(rng);
  return m;
}

TEST(KlemsBasis, StandardBasesCoverTheHemisphere) {
  for (auto [name, count] : {std::pair{"LBNL/Klems Full", 145}, {"LBNL/Klems Half", 73}, {"lbnl/klems quarter", 41}}) {
    const auto b = KlemsBasis::standard(name);
    ASSERT_TRUE(b) << name;
    EXPECT_EQ(b->count, count);
    double sum = 0.0;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < b->count; ++k) {
      sum += b->projSA(k);
      for (int t = 0; t < 20; ++t) EXPECT_EQ(b->index(b->direction(k, Vec2(u(rng), u(rng)))), k) << name << " " << k;
    }
    EXPECT_NEAR(sum, kPi, 1e-12);  // Σ Λ_k = π (cos²0 − cos²90)
  }
  const auto full = KlemsBasis::standard("LBNL/Klems Full");
  for (int k = 0; k < kFull; ++k) {
    EXPECT_NEAR(full->projSA(k), klemsFullLambda(k), 1e-15);
    EXPECT_EQ(full->index(klemsFullCentre(k)), k);
    EXPECT_EQ(fullIndex(klemsFullCentre(k)), k);
  }
  EXPECT_FALSE(KlemsBasis::standard("LBNL/Klems Double"));
}

TEST(KlemsBsdf, LambertianHalfTransmitter) {
  const auto b = parseBsdfXml(bsdfXml({{"Transmission Front", std::vector<double>(kFull * kFull, 0.5 / kPi)}}), "lamb.xml");
  EXPECT_EQ(b->kind(), "Klems full");
  EXPECT_TRUE(b->transmits());
  EXPECT_FALSE(b->reflects(true));
  EXPECT_FALSE(b->reflects(false));
  std::mt19937_64 rng(1);
  for (int t = 0; t < 200; ++t) {
    const double side = t % 2 ? 1.0 : -1.0;
    const Vec3 in = randomDir(rng, side), out = randomDir(rng, -side), refl = randomDir(rng, side);
    // Both ways: from the front as given, from the back by reciprocity.
    EXPECT_NEAR(b->eval(in, out).x, 0.5 / kPi, 1e-15);
    EXPECT_NEAR(b->eval(in, out).z, 0.5 / kPi, 1e-15);
    EXPECT_EQ(b->eval(in, refl), Rgb(0.0));
    EXPECT_NEAR(b->hemispherical(in, true).y, 0.5, 1e-6);
    EXPECT_EQ(b->hemispherical(in, false), Rgb(0.0));
    EXPECT_NEAR(b->albedoToward(out, true).y, 0.5, 1e-6);
    EXPECT_EQ(b->peakThrough(in), Rgb(0.0));  // flat: nothing stands out
  }
}

// T = 0.8 straight through: f(k, k) = 0.8 / Λ_k. Incident patch k from the front is the
// direction −centre_k (Radiance's bi_getvec), outgoing patch k is centre_k.
TEST(KlemsBsdf, ClearGlassDiagonalAndItsPeak) {
  std::vector<double> m(kFull * kFull, 0.0);
  for (int k = 0; k < kFull; ++k) m[k * kFull + k] = 0.8 / klemsFullLambda(k);
  const auto b = parseBsdfXml(bsdfXml({{"Transmission Front", m}}), "glass.xml");
  const auto* tab = dynamic_cast<const TabulatedBsdf*>(b.get());
  ASSERT_TRUE(tab);
  for (int k : {0, 3, 20, 60, 100, 140}) {
    const Vec3 c = klemsFullCentre(k);
    EXPECT_NEAR(b->eval(-c, c).y, 0.8 / klemsFullLambda(k), 1e-9);
    EXPECT_NEAR(b->hemispherical(-c, true).y, 0.8, 1e-9);
    // By reciprocity from the back: light from c goes to −c through the same pair.
    EXPECT_NEAR(b->eval(c, -c).y, 0.8 / klemsFullLambda(k), 1e-9);
    EXPECT_NEAR(b->hemispherical(c, true).y, 0.8, 1e-9);
    // Off the diagonal: nothing.
    EXPECT_EQ(b->eval(-c, klemsFullCentre((k + 7) % kFull)).y, 0.0);
  }
  // The peak: the whole 0.8 of the one patch (the probes in the neighbours see 0, the
  // surround). Near grazing the probes leave the hemisphere, so only up to ring 6.
  for (int k : {0, 1, 9, 30, 70, 100}) {
    const Vec3 in = -klemsFullCentre(k);
    const BsdfPeak p = tab->peakFor(in);
    EXPECT_TRUE(p.found) << k;
    EXPECT_NEAR(b->peakThrough(in).y, 0.8, 1e-9) << k;
    EXPECT_EQ(p.surround, Rgb(0.0));
    EXPECT_EQ(b->eval(in, -in, true), Rgb(0.0));  // without the peak: its surround, 0
  }
  // Without the peak nothing is left: the peak's cell holds the whole 0.8.
  for (int k : {0, 50}) {
    const Vec3 out = klemsFullCentre(k);
    EXPECT_NEAR(b->albedoToward(out, true).y, 0.8, 1e-9);
    EXPECT_NEAR(b->albedoToward(out, true, true).y, 0.0, 1e-9);
  }
}

// A glass with a diffusing coat: 0.5 straight through plus a Lambertian 0.1. Without the peak
// only the 0.1 is left, and the draws without it average to that.
TEST(KlemsBsdf, SamplingWithoutThePeak) {
  std::vector<double> m(kFull * kFull, 0.1 / kPi);
  for (int k = 0; k < kFull; ++k) m[k * kFull + k] += 0.5 / klemsFullLambda(k);
  const auto b = parseBsdfXml(bsdfXml({{"Transmission Front", m}}), "coat.xml");
  for (int k : {0, 30}) {
    const Vec3 out = klemsFullCentre(k);
    EXPECT_NEAR(b->albedoToward(out, true).y, 0.6, 1e-9);
    EXPECT_NEAR(b->peakThrough(-out).y, 0.5 + 0.1 / kPi * klemsFullLambda(k), 1e-9);
    EXPECT_NEAR(b->albedoToward(out, true, true).y, 0.1, 1e-9);
    EXPECT_NEAR(b->eval(-out, out, true).y, 0.1 / kPi, 1e-12);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 50000;
    double sum = 0.0, sum2 = 0.0;
    for (int t = 0; t < n; ++t) {
      Bsdf::Sample s;
      ASSERT_TRUE(b->sampleIn(out, Vec2(u(rng), u(rng)), u(rng), s, true));
      const double w = photopic(s.weight);
      sum += w, sum2 += w * w;
    }
    const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 0.1, 4.0 * se);
  }
}

TEST(KlemsBsdf, HemisphericalIsTheMatrixSum) {
  const std::vector<double> m = randomMatrix(11, 0.3);
  const auto b = parseBsdfXml(bsdfXml({{"Transmission Front", m}}), "r.xml");
  for (int k = 0; k < kFull; ++k) {
    double sum = 0.0;
    for (int o = 0; o < kFull; ++o) sum += m[o * kFull + k] * klemsFullLambda(o);
    const Vec3 in = -klemsFullCentre(k);  // front incident patch k
    EXPECT_NEAR(b->hemispherical(in, true).y, sum, 1e-12 * (1.0 + sum)) << k;
  }
}

// The "Rows" layout is the transpose of "Columns" in the file, the same matrix in memory.
TEST(KlemsBsdf, RowsLayoutIsTheTransposedText) {
  const std::vector<double> m = randomMatrix(12, 0.2);
  std::vector<double> t(m.size());
  for (int i = 0; i < kFull; ++i)
    for (int o = 0; o < kFull; ++o) t[i * kFull + o] = m[o * kFull + i];
  const auto a = parseBsdfXml(bsdfXml({{"Reflection Back", m}}), "c.xml");
  const auto b = parseBsdfXml(bsdfXml({{"Reflection Back", t}}, "Rows"), "r.xml");
  std::mt19937_64 rng(5);
  for (int n = 0; n < 300; ++n) {
    const Vec3 in = randomDir(rng, 1.0), out = randomDir(rng, 1.0);
    EXPECT_EQ(a->eval(in, out), b->eval(in, out));
  }
}

// A missing "Transmission Back" is the front one read backwards (Radiance's reciprocity,
// bsdf_m.c SDgetMtxBSDF): in Radiance's frame both sides' patches are numbered by the azimuth
// of propagation, so reversing a path turns each patch half a turn: back(a, b) =
// front(R b, R a) with R the patch opposite in azimuth (for the symmetric Klems bases).
TEST(KlemsBsdf, MissingTransmissionByReciprocity) {
  const std::vector<double> front = randomMatrix(13, 0.2);
  std::vector<double> back(front.size());
  for (int a = 0; a < kFull; ++a)
    for (int bb = 0; bb < kFull; ++bb)
      back[bb * kFull + a] = front[klemsFullOpposite(a) * kFull + klemsFullOpposite(bb)];
  const auto one = parseBsdfXml(bsdfXml({{"Transmission Front", front}}), "one.xml");
  const auto both = parseBsdfXml(bsdfXml({{"Transmission Front", front}, {"Transmission Back", back}}), "both.xml");
  std::mt19937_64 rng(6);
  for (int n = 0; n < 400; ++n) {
    const Vec3 in = randomDir(rng, 1.0), out = randomDir(rng, -1.0);  // from the back (+z)
    EXPECT_EQ(one->eval(in, out), both->eval(in, out));
    EXPECT_NEAR(one->hemispherical(in, true).y, both->hemispherical(in, true).y, 1e-12);
    EXPECT_NEAR(one->albedoToward(out, true).y, both->albedoToward(out, true).y, 1e-12);
    EXPECT_EQ(one->eval(-in, -out), both->eval(-in, -out));  // from the front: as given
  }
}

// Colour: X, Y and Z blocks become Radiance RGB; Y stays the photopic value, and X = Y = Z
// (the equal-energy white of Radiance's primaries) is grey.
TEST(KlemsBsdf, XyzBlocksMakeRgb) {
  std::vector<double> y = randomMatrix(14, 0.1), x = y, z = y;
  for (size_t n = 0; n < y.size(); ++n) {
    x[n] = n % 3 ? y[n] : 0.6 * y[n];
    z[n] = n % 5 ? y[n] : 1.4 * y[n];
  }
  XmlBlock bx{"Reflection Back", x, "ASTM E308 1931 X.dsp"}, by{"Reflection Back", y}, bz{"Reflection Back", z, "CIE-Z"};
  const auto b = parseBsdfXml(bsdfXml({bx, by, bz}), "rgb.xml");
  for (int k = 0; k < kFull; ++k) {
    const Vec3 in(-klemsFullCentre(k).x, -klemsFullCentre(k).y, klemsFullCentre(k).z);
    for (int o : {0, 17, 88}) {
      const size_t n = static_cast<size_t>(o) * kFull + k;
      const Rgb v = b->eval(in, klemsFullCentre(o));
      // Radiance's RGB keeps Y; candela's photopic weights are it rounded to three decimals
      // (base/units.h: 0.265, 0.670, 0.065 for 0.26507, 0.67011, 0.06481), within 4e-4 of Y.
      EXPECT_NEAR(photopic(v), y[n], 4e-4 * y[n]);
      if (x[n] == y[n] && z[n] == y[n]) {
        EXPECT_NEAR(v.x, y[n], 1e-9);
        EXPECT_NEAR(v.z, y[n], 1e-9);
      } else if (x[n] < y[n] && z[n] == y[n]) {
        EXPECT_LT(v.x, v.y);  // less X: less red
      }
    }
  }
}

struct SamplingCase {
  const char* name;
  bool outPlusZ;
};

// sampleIn against eval: the patches drawn (chi-square against w(i,o)Λ_i / Σ), pdfIn equal to
// the draw's pdf, and the mean weight against albedoToward (reflected + transmitted).
void checkSampling(const Bsdf& b, const std::vector<double>& trans, const std::vector<double>* refl, const Vec3& out,
                   bool transReversed) {
  // Expected probabilities per bin: bins 0..144 transmission, 145..289 reflection.
  std::vector<double> p(2 * kFull, 0.0);
  const int fixedT = transReversed ? fullIndex(Vec3(-out.x, -out.y, std::abs(out.z))) : fullIndex(Vec3(out.x, out.y, std::abs(out.z)));
  for (int k = 0; k < kFull; ++k) {
    // Not reversed: fixed outgoing patch, k incident; reversed: fixed incident patch, k outgoing.
    p[k] = (transReversed ? trans[k * kFull + fixedT] : trans[fixedT * kFull + k]) * klemsFullLambda(k);
    if (refl) p[kFull + k] = (*refl)[fullIndex(Vec3(out.x, out.y, std::abs(out.z))) * kFull + k] * klemsFullLambda(k);
  }
  double total = 0.0;
  for (double v : p) total += v;
  const Rgb albedo = b.albedoToward(out, true) + b.albedoToward(out, false);
  EXPECT_NEAR(photopic(albedo), total, 1e-12 * total);
  const int n = 200000;
  std::vector<int> counts(2 * kFull, 0);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double sum = 0.0, sum2 = 0.0;
  for (int t = 0; t < n; ++t) {
    Bsdf::Sample s;
    ASSERT_TRUE(b.sampleIn(out, Vec2(u(rng), u(rng)), u(rng), s));
    const bool transmitted = s.in.z * out.z < 0;
    // The patch as the matrix indexes it: incident (−x, −y, |z|) unless the transmission is
    // read by reciprocity (then the sample is the matrix's outgoing direction, (x, y, |z|)).
    const Vec3 a = (transmitted && transReversed) ? Vec3(s.in.x, s.in.y, std::abs(s.in.z))
                                                  : Vec3(-s.in.x, -s.in.y, std::abs(s.in.z));
    const int k = fullIndex(a);
    ASSERT_GE(k, 0);
    ++counts[(transmitted ? 0 : kFull) + k];
    ASSERT_NEAR(b.pdfIn(s.in, out), s.pdf, 1e-9 * s.pdf);
    const double w = photopic(s.weight);
    sum += w;
    sum2 += w * w;
  }
  double chi2 = 0.0;
  int bins = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    if (p[k] <= 0.0) {
      EXPECT_EQ(counts[k], 0) << k;
      continue;
    }
    const double e = n * p[k] / total;
    chi2 += (counts[k] - e) * (counts[k] - e) / e;
    ++bins;
  }
  // The chi-square quantile at z = 4 (p ≈ 3e-5) by Wilson–Hilferty for bins − 1 degrees of freedom.
  const double df = bins - 1, q = df * std::pow(1.0 - 2.0 / (9.0 * df) + 4.0 * std::sqrt(2.0 / (9.0 * df)), 3.0);
  EXPECT_LT(chi2, q) << "bins " << bins;
  const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, photopic(albedo), 4.0 * se + 1e-9 * mean);
}

TEST(KlemsBsdf, SamplingMatchesEvaluation) {
  const std::vector<double> t = randomMatrix(21, 0.3), r = randomMatrix(22, 0.5);
  const auto b = parseBsdfXml(bsdfXml({{"Transmission Front", t}, {"Reflection Back", r}}), "s.xml");
  // A viewer on +z: transmission from the front as given, reflection on +z.
  checkSampling(*b, t, &r, glm::normalize(Vec3(0.3, -0.2, 0.8)), false);
  // A viewer on −z: the transmission from the back by reciprocity, no reflection there.
  checkSampling(*b, t, nullptr, glm::normalize(Vec3(-0.5, 0.1, -0.6)), true);
}

// With colour the weights vary (w = max(R, G, B) steers the draws): their mean is still the
// albedo, per channel.
TEST(KlemsBsdf, ColourWeightsAverageToTheAlbedo) {
  std::vector<double> y = randomMatrix(31, 0.2), x = y, z = y;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.5, 1.5);
  for (size_t n = 0; n < y.size(); ++n) x[n] = y[n] * u(rng), z[n] = y[n] * u(rng);
  XmlBlock bx{"Transmission Back", x, "ASTM E308 1931 X.dsp"}, by{"Transmission Back", y},
      bz{"Transmission Back", z, "ASTM E308 1931 Z.dsp"};
  const auto b = parseBsdfXml(bsdfXml({bx, by, bz}), "c.xml");
  const Vec3 out = glm::normalize(Vec3(0.2, 0.4, -0.7));
  const Rgb albedo = b->albedoToward(out, true);
  const int n = 100000;
  Rgb sum(0.0), sum2(0.0);
  std::uniform_real_distribution<double> v(0.0, 1.0);
  for (int t = 0; t < n; ++t) {
    Bsdf::Sample s;
    ASSERT_TRUE(b->sampleIn(out, Vec2(v(rng), v(rng)), v(rng), s));
    sum += s.weight;
    sum2 += s.weight * s.weight;
  }
  for (int c = 0; c < 3; ++c) {
    const double mean = sum[c] / n, se = std::sqrt((sum2[c] / n - mean * mean) / n);
    EXPECT_GT(se, 0.0);
    EXPECT_NEAR(mean, albedo[c], 4.0 * se) << c;
  }
}

}  // namespace
}  // namespace candela
