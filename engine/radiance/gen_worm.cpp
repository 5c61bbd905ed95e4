// genworm(1), interpreted: `genworm mat name 'x(t)' 'y(t)' 'z(t)' 'r(t)' nseg [-e expr] [-f file]`,
// a string of varying thickness along the curve (x, y, z)(t), t from 0 to 1 in nseg segments: a
// sphere name.s<i> at each of the nseg + 1 points and, between neighbours, a cylinder name.c<i>
// where the radius stays (within 1e-6) or a cone tangent to both spheres where it changes. The
// primitives, names and the cones' tangent construction are those of Radiance's
// src/gen/genworm.c (facts of its output); the functions are the function language's; the code is
// candela's.
#include "engine/radiance/gen.h"

#include <cmath>

namespace candela {
namespace {

constexpr double kTiny = 1e-6;          // genworm.c's FTINY
constexpr long kMaxSegments = 1000000;  // the bound on what one command may make

}  // namespace

std::vector<RadPrimitive> expandGenworm(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::vector<std::string>& w = cmd.words;
  auto fail = [&](const std::string& msg) -> void { throw InputError(cmd.loc, "genworm: " + msg); };
  if (w.size() < 8) fail("usage: genworm material name 'x(t)' 'y(t)' 'z(t)' 'r(t)' nseg [-e expr] [-f file]");
  const std::string& mat = w[1];
  const std::string& name = w[2];
  FunctionFiles files;
  cal::Program& program = *files.program();
  readFunctionOptions(cmd, ctx, 8, files, nullptr);
  static const char* const kName[] = {"`genworm.x", "`genworm.y", "`genworm.z", "`genworm.r"};
  static const char* const kWhat[] = {"x(t)", "y(t)", "z(t)", "r(t)"};
  cal::Symbol f[4];
  for (size_t k = 0; k < 4; ++k) f[k] = defineGeneratorFunction(program, cmd, kName[k], "t", 1, w[3 + k], kWhat[k]);
  // nseg as genworm reads it (atoi): a whole number.
  char* end = nullptr;
  const long nseg = std::strtol(w[7].c_str(), &end, 10);
  if (end == w[7].c_str() || *end != '\0' || nseg < 1 || nseg > kMaxSegments)
    fail("the number of segments must be a whole number from 1 to " + std::to_string(kMaxSegments) + ", got '" +
         w[7] + "'");
  cal::Evaluator eval(program);
  std::vector<RadPrimitive> out;
  Vec3 lastp(0.0);
  double lastr = 0.0;
  for (long i = 0; i <= nseg; ++i) {
    const double t[] = {static_cast<double>(i) / static_cast<double>(nseg)};
    double v[4];
    for (int k = 0; k < 4; ++k) {
      eval.begin({});
      v[k] = eval.call(f[k], t);
      if (!std::isfinite(v[k])) fail(std::string(kWhat[k]) + " is not a finite number at t = " + std::to_string(t[0]));
    }
    const Vec3 p(v[0], v[1], v[2]);
    const double r = v[3];
    if (r < 0.0) fail("r(t) is negative at t = " + std::to_string(t[0]) + " (genworm forbids negative radii)");
    if (i > 0) {
      const std::string id = name + ".c" + std::to_string(i);
      if (std::abs(lastr - r) <= kTiny) {
        out.push_back(generatedPrimitive(mat, "cylinder", id, cmd.loc, {},
                                         {lastp.x, lastp.y, lastp.z, p.x, p.y, p.z, r}));
      } else {
        // The cone tangent to both spheres: its ends moved along the axis by f·r, its radii
        // scaled by √(1 − (r0 − r1) f), f = (r0 − r1)/|p1 − p0|².
        const Vec3 d = p - lastp;
        const double d2 = glm::dot(d, d);
        if (!(d2 > 0.0)) fail("two points of the curve coincide where the radius changes (t = " + std::to_string(t[0]) + ")");
        double g = (lastr - r) / d2;
        const Vec3 a = lastp + g * lastr * d, b = p + g * r * d;
        g = 1.0 - (lastr - r) * g;
        g = g <= 0.0 ? 0.0 : std::sqrt(g);
        out.push_back(generatedPrimitive(mat, "cone", id, cmd.loc, {}, {a.x, a.y, a.z, b.x, b.y, b.z, g * lastr, g * r}));
      }
    }
    out.push_back(generatedPrimitive(mat, "sphere", name + ".s" + std::to_string(i), cmd.loc, {}, {p.x, p.y, p.z, r}));
    lastp = p;
    lastr = r;
  }
  return out;
}

}  // namespace candela
