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

void Distribution::fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                             const std::function<void(size_t, std::vector<std::byte>&)>& compute) const {
  (void)use;
  parallelFor(lists.size(), threads, [&](size_t i) {
    lists[i].clear();
    compute(i, lists[i]);
  });
}

const Distribution& localDistribution() {
  static const Distribution local;
  return local;
}

}  // namespace candela
