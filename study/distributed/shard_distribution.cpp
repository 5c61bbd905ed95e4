#include "study/distributed/shard_distribution.h"

#include "base/atomic_file.h"
#include "base/error.h"
#include "base/input_file.h"
#include "base/parallel.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

namespace candela {

namespace fs = std::filesystem;

namespace {

// fills.bin: per fill a header of six little-endian uint64 (magic, items, itemBytes, chunk,
// use, data bytes) and the data.
constexpr uint64_t kFillMagic = 0x4c4c49464c444e43ULL;  // "CNDLFILL"
// 2: part.json carries fills.bin's checksum.
constexpr int kPartFormat = 2;
// What a part.json may say before anything is made of it: a merge of more shards than --shard
// accepts (6 digits) is not a part, and no manifest this candela writes comes near 1 MiB.
constexpr int64_t kMaxShards = 999'999;
constexpr uint64_t kMaxManifestBytes = 1 << 20;
constexpr size_t kMaxManifestText = 4096;  // a field quoted in messages or compared (version, case path)

// fills.bin's checksum as part.json gives it: FNV-1a 64 of every byte, 16 hex digits.
std::string checksumText(uint64_t h) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

uint64_t fileChecksum(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> buf(1 << 16);
  uint64_t h = fnv1a("", 0);
  while (in.read(buf.data(), static_cast<std::streamsize>(buf.size())) || in.gcount() > 0)
    h = fnv1a(buf.data(), static_cast<size_t>(in.gcount()), h);
  return h;
}

struct FillHeader {
  uint64_t magic = kFillMagic, items = 0, itemBytes = 0, chunk = 0, use = 0, dataBytes = 0;
};
static_assert(sizeof(FillHeader) == 48);

FileLoc at(const fs::path& dir, const char* file) { return FileLoc{(dir / file).string(), 0, 0}; }

// The items of shard `index` of `shards` in a fill of n: chunks c with c mod shards = index.
std::vector<size_t> shareOf(uint64_t n, uint64_t chunk, int index, int shards) {
  std::vector<size_t> mine;
  for (uint64_t b = chunk * index; b < n; b += chunk * shards)
    for (uint64_t i = b; i < std::min<uint64_t>(n, b + chunk); ++i) mine.push_back(i);
  return mine;
}

// Sizes, then bytes, of the lists `which`.
std::vector<std::byte> packLists(const std::vector<std::vector<std::byte>>& lists, const std::vector<size_t>& which) {
  std::vector<std::byte> out(which.size() * sizeof(uint64_t));
  for (size_t k = 0; k < which.size(); ++k) {
    const uint64_t size = lists[which[k]].size();
    std::memcpy(out.data() + k * sizeof size, &size, sizeof size);
  }
  for (size_t i : which) out.insert(out.end(), lists[i].begin(), lists[i].end());
  return out;
}


}  // namespace

ShardSpec parseShard(const std::string& text) {
  const std::invalid_argument bad("--shard wants i/N with 0 <= i < N (e.g. 0/4), got '" + text + "'");
  const size_t slash = text.find('/');
  auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) throw bad;
    return std::stoi(s);
  };
  if (slash == std::string::npos) throw bad;
  ShardSpec s{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (s.count < 1 || s.index >= s.count) throw bad;
  return s;
}

uint64_t shardChunkItems(uint64_t items, int shards) {
  const uint64_t parts = 16 * static_cast<uint64_t>(std::max(1, shards));
  return std::max<uint64_t>(1, (items + parts - 1) / parts);
}

void ShardDistribution::fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
                             const std::function<void(size_t)>& compute) const {
  FillRecord rec;
  rec.items = n;
  rec.itemBytes = itemBytes;
  rec.use = use;
  rec.chunk = shardChunkItems(n, spec_.count);
  if (use == ItemUse::kShared) {
    parallelFor(n, threads, compute);
    if (spec_.index == 0) rec.data.assign(items, items + n * itemBytes);
  } else {
    // This shard's chunks, in order, as one list of items.
    const std::vector<size_t> mine = shareOf(n, rec.chunk, spec_.index, spec_.count);
    parallelFor(mine.size(), threads, [&](size_t k) { compute(mine[k]); });
    rec.data.resize(mine.size() * itemBytes);
    for (size_t k = 0; k < mine.size(); ++k)
      std::memcpy(rec.data.data() + k * itemBytes, items + mine[k] * itemBytes, itemBytes);
  }
  fills_.push_back(std::move(rec));
}


void ShardDistribution::fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                                  const std::function<void(size_t, std::vector<std::byte>&)>& compute) const {
  FillRecord rec;
  rec.items = lists.size();
  rec.itemBytes = 0;
  rec.use = use;
  rec.chunk = shardChunkItems(lists.size(), spec_.count);
  std::vector<size_t> which;
  if (use == ItemUse::kShared) {
    for (size_t i = 0; i < lists.size(); ++i) which.push_back(i);
  } else {
    which = shareOf(lists.size(), rec.chunk, spec_.index, spec_.count);
  }
  parallelFor(which.size(), threads, [&](size_t k) {
    lists[which[k]].clear();
    compute(which[k], lists[which[k]]);
  });
  if (use == ItemUse::kResult || spec_.index == 0) rec.data = packLists(lists, which);
  fills_.push_back(std::move(rec));
}

void writePart(const fs::path& dir, const PartIdentity& id, ShardSpec spec, const std::vector<FillRecord>& fills) {
  // The folder is the run's fresh temporary one (study/run_outputs.h): a new file in it cannot
  // meet a planted link.
  std::ofstream out(dir / kPartData, std::ios::binary | std::ios::trunc);
  uint64_t bytes = 0, sum = fnv1a("", 0);
  for (const FillRecord& f : fills) {
    FillHeader h;
    h.items = f.items;
    h.itemBytes = f.itemBytes;
    h.chunk = f.chunk;
    h.use = f.use == ItemUse::kShared ? 1 : 0;
    h.dataBytes = f.data.size();
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(reinterpret_cast<const char*>(f.data.data()), static_cast<std::streamsize>(f.data.size()));
    sum = fnv1a(f.data.data(), f.data.size(), fnv1a(&h, sizeof h, sum));
    bytes += sizeof h + f.data.size();
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write " + (dir / kPartData).string());
  nlohmann::json j;
  j["format"] = "candela-part";
  j["format_version"] = kPartFormat;
  j["candela"] = id.version;
  j["case"] = id.caseFile;
  j["fingerprint"] = id.fingerprint;
  j["request"] = id.request;
  j["shard"] = spec.index;
  j["shards"] = spec.count;
  j["fills"] = fills.size();
  j["data_bytes"] = bytes;
  j["data_checksum"] = checksumText(sum);
  writeFileAtomic(dir / kPartManifest, j.dump(2) + "\n");
}

PartHeader readPartHeader(const fs::path& dir) {
  const FileLoc manifest = at(dir, kPartManifest);
  std::error_code sizeError;
  const uintmax_t manifestBytes = fs::file_size(dir / kPartManifest, sizeError);
  std::ifstream in(dir / kPartManifest);
  if (sizeError || !in) throw InputError(manifest, "not a candela part (no part.json): was the shard run finished?");
  if (manifestBytes > kMaxManifestBytes)
    throw InputError(manifest, "not a candela part (part.json has " + std::to_string(manifestBytes) +
                                   " bytes, a part's has a few hundred)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    throw InputError(manifest, "not a candela part (part.json is not JSON)");
  }
  PartHeader h;
  h.dir = dir;
  // Every count is checked before it is used: a 280-byte part.json with "shards": 20000000 once
  // printed a 369 MB message naming each missing shard.
  auto count = [&](const char* key, int64_t lo, int64_t hi) {
    const nlohmann::json& v = j.at(key);
    if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi || (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(hi)))
      throw InputError(manifest, std::string("part.json: \"") + key + "\" must be an integer from " + std::to_string(lo) +
                                     " to " + std::to_string(hi));
    return v.get<int64_t>();
  };
  auto text = [&](const char* key) {
    std::string v = j.at(key).get<std::string>();
    if (v.size() > kMaxManifestText)
      throw InputError(manifest, std::string("part.json: \"") + key + "\" is longer than " +
                                     std::to_string(kMaxManifestText) + " characters");
    return v;
  };
  std::string checksum;
  try {
    if (!j.is_object() || j.at("format") != "candela-part" || j.at("format_version") != kPartFormat)
      throw InputError(manifest, "a part of another format (this candela reads version " + std::to_string(kPartFormat) +
                                     "): run the shards again with this candela");
    h.id.version = text("candela");
    h.id.caseFile = text("case");
    h.id.fingerprint = text("fingerprint");
    h.id.request = j.at("request").get<std::string>();
    if (h.id.request.size() > kMaxManifestBytes) throw InputError(manifest, "part.json: \"request\" is too long");
    h.id.shards = static_cast<int>(count("shards", 1, kMaxShards));
    h.spec = {static_cast<int>(count("shard", 0, kMaxShards - 1)), h.id.shards};
    h.dataBytes = static_cast<uint64_t>(count("data_bytes", 0, std::numeric_limits<int64_t>::max()));
    // Each fill has a header of 48 bytes.
    h.fills = static_cast<uint64_t>(count("fills", 0, static_cast<int64_t>(h.dataBytes / sizeof(FillHeader))));
    checksum = text("data_checksum");
  } catch (const nlohmann::json::exception&) {
    throw InputError(manifest, "part.json lacks a field or has one of the wrong type");
  }
  if (h.spec.index >= h.spec.count)
    throw InputError(manifest, "part.json: shard " + std::to_string(h.spec.index) + " of " +
                                   std::to_string(h.spec.count) + " is not a shard");
  std::error_code ec;
  const uint64_t size = fs::file_size(dir / kPartData, ec);
  if (ec || size != h.dataBytes)
    throw InputError(at(dir, kPartData), "the part is incomplete: fills.bin holds " +
                                             (ec ? std::string("nothing") : std::to_string(size) + " bytes") + ", part.json says " +
                                             std::to_string(h.dataBytes));
  // A same-size damaged copy (one double changed) once merged into -179 000 lx.
  if (checksumText(fileChecksum(dir / kPartData)) != checksum)
    throw InputError(at(dir, kPartData), "the part is damaged: fills.bin's checksum differs from part.json's");
  return h;
}

std::vector<PartHeader> checkPartSet(std::vector<PartHeader> parts) {
  if (parts.empty()) throw InputError(FileLoc{"merge", 0, 0}, "no parts to merge");
  const PartHeader& first = parts.front();
  for (const PartHeader& p : parts) {
    auto differs = [&](const std::string& what) {
      return InputError(at(p.dir, kPartManifest), "belongs to another run than " + first.dir.string() + " (" + what +
                                                     " differ)");
    };
    if (p.id.version != first.id.version) throw differs("candela versions");
    if (p.id.caseFile != first.id.caseFile) throw differs("case files");
    if (p.id.fingerprint != first.id.fingerprint) throw differs("the case's files");
    if (p.id.request != first.id.request) throw differs("settings or seed");
    if (p.id.shards != first.id.shards) throw differs("shard counts");
  }
  const int n = first.id.shards;
  std::map<int, PartHeader> byIndex;
  for (PartHeader& p : parts) {
    const auto [it, fresh] = byIndex.emplace(p.spec.index, p);
    if (!fresh)
      throw InputError(at(p.dir, kPartManifest), "shard " + std::to_string(p.spec.index) + " is given twice (also " +
                                                     it->second.dir.string() + ")");
  }
  // Named up to 8 (the count says the rest): the message stays one short line for any N.
  std::string missing;
  int absent = 0;
  for (int i = 0; i < n; ++i)
    if (!byIndex.count(i) && ++absent <= 8)
      missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(n);
  if (absent > 8) missing += " and " + std::to_string(absent - 8) + " more";
  if (absent > 0)
    throw InputError(at(first.dir, kPartManifest), "the parts are incomplete: shard " + missing + " missing");
  std::vector<PartHeader> ordered;
  for (auto& [i, p] : byIndex) ordered.push_back(std::move(p));
  return ordered;
}

struct MergeDistribution::Reader {
  std::ifstream in;
  uint64_t read = 0;  // fills read
  uint64_t left = 0;  // bytes of fills.bin not read yet
};

MergeDistribution::MergeDistribution(std::vector<PartHeader> parts) : parts_(std::move(parts)) {
  for (const PartHeader& p : parts_) {
    auto r = std::make_unique<Reader>();
    r->in.open(p.dir / kPartData, std::ios::binary);
    if (!r->in) throw InputError(at(p.dir, kPartData), "cannot read the part");
    r->left = p.dataBytes;
    readers_.push_back(std::move(r));
  }
}

MergeDistribution::~MergeDistribution() = default;

uint64_t MergeDistribution::nextFill(size_t part, uint64_t n, uint64_t itemBytes, ItemUse use) const {
  const PartHeader& p = parts_[part];
  Reader& r = *readers_[part];
  const uint64_t k = next_;
  auto foreign = [&](const std::string& what) {
    return InputError(at(p.dir, kPartData), "fill " + std::to_string(k + 1) + " " + what +
                                                ": the part was computed from another case, scene or settings");
  };
  FillHeader h;
  if (r.read >= p.fills || r.left < sizeof h || !r.in.read(reinterpret_cast<char*>(&h), sizeof h))
    throw foreign("is missing");
  ++r.read;
  r.left -= sizeof h;
  if (h.magic != kFillMagic) throw foreign("is damaged");
  const uint64_t chunk = shardChunkItems(n, static_cast<int>(parts_.size()));
  if (h.items != n || h.itemBytes != itemBytes || h.chunk != chunk || h.use != (use == ItemUse::kShared ? 1u : 0u))
    throw foreign("has " + std::to_string(h.items) + " items of " + std::to_string(h.itemBytes) + " bytes, the case " +
                  std::to_string(n) + " of " + std::to_string(itemBytes));
  // The fill's size, bounded by what the file holds before anything is allocated for it.
  if (h.dataBytes > r.left) throw damaged(part, h.dataBytes);
  r.left -= h.dataBytes;
  return h.dataBytes;
}

// The items of part s in a fill: all (kShared, part 0), none (kShared, the others), its share.
std::vector<size_t> MergeDistribution::itemsOfPart(size_t s, uint64_t n, ItemUse use) const {
  const int shards = static_cast<int>(parts_.size());
  if (use == ItemUse::kResult) return shareOf(n, shardChunkItems(n, shards), static_cast<int>(s), shards);
  std::vector<size_t> all;
  if (s == 0)
    for (size_t i = 0; i < n; ++i) all.push_back(i);
  return all;
}

void MergeDistribution::fill(std::byte* items, size_t n, size_t itemBytes, ItemUse use, int threads,
                             const std::function<void(size_t)>& compute) const {
  (void)threads;
  (void)compute;  // nothing is computed again: the parts hold every item
  for (size_t s = 0; s < parts_.size(); ++s) {
    const uint64_t bytes = nextFill(s, n, itemBytes, use);
    const std::vector<size_t> which = itemsOfPart(s, n, use);
    Reader& r = *readers_[s];
    if (bytes != which.size() * itemBytes) throw damaged(s, bytes);
    // The share's items in order: read run by run of consecutive items.
    for (size_t k = 0; k < which.size();) {
      size_t e = k + 1;
      while (e < which.size() && which[e] == which[e - 1] + 1) ++e;
      r.in.read(reinterpret_cast<char*>(items + which[k] * itemBytes), static_cast<std::streamsize>((e - k) * itemBytes));
      k = e;
    }
    if (!r.in) throw damaged(s, bytes);
  }
  ++next_;
}

void MergeDistribution::fillLists(std::vector<std::vector<std::byte>>& lists, ItemUse use, int threads,
                                  const std::function<void(size_t, std::vector<std::byte>&)>& compute) const {
  (void)threads;
  (void)compute;
  for (size_t s = 0; s < parts_.size(); ++s) {
    const uint64_t bytes = nextFill(s, lists.size(), 0, use);
    const std::vector<size_t> which = itemsOfPart(s, lists.size(), use);
    Reader& r = *readers_[s];
    if (which.size() > bytes / sizeof(uint64_t)) throw damaged(s, bytes);
    std::vector<uint64_t> sizes(which.size());
    r.in.read(reinterpret_cast<char*>(sizes.data()), static_cast<std::streamsize>(sizes.size() * sizeof(uint64_t)));
    // Summed without wrapping: sizes whose sum wraps to the fill's size once allocated 3 GiB.
    uint64_t total = sizes.size() * sizeof(uint64_t);
    for (uint64_t z : sizes) {
      if (z > bytes - total) throw damaged(s, bytes);
      total += z;
    }
    if (!r.in || total != bytes) throw damaged(s, bytes);
    for (size_t k = 0; k < which.size(); ++k) {
      lists[which[k]].resize(sizes[k]);
      r.in.read(reinterpret_cast<char*>(lists[which[k]].data()), static_cast<std::streamsize>(sizes[k]));
    }
    if (!r.in) throw damaged(s, bytes);
  }
  ++next_;
}

InputError MergeDistribution::damaged(size_t part, uint64_t bytes) const {
  return InputError(at(parts_[part].dir, kPartData), "fill " + std::to_string(next_ + 1) + " holds " +
                                                         std::to_string(bytes) +
                                                         " bytes, not the case's: the part is damaged or was computed "
                                                         "from another case, scene or settings");
}

void MergeDistribution::finish() const {
  for (size_t s = 0; s < parts_.size(); ++s)
    if (readers_[s]->read != parts_[s].fills)
      throw InputError(at(parts_[s].dir, kPartData), "holds " + std::to_string(parts_[s].fills) + " fills, the case made " +
                                                         std::to_string(readers_[s]->read) +
                                                         ": the part was computed from another case, scene or settings");
}

}  // namespace candela
