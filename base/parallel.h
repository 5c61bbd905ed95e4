// Parallel loops (oneTBB). Work items carry their own random streams, so results are identical
// for any thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace candela {

// Calls body(i) for i in [0, n) on up to `threads` threads (0 = all cores).
void parallelFor(size_t n, int threads, const std::function<void(size_t)>& body);

}  // namespace candela
