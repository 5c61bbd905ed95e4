#include "study/distributed/mpi_distribution.h"

#include "base/parallel.h"
#include "study/trace_options.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef CANDELA_HAVE_MPI
#include <mpi.h>

#include <algorithm>
#include <limits>
#include <vector>
#endif

namespace candela {

namespace {

// Launched by mpirun/mpiexec (Open MPI), srun or another PMI/PMIx launcher.
bool launchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

// The job's size as the launcher tells it (0: not told).
[[maybe_unused]] int launcherSize() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* s = std::getenv(v)) return std::atoi(s);
  return 0;
}

}  // namespace

#ifdef CANDELA_HAVE_MPI

namespace {

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// Items per chunk: about 32 chunks a rank, so that the last chunks to finish (points differ in
// cost by 100×) leave the other ranks idle for a small share of the fill, and at least 4 items
// a thread, so that a chunk keeps the rank's threads busy.
size_t chunkItems(size_t n, int ranks, int threads) {
  const size_t perThread = 4 * static_cast<size_t>(threadsUsed(threads));
  const size_t even = (n + 32 * static_cast<size_t>(ranks) - 1) / (32 * static_cast<size_t>(ranks));
  return std::max<size_t>(1, std::max(perThread, even));
}

class MpiDistribution : public Distribution {
 public:
  explicit MpiDistribution(MPI_Comm comm) : comm_(comm) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &ranks_);
  }
  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }
  std::string describe() const override {
    return ranks_ == 1 ? "1 process" : std::to_string(ranks_) + " MPI ranks";
  }

  void fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
            const std::function<void(size_t)>& compute) const override {
    (void)use;  // every rank receives every item, whatever its use
    if (ranks_ == 1 || n == 0) {
      Distribution::fill(items, n, itemBytes, use, threads, compute);
      return;
    }
    const Claimed c = claimChunks(n, threads, compute);
    exchange(items, n, itemBytes, c);
  }

  void fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                 const std::function<void(size_t, std::vector<std::byte>&)>& compute) const override {
    if (ranks_ == 1 || lists.empty()) {
      Distribution::fillLists(lists, use, threads, compute);
      return;
    }
    const Claimed c = claimChunks(lists.size(), threads, [&](size_t i) {
      lists[i].clear();
      compute(i, lists[i]);
    });
    exchangeLists(lists, c);
  }

  uint64_t sum(uint64_t local) const override {
    uint64_t total = 0;
    check(MPI_Allreduce(&local, &total, 1, MPI_UINT64_T, MPI_SUM, comm_), "MPI_Allreduce");
    return total;
  }

  void broadcast(std::string& text) const override {
    uint64_t size = text.size();
    check(MPI_Bcast(&size, 1, MPI_UINT64_T, 0, comm_), "MPI_Bcast");
    text.resize(size);
    // In pieces below MPI's int count.
    constexpr uint64_t kPiece = 1u << 30;
    for (uint64_t at = 0; at < size; at += kPiece)
      check(MPI_Bcast(text.data() + at, static_cast<int>(std::min(kPiece, size - at)), MPI_BYTE, 0, comm_),
            "MPI_Bcast");
  }

 private:
  // The chunks of a fill this rank computed, and every rank's chunk ids.
  struct Claimed {
    size_t n = 0, chunk = 1;
    std::vector<uint64_t> mine;
    std::vector<int> chunkCount, chunkAt;  // per rank, into all
    std::vector<uint64_t> all;             // every rank's chunks, rank by rank
    size_t itemsOf(uint64_t c) const { return std::min(n, (c + 1) * chunk) - c * chunk; }
  };

  // Takes chunks from the counter on rank 0 until none is left, computing each on the rank's
  // threads; then every rank learns every rank's chunks.
  Claimed claimChunks(size_t n, int threads, const std::function<void(size_t)>& compute) const {
    Claimed c;
    c.n = n;
    c.chunk = chunkItems(n, ranks_, threads);
    const uint64_t chunks = (n + c.chunk - 1) / c.chunk;
    // The counter: one uint64 on rank 0, taken by MPI_Fetch_and_op (passive target).
    uint64_t* counter = nullptr;
    MPI_Win win;
    check(MPI_Win_allocate(rank_ == 0 ? sizeof(uint64_t) : 0, sizeof(uint64_t), MPI_INFO_NULL, comm_, &counter, &win),
          "MPI_Win_allocate");
    if (rank_ == 0) *counter = 0;
    MPI_Barrier(comm_);  // rank 0's counter is 0 before anyone takes from it
    check(MPI_Win_lock_all(0, win), "MPI_Win_lock_all");
    const uint64_t one = 1;
    for (;;) {
      uint64_t k = 0;
      check(MPI_Fetch_and_op(&one, &k, MPI_UINT64_T, 0, 0, MPI_SUM, win), "MPI_Fetch_and_op");
      check(MPI_Win_flush(0, win), "MPI_Win_flush");
      if (k >= chunks) break;
      c.mine.push_back(k);
      const size_t b = k * c.chunk, e = std::min(n, b + c.chunk);
      parallelFor(e - b, threads, [&](size_t i) { compute(b + i); });
    }
    MPI_Win_unlock_all(win);
    MPI_Win_free(&win);
    const int myChunks = static_cast<int>(c.mine.size());
    c.chunkCount.assign(ranks_, 0);
    c.chunkAt.assign(ranks_, 0);
    check(MPI_Allgather(&myChunks, 1, MPI_INT, c.chunkCount.data(), 1, MPI_INT, comm_), "MPI_Allgather");
    int total = 0;
    for (int r = 0; r < ranks_; ++r) c.chunkAt[r] = total, total += c.chunkCount[r];
    c.all.resize(total);
    check(MPI_Allgatherv(c.mine.data(), myChunks, MPI_UINT64_T, c.all.data(), c.chunkCount.data(), c.chunkAt.data(),
                         MPI_UINT64_T, comm_),
          "MPI_Allgatherv");
    size_t covered = 0;
    for (uint64_t k : c.all) covered += c.itemsOf(k);
    if (covered != n) throw std::runtime_error("MPI: the ranks' chunks do not cover the items");
    return c;
  }

  // Items per rank, in the order of its chunks.
  std::vector<int> itemCounts(const Claimed& c) const {
    std::vector<int> count(ranks_, 0);
    for (int r = 0; r < ranks_; ++r)
      for (int k = 0; k < c.chunkCount[r]; ++k) count[r] += static_cast<int>(c.itemsOf(c.all[c.chunkAt[r] + k]));
    return count;
  }

  // Variable-size items: every item's size (uint64), then the bytes (at most 2 GiB a fill: MPI
  // counts bytes in int here).
  void exchangeLists(std::vector<std::vector<std::byte>>& lists, const Claimed& c) const {
    const std::vector<int> count = itemCounts(c);
    std::vector<int> at(ranks_, 0);
    for (int r = 1; r < ranks_; ++r) at[r] = at[r - 1] + count[r - 1];
    std::vector<uint64_t> mySizes;
    std::vector<std::byte> myBytes;
    for (uint64_t k : c.mine)
      for (size_t i = k * c.chunk; i < k * c.chunk + c.itemsOf(k); ++i) {
        mySizes.push_back(lists[i].size());
        myBytes.insert(myBytes.end(), lists[i].begin(), lists[i].end());
      }
    std::vector<uint64_t> sizes(c.n);
    check(MPI_Allgatherv(mySizes.data(), count[rank_], MPI_UINT64_T, sizes.data(), count.data(), at.data(),
                         MPI_UINT64_T, comm_),
          "MPI_Allgatherv");
    std::vector<int> byteCount(ranks_, 0), byteAt(ranks_, 0);
    uint64_t total = 0;
    for (int r = 0; r < ranks_; ++r) {
      uint64_t b = 0;
      for (int i = 0; i < count[r]; ++i) b += sizes[at[r] + i];
      byteAt[r] = static_cast<int>(total);
      byteCount[r] = static_cast<int>(b);
      total += b;
    }
    if (total > static_cast<uint64_t>(std::numeric_limits<int>::max()))
      throw std::runtime_error("MPI: a fill of lists holds more than 2 GiB");
    std::vector<std::byte> bytes(total);
    check(MPI_Allgatherv(myBytes.data(), byteCount[rank_], MPI_BYTE, bytes.data(), byteCount.data(), byteAt.data(),
                         MPI_BYTE, comm_),
          "MPI_Allgatherv");
    size_t item = 0, pos = 0;
    for (int r = 0; r < ranks_; ++r)
      for (int k = 0; k < c.chunkCount[r]; ++k) {
        const uint64_t ch = c.all[c.chunkAt[r] + k];
        for (size_t i = ch * c.chunk; i < ch * c.chunk + c.itemsOf(ch); ++i, ++item) {
          lists[i].assign(bytes.begin() + pos, bytes.begin() + pos + sizes[item]);
          pos += sizes[item];
        }
      }
  }

  // Fixed-size items, counted in items of an MPI type of itemBytes bytes (so that a rank's
  // share may exceed 2 GiB).
  void exchange(std::byte* items, size_t n, size_t itemBytes, const Claimed& c) const {
    const std::vector<int> count = itemCounts(c);
    std::vector<int> at(ranks_, 0);
    for (int r = 1; r < ranks_; ++r) at[r] = at[r - 1] + count[r - 1];
    std::vector<std::byte> send(static_cast<size_t>(count[rank_]) * itemBytes);
    size_t pos = 0;
    for (uint64_t k : c.mine) {
      const size_t bytes = c.itemsOf(k) * itemBytes;
      std::copy_n(items + k * c.chunk * itemBytes, bytes, send.data() + pos);
      pos += bytes;
    }
    std::vector<std::byte> received(n * itemBytes);
    MPI_Datatype item;
    check(MPI_Type_contiguous(static_cast<int>(itemBytes), MPI_BYTE, &item), "MPI_Type_contiguous");
    MPI_Type_commit(&item);
    const int rc =
        MPI_Allgatherv(send.data(), count[rank_], item, received.data(), count.data(), at.data(), item, comm_);
    MPI_Type_free(&item);
    check(rc, "MPI_Allgatherv");
    pos = 0;
    for (int r = 0; r < ranks_; ++r)
      for (int k = 0; k < c.chunkCount[r]; ++k) {
        const uint64_t ch = c.all[c.chunkAt[r] + k];
        const size_t bytes = c.itemsOf(ch) * itemBytes;
        std::copy_n(received.data() + pos, bytes, items + ch * c.chunk * itemBytes);
        pos += bytes;
      }
  }

  MPI_Comm comm_;
  int rank_ = 0, ranks_ = 1;
};

}  // namespace

struct MpiSession::Impl {
  MPI_Comm comm = MPI_COMM_NULL;
  std::unique_ptr<MpiDistribution> distribution;
};

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!launchedByMpi()) return;
  int provided = 0;
  // Only the main thread calls MPI; the worker threads never do.
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  impl_ = std::make_unique<Impl>();
  MPI_Comm_dup(MPI_COMM_WORLD, &impl_->comm);
  impl_->distribution = std::make_unique<MpiDistribution>(impl_->comm);
}

MpiSession::~MpiSession() {
  if (!impl_) return;
  impl_->distribution.reset();
  MPI_Comm_free(&impl_->comm);
  MPI_Finalize();
}

const Distribution& MpiSession::distribution() const {
  return impl_ ? static_cast<const Distribution&>(*impl_->distribution) : localDistribution();
}

void MpiSession::abort(int exitCode) const {
  if (impl_) MPI_Abort(MPI_COMM_WORLD, exitCode);
}

bool mpiAvailable() { return true; }

#else  // without MPI: one process; a launch by mpirun is refused rather than run N times over

struct MpiSession::Impl {};

MpiSession::MpiSession(int& argc, char**& argv) {
  (void)argc;
  (void)argv;
  if (launcherSize() > 1)
    throw std::runtime_error(
        "this candela was built without MPI (libopenmpi-dev); under mpirun every rank would compute the whole run");
}

MpiSession::~MpiSession() = default;

const Distribution& MpiSession::distribution() const { return localDistribution(); }

void MpiSession::abort(int exitCode) const { (void)exitCode; }

bool mpiAvailable() { return false; }

#endif

}  // namespace candela
