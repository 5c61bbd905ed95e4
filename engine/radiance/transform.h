// Radiance's transform arguments (xform(1), and the transform that patterns, meshes and
// instances take after their own arguments): -t x y z, -rx/-ry/-rz degrees (counter-clockwise
// looking down the axis), -s factor, -mx/-my/-mz mirrors, applied in the order given; -i N repeats
// the transform written since the previous -i (or the start) N times (Radiance src/common/xf.c).
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <string>
#include <vector>

namespace candela {

struct RadTransform {
  glm::dmat4 matrix{1.0};  // maps a point p (column vector, w = 1) to matrix · p
  double scale = 1.0;      // product of the scale factors and mirrors (negative: handedness flips)

  Vec3 point(const Vec3& p) const { return Vec3(matrix * glm::dvec4(p, 1.0)); }
  // A direction (no translation), not renormalised: its length grows by |scale|.
  Vec3 direction(const Vec3& d) const { return Vec3(matrix * glm::dvec4(d, 0.0)); }
  bool isIdentity() const { return matrix == glm::dmat4(1.0) && scale == 1.0; }
  // Its inverse (a transform is a similarity: rotation, uniform scale, mirror, translation).
  RadTransform inverse() const;
};

// `first` then `second`.
RadTransform thenApply(const RadTransform& first, const RadTransform& second);

// True when `word` begins a transform option (-t, -s, -i, -rx..-rz, -mx..-mz), as xf.c's isxfopt.
bool isRadTransformOption(const std::string& word);

// Reads transform options from words[begin...] up to the first word that is not one, and returns
// the index of that word. A transform option without its numbers, or with a number that does not
// parse, a zero scale or a negative repeat count, is an InputError at `loc` naming `what`
// (e.g. "xform").
size_t parseRadTransform(const std::vector<std::string>& words, size_t begin, RadTransform& out,
                         const FileLoc& loc, const std::string& what);

}  // namespace candela
