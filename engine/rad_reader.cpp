#include "engine/rad_reader.h"
#include "base/input_file.h"
#include "base/units.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace candela {

namespace {
constexpr double kMaxRadiance = 1e30;
}  // namespace

namespace {

constexpr const char* kSupported =
    "supported: polygon, sphere, bubble, ring, cone, cup, cylinder, tube, source; "
    "plastic, metal, trans, mirror, glass, dielectric, light, illum, glow";

struct Token {
  std::string_view text;
  int line;
};

class Tokenizer {
 public:
  Tokenizer(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  bool next(Token& tok) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
        atLineStart_ = true;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (c == '!' && atLineStart_) {
        throw InputError(FileLoc{file_, line_, 0},
                         "inline commands ('!') are refused: scene files never run programs");
      } else if (c == '"' || c == '\'') {
        // A quoted word (Radiance's fgetword, either quote): everything up to the same closing
        // quote, blanks included, without the quotes; an expression such as "if(a, 1, 0)".
        const int line = line_;
        const size_t start = ++pos_;
        while (pos_ < text_.size() && text_[pos_] != c) {
          if (text_[pos_] == '\n') ++line_;
          ++pos_;
        }
        if (pos_ >= text_.size()) throw InputError(FileLoc{file_, line, 0}, "a quoted string is not closed");
        tok = Token{text_.substr(start, pos_ - start), line};
        ++pos_;
        lastTokenLine_ = line_;
        atLineStart_ = false;
        return true;
      } else {
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        tok = Token{text_.substr(start, pos_ - start), line_};
        lastTokenLine_ = line_;
        atLineStart_ = false;
        return true;
      }
    }
    return false;
  }

  // Line of the last token read (where an unexpected end of file is reported).
  int lastTokenLine() const { return lastTokenLine_; }
  const std::string& file() const { return file_; }

 private:
  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1;
  bool atLineStart_ = true;
  int lastTokenLine_ = 1;
};

struct Primitive {
  std::string modifier, type, name;
  int line = 0;
  std::vector<std::string> strings;
  std::vector<double> reals;
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& file, Scene& scene) : tok_(text, file), scene_(scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i) materials_[scene.materials[i].name] = static_cast<int>(i);
  }

  void run() {
    Token first;
    while (tok_.next(first)) {
      Primitive p;
      p.line = first.line;
      p.modifier = std::string(first.text);
      p.type = std::string(need("a primitive type after '" + p.modifier + "'").text);
      p.name = std::string(need("an identifier for " + p.type).text);
      const int ns = count("string");
      for (int i = 0; i < ns; ++i) p.strings.emplace_back(need("a string argument").text);
      const int ni = count("integer");
      for (int i = 0; i < ni; ++i) need("an integer argument");
      if (ni != 0) fail(p.line, p.type + " '" + p.name + "' takes no integer arguments, got " + std::to_string(ni));
      const int nr = count("real");
      for (int i = 0; i < nr; ++i) {
        const Token t = need("a real argument");
        p.reals.push_back(number(t));
      }
      add(p);
    }
  }

 private:
  [[noreturn]] void fail(int line, const std::string& msg) { throw InputError(FileLoc{tok_.file(), line, 0}, msg); }

  Token need(const std::string& what) {
    Token t;
    if (!tok_.next(t)) fail(tok_.lastTokenLine(), "unexpected end of file: expected " + what);
    return t;
  }

  double number(const Token& t) {
    double v = 0.0;
    const char* b = t.text.data();
    const char* e = b + t.text.size();
    if (*b == '+') ++b;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
      fail(t.line, "'" + std::string(t.text) + "' is not a number");
    return v;
  }

  int count(const char* kind) {
    const Token t = need(std::string("the number of ") + kind + " arguments");
    int v = 0;
    const auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (r.ec != std::errc() || r.ptr != t.text.data() + t.text.size() || v < 0)
      fail(t.line, "'" + std::string(t.text) + "' is not a valid count of " + kind + " arguments");
    return v;
  }

  void expectReals(const Primitive& p, size_t n) {
    if (p.reals.size() != n)
      fail(p.line, p.type + " '" + p.name + "' needs " + std::to_string(n) + " real arguments, got " +
                       std::to_string(p.reals.size()));
  }
  void expectStrings(const Primitive& p, size_t maxN) {
    if (p.strings.size() > maxN)
      fail(p.line, p.type + " '" + p.name + "' takes at most " + std::to_string(maxN) + " string arguments, got " +
                       std::to_string(p.strings.size()));
  }

  Vec3 vec(const Primitive& p, size_t i) const { return Vec3(p.reals[i], p.reals[i + 1], p.reals[i + 2]); }

  int modifierOf(const Primitive& p) {
    if (p.modifier == "void") return -1;
    const auto it = materials_.find(p.modifier);
    if (it == materials_.end())
      fail(p.line, "modifier '" + p.modifier + "' of " + p.type + " '" + p.name + "' is not defined before use");
    return it->second;
  }

  void addMaterial(const Primitive& p, MaterialType type) {
    if (p.modifier != "void" && materials_.find(p.modifier) == materials_.end())
      fail(p.line, "modifier '" + p.modifier + "' of " + p.type + " '" + p.name + "' is not defined before use");
    Material m;
    m.type = type;
    m.name = p.name;
    m.loc = FileLoc{tok_.file(), p.line, 0};
    switch (type) {
      case MaterialType::kPlastic:
      case MaterialType::kMetal:
        expectStrings(p, 0);
        expectReals(p, 5);
        m.color = vec(p, 0);
        m.specularity = p.reals[3];
        m.roughness = p.reals[4];
        break;
      case MaterialType::kTrans:
        expectStrings(p, 0);
        expectReals(p, 7);
        m.color = vec(p, 0);
        m.specularity = p.reals[3];
        m.roughness = p.reals[4];
        m.transmissivity = p.reals[5];
        m.transmittedSpecular = p.reals[6];
        break;
      case MaterialType::kMirror:
      case MaterialType::kIllum:
      case MaterialType::kLight:
        expectStrings(p, type == MaterialType::kLight ? 0 : 1);
        expectReals(p, 3);
        m.color = vec(p, 0);
        if (!p.strings.empty() && p.strings[0] != "void") {
          const auto it = materials_.find(p.strings[0]);
          if (it == materials_.end())
            fail(p.line, "alternate material '" + p.strings[0] + "' of " + p.type + " '" + p.name +
                             "' is not defined before use");
          m.alternate = it->second;
        }
        break;
      case MaterialType::kGlass:
        expectStrings(p, 0);
        if (p.reals.size() != 3 && p.reals.size() != 4)
          fail(p.line, "glass '" + p.name + "' needs 3 or 4 real arguments, got " + std::to_string(p.reals.size()));
        m.color = vec(p, 0);
        if (p.reals.size() == 4) m.refractiveIndex = p.reals[3];
        break;
      case MaterialType::kDielectric:
        // Radiance reference manual: "mod dielectric id 0 0 5 rtn gtn btn n hc", transmission
        // per unit length (scene units: metres), refractive index, Hartmann constant.
        expectStrings(p, 0);
        expectReals(p, 5);
        m.color = vec(p, 0);
        m.refractiveIndex = p.reals[3];
        m.hartmannConstant = p.reals[4];
        for (int c = 0; c < 3; ++c)
          if (!(m.color[c] > 0.0 && m.color[c] <= 1.0))
            fail(p.line, "dielectric '" + p.name + "' needs a transmission per metre in (0, 1] for each channel");
        if (!(m.refractiveIndex > 0.0))
          fail(p.line, "dielectric '" + p.name + "' needs a refractive index > 0");
        break;
      case MaterialType::kGlow:
        expectStrings(p, 0);
        expectReals(p, 4);
        m.color = vec(p, 0);
        m.glowRadiusM = p.reals[3];
        break;
      case MaterialType::kVoid:
        break;
    }
    for (int c = 0; c < 3; ++c)
      if (m.color[c] < 0.0) fail(p.line, p.type + " '" + p.name + "' has a negative colour component");
    checkPhysical(p, m);
    materials_[p.name] = static_cast<int>(scene_.addMaterial(std::move(m)));
  }

  // Materials that cannot exist are refused: they would create light or give nonsense, and an
  // overflowing emitter gives NaN lux. A surface reflects and transmits at most what it receives
  // (Radiance reference manual: plastic reflects colour·(1 − spec) diffusely and spec specularly;
  // trans transmits a fraction trans of what is not reflected specularly).
  void checkPhysical(const Primitive& p, const Material& m) {
    const std::string what = p.type + " '" + p.name + "'";
    const double cmax = std::max({m.color.x, m.color.y, m.color.z});
    switch (m.type) {
      case MaterialType::kPlastic:
      case MaterialType::kMetal:
      case MaterialType::kTrans:
        if (cmax > 1.0) fail(p.line, what + " reflects more than it receives: a colour component above 1");
        if (!(m.specularity >= 0.0 && m.specularity <= 1.0)) fail(p.line, what + " needs a specularity in [0, 1]");
        if (m.roughness < 0.0) fail(p.line, what + " has a negative roughness");
        if (m.type == MaterialType::kTrans &&
            !(m.transmissivity >= 0.0 && m.transmissivity <= 1.0 && m.transmittedSpecular >= 0.0 &&
              m.transmittedSpecular <= 1.0))
          fail(p.line, what + " needs its transmission and transmitted specularity in [0, 1]");
        break;
      case MaterialType::kMirror:
      case MaterialType::kGlass:
        if (cmax > 1.0) fail(p.line, what + " transmits or reflects more than it receives: a component above 1");
        break;
      case MaterialType::kLight:
      case MaterialType::kIllum:
      case MaterialType::kGlow:
        // 1e30 W/sr/m² is far above the sun's 2e7; beyond it the light would overflow in products.
        if (cmax > kMaxRadiance) fail(p.line, what + " has a radiance above 1e30 W/sr/m2");
        break;
      default:
        break;
    }
  }

  // Geometry within 10 000 km of the origin: beyond, ray offsets and the accelerators' single
  // precision lose the surfaces (Embree aborts at ~1.8e18 m).
  void checkCoordinates(const Primitive& p) {
    for (double v : p.reals)
      if (std::abs(v) > kMaxCoordinateM)
        fail(p.line, p.type + " '" + p.name + "' has a coordinate or size beyond 1e7 m (" + std::to_string(v) + ")");
  }

  void addPolygon(const Primitive& p, uint32_t mat, Scene& target) {
    expectStrings(p, 0);
    if (p.reals.size() % 3 != 0)
      fail(p.line, "polygon '" + p.name + "' needs a multiple of 3 real arguments, got " +
                       std::to_string(p.reals.size()));
    const size_t nv = p.reals.size() / 3;
    if (nv < 3) fail(p.line, "polygon '" + p.name + "' needs at least 3 vertices, got " + std::to_string(nv));
    std::vector<Vec3> pts;
    for (size_t i = 0; i < nv; ++i) pts.push_back(vec(p, 3 * i));
    Box b;
    for (const Vec3& v : pts) b.extend(v);
    const double diameter = glm::length(b.size());
    const Vec3 nn = newellNormal(pts);
    const double area = 0.5 * glm::length(nn);
    if (!(diameter > 0.0) || area <= kDegenerateTolerance * diameter * diameter)
      fail(p.line, "polygon '" + p.name + "' is degenerate (zero area)");
    const Vec3 n = nn / (2.0 * area);
    Vec3 centroid(0.0);
    for (const Vec3& v : pts) centroid += v;
    centroid /= static_cast<double>(nv);
    for (size_t i = 0; i < nv; ++i) {
      const double off = std::abs(glm::dot(n, pts[i] - centroid));
      if (off > kPlanarTolerance * diameter) {
        std::ostringstream msg;
        msg << "polygon '" << p.name << "' is not planar: vertex " << (i + 1) << " is " << off
            << " m from its plane (tolerance 0.1 % of its size, " << kPlanarTolerance * diameter << " m)";
        fail(p.line, msg.str());
      }
    }
    target.addPolygon(pts, mat, p.name);
  }

  void checkRadius(const Primitive& p, double r) {
    if (r < 0.0) fail(p.line, p.type + " '" + p.name + "' has a negative radius");
  }

  void add(const Primitive& p) {
    const std::string& t = p.type;
    if (t == "plastic") return addMaterial(p, MaterialType::kPlastic);
    if (t == "metal") return addMaterial(p, MaterialType::kMetal);
    if (t == "trans") return addMaterial(p, MaterialType::kTrans);
    if (t == "mirror") return addMaterial(p, MaterialType::kMirror);
    if (t == "glass") return addMaterial(p, MaterialType::kGlass);
    if (t == "dielectric") return addMaterial(p, MaterialType::kDielectric);
    if (t == "light") return addMaterial(p, MaterialType::kLight);
    if (t == "illum") return addMaterial(p, MaterialType::kIllum);
    if (t == "glow") return addMaterial(p, MaterialType::kGlow);
    const bool isSurface = t == "polygon" || t == "sphere" || t == "bubble" || t == "ring" || t == "cone" ||
                           t == "cup" || t == "cylinder" || t == "tube" || t == "source";
    if (!isSurface) fail(p.line, "primitive type '" + t + "' is not supported (" + kSupported + ")");
    const int mod = modifierOf(p);
    if (t == "source") {
      expectStrings(p, 0);
      expectReals(p, 4);
      const Vec3 dir = vec(p, 0);
      if (glm::length(dir) == 0.0) fail(p.line, "source '" + p.name + "' has a zero direction");
      if (!(p.reals[3] > 0.0 && p.reals[3] <= 360.0))
        fail(p.line, "source '" + p.name + "' needs an angle in (0, 360] degrees");
      if (mod < 0) return;  // void: invisible, as in Radiance
      const MaterialType mt = scene_.materials[mod].type;
      if (mt != MaterialType::kLight && mt != MaterialType::kGlow && mt != MaterialType::kIllum)
        fail(p.line, "source '" + p.name + "' needs a light, illum or glow modifier, not " + materialTypeName(mt));
      scene_.addDistant(dir, p.reals[3], static_cast<uint32_t>(mod), p.name);
      return;
    }
    // Geometry is checked even when its modifier is void (void surfaces are invisible in Radiance).
    const uint32_t mat = mod < 0 ? 0 : static_cast<uint32_t>(mod);
    Scene probe;  // void surfaces are validated into a scratch scene and dropped
    Scene& target = mod < 0 ? probe : scene_;
    checkCoordinates(p);
    if (t == "polygon") {
      addPolygon(p, mat, target);
    } else if (t == "sphere" || t == "bubble") {
      expectStrings(p, 0);
      expectReals(p, 4);
      checkRadius(p, p.reals[3]);
      if (p.reals[3] == 0.0) fail(p.line, t + " '" + p.name + "' has a zero radius");
      target.addSphere(vec(p, 0), p.reals[3], mat, t == "bubble", p.name);
    } else if (t == "ring") {
      expectStrings(p, 0);
      expectReals(p, 8);
      checkRadius(p, p.reals[6]);
      checkRadius(p, p.reals[7]);
      if (!(p.reals[7] > p.reals[6]))
        fail(p.line, "ring '" + p.name + "' needs an outer radius larger than its inner radius");
      if (glm::length(vec(p, 3)) == 0.0) fail(p.line, "ring '" + p.name + "' has a zero normal");
      target.addRing(vec(p, 0), vec(p, 3), p.reals[6], p.reals[7], mat, p.name);
    } else {
      const bool isCone = t == "cone" || t == "cup";
      expectStrings(p, 0);
      expectReals(p, isCone ? 8 : 7);
      const double ra = p.reals[6];
      const double rb = isCone ? p.reals[7] : p.reals[6];
      checkRadius(p, ra);
      checkRadius(p, rb);
      if (ra == 0.0 && rb == 0.0) fail(p.line, t + " '" + p.name + "' has zero radii");
      if (glm::length(vec(p, 3) - vec(p, 0)) == 0.0) fail(p.line, t + " '" + p.name + "' has zero length");
      target.addCone(vec(p, 0), vec(p, 3), ra, rb, mat, t == "cup" || t == "tube", p.name);
    }
  }

  Tokenizer tok_;
  Scene& scene_;
  std::unordered_map<std::string, int> materials_;
};

}  // namespace

void readRadianceText(std::string_view text, const std::string& fileName, Scene& scene) {
  Reader(text, fileName, scene).run();
}

void readRadianceFile(const std::filesystem::path& path, Scene& scene) {
  readRadianceText(readInputFile(path, "scene file"), path.string(), scene);
}

}  // namespace candela
