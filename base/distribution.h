// How the work items of a run are shared between processes: one process (the default), the ranks
// of an MPI job (study/distributed/mpi_distribution.h), or the shards of a batch-scheduler array
// (study/distributed/shard_distribution.h). Every item carries its own random stream, so an item's value does
// not depend on which process or thread computed it: the results are the same bytes for any
// split (docs/distributed.md).
//
// Every process runs the same program on the same input and calls the same fills in the same
// order; a fill hands each process a share of the items and leaves every item computed on every
// process (received from the one that computed it), so the control flow after it is the same
// everywhere. Only rank 0 writes results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace candela {

// What the items of a fill are for. Shards, which cannot exchange items, compute the items later
// work depends on (kShared: cache records, the pixels that steer an image's refinement) in full
// each, and only their share of the items that go straight to the outputs (kResult).
enum class ItemUse { kShared, kResult };

class Distribution {
 public:
  virtual ~Distribution() = default;
  virtual int rank() const { return 0; }
  virtual int ranks() const { return 1; }
  // Whether this process writes the run's result folder: rank 0 of a job, the one process, a
  // merge; not the other ranks, nor a shard (which writes its part instead, see partial()).
  bool writesOutputs() const { return rank() == 0 && !partial(); }
  // Whether this process holds only its share of the kResult items (a shard): its outputs are a
  // part for `candela merge`, not a result.
  virtual bool partial() const { return false; }
  // Calls compute(i) for this process's items i of [0, n), on up to `threads` threads (0: all
  // cores), each writing item i in place at items + i·itemBytes; then receives every other item
  // (an item is trivially copyable bytes). compute is called concurrently.
  // 6 parameters: the item array (pointer, count, size), its use, threads and the work.
  virtual void fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
                    const std::function<void(size_t)>& compute) const;
  // What the report's settings say of the processes ("1 process", "4 MPI ranks", ...).
  virtual std::string describe() const { return "1 process"; }
  // Items of varying size: compute(i, bytes) writes item i's bytes (bytes starts empty), for
  // this process's items; afterwards lists[i] holds every item's bytes on every process.
  // `lists` has n entries. The same shares and uses as fill.
  virtual void fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                         const std::function<void(size_t, std::vector<std::byte>&)>& compute) const;
  // The sum over all processes (counters such as rays traced).
  virtual uint64_t sum(uint64_t local) const { return local; }
  // Rank 0's text on every process (e.g. points read from rank 0's standard input).
  virtual void broadcast(std::string& text) const { (void)text; }
  // Called once the run's work is done, before its results are written: a merge checks here
  // that its parts held nothing the run did not ask for (throws InputError).
  virtual void finish() const {}
};

// The one-process distribution: fill is a parallel loop.
const Distribution& localDistribution();

// Typed fill: compute(i, items[i]) for this process's items, every item present afterwards.
// 6 parameters: the distribution, the items (pointer and count), their use, threads and the work.
template <class T, class F>
void distributedFill(const Distribution& d, T* items, size_t n, ItemUse use, int threads, F&& compute) {
  static_assert(std::is_trivially_copyable_v<T>, "items travel between processes as bytes");
  d.fill(reinterpret_cast<std::byte*>(items), n, sizeof(T), use, threads, [&](size_t i) { compute(i, items[i]); });
}
template <class T, class F>
void distributedFill(const Distribution& d, std::vector<T>& items, ItemUse use, int threads, F&& compute) {
  distributedFill(d, items.data(), items.size(), use, threads, std::forward<F>(compute));
}

// Row fill: n rows of `rowLength` values each, row i at values[i·rowLength ...]; compute(i)
// writes row i.
// 6 parameters: the distribution, the rows (values and their shape), their use, threads and the work.
template <class T>
void distributedRows(const Distribution& d, std::vector<T>& values, size_t rowLength, ItemUse use, int threads,
                     const std::function<void(size_t)>& compute) {
  static_assert(std::is_trivially_copyable_v<T>, "rows travel between processes as bytes");
  const size_t n = rowLength > 0 ? values.size() / rowLength : 0;
  d.fill(reinterpret_cast<std::byte*>(values.data()), n, rowLength * sizeof(T), use, threads, compute);
}

}  // namespace candela
