#include "engine/obj_reader.h"

#include "base/input_file.h"
#include "base/units.h"
#include "engine/materials/family.h"
#include "engine/polygon_split.h"
#include "engine/radiance/reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace candela {

namespace {

// obj2rad reads at most MAXARG − 1 = 8191 words a statement (obj2rad.c): a face of more
// vertices than that is refused rather than cut short.
constexpr size_t kMaxFaceVertices = 8191;
constexpr uint32_t kMaxIndex = std::numeric_limits<uint32_t>::max() - 1;

bool parseDouble(std::string_view w, double& v) {
  const char* end = w.data() + w.size();
  const char* b = w.data();
  if (b != end && *b == '+') ++b;  // from_chars takes no leading '+'
  const auto r = std::from_chars(b, end, v);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(v);
}

bool parseLong(std::string_view w, long& v) {
  const char* end = w.data() + w.size();
  const char* b = w.data();
  if (b != end && *b == '+') ++b;
  const auto r = std::from_chars(b, end, v);
  return r.ec == std::errc() && r.ptr == end;
}

// Splits a statement into words (spaces, tabs and obj2rad's backslashes separate words).
void splitStatement(std::string_view s, std::vector<std::string_view>& words) {
  words.clear();
  size_t i = 0;
  auto sep = [](char c) { return c == ' ' || c == '\t' || c == '\\' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
  while (i < s.size()) {
    while (i < s.size() && sep(s[i])) ++i;
    const size_t b = i;
    while (i < s.size() && !sep(s[i])) ++i;
    if (i > b) words.push_back(s.substr(b, i - b));
  }
}

// ---- mapping files (obj2rad -m; Radiance src/cv/trans.c, getmapping) ----

int qualifierOf(const std::string& w) {
  static const char* const kNames[] = {"Material", "Map", "Group", "Object", "Face"};
  for (int q = 0; q < ObjRule::kQualifiers; ++q)
    if (w == kNames[q]) return q;
  return -1;
}

class MappingParser {
 public:
  MappingParser(std::string_view text, const std::string& file) : s_(text), file_(file) {}

  ObjMapping parse() {
    ObjMapping m;
    for (;;) {
      skipSpace();
      if (i_ >= s_.size()) break;
      if (s_[i_] == '#') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
        continue;
      }
      ObjRule r;
      r.loc = here();
      const size_t b = i_;
      while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) && s_[i_] != ';') ++i_;
      r.modifier = std::string(s_.substr(b, i_ - b));
      if (r.modifier.empty()) fail("a rule needs a modifier name before ';'");
      conditions(r);
      m.rules.push_back(std::move(r));
    }
    return m;
  }

 private:
  [[noreturn]] void fail(const std::string& msg) { throw InputError(here(), msg); }
  FileLoc here() const { return FileLoc{file_, line_, 0}; }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) {
      if (s_[i_] == '\n') ++line_;
      ++i_;
    }
  }
  std::string word() {
    skipSpace();
    const size_t b = i_;
    while (i_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[i_])) && s_[i_] != ')' && s_[i_] != '"' &&
           s_[i_] != '[')
      ++i_;
    return std::string(s_.substr(b, i_ - b));
  }
  void expect(char c, const std::string& what) {
    skipSpace();
    if (i_ >= s_.size() || s_[i_] != c) fail(std::string("expected '") + c + "' " + what);
    ++i_;
  }
  long number(const std::string& what) {
    skipSpace();
    const size_t b = i_;
    if (i_ < s_.size() && (s_[i_] == '-' || s_[i_] == '+')) ++i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    long v = 0;
    if (!parseLong(s_.substr(b, i_ - b), v)) fail("bad " + what + " (an integer)");
    return v;
  }

  // The conditions after the modifier, up to ';' (or the end of the file).
  void conditions(ObjRule& r) {
    for (;;) {
      skipSpace();
      if (i_ >= s_.size() || s_[i_] == ';') {
        if (i_ < s_.size()) ++i_;
        return;
      }
      if (s_[i_] != '(') fail("expected '(' or ';' in the rule for '" + r.modifier + "'");
      ++i_;
      const std::string qn = word();
      const int q = qualifierOf(qn);
      if (q < 0) fail("unknown qualifier '" + qn + "' (obj2rad's are Material, Map, Group, Object and Face)");
      ObjRule::Condition& c = r.conditions[q];
      if (c.set) fail("qualifier " + qn + " given twice in one rule");
      c.set = true;
      skipSpace();
      if (i_ < s_.size() && s_[i_] == '"') {
        const size_t b = ++i_;
        while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\n') ++i_;
        if (i_ >= s_.size() || s_[i_] != '"') fail("unclosed quote in a " + qn + " value");
        c.isName = true;
        c.name = std::string(s_.substr(b, i_ - b));
        ++i_;
      } else if (i_ < s_.size() && s_[i_] == '[') {
        ++i_;
        c.lo = number("range start");
        expect(':', "in a range [lo:hi]");
        c.hi = number("range end");
        expect(']', "closing a range");
        if (c.lo > c.hi) fail("reversed range [" + std::to_string(c.lo) + ":" + std::to_string(c.hi) + "]");
      } else {
        c.lo = c.hi = number(qn + " value (\"a name\", a number or [lo:hi])");
      }
      expect(')', "closing a condition");
    }
  }

  std::string_view s_;
  std::string file_;
  size_t i_ = 0;
  int line_ = 1;
};

// ---- the OBJ reader ----

// The per-file state of obj2rad's convert(): current material, map, groups and object.
class ObjReader {
 public:
  ObjReader(const std::string& file, Scene& scene, const ObjReadOptions& opt)
      : file_(file), scene_(scene), opt_(opt), base_(static_cast<uint32_t>(scene.mesh.vertices.size())) {
    if (opt.mapping)
      for (const ObjRule& r : opt.mapping->rules) faceRules_ |= r.conditions[ObjRule::kFace].set;
  }

  ObjReadStats read(std::string_view text) {
    size_t pos = 0;
    int line = 0;
    std::string joined;
    while (pos < text.size()) {
      const int first = line + 1;
      std::string_view stmt = nextLine(text, pos, line);
      // A line ending in '\' goes on on the next (obj2rad's fgetline).
      if (!stmt.empty() && stmt.back() == '\\') {
        joined.assign(stmt.substr(0, stmt.size() - 1));
        while (pos < text.size()) {
          std::string_view more = nextLine(text, pos, line);
          const bool cont = !more.empty() && more.back() == '\\';
          joined += ' ';
          joined.append(more.substr(0, more.size() - (cont ? 1 : 0)));
          if (!cont) break;
        }
        stmt = joined;
      }
      statement(stmt, first);
    }
    finish();
    return stats_;
  }

 private:
  static std::string_view nextLine(std::string_view text, size_t& pos, int& line) {
    const size_t e = text.find('\n', pos);
    const size_t end = e == std::string_view::npos ? text.size() : e;
    std::string_view l = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    const size_t hash = l.find('#');
    if (hash != std::string_view::npos) l = l.substr(0, hash);
    while (!l.empty() && std::isspace(static_cast<unsigned char>(l.back()))) l.remove_suffix(1);
    return l;
  }

  [[noreturn]] void fail(int line, const std::string& msg) const { throw InputError(FileLoc{file_, line, 0}, msg); }

  void statement(std::string_view stmt, int line) {
    splitStatement(stmt, words_);
    if (words_.empty()) return;
    const std::string_view k = words_[0];
    if (k == "v") return vertex(line);
    if (k == "f") return face(line);
    if (k == "vt") { ++vts_; return; }
    if (k == "vn") return normal(line);
    if (k == "g") {
      groups_.clear();
      for (size_t i = 1; i < words_.size(); ++i) groups_.emplace_back(words_[i]);
      return stateChanged();
    }
    if (k == "o") {
      if (words_.size() >= 2) objName_ = std::string(words_[1]);  // obj2rad: `o` alone is not fatal
      return stateChanged();
    }
    if (k == "usemtl") {
      if (words_.size() >= 2) matName_ = std::string(words_[1]);
      return stateChanged();
    }
    if (k == "usemap") {
      if (words_.size() >= 2) mapName_ = words_[1] == "off" ? std::string() : std::string(words_[1]);
      return stateChanged();
    }
    if (k == "mtllib" && !warnedMtllib_) {
      warnedMtllib_ = true;
      scene_.inputWarnings.push_back(
          {"obj_mtllib_ignored",
           "mtllib " + std::string(words_.size() > 1 ? words_[1] : "") +
               " is not read: faces take the Radiance materials their usemtl (or group) names",
           FileLoc{file_, line, 0}});
    }
    // s, vp, usemap, mtllib, curves and the rest: geometry candela does not take (obj2rad too).
  }

  void vertex(int line) {
    if (words_.size() < 4) fail(line, "vertex needs 3 coordinates, got " + std::to_string(words_.size() - 1));
    Vec3 p;
    for (int k = 0; k < 3; ++k)
      if (!parseDouble(words_[1 + k], p[k]))
        fail(line, "vertex coordinate '" + std::string(words_[1 + k]) + "' is not a number");
    p = opt_.transform.point(p);
    for (int k = 0; k < 3; ++k)
      if (std::abs(p[k]) > kMaxCoordinateM)
        fail(line, "vertex coordinate " + compactNumber(p[k]) + " is beyond 1e7 m");
    if (scene_.mesh.vertices.size() >= kMaxIndex) fail(line, "more than 2^32 - 2 vertices");
    scene_.mesh.vertices.push_back(p);
    ++stats_.vertices;
  }

  // A vertex normal: transformed as the vertices' directions, unit; a zero one smooths nothing.
  void normal(int line) {
    if (words_.size() < 4) fail(line, "vertex normal needs 3 components, got " + std::to_string(words_.size() - 1));
    Vec3 n;
    for (int k = 0; k < 3; ++k)
      if (!parseDouble(words_[1 + k], n[k]) || !std::isfinite(n[k]))
        fail(line, "vertex normal component '" + std::string(words_[1 + k]) + "' is not a number");
    n = opt_.transform.direction(n);
    const double l = glm::length(n);
    normals_.push_back(l > 0.0 ? n / l : Vec3(0.0));
    ++vns_;
  }

  // One index of a face vertex: 1-based, or negative counting back from the last of `count`.
  bool index(std::string_view w, size_t count, long& out) const {
    long v = 0;
    if (w.empty() || !parseLong(w, v) || v == 0) return false;
    if (v > 0) {
      if (static_cast<size_t>(v) > count) return false;
      out = v - 1;
    } else {
      if (v < -static_cast<long>(count)) return false;  // (no negation: -LONG_MIN overflows)
      out = static_cast<long>(count) + v;
    }
    return true;
  }

  void faceIndices(int line) {
    idx_.clear();
    nidx_.clear();
    for (size_t i = 1; i < words_.size(); ++i) {
      const std::string_view w = words_[i];
      const size_t s1 = w.find('/');
      long v = 0;
      if (!index(w.substr(0, s1), stats_.vertices, v))
        fail(line, "face vertex '" + std::string(w) + "' names no vertex: " + std::to_string(stats_.vertices) +
                       " are defined before this line (indices count from 1, negative ones back from the last)");
      if (s1 != std::string_view::npos) {  // v/vt, v//vn, v/vt/vn: the texture and normal indices are checked, not used
        const std::string_view rest = w.substr(s1 + 1);
        const size_t s2 = rest.find('/');
        const std::string_view vt = rest.substr(0, s2);
        const std::string_view vn = s2 == std::string_view::npos ? std::string_view() : rest.substr(s2 + 1);
        long dummy = 0, vnIndex = -1;
        if ((!vt.empty() && !index(vt, vts_, dummy)) || (!vn.empty() && !index(vn, vns_, vnIndex)))
          fail(line, "face vertex '" + std::string(w) + "' names a texture or normal index that is not defined");
        nidx_.push_back(vnIndex);
      } else {
        nidx_.push_back(-1);
      }
      idx_.push_back(base_ + static_cast<uint32_t>(v));
    }
    // xform: a mirroring transform (negative scale) reverses the vertex order, so fronts stay fronts.
    if (opt_.transform.scale < 0.0) {
      std::reverse(idx_.begin(), idx_.end());
      std::reverse(nidx_.begin(), nidx_.end());
    }
  }

  void face(int line) {
    ++faceNo_;
    ++stats_.faces;
    if (words_.size() < 4)
      fail(line, "face needs at least 3 vertices, got " + std::to_string(words_.size() - 1));
    if (words_.size() - 1 > kMaxFaceVertices)
      fail(line, "face has " + std::to_string(words_.size() - 1) + " vertices, more than " +
                     std::to_string(kMaxFaceVertices));
    faceIndices(line);
    const int mat = material(line);
    if (mat < 0) {
      ++stats_.dropped;
      return;
    }
    const std::vector<Vec3>& V = scene_.mesh.vertices;
    pts_.clear();
    for (uint32_t i : idx_) pts_.push_back(V[i]);
    Box b;
    for (const Vec3& p : pts_) b.extend(p);
    const double diameter = glm::length(b.size());
    const Vec3 nn = idx_.size() == 3 ? glm::cross(pts_[1] - pts_[0], pts_[2] - pts_[0]) : newellNormal(pts_);
    const double area = 0.5 * glm::length(nn);
    if (!(diameter > 0.0) || area <= kDegenerateTolerance * diameter * diameter) {
      if (stats_.degenerate++ == 0) firstDegenerate_ = line;
      return;
    }
    const Vec3 n = nn / (2.0 * area);
    const bool planar = idx_.size() == 3 || planeDeviation(pts_, n) <= kPlanarTolerance * diameter;
    stats_.nonplanar += !planar;
    tris_.clear();
    if (idx_.size() == 3) {
      tris_.push_back({0, 1, 2});
    } else {
      // 10^8 point tests a face, opt_.maxSplitTests a file.
      const uint64_t left = opt_.maxSplitTests - std::min(splitTests_, opt_.maxSplitTests);
      uint64_t used = 0;
      const bool ok = splitPolygon(pts_, n, tris_, std::min<uint64_t>(100000000, left), &used);
      splitTests_ += used;
      if (!ok && left < 100000000)
        fail(line, "the file's faces need more than " + std::to_string(opt_.maxSplitTests) +
                       " point tests to split into triangles (10^9: about 3 s of work); split them in the "
                       "modelling tool");
      if (!ok)
        fail(line, "face of " + std::to_string(idx_.size()) +
                       " vertices is too intricate to split into triangles (more than 10^8 point tests); split "
                       "it in the modelling tool");
    }
    const Material& m = scene_.materials[static_cast<size_t>(mat)];
    if (m.isEmitter() || familyOf(m).mirrorsSources()) return addShapes(mat, planar);
    const Smoothing sm = smoothing(n);
    for (const auto& t : tris_) {
      const std::array<uint32_t, 3> c = sm.flip ? std::array<uint32_t, 3>{t[0], t[2], t[1]} : t;
      addTriangle(idx_[c[0]], idx_[c[1]], idx_[c[2]], static_cast<uint32_t>(mat), line);
      if (sm.smooth) smoothLast({meshNormal(nidx_[c[0]]), meshNormal(nidx_[c[1]]), meshNormal(nidx_[c[2]])});
    }
  }

  // obj2rad's test (convertobj.c's checksmooth, tmesh.h's cosine 0.999995): a face is smoothed
  // when every corner has a normal and some normal departs from the face's (n, unit); a face whose
  // normals all point against it is turned round and stays flat.
  struct Smoothing {
    bool smooth = false, flip = false;
  };
  Smoothing smoothing(const Vec3& n) const {
    constexpr double kCosTol = 0.999995;
    Smoothing s;
    size_t reversed = 0;
    for (long k : nidx_) {
      if (k < 0 || normals_[static_cast<size_t>(k)] == Vec3(0.0)) return Smoothing{};  // a corner without
      const double d = glm::dot(normals_[static_cast<size_t>(k)], n);
      if (d >= kCosTol) continue;
      if (d > -kCosTol) s.smooth = true;
      else ++reversed;
    }
    s.flip = !s.smooth && reversed == nidx_.size();
    return s;
  }

  // The mesh's index of OBJ normal k, added on first use.
  uint32_t meshNormal(long k) {
    if (normalIndex_.size() < normals_.size()) normalIndex_.resize(normals_.size(), TriangleMesh::kNoCornerNormal);
    uint32_t& at = normalIndex_[static_cast<size_t>(k)];
    if (at == TriangleMesh::kNoCornerNormal) {
      at = static_cast<uint32_t>(scene_.mesh.normals.size());
      scene_.mesh.normals.push_back(normals_[static_cast<size_t>(k)]);
    }
    return at;
  }

  // The last triangle added takes corner normals `c` (earlier ones flat).
  void smoothLast(const std::array<uint32_t, 3>& c) {
    TriangleMesh& mesh = scene_.mesh;
    mesh.cornerNormals.resize(mesh.triangles.size(),
                              {TriangleMesh::kNoCornerNormal, TriangleMesh::kNoCornerNormal, TriangleMesh::kNoCornerNormal});
    mesh.cornerNormals.back() = c;
    ++stats_.smoothed;
  }

  // Sources and mirrors are Shapes: the light sampling and the mirrors' virtual sources find
  // them there. Planar faces stay one polygon (as obj2rad writes them), others are triangles.
  void addShapes(int mat, bool planar) {
    const std::string name = objectName() + "." + std::to_string(faceNo_);
    if (planar) {
      scene_.addPolygon(pts_, static_cast<uint32_t>(mat), name);
      ++stats_.shapes;
      return;
    }
    for (const auto& t : tris_) {
      scene_.addPolygon({pts_[t[0]], pts_[t[1]], pts_[t[2]]}, static_cast<uint32_t>(mat), name);
      ++stats_.shapes;
    }
  }

  void addTriangle(uint32_t a, uint32_t b, uint32_t c, uint32_t mat, int line) {
    TriangleMesh& mesh = scene_.mesh;
    if (mesh.triangles.size() >= kMaxIndex) fail(line, "more than 2^32 - 2 mesh triangles");
    const uint32_t name = nameIndex();
    if (mesh.runs.empty() || mesh.runs.back().material != mat || mesh.runs.back().name != name)
      mesh.runs.push_back({static_cast<uint32_t>(mesh.triangles.size()), mat, name});
    mesh.triangles.push_back({a, b, c});
    ++stats_.meshTriangles;
  }

  // obj2rad's getonm: the `o` name, else the groups joined by '.', else "unnamed".
  std::string objectName() const {
    if (!objName_.empty()) return objName_;
    if (groups_.empty()) return "unnamed";
    std::string n;
    for (const std::string& g : groups_) n += (n.empty() ? "" : ".") + g;
    return n;
  }

  uint32_t nameIndex() {
    if (nameValid_) return name_;
    const std::string n = objectName();
    const auto it = names_.find(n);
    if (it != names_.end()) {
      name_ = it->second;
    } else {
      name_ = static_cast<uint32_t>(scene_.mesh.names.size());
      scene_.mesh.names.push_back(n);
      names_.emplace(n, name_);
    }
    nameValid_ = true;
    return name_;
  }

  void stateChanged() {
    matValid_ = false;
    nameValid_ = false;
  }

  // The face's material (-1: left out), obj2rad's getmtl.
  int material(int line) {
    if (matValid_ && !faceRules_) return mat_;
    std::string name, why;
    if (opt_.forcedModifier) {
      name = *opt_.forcedModifier;
      why = "the mesh's modifier";
    } else if (opt_.mapping) {
      const ObjRule* r = matchRule();
      if (!r) return remember(-1);
      name = r->modifier;
      why = "mapping rule at line " + std::to_string(r->loc.line) + " of " + r->loc.file;
    } else if (!matName_.empty()) {
      name = matName_;
      why = "usemtl";
    } else if (!groups_.empty()) {
      name = groups_.front();
      why = "the group name (no usemtl)";
    } else {
      name = opt_.defaultModifier;
      why = "the default modifier (no usemtl or group)";
    }
    const auto it = resolved_.find(name);
    const int m = it != resolved_.end() ? it->second
                                        : resolved_.emplace(name, opt_.resolve(name, why, FileLoc{file_, line, 0}))
                                              .first->second;
    return remember(m);
  }
  int remember(int m) {
    mat_ = m;
    matValid_ = true;
    return m;
  }

  static bool matchName(const ObjRule::Condition& c, const std::string& v) {
    return !c.set || (c.isName && !v.empty() && c.name == v);
  }

  // The last rule the current face satisfies (obj2rad.1: "the last rule satisfied determines").
  const ObjRule* matchRule() const {
    const auto& rules = opt_.mapping->rules;
    for (auto it = rules.rbegin(); it != rules.rend(); ++it) {
      const ObjRule& r = *it;
      if (!matchName(r.conditions[ObjRule::kMaterial], matName_)) continue;
      if (!matchName(r.conditions[ObjRule::kMap], mapName_)) continue;
      if (!matchName(r.conditions[ObjRule::kObject], objName_)) continue;
      const ObjRule::Condition& g = r.conditions[ObjRule::kGroup];
      if (g.set && !(g.isName && std::find(groups_.begin(), groups_.end(), g.name) != groups_.end())) continue;
      const ObjRule::Condition& f = r.conditions[ObjRule::kFace];
      if (f.set && (f.isName || faceNo_ < f.lo || faceNo_ > f.hi)) continue;
      return &r;
    }
    return nullptr;
  }

  void finish() {
    if (stats_.degenerate > 0)
      scene_.inputWarnings.push_back(
          {"obj_degenerate_faces",
           std::to_string(stats_.degenerate) + " face(s) of zero area left out (as obj2rad does), the first at line " +
               std::to_string(firstDegenerate_),
           FileLoc{file_, firstDegenerate_, 0}});
  }

  std::string file_;
  Scene& scene_;
  const ObjReadOptions& opt_;
  uint32_t base_;  // this file's first vertex in Scene::mesh
  ObjReadStats stats_;
  uint64_t splitTests_ = 0;  // ear-clipper tests so far in this file (ObjReadOptions::maxSplitTests)
  size_t vts_ = 0, vns_ = 0;
  long faceNo_ = 0;
  std::string matName_, mapName_, objName_;
  std::vector<std::string> groups_;
  bool faceRules_ = false, warnedMtllib_ = false;
  bool matValid_ = false, nameValid_ = false;
  int mat_ = -1;
  uint32_t name_ = 0;
  int firstDegenerate_ = 0;
  std::unordered_map<std::string, int> resolved_;
  std::unordered_map<std::string, uint32_t> names_;
  // Scratch reused from face to face (no allocation per face once grown).
  std::vector<std::string_view> words_;
  std::vector<uint32_t> idx_;
  std::vector<long> nidx_;             // each face vertex's normal (index into normals_), -1: none
  std::vector<Vec3> normals_;          // the file's `vn`, transformed, unit (zero: unusable)
  std::vector<uint32_t> normalIndex_;  // their indices in the mesh's normals, once used
  std::vector<Vec3> pts_;
  std::vector<std::array<uint32_t, 3>> tris_;
};

}  // namespace

ObjMapping parseObjMapping(std::string_view text, const std::string& fileName) {
  return MappingParser(text, fileName).parse();
}

ObjMapping readObjMapping(const std::filesystem::path& path) {
  const std::string text = readInputFile(path, "OBJ mapping file");
  return parseObjMapping(text, path.string());
}

ObjReadStats readObjText(std::string_view text, const std::string& fileName, Scene& scene,
                         const ObjReadOptions& options) {
  return ObjReader(fileName, scene, options).read(text);
}

ObjReadStats readObjFile(const std::filesystem::path& path, Scene& scene, const ObjReadOptions& options) {
  const std::string text = readInputFile(path, "OBJ file");
  return readObjText(text, path.string(), scene, options);
}

bool isObjPath(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ".obj";
}

}  // namespace candela
