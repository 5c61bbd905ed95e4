// Closed-form and quadrature references for the validation cases. Written independently of the
// engine's estimators (no shared code), so that agreement means something.
// All radiances are Radiance values in W/sr/m² per channel; results are irradiances in W/m²
// (multiply by 179 lm/W for lux on a grey scene).
#pragma once

namespace candela::analytic {

// Small spherical source of radiance L and radius r (m) whose centre is d (m) from the receiver,
// at angle θ from its normal, wholly above its horizon: E = π L r² cos θ / d².
double sphereSource(double radiance, double radiusM, double distanceM, double cosTheta);

// Lambertian rectangle a × b (m) parallel to the receiver at height h (m), the receiver below one
// corner: the differential-area-to-parallel-rectangle configuration factor (e.g. Howell's
// catalogue of configuration factors, case B-3):
// F = 1/(2π) [A/√(1+A²) atan(B/√(1+A²)) + B/√(1+B²) atan(A/√(1+B²))], A = a/h, B = b/h;
// E = π L F.
double rectangleCorner(double radiance, double aM, double bM, double hM);

// An axis-aligned rectangle [x0, x1] × [y0, y1] (m) in a horizontal plane; corners (x0, y0) and
// (x1, y1).
struct RectXY {
  double x0, y0, x1, y1;
};

// Receiver at (x, y) under rectangle r at height h (m) above it, by superposition of four corner
// rectangles (signed).
double rectangleAbove(double radiance, const RectXY& r, double hM, double x, double y);

// Coaxial Lambertian disk of radius R at distance h: E = π L R² / (R² + h²).
double coaxialDisk(double radiance, double radiusM, double hM);

// Uniform sky of radiance L over an unobstructed horizontal plane: E = π L.
double uniformSky(double radiance);

// The paper's check: a Lambertian sphere (radius R, reflectance ρ) resting on an infinite black
// plane under a uniform sky of radiance L; a horizontal sensor at height h above the plane, x from
// the contact point. A point of the sphere with normal n sees the sky over the half of its
// hemisphere above the horizon, irradiance π L (1 + n_z)/2 (the plane is black and the sphere
// convex), so its radiance is ρ L (1 + n_z)/2. The sensor's irradiance
// E = ∫ L(ω) cos θ dω is integrated by the midpoint rule in (sin²θ, φ), which makes cos θ dω
// uniform; `n` cells per axis (n² rays).
double sphereOnPlane(double rho, double skyRadiance, double radiusM, double xM, double hM, int n = 3000);

// Illuminance (lux) at p on a sensor with unit normal (nx, ny, nz) through a parallelogram
// aperture (corner c, edges u and v, m) under the CIE overcast sky of horizontal illuminance eh
// (lux), nothing else visible: E = ∫ L(ω) max(0, cos ι) |cos θ_a| / r² dA with the Moon–Spencer
// luminance L = Lz (1 + 2 sin h)/3, Lz = 9 eh/(7π), and L = 0 below the horizon; midpoint rule
// on n × n cells.
double overcastAperture(const double p[3], const double normal[3], const double c[3], const double u[3],
                        const double v[3], double eh, int n);

// Integrating sphere (closed, uniform reflectance ρ): with direct irradiance E_d everywhere on the
// wall, the total is E_d / (1 − ρ) (geometric series of interreflections).
double integratingSphere(double directIrradiance, double rho);

}  // namespace candela::analytic
