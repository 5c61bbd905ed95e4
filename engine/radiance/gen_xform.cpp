// xform(1), interpreted: the facts (option order, -a and -f rewritten into separate invocations,
// names, what each type's arguments become) are those of Radiance's src/gen/xform.c and
// doc/man/man1/xform.1; the code is candela's. docs/engine.md, "xform: names and files", states
// the rules and where candela differs.
#include "base/input_file.h"
#include "engine/radiance/file_lookup.h"
#include "engine/radiance/gen.h"
#include "engine/radiance/transform.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

namespace candela {

namespace {

namespace fs = std::filesystem;


// Argument files naming argument files: refused this deep (a file naming itself).
constexpr int kMaxArgFileDepth = 32;
// The largest -a count (the -i count it becomes has the same bound in radiance/transform).
constexpr long kMaxArrayCount = 1000000;
// The most -a and -f options one command may hold (each nests the expansion once more).
constexpr size_t kMaxArrayOptions = 1000;

// What xform does to a type's arguments (xform.c's initotypes: o_* and m_* functions, addxform for
// every type with a function file, o_default for the rest).
enum class Args {
  kDefault, kSource, kSphere, kFace, kCone, kCylinder, kRing, kAddXform,
  kGlow, kSpot, kDielectric, kInterface, kMist, kText, kAlias
};

struct TypeRule {
  Args args;
  bool object;          // a surface or volume (otypes.h T_S|T_V): gets -n, -m and -I; modifiers do not
  const char* inverse;  // the type -I turns it into (xform.c's tinvers)
};

const std::map<std::string, TypeRule>& typeRules() {
  static const std::map<std::string, TypeRule> rules = [] {
    std::map<std::string, TypeRule> r = {
        {"polygon", {Args::kFace, true, "polygon"}},       {"source", {Args::kSource, true, "source"}},
        {"sphere", {Args::kSphere, true, "bubble"}},       {"bubble", {Args::kSphere, true, "sphere"}},
        {"cone", {Args::kCone, true, "cup"}},              {"cup", {Args::kCone, true, "cone"}},
        {"cylinder", {Args::kCylinder, true, "tube"}},     {"tube", {Args::kCylinder, true, "cylinder"}},
        {"ring", {Args::kRing, true, "ring"}},             {"instance", {Args::kAddXform, true, "instance"}},
        {"mesh", {Args::kAddXform, true, "mesh"}},         {"alias", {Args::kAlias, false, ""}},
        {"glow", {Args::kGlow, false, ""}},                {"spotlight", {Args::kSpot, false, ""}},
        {"dielectric", {Args::kDielectric, false, ""}},    {"interface", {Args::kInterface, false, ""}},
        {"mist", {Args::kMist, false, ""}},                {"colortext", {Args::kText, false, ""}},
        {"brighttext", {Args::kText, false, ""}},          {"mixtext", {Args::kText, false, ""}},
    };
    // otypes.h: the types flagged T_F (a function file) take the transform after their strings.
    for (const char* t : {"texfunc", "plastic2", "metal2", "trans2", "plasfunc", "metfunc", "brightfunc",
                          "brightdata", "colorpict", "transfunc", "BRTDfunc", "BSDF", "aBSDF", "WGMDfunc",
                          "plasdata", "metdata", "transdata", "colorfunc", "colordata", "texdata", "mixfunc",
                          "mixdata", "mixpict", "prism1", "prism2", "ashik2", "specfunc", "specdata", "specpict"})
      r[t] = {Args::kAddXform, false, ""};
    for (const char* t : {"plastic", "metal", "glass", "trans", "light", "illum", "mirror", "antimatter",
                          "spectrum", "specfile"})
      r[t] = {Args::kDefault, false, ""};
    return r;
  }();
  return rules;
}

// One invocation's settings, after -a and -f are rewritten away (xform.c's globals).
struct Invocation {
  RadTransform xf;
  double scale = 1.0;     // |xf.scale|
  bool reverse = false;   // polygon vertices in reverse order: a mirror, or -I (not both)
  bool invert = false;    // -I
  std::optional<std::string> newmod, prefix;
  std::vector<std::string> xfWords;  // the transform as written, appended to function types' strings
};

// Argument counts xform checks before it transforms (it stops with "bad TYPE" otherwise).
void expectCounts(const RadPrimitive& p, size_t strings, size_t reals, bool atLeast = false) {
  const bool ok = p.strings.size() == strings && (atLeast ? p.reals.size() >= reals : p.reals.size() == reals);
  if (!ok)
    throw InputError(p.loc, p.type + " '" + p.name + "' needs " + std::to_string(strings) + " string and " +
                                (atLeast ? "at least " : "") + std::to_string(reals) +
                                " real arguments to be transformed by xform, got " + std::to_string(p.strings.size()) +
                                " and " + std::to_string(p.reals.size()));
}

void setPoint(std::vector<double>& r, size_t i, const RadTransform& xf) {
  const Vec3 q = xf.point(Vec3(r[i], r[i + 1], r[i + 2]));
  r[i] = q.x, r[i + 1] = q.y, r[i + 2] = q.z;
}

// A direction through the matrix (xform.c's multv3: its length grows by the scale).
void setDirection(std::vector<double>& r, size_t i, const RadTransform& xf) {
  const Vec3 q = xf.direction(Vec3(r[i], r[i + 1], r[i + 2]));
  r[i] = q.x, r[i + 1] = q.y, r[i + 2] = q.z;
}

// xform.c's m_mist: each source name in a string ("a>b" lists several) gets the prefix.
std::string prefixEach(const std::string& s, const std::string& prefix) {
  std::string out;
  size_t start = 0;
  while (start < s.size()) {
    const size_t gt = s.find('>', start);
    const size_t end = gt == std::string::npos ? s.size() : gt + 1;
    out += prefix + "." + s.substr(start, end - start);
    start = end;
  }
  return out;
}

void transformArguments(RadPrimitive& p, Args args, const Invocation& v) {
  std::vector<double>& r = p.reals;
  switch (args) {
    case Args::kDefault:
    case Args::kAlias:
      return;
    case Args::kSource:
      expectCounts(p, 0, 4);
      setDirection(r, 0, v.xf);
      return;
    case Args::kSphere:
      expectCounts(p, 0, 4);
      setPoint(r, 0, v.xf);
      r[3] *= v.scale;
      return;
    case Args::kFace: {
      if (!p.strings.empty() || r.size() % 3 != 0)
        throw InputError(p.loc, "polygon '" + p.name + "' needs no string arguments and a multiple of 3 reals "
                                "to be transformed by xform, got " + std::to_string(r.size()));
      for (size_t i = 0; i < r.size(); i += 3) setPoint(r, i, v.xf);
      if (v.reverse && r.size() >= 6)  // fewer vertices: left for the reader to refuse
        for (size_t i = 0, j = r.size() - 3; i < j; i += 3, j -= 3)
          for (size_t c = 0; c < 3; ++c) std::swap(r[i + c], r[j + c]);
      return;
    }
    case Args::kCone:
      expectCounts(p, 0, 8);
      setPoint(r, 0, v.xf);
      setPoint(r, 3, v.xf);
      r[6] *= v.scale, r[7] *= v.scale;
      return;
    case Args::kCylinder:
      expectCounts(p, 0, 7);
      setPoint(r, 0, v.xf);
      setPoint(r, 3, v.xf);
      r[6] *= v.scale;
      return;
    case Args::kRing:
      expectCounts(p, 0, 8);
      setPoint(r, 0, v.xf);
      setDirection(r, 3, v.xf);
      if (v.invert) r[3] = -r[3], r[4] = -r[4], r[5] = -r[5];
      r[6] *= v.scale, r[7] *= v.scale;
      return;
    case Args::kAddXform: {
      // xform.c's addxform: "-i 1" first closes a repeat the strings may already end in.
      std::vector<std::string>& s = p.strings;
      if (!v.xfWords.empty() && v.xfWords.front() != "-i") s.insert(s.end(), {"-i", "1"});
      s.insert(s.end(), v.xfWords.begin(), v.xfWords.end());
      return;
    }
    case Args::kGlow:
      expectCounts(p, 0, 4);
      r[3] *= v.scale;  // the radius of influence is a length
      return;
    case Args::kSpot:
      expectCounts(p, 0, 7);
      setDirection(r, 4, v.xf);
      return;
    case Args::kDielectric:
      // Transmission per unit length: over a length scaled by s it is t^(1/s) per new unit.
      expectCounts(p, 0, 5);
      for (size_t i = 0; i < 3; ++i) r[i] = std::pow(r[i], 1.0 / v.scale);
      return;
    case Args::kInterface:
      expectCounts(p, 0, 8);
      for (size_t i : {0, 1, 2, 4, 5, 6}) r[i] = std::pow(r[i], 1.0 / v.scale);
      return;
    case Args::kMist:
      if (r.size() > 7)
        throw InputError(p.loc, "mist '" + p.name + "' takes at most 7 real arguments, got " + std::to_string(r.size()));
      if (v.prefix)
        for (std::string& s : p.strings) s = prefixEach(s, *v.prefix);
      if (r.size() > 2)
        for (size_t i = 0; i < 3; ++i) r[i] /= v.scale;  // extinction per unit length
      return;
    case Args::kText:
      if (r.size() < 9)
        throw InputError(p.loc, p.type + " '" + p.name + "' needs at least 9 real arguments, got " +
                                    std::to_string(r.size()));
      setPoint(r, 0, v.xf);
      setDirection(r, 3, v.xf);
      setDirection(r, 6, v.xf);
      return;
  }
}

// xform.c's xfobject: objects get the new modifier, the inverse type and the prefixed name;
// modifiers keep theirs. A type xform does not know passes untouched, for the reader to report.
RadPrimitive transformPrimitive(const RadPrimitive& in, const Invocation& v) {
  RadPrimitive p = in;
  const auto it = typeRules().find(p.type);
  if (it == typeRules().end()) return p;
  const TypeRule& rule = it->second;
  transformArguments(p, rule.args, v);
  if (rule.object) {
    if (v.newmod) p.modifier = *v.newmod;
    if (v.invert) p.type = rule.inverse;
    if (v.prefix) p.name = *v.prefix + "." + p.name;
  }
  return p;
}

bool parseCount(const std::string& w, long& n) {
  const char* b = w.data();
  const char* e = b + w.size();
  const auto r = std::from_chars(b, e, n);
  return r.ec == std::errc() && r.ptr == e;
}

std::string formatCount(double n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, n < 1e15 ? "%.0f" : "%.3g", n);
  return buf;
}

// One `!xform` command, run as xform.c's main: -f and -a become separate invocations with
// rewritten arguments, each of which transforms its files.
class XformExpansion {
 public:
  XformExpansion(const RadCommand& cmd, const RadExpandContext& ctx, const std::vector<RadPrimitive>* input)
      : cmd_(cmd), ctx_(ctx), input_(input) {}

  std::vector<RadPrimitive> run() {
    checkOptions(cmd_.words);
    std::vector<std::string> words = cmd_.words;  // edited in place by array(), restored after
    invoke(words, 1.0, 0);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& msg) const { throw InputError(cmd_.loc, "xform: " + msg); }

  // At most kMaxArrayOptions -a and -f options in one invocation (each nests it once more).
  void checkOptions(const std::vector<std::string>& av) const {
    size_t options = 0;
    for (const std::string& w : av) options += w == "-a" || w == "-f";
    if (options > kMaxArrayOptions)
      fail(std::to_string(options) + " -a and -f options in one command, more than " +
           std::to_string(kMaxArrayOptions) + " (each nests the command once more)");
  }

  // `copies`: how many invocations this one stands for (the product of the enclosing -a counts
  // and argument files' line counts), for the bound.
  void invoke(std::vector<std::string>& av, double copies, int argDepth) {
    for (size_t a = 1; a < av.size(); ++a)
      if (av[a] == "-f") return fromArgFile(av, a, copies, argDepth);
    for (size_t a = 1; a < av.size(); ++a)
      if (av[a] == "-a") return array(av, a, copies, argDepth);
    single(av, copies);
  }

  // A file the command names, found as Radiance finds files (engine/radiance/file_lookup.h).
  fs::path resolve(const std::string& name, const char* role) const {
    return findSceneFile(name, ctx_.folder, cmd_.loc, "xform", role, ctx_.root);
  }

  // xform.c's doargf: each line not empty and not a comment is one invocation, the line's words
  // put in place of "-f file"; its name prefix is "-n" X.k (k the line's index) or "ik".
  void fromArgFile(const std::vector<std::string>& av, size_t fi, double copies, int argDepth) {
    if (fi + 1 >= av.size() || (av[fi + 1][0] == '-' && av[fi + 1].size() > 1)) fail("-f needs an argument file");
    if (av[fi + 1] == "-") fail("-f - reads arguments from the standard input, which a scene file cannot give");
    if (argDepth >= kMaxArgFileDepth)
      fail("argument files name each other more than " + std::to_string(kMaxArgFileDepth) +
           " levels deep (does '" + av[fi + 1] + "' name itself?)");
    const fs::path path = resolve(av[fi + 1], "argument file");
    const std::vector<ArgLine> lines = argLines(readInputFile(path, "xform argument file"));
    long n = 0;
    for (const ArgLine& l : lines) n += !l.text.empty() && l.text[0] != '#';
    if (n == 0) fail("the argument file '" + av[fi + 1] + "' has no argument lines");
    multipliers_.push_back("-f " + av[fi + 1] + " (" + std::to_string(n) + " lines)");
    checkCopies(copies * n);
    long k = 0;
    for (const ArgLine& line : lines) {
      const std::string& l = line.text;
      if (l.empty() || l[0] == '#') continue;
      std::string_view rest(l);
      if (!rest.empty() && rest[0] == '!') rest.remove_prefix(1);
      if (rest.substr(0, 6) == "xform ") rest.remove_prefix(6);
      std::vector<std::string> nav(av.begin(), av.begin() + fi);
      for (std::string& w : splitWords(rest, FileLoc{path.string(), line.line, 0})) nav.push_back(std::move(w));
      nav.insert(nav.end(), av.begin() + fi + 2, av.end());
      bool named = false;
      for (size_t i = 2; i < nav.size() && !named; ++i)
        if (nav[i - 1] == "-n") nav[i].append(".").append(std::to_string(k)), named = true;
      if (!named) nav.insert(nav.begin() + 1, {"-n", std::string("i").append(std::to_string(k))});
      try {
        checkOptions(nav);
        invoke(nav, copies * n, argDepth + 1);
      } catch (const InputError& e) {
        // The command's own errors: say which argument line made them.
        if (e.loc().file != cmd_.loc.file || e.loc().line != cmd_.loc.line) throw;
        throw InputError(e.loc(), e.message() + " (argument file '" + av[fi + 1] + "' line " +
                                      std::to_string(line.line) + ")");
      }
      ++k;
    }
    multipliers_.pop_back();
  }

  struct ArgLine {
    std::string text;
    int line;  // where it starts in the argument file
  };

  // Lines as Radiance's fgetline reads them: a backslash before the newline continues the line.
  static std::vector<ArgLine> argLines(const std::string& text) {
    std::vector<ArgLine> lines;
    bool continued = false;
    int lineNo = 1;
    for (size_t start = 0; start < text.size(); ++lineNo) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      const std::string part = text.substr(start, end - start);
      if (continued) lines.back().text += part;
      else lines.push_back({part, lineNo});
      std::string& t = lines.back().text;
      continued = !t.empty() && t.back() == '\\';
      if (continued) t.back() = ' ';
      start = end + 1;
    }
    return lines;
  }

  // xform.c's doarray: copy i replaces "-a N" by "-i i" (zero applications for the first copy)
  // and its name prefix is "-n" X.i, or "ai". The words are edited in place and restored, so
  // that nested arrays take memory in proportion to the command, not its square.
  void array(std::vector<std::string>& av, size_t ai, double copies, int argDepth) {
    long n = 0;
    if (ai + 1 >= av.size() || !parseCount(av[ai + 1], n) || n <= 0 || n > kMaxArrayCount)
      fail("-a needs a whole count from 1 to " + std::to_string(kMaxArrayCount) +
           (ai + 1 < av.size() ? ", not '" + av[ai + 1] + "'" : std::string()));
    multipliers_.push_back("-a " + av[ai + 1]);
    checkCopies(copies * n);
    std::vector<size_t> names;
    for (size_t i = 1; i < av.size(); ++i)
      if (av[i - 1] == "-n") names.push_back(i);
    std::vector<std::string> savedNames;
    for (size_t j : names) savedNames.push_back(av[j]);
    const std::string count = av[ai + 1];
    const std::string last = names.empty() ? std::string() : av[names.back()];
    av[ai] = "-i";
    for (long i = 0; i < n; ++i) {
      for (size_t j : names) av[j] = last + "." + std::to_string(i);
      av[ai + 1] = std::to_string(i);
      if (names.empty()) {
        av.insert(av.begin() + 1, {"-n", "a" + std::to_string(i)});
        invoke(av, copies * n, argDepth);
        av.erase(av.begin() + 1, av.begin() + 3);
      } else {
        invoke(av, copies * n, argDepth);
      }
    }
    av[ai] = "-a";
    av[ai + 1] = count;
    for (size_t k = 0; k < names.size(); ++k) av[names[k]] = savedNames[k];
    multipliers_.pop_back();
  }

  void checkCopies(double copies) const {
    if (copies > generatedPrimitivesAllowed(ctx_))
      fail("makes " + formatCount(copies) + " copies (" + multiplierText() + "), more than " + generatedLimitText(ctx_));
  }

  std::string multiplierText() const {
    std::string s;
    for (const std::string& m : multipliers_) s += (s.empty() ? "" : " × ") + m;
    return s;
  }

  // xform.c's main without -f and -a: initial options, the transform, then the files.
  void single(const std::vector<std::string>& av, double copies) {
    Invocation v;
    size_t a = 1;
    for (; a < av.size(); ++a) {
      const std::string& w = av[a];
      if (w.size() != 2 || w[0] != '-') break;
      if ((w[1] == 'm' || w[1] == 'n') && a + 1 < av.size()) {
        const std::string& value = av[++a];
        if (w[1] == 'm') {
          if (!v.newmod) v.newmod = value;
        } else {
          v.prefix = v.prefix ? *v.prefix + "." + value : value;
        }
      } else if (w[1] == 'I') {
        v.invert = !v.invert;
      } else if (w[1] != 'c' && w[1] != 'e') {  // commands are expanded either way (docs/engine.md)
        break;
      }
    }
    const size_t xfa = a;
    const size_t xac = parseRadTransform(av, xfa, v.xf, cmd_.loc, "xform");
    if (xac < av.size() && av[xac].size() > 0 && av[xac][0] == '-')
      fail("'" + av[xac] + "' is not an option here: -c, -I, -n name, -m mod come first, then the transform, "
           "then the files");
    v.xfWords.assign(av.begin() + xfa, av.begin() + xac);
    v.scale = std::abs(v.xf.scale);
    v.reverse = (v.xf.scale < 0.0) != v.invert;
    if (xac == av.size()) {
      if (!input_) fail("no file named: xform would read the standard input, which a scene file cannot give");
      emit(*input_, v, copies);
      return;
    }
    for (size_t f = xac; f < av.size(); ++f) emit(scene(av[f]), v, copies);
  }

  // A file's primitives, its own commands expanded relative to its folder; read once per command.
  const std::vector<RadPrimitive>& scene(const std::string& name) {
    const fs::path path = resolve(name, "file");
    const auto it = files_.find(path);
    if (it != files_.end()) return it->second;
    return files_.emplace(path, ctx_.readFile(path, cmd_.loc)).first->second;
  }

  // What a primitive becomes once read: a mesh its OBJ file's triangles (an n-gon face n − 2), the
  // rest one each; a mesh whose OBJ cannot be found counts one (the reader refuses it later).
  double weight(const RadPrimitive& p) {
    if (p.type != "mesh" || p.strings.empty()) return 1.0;
    fs::path obj(p.strings[0]);
    const std::string ext = obj.extension().string();
    if (ext == ".rtm" || ext == ".msh") obj.replace_extension(".obj");
    fs::path path;
    try {
      path = findSceneFile(obj.string(), fs::path(p.loc.file).parent_path(), p.loc, "mesh", "OBJ file", ctx_.root);
    } catch (const InputError&) {
      return 1.0;
    }
    const auto it = meshTriangles_.find(path);
    if (it != meshTriangles_.end()) return it->second;
    double triangles = 0.0;
    std::istringstream in(readInputFile(path, "OBJ file"));
    std::string line;
    while (std::getline(in, line)) {
      if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
      std::istringstream words(line.substr(1));
      std::string w;
      double corners = 0.0;
      while (words >> w) corners += 1.0;
      triangles += std::max(1.0, corners - 2.0);
    }
    return meshTriangles_[path] = std::max(1.0, triangles);
  }

  void emit(const std::vector<RadPrimitive>& prims, const Invocation& v, double copies) {
    double perCopy = 0.0;
    for (const RadPrimitive& p : prims) perCopy += weight(p);
    const double projected = copies * perCopy;
    if (projected > generatedPrimitivesAllowed(ctx_))
      fail("makes about " + formatCount(projected) + " primitives (" + formatCount(perCopy) +
           " per copy, meshes counted by their triangles, " + formatCount(copies) + " copies: " + multiplierText() +
           "), more than " + generatedLimitText(ctx_));
    made_ += perCopy;
    if (made_ > generatedPrimitivesAllowed(ctx_))
      fail("makes more than " + generatedLimitText(ctx_) + " (meshes counted by their triangles)");
    for (const RadPrimitive& p : prims) out_.push_back(transformPrimitive(p, v));
  }

  const RadCommand& cmd_;
  const RadExpandContext& ctx_;
  const std::vector<RadPrimitive>* input_;
  std::map<fs::path, std::vector<RadPrimitive>> files_;
  std::vector<std::string> multipliers_;
  std::vector<RadPrimitive> out_;
  std::map<fs::path, double> meshTriangles_;  // per OBJ file read for weight()
  double made_ = 0.0;                          // primitives made so far, meshes by their triangles
};

}  // namespace

// In a pipeline (`!genbox ... | xform ...`) the stage before is xform's standard input.
std::vector<RadPrimitive> expandXform(const RadCommand& cmd, const RadExpandContext& ctx) {
  return XformExpansion(cmd, ctx, ctx.standardInput).run();
}

}  // namespace candela
