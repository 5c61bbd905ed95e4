#include "engine/radiance/transform.h"

#include <glm/gtc/matrix_transform.hpp>

#include <charconv>
#include <cmath>

namespace candela {

namespace {

double numberAt(const std::vector<std::string>& words, size_t i, const FileLoc& loc, const std::string& what,
                const std::string& option) {
  if (i >= words.size()) throw InputError(loc, what + ": " + option + " needs a number after it");
  const std::string& w = words[i];
  double v = 0.0;
  const char* b = w.data();
  const char* e = b + w.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
    throw InputError(loc, what + ": " + option + " needs a number, not '" + w + "'");
  return v;
}

glm::dmat4 rotation(int axis, double degrees) {
  const double a = degrees * kPi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  glm::dmat4 m(1.0);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // x: (y, z), y: (z, x), z: (x, y)
  // Counter-clockwise looking down the axis: i → j.  glm is column-major: m[col][row].
  m[i][i] = c;
  m[i][j] = s;
  m[j][i] = -s;
  m[j][j] = c;
  return m;
}

}  // namespace

RadTransform RadTransform::inverse() const {
  RadTransform r;
  r.matrix = glm::inverse(matrix);
  r.scale = 1.0 / scale;
  return r;
}

RadTransform thenApply(const RadTransform& first, const RadTransform& second) {
  RadTransform r;
  r.matrix = second.matrix * first.matrix;
  r.scale = first.scale * second.scale;
  return r;
}

bool isRadTransformOption(const std::string& w) {
  if (w.size() == 2 && w[0] == '-') return w[1] == 't' || w[1] == 's' || w[1] == 'i';
  if (w.size() == 3 && w[0] == '-') return (w[1] == 'r' || w[1] == 'm') && w[2] >= 'x' && w[2] <= 'z';
  return false;
}

size_t parseRadTransform(const std::vector<std::string>& words, size_t begin, RadTransform& out, const FileLoc& loc,
                         const std::string& what) {
  RadTransform total;
  RadTransform block;
  long repeat = 1;
  // total · block^repeat. The powers of one block commute, so squaring gives the same product
  // in O(log repeat) steps: copy i of an `-a N` array is `-i i`, and an array of 10⁵ copies
  // would otherwise cost 5·10⁹ products.
  auto flush = [&] {
    RadTransform power = block;
    for (long k = repeat; k > 0; k >>= 1) {
      if (k & 1) total = thenApply(total, power);
      power = thenApply(power, power);
    }
    block = RadTransform{};
  };
  size_t i = begin;
  while (i < words.size() && isRadTransformOption(words[i])) {
    const std::string& w = words[i];
    RadTransform step;
    if (w == "-t") {
      const Vec3 t(numberAt(words, i + 1, loc, what, w), numberAt(words, i + 2, loc, what, w),
                   numberAt(words, i + 3, loc, what, w));
      step.matrix = glm::translate(glm::dmat4(1.0), t);
      i += 4;
    } else if (w == "-s") {
      const double f = numberAt(words, i + 1, loc, what, w);
      if (f == 0.0) throw InputError(loc, what + ": -s needs a non-zero factor");
      step.matrix = glm::scale(glm::dmat4(1.0), Vec3(f));
      step.scale = f;
      i += 2;
    } else if (w == "-i") {
      const double n = numberAt(words, i + 1, loc, what, w);
      if (!(n >= 0.0) || n != std::floor(n) || n > 1e6)
        throw InputError(loc, what + ": -i needs a whole count from 0 to 1000000, not '" + words[i + 1] + "'");
      flush();
      repeat = static_cast<long>(n);
      i += 2;
      continue;
    } else if (w[1] == 'r') {
      step.matrix = rotation(w[2] - 'x', numberAt(words, i + 1, loc, what, w));
      i += 2;
    } else {  // mirror
      Vec3 f(1.0);
      f[w[2] - 'x'] = -1.0;
      step.matrix = glm::scale(glm::dmat4(1.0), f);
      step.scale = -1.0;
      i += 1;
    }
    block = thenApply(block, step);
  }
  flush();
  out = total;
  return i;
}

}  // namespace candela
