// Shards for batch schedulers without MPI (SLURM job arrays, Kubernetes Jobs): `candela run
// case.toml --shard i/N --out part_i` computes one deterministic share of the run and writes a
// part; `candela merge part_0 ... part_{N-1} --out out` checks the parts and writes exactly the
// files of a one-process run (docs/distributed.md).
//
// A shard runs the whole study, as every MPI rank does, with a Distribution (base/distribution.h)
// that cannot exchange items: it computes the items later work depends on (ItemUse::kShared)
// in full, and of the items that go straight to the outputs (kResult) the chunks c with
// c mod N = i. It records every fill: the counts of all, the items of its share of the kResult
// fills, and (shard 0 only) the kShared items. Merge runs the study again with a Distribution
// that takes every fill's items from the parts instead of computing them: only the serial
// work (reading, the cache's placement walk, metrics, writing) is done again.
#pragma once

#include "base/distribution.h"
#include "base/error.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace candela {

// "i/N" (0 ≤ i < N) as (i, N); throws std::invalid_argument otherwise.
struct ShardSpec {
  int index = 0, count = 1;
};
ShardSpec parseShard(const std::string& text);

// One fill as a part records it.
struct FillRecord {
  uint64_t items = 0, itemBytes = 0, chunk = 0;  // itemBytes 0: items of varying size (fillLists)
  ItemUse use = ItemUse::kResult;
  // This shard's chunks in order (kResult); all items (kShared, shard 0). Items of varying size:
  // their sizes (uint64 each), then their bytes.
  std::vector<std::byte> data;
};

// Items per chunk of a shard's fill: about 16 chunks a shard, interleaved (chunk c to shard
// c mod N), so that the expensive items of a grid (beside its walls, say) are shared too.
uint64_t shardChunkItems(uint64_t items, int shards);

class ShardDistribution : public Distribution {
 public:
  explicit ShardDistribution(ShardSpec spec) : spec_(spec) {}
  int rank() const override { return spec_.index; }
  int ranks() const override { return spec_.count; }
  bool partial() const override { return true; }
  std::string describe() const override {
    return "shard " + std::to_string(spec_.index) + " of " + std::to_string(spec_.count);
  }
  void fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
            const std::function<void(size_t)>& compute) const override;
  void fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                 const std::function<void(size_t, std::vector<std::byte>&)>& compute) const override;
  const std::vector<FillRecord>& fills() const { return fills_; }

 private:
  ShardSpec spec_;
  // What the part will hold; a record of the run, it changes no result.
  mutable std::vector<FillRecord> fills_;
};

// What a part belongs to: merge refuses parts whose identities differ.
struct PartIdentity {
  std::string caseFile;     // absolute path of the case file
  std::string fingerprint;  // of the case file and the files it names (hex)
  std::string request;      // the run's options that change results (JSON text)
  std::string version;      // candela's
  int shards = 1;
  bool operator==(const PartIdentity&) const = default;
};

// The part folder's files.
inline constexpr const char* kPartManifest = "part.json";
inline constexpr const char* kPartData = "fills.bin";

// Writes shard `spec`'s part into `dir` (an empty folder): the manifest and the fills.
void writePart(const std::filesystem::path& dir, const PartIdentity& id, ShardSpec spec,
               const std::vector<FillRecord>& fills);

// A part as merge reads it: its manifest, checked; its fills are read one at a time.
struct PartHeader {
  std::filesystem::path dir;
  PartIdentity id;
  ShardSpec spec;
  uint64_t fills = 0, dataBytes = 0;
};
// Throws InputError naming the folder when it holds no part, an incomplete one, or one of
// another format.
PartHeader readPartHeader(const std::filesystem::path& dir);

// Merge: every fill's items from the parts, in the order the shards made them. Throws
// InputError (at the part) when a part's fill does not match the one the study asks for:
// the parts come from another case or settings.
class MergeDistribution : public Distribution {
 public:
  // `parts` in shard order, checked to be one complete set (checkPartSet).
  explicit MergeDistribution(std::vector<PartHeader> parts);
  ~MergeDistribution() override;
  std::string describe() const override { return std::to_string(parts_.size()) + " shards (merged)"; }
  void fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
            const std::function<void(size_t)>& compute) const override;
  void fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                 const std::function<void(size_t, std::vector<std::byte>&)>& compute) const override;
  // Throws InputError when the parts hold fills the study did not ask for.
  void finish() const override;
  const std::vector<PartHeader>& parts() const { return parts_; }

 private:
  struct Reader;
  std::vector<PartHeader> parts_;
  std::vector<std::unique_ptr<Reader>> readers_;
  // Reads part `part`'s next fill header, checked against the study's fill (n, itemBytes, use);
  // returns its data bytes.
  uint64_t nextFill(size_t part, uint64_t n, uint64_t itemBytes, ItemUse use) const;
  std::vector<size_t> itemsOfPart(size_t part, uint64_t n, ItemUse use) const;
  InputError damaged(size_t part, uint64_t bytes) const;
  mutable uint64_t next_ = 0;  // fills taken so far
};

// Orders the parts by shard and checks that they are one complete set: the same identity, N
// parts, each index once. Throws InputError naming what is missing or foreign.
std::vector<PartHeader> checkPartSet(std::vector<PartHeader> parts);

}  // namespace candela
