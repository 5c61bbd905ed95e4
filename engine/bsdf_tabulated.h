// What the Klems (engine/bsdf_klems.h) and tensor-tree (engine/bsdf_tree.h) representations
// share behind engine/bsdf.h: the four components' sides, Radiance's choice of component for a
// pair of directions (src/common/bsdf.c, SDevalBSDF), and the aBSDF peak extraction
// (src/rt/m_bsdf.c, compute_through) with the "without peak" queries built on it.
#pragma once

#include "base/units.h"
#include "engine/bsdf.h"

#include <array>

namespace candela {

// The four scattering components in the local frame (+z: the XML's back, Radiance's front).
enum class BsdfPart { ReflPlusZ, ReflMinusZ, TransFromPlusZ, TransFromMinusZ };
inline constexpr int kBsdfParts = 4;

// Where light of a component arrives from and leaves to (+1: +z side, -1: -z side).
inline int bsdfInSide(BsdfPart p) { return (p == BsdfPart::ReflPlusZ || p == BsdfPart::TransFromPlusZ) ? 1 : -1; }
inline int bsdfOutSide(BsdfPart p) { return (p == BsdfPart::ReflPlusZ || p == BsdfPart::TransFromMinusZ) ? 1 : -1; }

// How a query on (in, out) reads a component: which one, and whether by reciprocity (the
// component's incident direction is then the query's `out`).
struct BsdfLookup {
  int part = -1;  // -1: nothing scatters between these sides
  bool reversed = false;
};

// The peak of the direct ("through") component for light arriving from one direction, as the
// viewer on the other side sees it: the cells of the incident direction that make it.
struct BsdfPeak {
  static constexpr int kMaxCells = 29;  // Radiance's probes (m_bsdf.c, NDIR2CHECK)
  bool found = false;
  Rgb through{0.0};   // Σ f·Ω over the peak's cells: the fraction passing straight through
  Rgb surround{0.0};  // the mean BTDF (per sr) of the cells around it
  int cells = 0;      // the peak's cells (incident directions for the fixed viewer)
  std::array<long, kMaxCells> cell{};
  std::array<double, kMaxCells> cellProjSA{};
  std::array<Rgb, kMaxCells> cellValue{};
};

class TabulatedBsdf : public Bsdf {
 public:
  Rgb eval(const Vec3& in, const Vec3& out, bool withoutPeak = false) const override;
  bool sampleIn(const Vec3& out, const Vec2& u, double pick, Sample& s, bool withoutPeak = false) const override;
  double pdfIn(const Vec3& in, const Vec3& out, bool withoutPeak = false) const override;
  Rgb albedoToward(const Vec3& out, bool transmitted, bool withoutPeak = false) const override;
  Rgb hemispherical(const Vec3& in, bool transmitted) const override;
  Rgb peakThrough(const Vec3& in) const override;
  bool reflects(bool plusZSide) const override;
  bool transmits() const override;

  // Radiance's peak search for light from `in` seen from −in (compute_through), public for
  // the tests.
  BsdfPeak peakFor(const Vec3& in) const;

 protected:
  // Which components the file gives (after dropping the insignificant ones).
  virtual bool hasPart(BsdfPart p) const = 0;
  // The component's value for the pair as the component is laid out (in on its in side, out on
  // its out side); 0 outside its cells.
  virtual Rgb partValue(int part, const Vec3& in, const Vec3& out) const = 0;
  // The projected solid angle of the smaller of the two cells the pair falls in (0: none), and
  // the smallest cell of a component (Radiance's minProjSA).
  virtual double pairProjSA(int part, const Vec3& in, const Vec3& out) const = 0;
  virtual double minProjSA(int part) const = 0;
  // The smallest Y value of a component (Radiance takes it out as the diffuse part).
  virtual double minValueY(int part) const = 0;
  // One direction of a component's pair held fixed (its incident one when fixedIsIn, else its
  // outgoing one), the other free: the integral of value·|cos free| over the free direction;
  // the sampling total T (the integral of the sampling weight w, a non-negative stand-in for
  // the value, times |cos|); a draw of the free direction with density w·|cos|/T (per sr) from
  // u and pick; and that density for a given free direction. No allocation.
  virtual Rgb integrateFree(int part, bool fixedIsIn, const Vec3& fixed) const = 0;
  virtual double samplingTotal(int part, bool fixedIsIn, const Vec3& fixed) const = 0;
  virtual bool sampleFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec2& u, double pick, Vec3& free,
                          double& pdf) const = 0;
  virtual double pdfFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free) const = 0;
  // The cell the free direction falls in for that fixed one: an identifier (-1: none) and its
  // projected solid angle.
  virtual long freeCell(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free, double& projSA) const = 0;

  // Radiance's rule for a pair of directions: reflection on the side both are on, transmission
  // from in's side, else the other transmission by reciprocity.
  BsdfLookup lookup(const Vec3& in, const Vec3& out) const;
  // The same for a viewer along `out` and light from out's side (transmitted false) or the
  // other (true).
  BsdfLookup lookupToward(const Vec3& out, bool transmitted) const;
  Rgb evalFull(const Vec3& in, const Vec3& out) const;

 private:
  double pdfFull(const Vec3& in, const Vec3& out) const;
};

}  // namespace candela
