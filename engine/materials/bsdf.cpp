// BSDF and aBSDF (Radiance reference manual, "BSDF", "aBSDF"; src/rt/m_bsdf.c): a window system's
// measured or simulated scattering from an LBNL XML file (engine/bsdf.h, read by
// engine/radiance/bsdf_xml.h),
//   mod BSDF id 6+ thick BSDFfile ux uy uz funcfile transform 0 0|3|6|9 rdf gdf bdf rdb gdb bdb rdt gdt bdt
//   mod aBSDF id 5+ BSDFfile ux uy uz funcfile transform 0 0|3|6|9 …
// The local frame's z is the surface normal and its y the up vector (three functions of the
// function file, evaluated at each hit) projected on the surface. The optional reals are diffuse
// parts added to the file's: reflection on the normal's side, on the other, and transmission.
// Patterns multiply everything but the file's reflection (as Radiance's m_bsdf.c).
//
// What a surface does (docs/bsdf.md): the sampled sources' light on either side is taken with the
// scattering function in their direction (MaterialFamily::sourceBrdf); the sky and every other
// light arrives by paths that go on in a direction drawn from the scattering function
// (sampleScattering). BSDF stops shadow rays; aBSDF takes the direct part that stands out in the
// straight-through direction (Bsdf::peakThrough) out of the data and lets shadow rays and paths
// through with it, as a window's clear view. A non-zero thickness makes the surface a proxy of
// detail geometry within that distance (pkgBSDF's use): shadow rays and rays from the hidden side
// pass it (the positive thickness hides the side opposite the normal), and transmitted paths
// start that far beyond it.
#include "engine/bsdf.h"
#include "engine/materials/normal.h"
#include "engine/materials/pattern_hook.h"
#include "engine/materials/registry.h"

#include <charconv>
#include <cmath>

namespace candela {
namespace {

// The local frame (src/common/bsdf.c, SDcompXform): z the normal, x = up × z, y = z × x. An up
// vector along the normal leaves no frame; Radiance then gives the ray nothing ("Illegal
// orientation vector"); candela takes x along the world's axis least aligned with the normal, so
// that the surface stays lit, and says so in docs/bsdf.md.
struct LocalFrame {
  Vec3 x{1.0, 0.0, 0.0}, y{0.0, 1.0, 0.0}, z{0.0, 0.0, 1.0};
  LocalFrame(const Vec3& normal, const Vec3& up) : z(normal) {
    Vec3 xv = glm::cross(up, z);
    double len = glm::length(xv);
    if (!(len > 1e-9)) {
      const Vec3 a = std::abs(z.x) < 0.6 ? Vec3(1.0, 0.0, 0.0) : std::abs(z.y) < 0.6 ? Vec3(0.0, 1.0, 0.0)
                                                                                      : Vec3(0.0, 0.0, 1.0);
      xv = glm::cross(glm::cross(z, a), z);
      len = glm::length(xv);
    }
    x = xv / len;
    y = glm::cross(z, x);
  }
  Vec3 toLocal(const Vec3& v) const { return {glm::dot(v, x), glm::dot(v, y), glm::dot(v, z)}; }
  Vec3 toWorld(const Vec3& v) const { return v.x * x + v.y * y + v.z * z; }
};

double readThickness(const MaterialReadContext& ctx) {
  const std::string& s = ctx.primitive.strings[0];
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
    ctx.fail(ctx.what() + ": its thickness '" + s +
             "' is not a number (candela reads the thickness as a constant, not a function file's variable)");
  // Radiance's m_bsdf.c: |thickness| ≤ FTINY (1e-7) is none.
  return std::abs(v) <= 1e-7 ? 0.0 : v;
}

class BsdfFamily : public MaterialFamily {
 public:
  explicit BsdfFamily(bool peak) : peak_(peak) {}
  MaterialType type() const override { return peak_ ? MaterialType::kABsdf : MaterialType::kBsdf; }
  const char* name() const override { return peak_ ? "aBSDF" : "BSDF"; }
  HitRole role() const override { return HitRole::kScatter; }
  int functionPatterns() const override { return 1; }  // the up vector

  void read(const MaterialReadContext& ctx, Material& m) const override {
    const RadPrimitive& p = ctx.primitive;
    const size_t fileAt = peak_ ? 0 : 1;
    // The strings were checked by the up vector's pattern (engine/radiance/function_patterns.cpp).
    if (p.reals.size() > 9 || p.reals.size() % 3 != 0)
      ctx.fail(ctx.what() + " takes 0, 3, 6 or 9 real arguments (front, back diffuse reflectance, diffuse "
                            "transmittance), got " + std::to_string(p.reals.size()));
    m.thicknessM = peak_ ? 0.0 : readThickness(ctx);
    m.bsdf = ctx.findBsdf(p.strings[fileAt]);
    m.color = p.reals.size() >= 3 ? ctx.vec(0) : Rgb(0.0);
    m.backColor = p.reals.size() >= 6 ? ctx.vec(3) : Rgb(0.0);
    m.transmissionColor = p.reals.size() >= 9 ? ctx.vec(6) : Rgb(0.0);
    for (const Rgb& c : {m.color, m.backColor, m.transmissionColor}) ctx.expectNonNegative(c);
  }
  // Without a hit: the diffuse parts added (the file's parts are direction-dependent).
  void derive(MaterialParameters& m) const override { deriveFromDiffuseReals(m); }
  void atHit(const Material& m, const PatternPoint& p, const Rgb& patternColour, PatternEvaluator& eval,
             MaterialParameters& out) const override {
    const bool front = glm::dot(p.d, p.ng) < 0.0;
    out.anisotropyU = eval.direction(m.functions, p);
    out.diffuseReflectance = (front ? m.color : m.backColor) * patternColour;
    out.diffuseTransmittance = m.transmissionColor * patternColour;
  }

  // Shadow rays: a proxy's pass (thickness), aBSDF's direct part; BSDF stops them.
  bool mayPassShadowRays(const Material& m) const override { return m.thicknessM != 0.0 || peak_; }
  std::optional<Rgb> straightTransmittance(const Material& m, const Vec3& dir, const Vec3& ng) const override {
    if (m.thicknessM != 0.0) return Rgb(1.0);
    if (!peak_) return std::nullopt;
    // Light arriving from dir's end; shadow rays see the material at the hit (the hook evaluated
    // its up vector: engine/materials/pattern_hook.h, straightThrough).
    const LocalFrame f(ng, m.anisotropyU);
    return peakOf(m).peakThrough(f.toLocal(dir)) * m.patternColour;
  }
  bool seeThrough(const Material& m) const override { return peak_ || m.thicknessM != 0.0; }
  bool isGlazing() const override { return true; }
  bool transmitting() const override { return true; }
  double viewTransmittance(const Material& m) const override {
    if (!peak_) return 0.0;
    return photopic(peakOf(m).peakThrough(Vec3(0.0, 0.0, -1.0)));
  }
  NormalIncidence normalIncidence(const Material& m) const override {
    const Bsdf& b = peakOf(m);
    const Vec3 n(0.0, 0.0, 1.0);
    return {photopic(b.hemispherical(n, false) + m.color), 0.0, photopic(b.hemispherical(-n, true) + m.transmissionColor)};
  }

  bool directionalSources(const Material&) const override { return true; }
  Rgb sourceBrdf(const Material& m, const PatternPoint& at, PatternEvaluator&, const Vec3& ldir, double,
                 bool transmitted) const override {
    const LocalFrame f(at.ng, m.anisotropyU);
    const Rgb fileF = peakOf(m).eval(f.toLocal(ldir), f.toLocal(-at.d), peak_);
    return (transmitted ? fileF * m.patternColour : fileF) +
           (transmitted ? m.diffuseTransmittance : m.diffuseReflectance) * kInvPi;
  }
  bool samplesScattering(const Material&) const override { return true; }
  bool sampleScattering(const Material& m, const PatternPoint& at, const Vec2& u, Rng& rng,
                        ScatterSample& s) const override {
    const Bsdf& b = peakOf(m);
    const LocalFrame f(at.ng, m.anisotropyU);
    const Vec3 out = f.toLocal(-at.d);
    const bool outPlus = out.z > 0.0;
    // The parts by their photopic albedo towards the viewer: the file's scattering (both sides,
    // drawn by Bsdf::sampleIn), the diffuse parts added, aBSDF's direct part; each chosen with
    // probability albedo / Σ albedo, so that a path never ends here: its weight carries Σ albedo
    // instead (a blind absorbing half the light halves the weight rather than ending every other
    // path: 20–40 % less CPU for the same error on cases/sidelit-bsdf, docs/bsdf.md). A draw's
    // weight is its value over its density, so that a draw that follows the file only roughly
    // stays unbiased.
    const Rgb fileA = b.albedoToward(out, false, peak_) + b.albedoToward(out, true, peak_) * m.patternColour;
    const Rgb through = peak_ ? b.peakThrough(f.toLocal(at.d)) * m.patternColour : Rgb(0.0);
    const double a[4] = {photopic(fileA), photopic(m.diffuseReflectance), photopic(m.diffuseTransmittance),
                         photopic(through)};
    const double sum = a[0] + a[1] + a[2] + a[3];
    if (!(sum > 0.0)) return false;
    const double norm = sum;
    double pick = rng.uniform() * norm;
    int part = 0;
    for (; part < 4; ++part) {
      if (pick < a[part]) break;
      pick -= a[part];
    }
    if (part == 4) {  // rounding left pick past the last part: the last part drawn
      part = 3;
      while (!(a[part] > 0.0)) --part;
      pick = std::nextafter(a[part], 0.0);
    }
    const double scale = norm / a[part];
    s = ScatterSample{};
    switch (part) {
      case 0: {
        Bsdf::Sample bs;
        if (!b.sampleIn(out, u, pick / a[part], bs, peak_)) return false;
        s.dir = f.toWorld(bs.in);
        s.transmitted = (bs.in.z > 0.0) != outPlus;
        s.weight = bs.weight * scale * (s.transmitted ? m.patternColour : Rgb(1.0));
        return true;
      }
      case 1:
      case 2: {
        const bool t = part == 2;
        const double side = (outPlus != t) ? 1.0 : -1.0;
        const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
        s.dir = f.toWorld(Vec3(r * std::cos(phi), r * std::sin(phi), side * std::sqrt(std::max(0.0, 1.0 - u.x))));
        s.transmitted = t;
        s.weight = (t ? m.diffuseTransmittance : m.diffuseReflectance) * scale;
        return true;
      }
      default:
        s.straight = true;
        s.transmitted = true;
        s.dir = at.d;
        s.weight = through * scale;
        return true;
    }
  }
  Vec3 transmittedOffset(const Material& m, const Vec3& ng) const override { return -m.thicknessM * ng; }
  bool passesPrimaryRays(const Material& m) const override { return m.thicknessM != 0.0; }
  bool hidesSide(const Material& m, bool front) const override {
    // A positive thickness hides what lies behind (opposite the normal): rays arriving there pass.
    return m.thicknessM != 0.0 && ((m.thicknessM > 0.0) != front);
  }

 private:
  static const Bsdf& peakOf(const Material& m) { return *m.bsdf; }
  bool peak_;
};

}  // namespace

const MaterialFamily& bsdfFamily() {
  static const BsdfFamily f(false);
  return f;
}

const MaterialFamily& aBsdfFamily() {
  static const BsdfFamily f(true);
  return f;
}

}  // namespace candela
