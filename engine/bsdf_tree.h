// LBNL's tensor trees (genBSDF's variable-resolution BSDFs, "TensorTree3" and "TensorTree4"),
// looked up as Radiance does (src/common/bsdf_t.c, SDqueryTre and SDlookupTre): a direction's
// projection (x, y) on the surface maps to the unit square by Shirley and Chiu's concentric map
// (Shirley & Chiu 1997, "A low distortion map between disk and square", JGT 2(3)), which keeps
// areas, so a square cell of side s covers π s² of projected solid angle.
//   TensorTree4: coordinates (sq(−in.x, −in.y), sq(out.x, out.y)).
//   TensorTree3 (isotropic): (½ − ½·|in.xy|, sq(out rotated about z by −atan2(−in.y, −in.x))).
// A node is either 2^n children (child bit d set for the upper half of coordinate d) or a grid
// of 2^(n·k) values with the first coordinate varying slowest. Values are nearest-cell, no
// interpolation. A colour is given, as bsdf_t.c reads it, by two more trees of the same
// coordinates holding the CIE 1976 chromaticity u′ and v′ (<Wavelength> CIE-u and CIE-v): a
// cell's colour is its Y with the u′v′ looked up at the same point (SDyuv2rgb), else grey.
#pragma once

#include "engine/bsdf_tabulated.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace candela {

struct TensorTree {
  struct Node {
    int child = -1;    // index of the first of 2^dims children; -1: a leaf grid
    int log2Grid = 0;  // leaf grid: 2^log2Grid cells per coordinate
    int first = 0;     // leaf grid: index of its first value
  };
  int dims = 4;              // 3 or 4
  std::vector<Node> nodes;   // nodes[0] is the root
  std::vector<double> values;  // 1/sr

  // The value at `pos` (each coordinate in [0, 1)) and the side of its cell.
  double lookup(const double* pos, double* cellSide = nullptr) const { return values[locate(pos, cellSide)]; }
  // The index in `values` of the cell holding `pos`.
  size_t locate(const double* pos, double* cellSide = nullptr) const;
};

// Shirley and Chiu's maps between the unit square [0,1]² and the unit disc.
Vec2 squareToDisk(const Vec2& s);
Vec2 diskToSquare(const Vec2& d);

class TreeBsdf final : public TabulatedBsdf {
 public:
  using Trees = std::array<std::optional<TensorTree>, kBsdfParts>;
  // Each part's Y tree and, where given, its u′ and v′ trees.
  TreeBsdf(Trees parts, Trees uPrime, Trees vPrime, std::string kind);
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
    TensorTree tree;
    std::optional<TensorTree> u, v;  // chromaticity (both or neither)
    double minProjSA = 0.0, minY = 0.0;
  };
  // The colour of Y value y at tree coordinates pos (grey without chromaticity trees).
  static Rgb colourAt(const Part& p, const double* pos, double y);
  // A slice of the tree: the two coordinates left free and the fixed ones' values, with how a
  // point of the free square becomes the free direction.
  struct Slice {
    int freeDim = 0;           // the free coordinates are freeDim and freeDim + 1
    double pos[4] = {0, 0, 0, 0};
    double spin = 0.0;         // rotation about z of the free direction (3-D trees)
    bool freeIsIncident = false;
    int freeSide = 1;          // side of the free direction
  };
  Slice slice(const Part& p, bool fixedIsIn, const Vec3& fixed) const;
  Vec3 freeDirection(const Slice& s, const Vec2& square) const;
  Vec2 freeSquare(const Slice& s, const Vec3& free) const;
  std::array<std::optional<Part>, kBsdfParts> parts_;
  std::string kind_;
};

}  // namespace candela
