#include "base/distribution.h"

#include "base/parallel.h"

namespace candela {

void Distribution::fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
                        const std::function<void(size_t)>& compute) const {
  (void)items;
  (void)itemBytes;
  (void)use;
  parallelFor(n, threads, compute);
}

const Distribution& localDistribution() {
  static const Distribution local;
  return local;
}

}  // namespace candela
