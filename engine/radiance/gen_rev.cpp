// genrev(1), interpreted: `genrev mat name 'z(t)' 'r(t)' nseg [-e expr] [-f file] [-s]`, the
// surface of revolution of the curve (r(t), z(t)), t from 0 to 1 in nseg segments, about the z
// axis. The functions are Radiance's function language (engine/radiance/cal/); the primitives,
// their names (name.1 … name.nseg) and orientation are those Radiance's src/gen/genrev.c writes:
// a cone where z rises and r changes, a cup where z falls, a cylinder or tube where r stays, a
// ring where z stays (facing down when r grows, up when it shrinks), nothing where neither
// changes. With -s each piece is modified by its own texfunc `Phong` of rev.cal (the material's
// pattern, as genrev.c writes it: `mat texfunc Phong`, then `Phong cone ...`): the shading normal
// turns from the bisector with the piece before at one end to the bisector with the piece after
// at the other (docs/engine.md). The code is candela's.
#include "engine/radiance/gen.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

constexpr double kTiny = 1e-9;          // genrev.c's FTINY: a change smaller than this is none
constexpr int kMaxSegments = 1000000;   // the bound on what one command may make
const std::string kPhong = "Phong";     // the name of genrev -s's texture of each piece

}  // namespace

std::vector<RadPrimitive> expandGenrev(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::vector<std::string>& w = cmd.words;
  auto fail = [&](const std::string& msg) -> void { throw InputError(cmd.loc, "genrev: " + msg); };
  if (w.size() < 6) fail("usage: genrev material name 'z(t)' 'r(t)' nseg [-e expr] [-f file] [-s]");
  const std::string& mat = w[1];
  const std::string& name = w[2];
  FunctionFiles files;
  cal::Program& program = *files.program();
  bool smooth = false;
  readFunctionOptions(cmd, ctx, 6, files, &smooth);
  // z and r as functions of t: each expression the body of a definition with the parameter t.
  const cal::Symbol zf = defineGeneratorFunction(program, cmd, "`genrev.zf", "t", 1, w[3], "z(t)");
  const cal::Symbol rf = defineGeneratorFunction(program, cmd, "`genrev.rf", "t", 1, w[4], "r(t)");
  cal::Symbol nName = -1;
  try {
    nName = program.addExpression(w[5], "`genrev.n", cmd.loc);
  } catch (const InputError& e) {
    fail("nseg '" + w[5] + "' is not an expression: " + e.message());
  }
  program.check("`genrev.n", -1, cmd.loc, w[5]);
  cal::Evaluator eval(program);
  eval.begin({});
  const double nsegValue = eval.value(nName) + 0.5;
  if (!(nsegValue >= 1.0 && nsegValue <= kMaxSegments))
    fail("the number of segments must be 1 to " + std::to_string(kMaxSegments) + ", got " + w[5]);
  const int nseg = static_cast<int>(nsegValue);
  auto at_t = [&](int i, double& z, double& r) {
    const double t[] = {static_cast<double>(i) / nseg};
    eval.begin({});
    z = eval.call(zf, t);
    eval.begin({});
    r = eval.call(rf, t);
    if (!std::isfinite(z) || !std::isfinite(r)) fail("z(t) or r(t) is not a finite number at t = " + std::to_string(t[0]));
    if (r < 0.0) fail("r(t) is negative at t = " + std::to_string(t[0]) + " (genrev forbids negative radii)");
  };
  // The unit normal (n_z, n_r) of the piece from (z0, r0) to (z1, r1): (0, 0) when it has no length.
  auto normal = [](double z0, double r0, double z1, double r1, double& nz, double& nr) {
    const double dz = r0 - r1, dr = z1 - z0, len = std::sqrt(dr * dr + dz * dz);
    nz = len > 0.0 ? dz / len : 0.0;
    nr = len > 0.0 ? dr / len : 0.0;
  };
  std::vector<RadPrimitive> out;
  double lastz = 0.0, lastr = 0.0, z = 0.0, r = 0.0;
  at_t(0, lastz, lastr);
  at_t(1, z, r);
  double lastnz = 0.0, lastnr = 0.0, nz = 0.0, nr = 0.0;  // the pieces' normals: before, this one
  normal(lastz, lastr, z, r, nz, nr);
  for (int i = 1; i <= nseg; ++i) {
    double nextz = 0.0, nextr = 0.0, nextnz = 0.0, nextnr = 0.0;  // the piece after (none after the last)
    if (i < nseg) {
      at_t(i + 1, nextz, nextr);
      normal(z, r, nextz, nextr, nextnz, nextnr);
    }
    const bool down = z < lastz - kTiny, up = z > lastz + kTiny;
    const bool in = r < lastr - kTiny, outward = r > lastr + kTiny;
    const std::string id = name + "." + std::to_string(i);
    const std::string& modifier = smooth ? kPhong : mat;
    if ((down || up || in || outward) && smooth) {
      // rev.cal's A1 z + A2 and A3 r + A4: the neighbours' normals, linear along the piece.
      const double az = down || up ? (nextnz - lastnz) / (z - lastz) : 0.0;
      const double bz = down || up ? lastnz - az * lastz : (in ? 1.0 : -1.0);
      const double ar = in || outward ? (nextnr - lastnr) / (r - lastr) : 0.0;
      const double br = in || outward ? lastnr - ar * lastr : (up ? 1.0 : -1.0);
      out.push_back(generatedPrimitive(mat, "texfunc", kPhong, cmd.loc, {"rev_dx", "rev_dy", "rev_dz", "rev.cal"},
                                       {az, bz, ar, br}));
    }
    if (!(down || up)) {
      if (in || outward)  // a ring at z, its radii in order, facing up where r shrinks
        out.push_back(generatedPrimitive(modifier, "ring", id, cmd.loc, {},
                                         {0, 0, z, 0, 0, in ? 1.0 : -1.0, std::min(lastr, r), std::max(lastr, r)}));
    } else if (!(in || outward)) {
      out.push_back(generatedPrimitive(modifier, down ? "tube" : "cylinder", id, cmd.loc, {}, {0, 0, lastz, 0, 0, z, r}));
    } else {
      out.push_back(generatedPrimitive(modifier, down ? "cup" : "cone", id, cmd.loc, {}, {0, 0, lastz, 0, 0, z, lastr, r}));
    }
    lastz = z, lastr = r, z = nextz, r = nextr;
    lastnz = nz, lastnr = nr, nz = nextnz, nr = nextnr;
  }
  return out;
}

}  // namespace candela
