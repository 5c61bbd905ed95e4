#include "engine/radiance/bsdf_xml.h"

#include "base/error.h"
#include "base/input_file.h"
#include "engine/bsdf_klems.h"
#include "engine/bsdf_tree.h"
#include "engine/radiance/spectrum.h"

#include <expat.h>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <strings.h>

namespace candela {
namespace {

// Elements and nesting a BSDF file may hold (a WINDOW or genBSDF file has a few hundred
// elements, five levels deep): more is refused while reading, before it costs memory.
constexpr size_t kMaxElements = size_t{1} << 20;
constexpr int kMaxNesting = 64;
// Radiance's limits on a custom Klems basis (src/common/bsdf_m.h, MAXLATS) and on how many
// custom bases a file may define (MAXABASES, less the three standard ones).
constexpr size_t kMaxRings = 46;
constexpr size_t kMaxCustomBases = 4;

// ---- The XML as a small tree of elements (expat's events collected) ----

struct Element {
  std::string name;       // without a namespace prefix
  std::string text;       // character data directly inside
  int line = 0;           // line of the start tag
  int textLine = 0;       // line where the character data begins
  std::vector<int> kids;  // indices into Doc::elements
};

struct Doc {
  std::vector<Element> elements;
  std::vector<int> open;  // the path of open elements
  std::string error;      // set by a handler that stopped the parser
  int errorLine = 0;
  XML_Parser parser = nullptr;
};

void stop(Doc& d, const std::string& message) {
  if (d.error.empty()) {
    d.error = message;
    d.errorLine = static_cast<int>(XML_GetCurrentLineNumber(d.parser));
  }
  XML_StopParser(d.parser, XML_FALSE);
}

void XMLCALL onStart(void* data, const XML_Char* name, const XML_Char**) {
  Doc& d = *static_cast<Doc*>(data);
  if (d.elements.size() >= kMaxElements) return stop(d, "more than " + std::to_string(kMaxElements) + " elements");
  if (d.open.size() >= static_cast<size_t>(kMaxNesting))
    return stop(d, "elements nested more than " + std::to_string(kMaxNesting) + " deep");
  Element e;
  const char* colon = std::strrchr(name, ':');
  e.name = colon ? colon + 1 : name;
  e.line = static_cast<int>(XML_GetCurrentLineNumber(d.parser));
  d.elements.push_back(std::move(e));
  const int index = static_cast<int>(d.elements.size()) - 1;
  if (!d.open.empty()) d.elements[d.open.back()].kids.push_back(index);
  d.open.push_back(index);
}

void XMLCALL onEnd(void* data, const XML_Char*) {
  Doc& d = *static_cast<Doc*>(data);
  if (!d.open.empty()) d.open.pop_back();
}

void XMLCALL onText(void* data, const XML_Char* s, int len) {
  Doc& d = *static_cast<Doc*>(data);
  if (d.open.empty()) return;
  Element& e = d.elements[d.open.back()];
  if (e.text.empty()) e.textLine = static_cast<int>(XML_GetCurrentLineNumber(d.parser));
  e.text.append(s, static_cast<size_t>(len));
}

// Entities declared in a DTD could expand without bound; no BSDF file has one.
void XMLCALL onDoctype(void* data, const XML_Char*, const XML_Char*, const XML_Char*, int) {
  stop(*static_cast<Doc*>(data), "a DOCTYPE declaration (not read in a BSDF file)");
}

// ---- Reading the elements ----

std::string trim(std::string_view s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

// A piece of the file quoted in a message: at most 40 characters.
std::string quote(std::string_view s) {
  std::string t = trim(s);
  if (t.size() > 40) {
    t.resize(37);
    t.append("...");
  }
  std::string q(1, '\'');
  q.append(printable(t));
  q.push_back('\'');
  return q;
}

bool same(std::string_view a, const char* b) {
  return a.size() == std::strlen(b) && strncasecmp(a.data(), b, a.size()) == 0;
}

class Reader {
 public:
  Reader(const Doc& doc, std::string name) : doc_(doc), name_(std::move(name)) {}

  std::shared_ptr<const Bsdf> read();

 private:
  struct Channels {  // one component's blocks: Y, X, Z
    std::array<std::vector<double>, 3> v;
    std::array<std::shared_ptr<const KlemsBasis>, 3> in, out;
    std::array<std::optional<TensorTree>, 5> tree;  // Y, (X, Z: unused), u′, v′
    int line = 0;
  };

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(FileLoc{name_, line, 0}, message);
  }
  const Element& el(int i) const { return doc_.elements[i]; }
  const Element* child(const Element& e, const char* name) const {
    for (int k : e.kids)
      if (same(el(k).name, name)) return &el(k);
    return nullptr;
  }
  const Element& need(const Element& e, const char* name) const {
    const Element* c = child(e, name);
    if (!c) fail(e.line, "<" + e.name + "> has no <" + name + ">");
    return *c;
  }
  double number(const Element& e) const;
  void readBases(const Element& def);
  std::shared_ptr<const KlemsBasis> findBasis(const std::string& name) const;
  std::shared_ptr<const KlemsBasis> basis(const Element& e) const;
  void readKlemsBlock(const Element& block, Channels& c, int channel, bool rowsIncident);
  void readTreeBlock(const Element& block, Channels& c, int channel, int dims);
  int parseTree(const Element& e, std::string_view text, size_t& at, int& line, TensorTree& t, int node,
                int depth) const;
  std::shared_ptr<const Bsdf> makeKlems(std::array<Channels, kBsdfParts>& parts, int layerLine) const;
  std::shared_ptr<const Bsdf> makeTree(std::array<Channels, kBsdfParts>& parts, int dims, int layerLine) const;

  const Doc& doc_;
  std::string name_;
  std::vector<std::shared_ptr<const KlemsBasis>> custom_;
};

double Reader::number(const Element& e) const {
  const std::string t = trim(e.text);
  double v = 0.0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
    fail(e.textLine ? e.textLine : e.line, "<" + e.name + "> is not a number: " + quote(t));
  return v;
}

// A custom angle basis (bsdf_m.c, load_angle_basis): rings with nPhis and θ bounds, contiguous
// from 0°. A standard name keeps the standard basis, as Radiance does.
void Reader::readBases(const Element& def) {
  for (int k : def.kids) {
    const Element& ab = el(k);
    if (!same(ab.name, "AngleBasis")) continue;
    const std::string name = trim(need(ab, "AngleBasisName").text);
    if (KlemsBasis::standard(name)) continue;
    if (findBasis(name)) continue;
    if (custom_.size() >= kMaxCustomBases)
      fail(ab.line, "more than " + std::to_string(kMaxCustomBases) + " custom angle bases");
    std::vector<KlemsBasis::Ring> rings;
    size_t patches = 0;
    for (int b : ab.kids) {
      const Element& block = el(b);
      if (!same(block.name, "AngleBasisBlock")) continue;
      if (rings.size() >= kMaxRings) fail(block.line, "angle basis " + quote(name) + " has more than 46 rings");
      const Element& bounds = need(block, "ThetaBounds");
      const double lo = number(need(bounds, "LowerTheta")), hi = number(need(bounds, "UpperTheta"));
      const double n = number(need(block, "nPhis"));
      const double prev = rings.empty() ? 0.0 : rings.back().thetaHiDeg;
      if (std::abs(lo - prev) > 1e-6 * std::max(1.0, prev))
        fail(bounds.line, "angle basis " + quote(name) + ": ring from " + compactNumber(lo) + "° does not start where the previous ends (" + compactNumber(prev) + "°)");
      if (!(hi > lo) || hi > 90.0)
        fail(bounds.line, "angle basis " + quote(name) + ": ring bounds " + compactNumber(lo) + "° to " + compactNumber(hi) + "° (need lower < upper ≤ 90°)");
      if (n != std::floor(n) || n < 1.0 || (n == 1.0 && lo > 0.0))
        fail(block.line, "angle basis " + quote(name) + ": nPhis " + compactNumber(n) + " (a whole number ≥ 1, 1 only for the ring at 0°)");
      patches += static_cast<size_t>(std::min(n, 1e9));
      if (patches > kMaxKlemsPatches)
        fail(block.line, "angle basis " + quote(name) + " has more than " + std::to_string(kMaxKlemsPatches) + " patches");
      rings.push_back({lo, hi, static_cast<int>(n), 0});
    }
    if (rings.empty()) fail(ab.line, "angle basis " + quote(name) + " has no <AngleBasisBlock>");
    custom_.push_back(std::make_shared<const KlemsBasis>(KlemsBasis::make(name, std::move(rings))));
  }
}

std::shared_ptr<const KlemsBasis> Reader::findBasis(const std::string& name) const {
  if (auto b = KlemsBasis::standard(name)) return b;
  for (const auto& b : custom_)
    if (strcasecmp(b->name.c_str(), name.c_str()) == 0) return b;
  return nullptr;
}

std::shared_ptr<const KlemsBasis> Reader::basis(const Element& e) const {
  const std::string name = trim(e.text);
  if (auto b = findBasis(name)) return b;
  fail(e.textLine ? e.textLine : e.line, "unknown angle basis " + quote(name) + " in <" + e.name + ">");
}

// Numbers separated by white space and commas, as in <ScatteringData>; each checked (finite,
// not negative) with the line it is on.
class NumberScanner {
 public:
  NumberScanner(std::string_view text, int line) : text_(text), line_(line) {}
  // Skips separators; false at the end of the text.
  bool more() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
      } else if (!(c == ',' || std::isspace(static_cast<unsigned char>(c)))) {
        return true;
      }
      ++at_;
    }
    return false;
  }
  char peek() const { return text_[at_]; }
  void skip() { ++at_; }
  int line() const { return line_; }
  // The number at the current place; an error message in `bad` when it is not one.
  bool next(double& v, std::string& bad) {
    size_t end = at_;
    while (end < text_.size() && !(text_[end] == ',' || text_[end] == '{' || text_[end] == '}' ||
                                   std::isspace(static_cast<unsigned char>(text_[end]))))
      ++end;
    const std::string_view word = text_.substr(at_, std::max<size_t>(end - at_, 1));
    const char* first = word.data();
    if (*first == '+') ++first;  // from_chars takes no '+'
    const auto r = std::from_chars(first, word.data() + word.size(), v);
    if (r.ec != std::errc() || r.ptr != word.data() + word.size()) {
      bad = "not a number: " + quote(word);
      return false;
    }
    if (!std::isfinite(v)) {
      bad = "not a finite number: " + quote(word);
      return false;
    }
    if (v < 0.0) {
      bad = "negative scattering value " + compactNumber(v);
      return false;
    }
    at_ = end;
    return true;
  }
  size_t at() const { return at_; }

 private:
  std::string_view text_;
  size_t at_ = 0;
  int line_;
};

// One Klems block: ni·no numbers, incident patches along a row ("Columns": each row of numbers
// one outgoing patch, bsdf_m.c's default) or down a column ("Rows"); the column basis is the
// incident one, the row basis the outgoing one either way (bsdf_m.c, load_bsdf_data).
void Reader::readKlemsBlock(const Element& block, Channels& c, int channel, bool rowsIncident) {
  const auto in = basis(need(block, "ColumnAngleBasis"));
  const auto out = basis(need(block, "RowAngleBasis"));
  const Element& data = need(block, "ScatteringData");
  const size_t ni = in->count, no = out->count, n = ni * no;
  std::vector<double> v(n);
  NumberScanner s(data.text, data.textLine ? data.textLine : data.line);
  size_t k = 0;
  std::string bad;
  while (s.more()) {
    if (k == n) fail(s.line(), "more than the " + std::to_string(n) + " numbers the bases need (" + std::to_string(ni) + " × " + std::to_string(no) + ")");
    double x;
    if (!s.next(x, bad)) fail(s.line(), bad);
    if (rowsIncident) {
      const size_t r = k / no, col = k % no;  // r incident, col outgoing
      v[col * ni + r] = x;
    } else {
      v[k] = x;
    }
    ++k;
  }
  if (k != n)
    fail(data.line, "<ScatteringData> has " + std::to_string(k) + " numbers, the bases need " + std::to_string(ni) + " × " + std::to_string(no) + " = " + std::to_string(n));
  c.v[channel] = std::move(v);
  c.in[channel] = in;
  c.out[channel] = out;
  c.line = block.line;
}

// A tensor tree (bsdf_t.c, load_tree_data): '{' then either 2^dims sub-trees or a grid of
// 2^(dims·k) values, then '}'; commas between are optional. Returns the node's depth.
int Reader::parseTree(const Element& e, std::string_view text, size_t& at, int& line, TensorTree& t, int node,
                      int depth) const {
  if (depth > kMaxTensorTreeDepth) fail(line, "tensor tree deeper than " + std::to_string(kMaxTensorTreeDepth) + " levels");
  NumberScanner s(text.substr(at), line);
  auto sync = [&] {
    at += s.at();
    line = s.line();
    s = NumberScanner(text.substr(at), line);
  };
  if (!s.more() || s.peek() != '{') {
    sync();
    fail(line, "tensor tree: expected '{'");
  }
  s.skip();
  sync();
  if (!s.more()) fail(line, "tensor tree: ends inside a node");
  int deepest = depth;
  if (s.peek() == '{') {
    sync();
    const int first = static_cast<int>(t.nodes.size());
    const int kids = 1 << t.dims;
    t.nodes[node].child = first;
    t.nodes.resize(t.nodes.size() + kids);
    for (int k = 0; k < kids; ++k) deepest = std::max(deepest, parseTree(e, text, at, line, t, first + k, depth + 1));
    s = NumberScanner(text.substr(at), line);
  } else {
    const size_t first = t.values.size();
    std::string bad;
    while (s.more() && s.peek() != '}') {
      double x;
      if (!s.next(x, bad)) {
        sync();
        fail(line, "tensor tree: " + bad);
      }
      t.values.push_back(x);
    }
    const size_t count = t.values.size() - first;
    int lg = 0;
    while ((size_t{1} << (lg * t.dims)) < count && lg * t.dims < 40) ++lg;
    if ((size_t{1} << (lg * t.dims)) != count) {
      sync();
      fail(line, "tensor tree: a leaf of " + std::to_string(count) + " values (need 2^(" + std::to_string(t.dims) + "·k))");
    }
    t.nodes[node].log2Grid = lg;
    t.nodes[node].first = static_cast<int>(first);
  }
  if (!s.more() || s.peek() != '}') {
    sync();
    fail(line, "tensor tree: expected '}'");
  }
  s.skip();
  sync();
  return deepest;
}

void Reader::readTreeBlock(const Element& block, Channels& c, int channel, int dims) {
  const Element& basisEl = need(block, "AngleBasis");
  if (!same(trim(basisEl.text), "LBNL/Shirley-Chiu"))
    fail(basisEl.line, "tensor tree with angle basis " + quote(basisEl.text) + " (only LBNL/Shirley-Chiu)");
  const Element& data = need(block, "ScatteringData");
  TensorTree t;
  t.dims = dims;
  t.nodes.resize(1);
  size_t at = 0;
  int line = data.textLine ? data.textLine : data.line;
  parseTree(data, data.text, at, line, t, 0, 1);
  NumberScanner rest(std::string_view(data.text).substr(at), line);
  if (rest.more()) fail(rest.line(), "tensor tree: text after the tree's last '}'");
  if (t.values.size() > static_cast<size_t>(std::numeric_limits<int>::max())) fail(data.line, "tensor tree too large");
  c.tree[channel] = std::move(t);
  c.line = block.line;
}

// X, Y, Z to Radiance's RGB (its primaries and equal-energy white: src/common/color.h, and
// xyz2rgbmat in src/common/spec_rgb.c).
Rgb rgbOf(double x, double y, double z) { return xyzToRadianceRgb(Vec3(x, y, z)); }

std::shared_ptr<const Bsdf> Reader::makeKlems(std::array<Channels, kBsdfParts>& parts, int layerLine) const {
  std::array<std::optional<KlemsMatrix>, kBsdfParts> m;
  std::string basisName;
  bool mixed = false;
  for (int p = 0; p < kBsdfParts; ++p) {
    Channels& c = parts[p];
    if (c.v[0].empty()) continue;  // no Y: nothing (X or Z alone is no component, as Radiance)
    KlemsMatrix km;
    km.in = c.in[0];
    km.out = c.out[0];
    const bool colour = !c.v[1].empty() && !c.v[2].empty() && c.in[1] == km.in && c.out[1] == km.out &&
                        c.in[2] == km.in && c.out[2] == km.out;
    km.value.resize(c.v[0].size());
    for (size_t n = 0; n < km.value.size(); ++n)
      km.value[n] = colour ? rgbOf(c.v[1][n], c.v[0][n], c.v[2][n]) : Rgb(c.v[0][n]);
    // Radiance drops a component whose largest hemispherical Y is ≤ 0.001 (bsdf.c, SDloadFile).
    double maxHemi = 0.0;
    for (int i = 0; i < km.in->count; ++i) {
      double h = 0.0;
      for (int o = 0; o < km.out->count; ++o) h += c.v[0][static_cast<size_t>(o) * km.in->count + i] * km.out->projSA(o);
      maxHemi = std::max(maxHemi, h);
    }
    if (maxHemi <= 0.001) continue;
    for (const auto* b : {km.in.get(), km.out.get()}) {
      if (basisName.empty()) basisName = b->name;
      mixed = mixed || b->name != basisName;
    }
    m[p] = std::move(km);
  }
  if (basisName.empty()) fail(layerLine, "no visible scattering in the layer (no photopic data, or all ≤ 0.001)");
  std::string kind = "Klems " + basisName;
  if (!mixed) {
    if (same(basisName, "LBNL/Klems Full")) kind = "Klems full";
    if (same(basisName, "LBNL/Klems Half")) kind = "Klems half";
    if (same(basisName, "LBNL/Klems Quarter")) kind = "Klems quarter";
  } else {
    kind = "Klems mixed bases";
  }
  return std::make_shared<KlemsBsdf>(std::move(m), printable(kind));
}

std::shared_ptr<const Bsdf> Reader::makeTree(std::array<Channels, kBsdfParts>& parts, int dims, int layerLine) const {
  TreeBsdf::Trees trees, uPrime, vPrime;
  bool any = false;
  for (int p = 0; p < kBsdfParts; ++p) {
    if (!parts[p].tree[0]) continue;
    TensorTree& t = *parts[p].tree[0];
    // No hemispherical value can exceed π·max: a component below 0.001 so is dropped, as
    // Radiance drops one whose largest hemispherical value is ≤ 0.001 (bsdf.c, SDloadFile).
    if (kPi * *std::max_element(t.values.begin(), t.values.end()) <= 0.001) continue;
    trees[p] = std::move(t);
    // Chromaticity trees of the same dimensions (both, else grey).
    if (parts[p].tree[3] && parts[p].tree[4]) {
      uPrime[p] = std::move(parts[p].tree[3]);
      vPrime[p] = std::move(parts[p].tree[4]);
    }
    any = true;
  }
  if (!any) fail(layerLine, "no visible scattering in the layer (no photopic data, or all ≤ 0.001)");
  return std::make_shared<TreeBsdf>(std::move(trees), std::move(uPrime), std::move(vPrime),
                                    dims == 3 ? "tensor tree 3" : "tensor tree 4");
}

// The component a <WavelengthDataDirection> names. The XML's front is the exterior, -z of the
// local frame (bsdf_m.c: "front and back are reversed from WINDOW 6 orientations").
int partOf(std::string_view direction) {
  if (same(direction, "Transmission Front")) return static_cast<int>(BsdfPart::TransFromMinusZ);
  if (same(direction, "Transmission Back")) return static_cast<int>(BsdfPart::TransFromPlusZ);
  if (same(direction, "Reflection Front")) return static_cast<int>(BsdfPart::ReflMinusZ);
  if (same(direction, "Reflection Back")) return static_cast<int>(BsdfPart::ReflPlusZ);
  return -1;
}

// The channel of a <WavelengthData>: 0 Y, 1 X, 2 Z (Klems), 3 u′, 4 v′ (tensor trees' CIE-u and
// CIE-v, bsdf_t.c); -1 to skip (solar, infrared).
// "Visible" is photopic unless its <DetectorSpectrum> names X or Z ("ASTM E308 1931 X.dsp",
// "CIE-X"); Radiance's older "CIE-X"/"CIE-Z" wavelength names are read too.
int channelOf(const std::string& wavelength, const std::string& detector) {
  if (same(wavelength, "CIE-X")) return 1;
  if (same(wavelength, "CIE-Y")) return 0;
  if (same(wavelength, "CIE-Z")) return 2;
  if (same(wavelength, "CIE-u")) return 3;
  if (same(wavelength, "CIE-v")) return 4;
  if (!same(wavelength, "Visible")) return -1;
  std::string word;
  int channel = 0;
  for (size_t k = 0; k <= detector.size(); ++k) {
    const char c = k < detector.size() ? detector[k] : ' ';
    if (std::isalnum(static_cast<unsigned char>(c))) {
      word += c;
      continue;
    }
    if (word == "X" || word == "x") channel = 1;
    if (word == "Z" || word == "z") channel = 2;
    word.clear();
  }
  return channel;
}

std::shared_ptr<const Bsdf> Reader::read() {
  if (doc_.elements.empty()) fail(1, "no XML element");
  const Element& root = el(0);
  if (!same(root.name, "WindowElement")) fail(root.line, "the top element is " + quote(root.name) + ", not <WindowElement>");
  if (const Element* ft = child(root, "FileType"); ft && !same(trim(ft->text), "BSDF"))
    fail(ft->line, "<FileType> is " + quote(ft->text) + ", not BSDF");
  const Element& layer = need(need(root, "Optical"), "Layer");
  const Element& def = need(layer, "DataDefinition");
  const Element& ids = need(def, "IncidentDataStructure");
  const std::string structure = trim(ids.text);
  int dims = 0;
  bool rowsIncident = false;
  if (same(structure, "Columns")) {
    rowsIncident = false;
  } else if (same(structure, "Rows")) {
    rowsIncident = true;
  } else if (same(structure, "TensorTree3")) {
    dims = 3;
  } else if (same(structure, "TensorTree4")) {
    dims = 4;
  } else {
    fail(ids.line, "unsupported <IncidentDataStructure> " + quote(structure) + " (Columns, Rows, TensorTree3, TensorTree4)");
  }
  if (dims == 0) readBases(def);
  std::array<Channels, kBsdfParts> parts;
  for (int k : layer.kids) {
    const Element& wd = el(k);
    if (!same(wd.name, "WavelengthData")) continue;
    const Element* det = child(wd, "DetectorSpectrum");
    const int channel = channelOf(trim(need(wd, "Wavelength").text), det ? trim(det->text) : "");
    if (channel < 0) continue;
    // Klems colour is X, Y, Z; a tree's is Y with u′ and v′ trees.
    if ((dims == 0 && channel > 2) || (dims != 0 && (channel == 1 || channel == 2))) continue;
    for (int b : wd.kids) {
      const Element& block = el(b);
      if (!same(block.name, "WavelengthDataBlock")) continue;
      const Element& dir = need(block, "WavelengthDataDirection");
      const int part = partOf(trim(dir.text));
      if (part < 0) fail(dir.line, "unknown <WavelengthDataDirection> " + quote(dir.text));
      if (dims == 0)
        readKlemsBlock(block, parts[part], channel, rowsIncident);
      else
        readTreeBlock(block, parts[part], channel, dims);
    }
  }
  return dims == 0 ? makeKlems(parts, layer.line) : makeTree(parts, dims, layer.line);
}

}  // namespace

std::shared_ptr<const Bsdf> parseBsdfXml(std::string_view text, const std::string& name) {
  if (text.size() > kMaxBsdfXmlBytes)
    throw InputError(FileLoc{name, 0, 0}, "BSDF file larger than " + std::to_string(kMaxBsdfXmlBytes >> 20) + " MiB");
  Doc doc;
  XML_Parser parser = XML_ParserCreate(nullptr);
  if (!parser) throw std::bad_alloc();
  doc.parser = parser;
  XML_SetUserData(parser, &doc);
  XML_SetElementHandler(parser, onStart, onEnd);
  XML_SetCharacterDataHandler(parser, onText);
  XML_SetStartDoctypeDeclHandler(parser, onDoctype);
  const XML_Status status = XML_Parse(parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
  std::string error;
  int line = 0;
  if (!doc.error.empty()) {
    error = doc.error;
    line = doc.errorLine;
  } else if (status != XML_STATUS_OK) {
    error = std::string("XML: ") + XML_ErrorString(XML_GetErrorCode(parser));
    line = static_cast<int>(XML_GetCurrentLineNumber(parser));
  }
  XML_ParserFree(parser);
  doc.parser = nullptr;
  if (!error.empty()) throw InputError(FileLoc{name, line, 0}, error);
  return Reader(doc, name).read();
}

std::shared_ptr<const Bsdf> readBsdfXml(const std::filesystem::path& path) {
  const std::string text = readInputFile(path, "BSDF file", kMaxBsdfXmlBytes);
  return parseBsdfXml(text, path.string());
}

}  // namespace candela
