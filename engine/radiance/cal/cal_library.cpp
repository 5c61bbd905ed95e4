// The library every .cal file sees, as Radiance provides it: calcomp's native functions, the ray
// library's (noise, arg), the ray's variables, and the definitions Radiance keeps in rayinit.cal
// (the names and their meaning from its list; written here in candela's own terms).
#include "engine/radiance/cal/cal_impl.h"

namespace candela::cal {
namespace {

struct NativeName {
  const char* name;
  Native native;
  int arity;  // -1: one or more
};

constexpr NativeName kNatives[] = {
    {"if", Native::kIf, 3},         {"select", Native::kSelect, -1}, {"min", Native::kMin, -1},
    {"max", Native::kMax, -1},      {"rand", Native::kRand, 1},      {"floor", Native::kFloor, 1},
    {"ceil", Native::kCeil, 1},     {"sqrt", Native::kSqrt, 1},      {"sin", Native::kSin, 1},
    {"cos", Native::kCos, 1},       {"tan", Native::kTan, 1},        {"asin", Native::kAsin, 1},
    {"acos", Native::kAcos, 1},     {"atan", Native::kAtan, 1},      {"atan2", Native::kAtan2, 2},
    {"exp", Native::kExp, 1},       {"log", Native::kLog, 1},        {"log10", Native::kLog10, 1},
    {"erf", Native::kErf, 1},       {"erfc", Native::kErfc, 1},      {"noise3", Native::kNoise3, 3},
    {"noise3x", Native::kNoise3x, 3}, {"noise3y", Native::kNoise3y, 3}, {"noise3z", Native::kNoise3z, 3},
    {"fnoise3", Native::kFnoise3, 3}, {"arg", Native::kArg, 1},
};
static_assert(std::size(kNatives) == static_cast<size_t>(Native::kCount), "every native function named once");

constexpr const char* kRayVarNames[kRayVarCount] = {
    "Dx", "Dy", "Dz", "Nx", "Ny", "Nz", "Px", "Py", "Pz", "T", "Ts", "Rdot", "S", "Tx", "Ty", "Tz",
    "Ix", "Iy", "Iz", "Jx", "Jy", "Jz", "Kx", "Ky", "Kz", "Lu", "Lv", "NxP", "NyP", "NzP", "RdotP",
    "CrP", "CgP", "CbP"};

// The definitions of Radiance's rayinit.cal, by name and meaning (Radiance reference manual and
// rayinit.cal's own list), written for candela. Names with a context mark (`) are internal.
constexpr const char* kLibrary = R"cal(
{ the primitive's real arguments }
AC = arg(0);
A1 = arg(1); A2 = arg(2); A3 = arg(3); A4 = arg(4); A5 = arg(5);
A6 = arg(6); A7 = arg(7); A8 = arg(8); A9 = arg(9); A10 = arg(10);
{ vectors by component: i = 1, 2, 3 }
D(i) = select(i, Dx, Dy, Dz);
N(i) = select(i, Nx, Ny, Nz);
P(i) = select(i, Px, Py, Pz);
noise3a(x, y, z) : noise3x(x, y, z);
noise3b(x, y, z) : noise3y(x, y, z);
noise3c(x, y, z) : noise3z(x, y, z);
noise3d(i, x, y, z) : select(i, noise3x(x, y, z), noise3y(x, y, z), noise3z(x, y, z));
{ constants }
PI : 3.14159265358979323846;
DEGREE : PI / 180;
FTINY : 1e-7;
{ x limited to [lo, hi] }
bound(lo, x, hi) : if(lo - x, lo, if(x - hi, hi, x));
{ library functions safe over every real }
Acos(x) : acos(bound(-1, x, 1));
Asin(x) : asin(bound(-1, x, 1));
Atan2(y, x) : if(x * x + y * y, atan2(y, x), 0);
Exp(x) : if(-100 - x, 0, exp(x));
Sqrt(x) : if(x, sqrt(x), 0);
{ logic on signs: positive is true }
and(a, b) : if(a, b, a);
or(a, b) : if(a, a, b);
not(a) : if(a, -1, 1);
xor(a, b) : if(a, not(b), b);
abs(x) : if(x, x, -x);
sgn(x) : if(x, 1, if(-x, -1, 0));
sq(x) : x * x;
inside(lo, x, hi) : and(x - lo, hi - x);
frac(x) : x - floor(x);
mod(n, d) : n - d * floor(n / d);
tri(n, d) : abs(d - mod(n - d, 2 * d));
linterp(t, a, b) : a + t * (b - a);
noop(v) : v;
clip(v) : bound(0, v, 1);
noneg(v) : max(v, 0);
red(r, g, b) : noneg(r);
green(r, g, b) : noneg(g);
blue(r, g, b) : noneg(b);
grey(r, g, b) : noneg(.265074126 * r + .670114631 * g + .064811243 * b);
clip_r(r, g, b) : clip(r);
clip_g(r, g, b) : clip(g);
clip_b(r, g, b) : clip(b);
clipgrey(r, g, b) : min(grey(r, g, b), 1);
{ vectors passed as functions of their component index }
dot(u, v) : u(1) * v(1) + u(2) * v(2) + u(3) * v(3);
cross(i, u, v) : select(i, u(2) * v(3) - u(3) * v(2), u(3) * v(1) - u(1) * v(3), u(1) * v(2) - u(2) * v(1));
{ a value that fades from near to far over distance d: near within 0, far beyond 16 }
fade(near, far, d) : far + if(16 - d, (near - far) / (1 + d * d), 0);
{ cubic curves of parameter t in [0, 1]: Hermite (end values p0, p1 and slopes r0, r1),
  Bezier (control points p1..p4), uniform B-spline (points pp, p0, p1, pn) }
hermite(p0, p1, r0, r1, t) : p0 * (1 + t * t * (2 * t - 3)) + p1 * t * t * (3 - 2 * t)
                           + r0 * t * (1 - t) * (1 - t) + r1 * t * t * (t - 1);
bezier(p1, p2, p3, p4, t) : p1 * (1 - t) * (1 - t) * (1 - t) + 3 * p2 * t * (1 - t) * (1 - t)
                          + 3 * p3 * t * t * (1 - t) + p4 * t * t * t;
bspline(pp, p0, p1, pn, t) : (pp * (1 - t) * (1 - t) * (1 - t) + p0 * (3 * t * t * t - 6 * t * t + 4)
                           + p1 * (-3 * t * t * t + 3 * t * t + 3 * t + 1) + pn * t * t * t) / 6;
{ turbulence: noise summed over octaves from scale s down to 1 }
turbulence(x, y, z, s) : if(s - 1.01, 0, abs(noise3(x / s, y / s, z / s) * s) + turbulence(x, y, z, 2 * s));
turbulencex(x, y, z, s) : if(s - 1.01, 0, sgn(noise3(x / s, y / s, z / s)) * noise3x(x / s, y / s, z / s)
                        + turbulencex(x, y, z, 2 * s));
turbulencey(x, y, z, s) : if(s - 1.01, 0, sgn(noise3(x / s, y / s, z / s)) * noise3y(x / s, y / s, z / s)
                        + turbulencey(x, y, z, 2 * s));
turbulencez(x, y, z, s) : if(s - 1.01, 0, sgn(noise3(x / s, y / s, z / s)) * noise3z(x / s, y / s, z / s)
                        + turbulencez(x, y, z, 2 * s));
{ a normal deviate from a uniform one (Abramowitz and Stegun 26.2.23, error below 4.5e-4) }
ndev`(t) : t - (2.515517 + t * (.802853 + t * .010328)) / (1 + t * (1.432788 + t * (.189269 + t * .001308)));
ntail`(p) : ndev`(sqrt(-2 * log(p)));
unif2norm(p) : if(.5 - p, -ntail`(p), ntail`(1 - p));
nrand(x) = unif2norm(rand(x));
{ local (u, v) on planar surfaces: U measured from the projected z axis, N = U x V }
nxy` = Nx * Nx + Ny * Ny;
U = if(nxy` - FTINY, (Py * Nx - Px * Ny) / nxy`, Px);
V = if(nxy` - FTINY, Pz - Nz * (Px * Nx + Py * Ny) / nxy`, Py);
{ *func and *data materials: a frame from the perturbed normal and the up vector of the last three
  real arguments, directions away from the surface in it }
upx` = arg(AC - 1) * NzP - arg(AC) * NyP;
upy` = arg(AC) * NxP - arg(AC - 2) * NzP;
upz` = arg(AC - 2) * NyP - arg(AC - 1) * NxP;
upn` = 1 / sqrt(upx` * upx` + upy` * upy` + upz` * upz`);
vx` = upx` * upn`; vy` = upy` * upn`; vz` = upz` * upn`;
ux` = NyP * vz` - NzP * vy`; uy` = NzP * vx` - NxP * vz`; uz` = NxP * vy` - NyP * vx`;
Ldx(dx, dy, dz) = dx * ux` + dy * uy` + dz * uz`;
Ldy(dx, dy, dz) = dx * vx` + dy * vy` + dz * vz`;
Ldz(dx, dy, dz) = dx * NxP + dy * NyP + dz * NzP;
Idx = Ldx(-Dx, -Dy, -Dz);
Idy = Ldy(-Dx, -Dy, -Dz);
Idz = RdotP;
)cal";

// The function files Radiance's generators name in what they write (gensurf -s, genrev -s, and
// the smoothed triangles of genbox -s and obj2rad), which a Radiance installation keeps in its
// library folder: their names and what they compute (the shading normal by Phong interpolation)
// are facts of that output; written here for candela.
struct LibraryFile {
  const char* name;
  const char* text;
};
constexpr LibraryFile kLibraryFiles[] = {
    // A1 the dominant axis (0, 1, 2: x, y, z); the perturbation is M [u v, u, v, 1], u and v the
    // point's two other coordinates in cyclic order, M's columns A2..A4, A5..A7, A8..A10, A11..A13.
    {"surf.cal", R"cal(
surf_u = select(arg(1) + 1, Py, Pz, Px);
surf_v = select(arg(1) + 1, Pz, Px, Py);
surf_dx = surf_u * surf_v * arg(2) + surf_u * arg(5) + surf_v * arg(8) + arg(11);
surf_dy = surf_u * surf_v * arg(3) + surf_u * arg(6) + surf_v * arg(9) + arg(12);
surf_dz = surf_u * surf_v * arg(4) + surf_u * arg(7) + surf_v * arg(10) + arg(13);
)cal"},
    // About the z axis: the radial part A3 r + A4 along the point's radial direction, the axial
    // part A1 z + A2.
    {"rev.cal", R"cal(
rev_rad = sqrt(Px * Px + Py * Py);
rev_dr = A3 * rev_rad + A4;
rev_dx = rev_dr * Px / rev_rad;
rev_dy = rev_dr * Py / rev_rad;
rev_dz = A1 * Pz + A2;
)cal"},
    // A triangle's normals by barycentric interpolation: A1 the dominant axis, then for each world
    // component a row (a, b, c) of a u + b v + c, u and v as in surf.cal; the perturbation turns
    // the normal to the interpolated one. u, v: the first two rows' values modulo 1 (tiled
    // texture coordinates, for patterns that use them).
    {"tmesh.cal", R"cal(
bu = select(arg(1) + 1, Py, Pz, Px);
bv = select(arg(1) + 1, Pz, Px, Py);
v1 = arg(2) * bu + arg(3) * bv + arg(4);
v2 = arg(5) * bu + arg(6) * bv + arg(7);
v3 = arg(8) * bu + arg(9) * bv + arg(10);
nf = 1 / sqrt(v1 * v1 + v2 * v2 + v3 * v3);
dx = v1 * nf - Nx;
dy = v2 * nf - Ny;
dz = v3 * nf - Nz;
u = frac(v1);
v = frac(v2);
)cal"},
};

}  // namespace

std::optional<std::string_view> libraryFile(std::string_view name) {
  for (const LibraryFile& f : kLibraryFiles)
    if (name == f.name) return std::string_view(f.text);
  return std::nullopt;
}

int nativeArity(Native n) {
  for (const NativeName& e : kNatives)
    if (e.native == n) return e.arity;
  return 0;
}

void addLibrary(Program::Impl& p) {
  for (const NativeName& e : kNatives) p.symbols[static_cast<size_t>(p.intern(e.name))].native = e.native;
  for (int i = 0; i < kRayVarCount; ++i) p.symbols[static_cast<size_t>(p.intern(kRayVarNames[i]))].rayVar = i;
  parseText(p, kLibrary, "<candela library>");
}

}  // namespace candela::cal
