#include "photometry/photometric_web.h"

#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace candela {

namespace {

constexpr double kAngleEps = 1e-6;  // deg; angles closer than this are the same plane

double wrap360(double deg) {
  double c = std::fmod(deg, 360.0);
  if (c < 0.0) c += 360.0;
  if (c >= 360.0 - kAngleEps) c = 0.0;
  return c;
}

// Index i of the grid cell [a[i], a[i+1]] holding x (a sorted, size >= 2), and the fraction.
std::pair<size_t, double> cell(const std::vector<double>& a, double x) {
  const auto it = std::upper_bound(a.begin(), a.end(), x);
  size_t i = it == a.begin() ? 0 : size_t(it - a.begin()) - 1;
  if (i + 1 >= a.size()) i = a.size() - 2;
  const double t = (x - a[i]) / (a[i + 1] - a[i]);
  return {i, std::clamp(t, 0.0, 1.0)};
}

// Mirrors a grid axis about 0: angles {0, a1, ...} become {-an, ..., -a1, 0, a1, ..., an}.
// `rows` are the slices along that axis (one per angle).
void mirrorAboutZero(std::vector<double>& angles, std::vector<std::vector<double>>& rows) {
  std::vector<double> a;
  std::vector<std::vector<double>> r;
  for (size_t k = angles.size(); k-- > 1;) {
    a.push_back(-angles[k]);
    r.push_back(rows[k]);
  }
  a.insert(a.end(), angles.begin(), angles.end());
  r.insert(r.end(), rows.begin(), rows.end());
  angles = std::move(a);
  rows = std::move(r);
}

}  // namespace

const char* openingShapeName(OpeningShape shape) {
  switch (shape) {
    case OpeningShape::kPoint: return "point";
    case OpeningShape::kRectangular: return "rectangular";
    case OpeningShape::kRectangularWithSides: return "rectangular with luminous sides";
    case OpeningShape::kCircular: return "circular";
    case OpeningShape::kEllipse: return "ellipse";
    case OpeningShape::kVerticalCylinder: return "vertical cylinder";
    case OpeningShape::kVerticalEllipticalCylinder: return "vertical elliptical cylinder";
    case OpeningShape::kSphere: return "sphere";
    case OpeningShape::kEllipsoid: return "ellipsoid";
    case OpeningShape::kHorizontalCylinderAlongWidth: return "horizontal cylinder along C0-C180";
    case OpeningShape::kHorizontalCylinderAlongLength: return "horizontal cylinder along C90-C270";
    case OpeningShape::kVerticalCircle: return "vertical circle";
    case OpeningShape::kVerticalEllipse: return "vertical ellipse";
    case OpeningShape::kOther: return "other";
  }
  return "other";
}

PhotometricWeb::PhotometricWeb(PhotometricInfo info, PhotometricType type, PlaneSymmetry symmetry,
                               std::vector<double> planeAnglesDeg,
                               std::vector<double> polarAnglesDeg, std::vector<double> candelaCd)
    : info_(std::move(info)), type_(type) {
  const size_t np = planeAnglesDeg.size(), nq = polarAnglesDeg.size();
  if (np == 0 || nq < 2 || candelaCd.size() != np * nq)
    throw std::invalid_argument("PhotometricWeb: inconsistent grid sizes");
  std::vector<std::vector<double>> rows(np);
  for (size_t i = 0; i < np; ++i)
    rows[i].assign(candelaCd.begin() + long(i * nq), candelaCd.begin() + long((i + 1) * nq));

  if (type == PhotometricType::kC) {
    std::vector<std::pair<double, size_t>> planes;  // (C in [0,360), source row)
    if (symmetry == PlaneSymmetry::kRotational || np == 1) {
      for (double c : {0.0, 90.0, 180.0, 270.0}) planes.push_back({c, 0});
    } else {
      // The symmetry group of the stored half or quadrant (CIE 121 / LM-63 symmetries).
      std::vector<double (*)(double)> ops = {[](double c) { return c; }};
      if (symmetry == PlaneSymmetry::kMirrorC0C180 || symmetry == PlaneSymmetry::kQuadrant)
        ops.push_back([](double c) { return -c; });
      if (symmetry == PlaneSymmetry::kMirrorC90C270 || symmetry == PlaneSymmetry::kQuadrant)
        ops.push_back([](double c) { return 180.0 - c; });
      if (symmetry == PlaneSymmetry::kQuadrant) ops.push_back([](double c) { return 180.0 + c; });
      for (auto op : ops)
        for (size_t i = 0; i < np; ++i) planes.push_back({wrap360(op(planeAnglesDeg[i])), i});
    }
    std::stable_sort(planes.begin(), planes.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<double> angles;
    std::vector<std::vector<double>> expanded;
    for (const auto& [c, i] : planes) {
      if (!angles.empty() && c - angles.back() < kAngleEps) continue;  // a plane mapped onto itself
      angles.push_back(c);
      expanded.push_back(rows[i]);
    }
    if (angles.front() > kAngleEps)
      throw std::invalid_argument("PhotometricWeb: C planes do not include C0");
    angles.push_back(360.0);  // periodic closure: the interpolant wraps from the last plane to C0
    expanded.push_back(expanded.front());
    planeAnglesDeg = std::move(angles);
    rows = std::move(expanded);
  } else {
    // LM-63 type B: horizontal angles 0..90 mean a laterally symmetric luminaire; vertical
    // angles 0..90 are taken as symmetric about the horizontal plane (docs/luminaires.md).
    if (planeAnglesDeg.front() == 0.0 && np > 1) mirrorAboutZero(planeAnglesDeg, rows);
    if (polarAnglesDeg.front() == 0.0) {
      // Mirror along the polar axis: transpose, mirror, transpose back.
      std::vector<std::vector<double>> cols(nq, std::vector<double>(rows.size()));
      for (size_t i = 0; i < rows.size(); ++i)
        for (size_t j = 0; j < nq; ++j) cols[j][i] = rows[i][j];
      mirrorAboutZero(polarAnglesDeg, cols);
      for (size_t i = 0; i < rows.size(); ++i) {
        rows[i].resize(cols.size());
        for (size_t j = 0; j < cols.size(); ++j) rows[i][j] = cols[j][i];
      }
    }
    if (planeAnglesDeg.size() < 2)
      throw std::invalid_argument("PhotometricWeb: type B needs at least two horizontal angles");
  }

  planes_ = std::move(planeAnglesDeg);
  polar_ = std::move(polarAnglesDeg);
  cd_.clear();
  cd_.reserve(planes_.size() * polar_.size());
  for (const auto& r : rows) cd_.insert(cd_.end(), r.begin(), r.end());

  // The interpolant's maximum sits on a grid node.
  maxCd_ = -1.0;
  for (size_t i = 0; i < planes_.size(); ++i)
    for (size_t j = 0; j < polar_.size(); ++j)
      if (gridCd(i, j) > maxCd_) {
        maxCd_ = gridCd(i, j);
        if (type_ == PhotometricType::kC) {
          maxDir_ = {planes_[i], polar_[j]};
        } else {
          const double h = degToRad(planes_[i]), v = degToRad(polar_[j]);
          maxDir_ = cGammaOf(Vec3(std::cos(h) * std::sin(v), std::sin(h), -std::cos(h) * std::cos(v)));
        }
      }
}

Vec3 PhotometricWeb::directionOf(double cDeg, double gammaDeg) {
  const double c = degToRad(cDeg), g = degToRad(gammaDeg);
  return {std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), -std::cos(g)};
}

CGamma PhotometricWeb::cGammaOf(const Vec3& dirLocal) {
  const Vec3 d = glm::normalize(dirLocal);
  CGamma r;
  r.gammaDeg = radToDeg(std::acos(std::clamp(-d.z, -1.0, 1.0)));
  r.cDeg = (d.x == 0.0 && d.y == 0.0) ? 0.0 : wrap360(radToDeg(std::atan2(d.y, d.x)));
  return r;
}

double PhotometricWeb::gridInterp(double planeDeg, double polarDeg) const {
  if (cd_.empty()) return 0.0;
  if (polarDeg < polar_.front() - kAngleEps || polarDeg > polar_.back() + kAngleEps) return 0.0;
  if (type_ == PhotometricType::kC) {
    planeDeg = wrap360(planeDeg);
  } else if (planeDeg < planes_.front() - kAngleEps || planeDeg > planes_.back() + kAngleEps) {
    return 0.0;
  }
  const auto [i, s] = cell(planes_, planeDeg);
  const auto [j, t] = cell(polar_, polarDeg);
  const double a = gridCd(i, j) * (1.0 - t) + gridCd(i, j + 1) * t;
  const double b = gridCd(i + 1, j) * (1.0 - t) + gridCd(i + 1, j + 1) * t;
  return a * (1.0 - s) + b * s;
}

double PhotometricWeb::intensityCd(double cDeg, double gammaDeg) const {
  if (type_ == PhotometricType::kC) return gridInterp(cDeg, gammaDeg);
  return intensityCd(directionOf(cDeg, gammaDeg));
}

double PhotometricWeb::intensityCd(const Vec3& dirLocal) const {
  const double len = glm::length(dirLocal);
  if (!(len > 0.0)) return 0.0;
  if (type_ == PhotometricType::kC) {
    const CGamma cg = cGammaOf(dirLocal);
    return gridInterp(cg.cDeg, cg.gammaDeg);
  }
  const Vec3 d = dirLocal / len;
  const double hDeg = radToDeg(std::asin(std::clamp(d.y, -1.0, 1.0)));
  const double vDeg = radToDeg(std::atan2(d.x, -d.z));
  return gridInterp(hDeg, vDeg);
}

double PhotometricWeb::lumensBetween(double gamma0Deg, double gamma1Deg) const {
  if (cd_.empty() || gamma1Deg <= gamma0Deg) return 0.0;
  if (type_ == PhotometricType::kC) {
    // Exact integral of the bilinear interpolant: over C each cell is linear, so its integral is
    // the trapezoid S(gamma_j); over gamma the linear weights are integrated against sin(gamma)
    // in closed form: int v sin g dg = [-(g - g0) cos g + sin g] / dg, v = (g - g0) / dg.
    const size_t nq = polar_.size();
    std::vector<double> sum(nq, 0.0);
    for (size_t i = 0; i + 1 < planes_.size(); ++i) {
      const double dc = degToRad(planes_[i + 1] - planes_[i]);
      for (size_t j = 0; j < nq; ++j) sum[j] += dc * 0.5 * (gridCd(i, j) + gridCd(i + 1, j));
    }
    double flux = 0.0;
    for (size_t j = 0; j + 1 < nq; ++j) {
      const double lo = std::max(gamma0Deg, polar_[j]), hi = std::min(gamma1Deg, polar_[j + 1]);
      if (!(hi > lo)) continue;
      const double g0 = degToRad(polar_[j]), dg = degToRad(polar_[j + 1] - polar_[j]);
      const double a = degToRad(lo), b = degToRad(hi);
      const auto prim = [g0](double g) { return -(g - g0) * std::cos(g) + std::sin(g); };
      const double w1 = (prim(b) - prim(a)) / dg;
      const double w0 = (std::cos(a) - std::cos(b)) - w1;
      flux += sum[j] * w0 + sum[j + 1] * w1;
    }
    return flux;
  }
  // Type B over a gamma zone: the zone boundaries are not grid lines of the (H, V) web, so use
  // midpoint quadrature in C and exact sin-weighted strips in gamma (0.25 deg x 0.5 deg cells;
  // the interpolant is piecewise bilinear, the error is O(h^2) ~ 1e-5 relative).
  const double lo = std::max(0.0, gamma0Deg), hi = std::min(180.0, gamma1Deg);
  const int ng = std::max(1, int(std::ceil((hi - lo) / 0.25)));
  const int nc = 720;
  const double dc = kTwoPi / nc;
  double flux = 0.0;
  for (int k = 0; k < ng; ++k) {
    const double a = lo + (hi - lo) * k / ng, b = lo + (hi - lo) * (k + 1) / ng;
    const double w = std::cos(degToRad(a)) - std::cos(degToRad(b));
    double ring = 0.0;
    for (int m = 0; m < nc; ++m) ring += intensityCd((m + 0.5) * 360.0 / nc, 0.5 * (a + b));
    flux += ring * dc * w;
  }
  return flux;
}

double PhotometricWeb::totalLumens() const {
  if (type_ == PhotometricType::kC) return lumensBetween(0.0, 180.0);
  // Exact integral in the native (H, V) web: d(omega) = cos H dH dV (H is the latitude from
  // the plane through the beam axis); int v cos H dH = [(H - H0) sin H + cos H] / dH.
  const size_t nq = polar_.size();
  std::vector<double> sum(planes_.size(), 0.0);
  for (size_t i = 0; i < planes_.size(); ++i)
    for (size_t j = 0; j + 1 < nq; ++j)
      sum[i] += degToRad(polar_[j + 1] - polar_[j]) * 0.5 * (gridCd(i, j) + gridCd(i, j + 1));
  double flux = 0.0;
  for (size_t i = 0; i + 1 < planes_.size(); ++i) {
    const double h0 = degToRad(planes_[i]), h1 = degToRad(planes_[i + 1]), dh = h1 - h0;
    const double w1 = (dh * std::sin(h1) + std::cos(h1) - std::cos(h0)) / dh;
    const double w0 = (std::sin(h1) - std::sin(h0)) - w1;
    flux += sum[i] * w0 + sum[i + 1] * w1;
  }
  return flux;
}

std::vector<double> PhotometricWeb::zonalLumens(double zoneDeg) const {
  std::vector<double> out;
  if (!(zoneDeg > 0.0)) return out;
  for (double g = 0.0; g < 180.0 - kAngleEps; g += zoneDeg)
    out.push_back(lumensBetween(g, std::min(180.0, g + zoneDeg)));
  return out;
}

double PhotometricWeb::lightOutputRatio() const {
  if (isAbsolute()) return std::numeric_limits<double>::quiet_NaN();
  return totalLumens() / info_.lampLumens;
}

}  // namespace candela
