// Klems matrices (LBNL's angle bases, WINDOW and genBSDF): the scattering is constant over each
// pair of patches, an incident patch i and an outgoing one o. The conventions are Radiance's
// (src/common/bsdf_m.c): a patch is a band of polar angle θ split into nPhis equal azimuth
// sectors centred on φ = 360°·k/nPhis (k from 0, counted anticlockwise from +x); an outgoing
// patch holds the directions (sinθ cosφ, sinθ sinφ, ±cosθ) and an incident patch the
// directions (−sinθ cosφ, −sinθ sinφ, ±cosθ), so that patch k in and patch k out of a
// transmission are the straight-through pair and of a reflection the mirror pair. Patch k's
// projected solid angle is Λ_k = π (cos²θ_lo − cos²θ_hi) / nPhis.
#pragma once

#include "engine/bsdf_tabulated.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

struct KlemsBasis {
  struct Ring {
    double thetaLoDeg = 0.0, thetaHiDeg = 0.0;  // polar band, degrees from the normal
    int nPhis = 0;                              // azimuth sectors
    int first = 0;                              // index of its first patch
  };
  std::string name;
  std::vector<Ring> rings;  // increasing θ, contiguous, from 0
  int count = 0;            // patches

  // From rings with nPhis and θ bounds (first and count are filled in).
  static KlemsBasis make(std::string name, std::vector<Ring> rings);
  // The standard bases of LBNL (Radiance's bsdf_m.c, abase_list): "LBNL/Klems Full" (145
  // patches), "LBNL/Klems Half" (73), "LBNL/Klems Quarter" (41); nullptr for another name
  // (compared without case).
  static std::shared_ptr<const KlemsBasis> standard(const std::string& name);

  // The patch of direction (x, y, z) with z ≥ 0 read as an outgoing direction; -1 when none
  // (z ≤ 0 or beyond the last ring).
  int index(const Vec3& v) const;
  // A direction of patch k, uniform in projected solid angle over it for u uniform in [0,1)²
  // (u = (0.5, 0.5): its centre); z ≥ 0, outgoing convention.
  Vec3 direction(int k, const Vec2& u) const;
  double projSA(int k) const;  // Λ_k, sr
  const Ring& ringOf(int k) const;
};

// One component's matrix: value[o * in->count + i] (1/sr) for incident patch i, outgoing o.
struct KlemsMatrix {
  std::shared_ptr<const KlemsBasis> in, out;
  std::vector<Rgb> value;
};

class KlemsBsdf final : public TabulatedBsdf {
 public:
  // parts indexed by BsdfPart; absent components empty. `kind` as Bsdf::kind.
  KlemsBsdf(std::array<std::optional<KlemsMatrix>, kBsdfParts> parts, std::string kind);

  Rgb hemisphericalPatch(int part, int inPatch) const;  // Σ_o f(i,o) Λ_o (for the tests)
  const KlemsMatrix* matrix(BsdfPart p) const { return parts_[static_cast<int>(p)] ? &parts_[static_cast<int>(p)]->m : nullptr; }
  std::string kind() const override { return kind_; }

 protected:
  bool hasPart(BsdfPart p) const override { return parts_[static_cast<int>(p)].has_value(); }
  Rgb partValue(int part, const Vec3& in, const Vec3& out) const override;
  double pairProjSA(int part, const Vec3& in, const Vec3& out) const override;
  double minProjSA(int part) const override { return parts_[part]->minProjSA; }
  double minValueY(int part) const override { return parts_[part]->minY; }
  Rgb integrateFree(int part, bool fixedIsIn, const Vec3& fixed) const override;
  double samplingTotal(int part, bool fixedIsIn, const Vec3& fixed) const override;
  bool sampleFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec2& u, double pick, Vec3& free,
                  double& pdf) const override;
  double pdfFree(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free) const override;
  long freeCell(int part, bool fixedIsIn, const Vec3& fixed, const Vec3& free, double& projSA) const override;

 private:
  struct Part {
    BsdfPart which;
    KlemsMatrix m;
    std::vector<double> weight;    // sampling weight per entry (max(R, G, B, 0)), as value
    std::vector<double> cdfByOut;  // per o: out->count rows of in->count + 1 cumulative w·Λ_i
    std::vector<double> cdfByIn;   // per i: in->count rows of out->count + 1 cumulative w·Λ_o
    std::vector<Rgb> albedoByOut;  // per o: Σ_i f Λ_i
    std::vector<Rgb> hemiByIn;     // per i: Σ_o f Λ_o
    double minProjSA = 0.0, minY = 0.0;
  };
  int inIndex(const Part& p, const Vec3& v) const;
  int outIndex(const Part& p, const Vec3& v) const;
  std::array<std::optional<Part>, kBsdfParts> parts_;
  std::string kind_;
};

}  // namespace candela
