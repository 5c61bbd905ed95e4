#include "study/run_case.h"

#include "base/error.h"
#include "study/annual_study.h"
#include "study/case_file.h"
#include "study/grid_study.h"
#include "study/run_outputs.h"
#include "study/shard_distribution.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <set>

namespace candela {

namespace {

namespace fs = std::filesystem;

// FNV-1a over the bytes of the case file and every file it names (scenes, luminaires, weather,
// points files), in a fixed order: parts computed from edited files are told apart. Files a
// scene file includes (`!xform`) are not followed.
std::string caseFingerprint(const CaseFile& c) {
  std::vector<fs::path> files{c.path};
  for (const ScenePath& s : c.scenes) files.push_back(s.file);
  std::set<fs::path> luminaires;
  for (const LuminairePlacement& l : c.luminaires) luminaires.insert(l.file);
  files.insert(files.end(), luminaires.begin(), luminaires.end());
  if (!c.sky.weather.empty()) files.push_back(c.sky.weather);
  for (const GridSpec& g : c.grids)
    if (!g.pointsFile.empty()) files.push_back(g.pointsFile);
  uint64_t h = 0xcbf29ce484222325ULL;
  auto mix = [&h](const char* p, size_t n) {
    for (size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(p[i])) * 0x100000001b3ULL;
  };
  char buf[1 << 16];
  for (const fs::path& f : files) {
    const std::string name = f.filename().string();
    mix(name.data(), name.size() + 1);
    std::ifstream in(f, std::ios::binary);
    while (in.read(buf, sizeof buf) || in.gcount() > 0) mix(buf, static_cast<size_t>(in.gcount()));
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

PartIdentity partIdentity(const CaseFile& c, const RunContext& run) {
  PartIdentity id;
  id.caseFile = fs::absolute(c.path).lexically_normal().string();
  id.fingerprint = caseFingerprint(c);
  RunRequest shown = run.request;
  shown.caseFileShown = c.path.string();  // merge names the case as the shards were given it
  id.request = requestJson(shown);
  id.version = CANDELA_VERSION;
  id.shards = run.request.processes().ranks();
  return id;
}

}  // namespace

std::string requestJson(const RunRequest& r) {
  const TraceOverrides& o = r.trace;
  nlohmann::json j = nlohmann::json::object();
  if (o.quality) j["quality"] = static_cast<int>(*o.quality);
  if (o.bounces) j["bounces"] = *o.bounces;
  if (o.samples) j["samples"] = *o.samples;
  if (o.seed) j["seed"] = *o.seed;
  if (o.method) j["method"] = static_cast<int>(*o.method);
  if (o.targetRelativeError) j["target_relative_error"] = *o.targetRelativeError;
  if (o.patterns) j["patterns"] = static_cast<int>(*o.patterns);
  if (o.nonplanar) j["nonplanar"] = static_cast<int>(*o.nonplanar);
  if (o.objMapping) j["obj_map"] = fs::absolute(*o.objMapping).string();
  j["strict"] = r.strict;
  if (!r.caseFileShown.empty()) j["case_shown"] = r.caseFileShown;
  return j.dump();
}

RunRequest requestFromJson(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  RunRequest r;
  TraceOverrides& o = r.trace;
  if (j.contains("quality")) o.quality = static_cast<Quality>(j["quality"].get<int>());
  if (j.contains("bounces")) o.bounces = j["bounces"].get<int>();
  if (j.contains("samples")) o.samples = j["samples"].get<int>();
  if (j.contains("seed")) o.seed = j["seed"].get<uint64_t>();
  if (j.contains("method")) o.method = static_cast<Method>(j["method"].get<int>());
  if (j.contains("target_relative_error")) o.targetRelativeError = j["target_relative_error"].get<double>();
  if (j.contains("patterns")) o.patterns = static_cast<PatternPolicy>(j["patterns"].get<int>());
  if (j.contains("nonplanar")) o.nonplanar = static_cast<NonplanarPolicy>(j["nonplanar"].get<int>());
  if (j.contains("obj_map")) o.objMapping = j["obj_map"].get<std::string>();
  r.strict = j.value("strict", false);
  r.caseFileShown = j.value("case_shown", std::string());
  return r;
}

void checkOnRankZero(const Distribution& d, const std::function<void()>& check) {
  if (d.ranks() == 1 || d.partial()) {
    check();
    return;
  }
  std::string failure;  // "file\nline\nmessage", empty when the check passed
  if (d.rank() == 0) try {
      check();
    } catch (const InputError& e) {
      failure = e.loc().file + "\n" + std::to_string(e.loc().line) + "\n" + e.message();
    }
  d.broadcast(failure);
  if (failure.empty()) return;
  const size_t a = failure.find('\n'), b = failure.find('\n', a + 1);
  throw InputError(FileLoc{failure.substr(0, a), std::stoi(failure.substr(a + 1, b - a - 1)), 0}, failure.substr(b + 1));
}

void commitRun(const CaseFile& c, const RunContext& run, const std::function<void(const fs::path&)>& write) {
  const Distribution& d = run.request.processes();
  d.finish();
  if (const auto* shard = dynamic_cast<const ShardDistribution*>(&d)) {
    const PartIdentity id = partIdentity(c, run);
    writeRunOutputs(run.outDir, [&](const fs::path& dir) {
      writePart(dir, id, ShardSpec{shard->rank(), shard->ranks()}, shard->fills());
    });
    return;
  }
  if (d.writesOutputs()) writeRunOutputs(run.outDir, write);
}

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

ReportData reportDataFor(const CaseFile& c, const RunContext& run, uint64_t seed) {
  ReportData data;
  data.run.caseName = c.name;
  data.run.description = c.description;
  data.run.caseFile = run.request.caseFileShown.empty() ? c.path.string() : run.request.caseFileShown;
  data.run.version = CANDELA_VERSION;
  data.run.startedAt = run.startedAt;
  data.run.seed = seed;
  data.northDeg = c.site.northDeg;
  return data;
}

RunResult runCase(const std::filesystem::path& caseFile, const RunRequest& request, StudyObserver& observer) {
  RunContext run;
  run.request = request;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = localTimeNow();
  CaseFile c = readCaseFile(caseFile);
  c.settings.scene = sceneReadOptions(&c.settings, request.trace);
  if (c.grids.empty() && c.surfaceGrids.empty())
    throw InputError(FileLoc{c.path.string(), 0, 0}, "the case has no [[grid]] to calculate");
  run.outDir = request.outDir.empty() ? c.output.dir : request.outDir;
  checkOnRankZero(request.processes(), [&] { checkResultFolder(run.outDir); });
  if (c.sky.type.kind == SkyKind::kAnnual) return runAnnualStudy(c, run, observer);
  return runGridStudy(c, run, observer);
}

RunResult mergeParts(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& outDir,
                     int threads, StudyObserver& observer) {
  std::vector<PartHeader> headers;
  for (const std::filesystem::path& p : parts) headers.push_back(readPartHeader(p));
  headers = checkPartSet(std::move(headers));
  const PartHeader& first = headers.front();
  const FileLoc part{(first.dir / kPartManifest).string(), 0, 0};
  if (first.id.version != CANDELA_VERSION)
    throw InputError(part, "computed by candela " + first.id.version + ", this is " + CANDELA_VERSION +
                               ": merge with the candela that ran the shards");
  const CaseFile c = readCaseFile(first.id.caseFile);
  if (caseFingerprint(c) != first.id.fingerprint)
    throw InputError(part, "the case " + first.id.caseFile +
                               " or a file it names changed since the shards ran: run the shards again");
  RunRequest request;
  try {
    request = requestFromJson(first.id.request);
  } catch (const nlohmann::json::exception&) {
    throw InputError(part, "the part's settings cannot be read");
  }
  request.outDir = outDir;
  request.trace.threads = threads;
  const MergeDistribution merge(std::move(headers));
  request.distribution = &merge;
  return runCase(first.id.caseFile, request, observer);
}

}  // namespace candela
