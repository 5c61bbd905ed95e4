#include "study/run_case.h"

#include "study/compliance/en12464_2.h"

#include "base/error.h"
#include "study/annual_study.h"
#include "study/case/case_file.h"
#include "study/compliance/en12464_2.h"
#include "study/compliance/en13201.h"
#include "study/compliance/en1838.h"
#include "study/finite_results.h"
#include "study/grid_study.h"
#include "study/run_outputs.h"
#include "study/distributed/shard_distribution.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <set>
#include <stdexcept>

namespace candela {

namespace {

namespace fs = std::filesystem;

// The content of every file the run read (base/input_file.h: the case, scene files and what
// they include, data, OBJ, function and vertex files, luminaires, weather, points and portal
// files), as 16 hex digits: parts traced against an edited file are told apart.
std::string inputFingerprint(const RunContext& run) {
  if (!run.inputs) throw std::logic_error("a sharded run without its input log");
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(run.inputs->fingerprint()));
  return hex;
}

PartIdentity partIdentity(const CaseFile& c, const RunContext& run) {
  PartIdentity id;
  id.caseFile = fs::absolute(c.path).lexically_normal().string();
  id.fingerprint = inputFingerprint(run);
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
  if (const auto* merge = dynamic_cast<const MergeDistribution*>(&d)) {
    // Checked once the run has read everything the shards read: a file a scene file includes
    // (`!xform`, a .dat, an OBJ) once changed between shards and the merge mixed both scenes.
    const PartHeader& first = merge->parts().front();
    if (inputFingerprint(run) != first.id.fingerprint)
      throw InputError(FileLoc{(first.dir / kPartManifest).string(), 0, 0},
                       "the case " + first.id.caseFile +
                           " or a file it reads (a scene, an included file, a data, OBJ or luminaire file) changed "
                           "since the shards ran, or differed between them: run the shards again");
  }
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
  const InputFileLog inputs;  // what the run reads: the parts' fingerprint (commitRun)
  RunContext run;
  run.inputs = &inputs;
  run.request = request;
  run.start = std::chrono::steady_clock::now();
  run.startedAt = localTimeNow();
  CaseFile c = readCaseFile(caseFile);
  c.settings.scene = sceneReadOptions(&c.settings, request.trace);
  c.settings.scene.maxMemoryBytes = request.limits.maxMemoryBytes;
  const ComplianceSpec* outdoor = en12464_2Entry(c);
  if (c.grids.empty() && c.surfaceGrids.empty() && !en1838Entry(c) && !en13201Entry(c) &&
      !(outdoor && outdoor->obtrusive.any()))
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
  // The case's files are compared with the parts' fingerprint once the run has read them all
  // (commitRun), before anything is written.
  RunRequest request;
  try {
    request = requestFromJson(first.id.request);
  } catch (const nlohmann::json::exception&) {
    throw InputError(part, "the part's settings cannot be read");
  }
  request.outDir = outDir;
  request.trace.threads = threads;
  const std::string firstDir = first.dir.string();
  const MergeDistribution merge(std::move(headers));
  request.distribution = &merge;
  try {
    return runCase(first.id.caseFile, request, observer);
  } catch (const NonFiniteResult& e) {
    // The shards checked their own items; a NaN now came from the parts' bytes (a part edited
    // with its checksum, say): bad input, not an internal failure.
    throw InputError(part, std::string("the parts hold a value that is not a number (") + e.what() +
                               "): a part in " + firstDir + "'s set is damaged; run the shards again");
  }
}

}  // namespace candela
