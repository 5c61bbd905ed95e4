#include "engine/radiance/generators.h"
#include "engine/radiance/gen.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace candela {

namespace {

using Generator = std::vector<RadPrimitive> (*)(const RadCommand&, const RadExpandContext&);

// Each generator lives in a file of its own (engine/radiance/gen_*.cpp), declared in engine/radiance/gen.h.
const std::map<std::string, Generator>& generators() {
  static const std::map<std::string, Generator> table = {
      {"xform", expandXform},
      {"genbox", expandGenbox},
      {"genprism", expandGenprism},
      {"gensky", expandGensky},
      {"gendaylit", expandGendaylit},
      {"genrev", expandGenrev},
      {"gensurf", expandGensurf},
      {"genworm", expandGenworm},
  };
  return table;
}

// "xform" for "xform", "/usr/local/bin/xform" and "xform.exe": the program's own name.
std::string programName(const std::string& word) {
  std::string name = word.substr(word.find_last_of("/\\") == std::string::npos ? 0 : word.find_last_of("/\\") + 1);
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".exe") == 0) name.resize(name.size() - 4);
  return name;
}

}  // namespace

RadPrimitive generatedPrimitive(const std::string& modifier, const std::string& type, const std::string& name,
                                const FileLoc& loc, std::vector<std::string> strings, std::vector<double> reals) {
  RadPrimitive p;
  p.modifier = modifier;
  p.type = type;
  p.name = name;
  p.loc = loc;
  p.strings = std::move(strings);
  p.reals = std::move(reals);
  return p;
}

void readFunctionOptions(const RadCommand& cmd, const RadExpandContext& ctx, size_t from, FunctionFiles& files,
                         bool* smooth) {
  const std::vector<std::string>& w = cmd.words;
  const std::string gen = w.empty() ? std::string("generator") : w[0];
  RadPrimitive self;  // for the function files' messages
  self.type = gen;
  self.name = w.size() > 2 ? w[2] : std::string();
  self.loc = cmd.loc;
  for (size_t i = from; i < w.size(); ++i) {
    if (w[i] == "-s" && smooth) {
      *smooth = true;
      continue;
    }
    if ((w[i] == "-e" || w[i] == "-f") && i + 1 < w.size()) {
      try {
        if (w[i] == "-e") files.program()->addText(w[i + 1], "-e");
        else files.load(w[i + 1], self, ctx.folder);
      } catch (const InputError& e) {
        if (w[i] == "-f") throw;  // a file's own line
        throw InputError(cmd.loc, gen + ": -e '" + w[i + 1] + "': " + e.message());
      }
      ++i;
      continue;
    }
    throw InputError(cmd.loc, gen + ": unknown option '" + w[i] + "' (-e expr, -f file" + (smooth ? ", -s)" : ")"));
  }
}

cal::Symbol defineGeneratorFunction(cal::Program& program, const RadCommand& cmd, const std::string& name,
                                    const std::string& params, int arity, const std::string& expression,
                                    const std::string& what) {
  try {
    program.addText(name + "(" + params + ") = " + expression + ";", "-");
  } catch (const InputError& e) {
    throw InputError(cmd.loc, cmd.words[0] + ": " + what + " '" + expression + "' is not an expression: " + e.message());
  }
  program.check(name, arity, cmd.loc, expression);
  return program.find(name);
}

double generatedPrimitivesAllowed(const RadExpandContext& ctx) {
  if (ctx.maxMemoryBytes == 0) return kMaxGeneratedPrimitives;
  return std::min(kMaxGeneratedPrimitives, std::floor(static_cast<double>(ctx.maxMemoryBytes) / kBytesPerGeneratedPrimitive));
}

std::string generatedLimitText(const RadExpandContext& ctx) {
  const double n = generatedPrimitivesAllowed(ctx);
  if (n >= kMaxGeneratedPrimitives) return "the 10000000 primitives a command may make";
  char gib[32];
  std::snprintf(gib, sizeof gib, "%.3g GiB", static_cast<double>(ctx.maxMemoryBytes) / 1073741824.0);
  return "the " + std::to_string(static_cast<long long>(n)) + " primitives --max-memory " + gib +
         " holds (about 1.2 KB each once read)";
}

bool mayExist(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::exists(p, ec) || ec;
}

const std::vector<std::string>& radGeneratorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [name, gen] : generators()) n.push_back(name);
    return n;
  }();
  return names;
}

namespace {

std::vector<RadPrimitive> expandOne(const RadCommand& cmd, const RadExpandContext& ctx) {
  const std::string name = programName(cmd.words.front());
  const auto it = generators().find(name);
  if (it == generators().end()) {
    std::string list;
    for (const std::string& n : radGeneratorNames()) list += (list.empty() ? "" : ", ") + n;
    throw InputError(cmd.loc, "'!" + name + "' is not a generator candela can expand; it expands: " +
                                  (list.empty() ? std::string("none yet") : list) +
                                  " (scene files never run programs)");
  }
  return it->second(cmd, ctx);
}

}  // namespace

std::vector<RadPrimitive> expandRadCommand(const RadCommand& cmd, const RadExpandContext& ctx) {
  // Split at "|" words; a pipe glued to a word ("a|b") is not a pipeline Radiance's files write.
  std::vector<RadCommand> stages(1);
  for (const std::string& w : cmd.words) {
    if (w == "|") {
      if (stages.back().words.empty()) throw InputError(cmd.loc, "an inline command has an empty stage before '|'");
      stages.emplace_back();
    } else {
      stages.back().words.push_back(w);
    }
  }
  if (stages.back().words.empty()) throw InputError(cmd.loc, "an inline command ends with '|'");
  std::vector<RadPrimitive> out;
  for (size_t i = 0; i < stages.size(); ++i) {
    stages[i].loc = cmd.loc;
    RadExpandContext stageCtx = ctx;
    stageCtx.standardInput = i == 0 ? ctx.standardInput : &out;
    std::vector<RadPrimitive> next = expandOne(stages[i], stageCtx);
    out = std::move(next);
  }
  return out;
}

}  // namespace candela
