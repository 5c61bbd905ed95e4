#include "study/case/case_toml.h"

#include "base/units.h"

#include <cmath>
#include <sstream>

namespace candela::case_toml {

namespace fs = std::filesystem;

namespace {

// No value of a case file is larger: coordinates stay within kMaxCoordinateM (base/units.h), and
// no illuminance, threshold or multiplier comes near it.
constexpr double kMaxCaseValue = kMaxCoordinateM;

const char* typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

}  // namespace

std::string keyText(std::string_view key) { return "'" + std::string(key) + "'"; }


double asNumber(const Context& c, const toml::node& n, std::string_view key) {
  double v = 0.0;
  if (auto f = n.as_floating_point()) {
    if (!std::isfinite(f->get())) c.fail(n, keyText(key) + " must be a finite number");
    v = f->get();
  } else if (auto i = n.as_integer()) {
    v = static_cast<double>(i->get());
  } else {
    c.fail(n, keyText(key) + " must be a number, got " + typeName(n));
  }
  if (std::abs(v) > kMaxCaseValue) c.fail(n, keyText(key) + " must lie within ±1e7 (coordinates in m)");
  return v;
}

int64_t asInteger(const Context& c, const toml::node& n, std::string_view key) {
  if (auto v = n.as_integer()) return v->get();
  c.fail(n, keyText(key) + " must be an integer, got " + typeName(n));
}

std::string asString(const Context& c, const toml::node& n, std::string_view key) {
  if (auto v = n.as_string()) return v->get();
  c.fail(n, keyText(key) + " must be a string, got " + typeName(n));
}

bool asBool(const Context& c, const toml::node& n, std::string_view key) {
  if (auto v = n.as_boolean()) return v->get();
  c.fail(n, keyText(key) + " must be true or false, got " + typeName(n));
}

const toml::array& asArray(const Context& c, const toml::node& n, std::string_view key, std::size_t size,
                           const char* what) {
  const toml::array* a = n.as_array();
  if (!a || (size > 0 && a->size() != size)) c.fail(n, keyText(key) + " must be " + what);
  return *a;
}

std::vector<const toml::table*> asTableList(const Context& c, const toml::node& n, std::string_view key,
                                            const char* shape) {
  const toml::array& a = asArray(c, n, key, 0, ("an array of " + std::string(shape)).c_str());
  if (a.empty()) c.fail(n, keyText(key) + " needs at least one entry " + shape);
  std::vector<const toml::table*> out;
  for (const toml::node& e : a) {
    const toml::table* t = e.as_table();
    if (!t) c.fail(e, "each of " + keyText(key) + " must be " + shape);
    out.push_back(t);
  }
  return out;
}

Vec3 asVec3(const Context& c, const toml::node& n, std::string_view key) {
  const toml::array& a = asArray(c, n, key, 3, "an array of 3 numbers [x, y, z]");
  return Vec3(asNumber(c, a[0], key), asNumber(c, a[1], key), asNumber(c, a[2], key));
}

Vec2 asVec2(const Context& c, const toml::node& n, std::string_view key, const char* what) {
  const toml::array& a = asArray(c, n, key, 2, what);
  return Vec2(asNumber(c, a[0], key), asNumber(c, a[1], key));
}

Vec3 asDirection(const Context& c, const toml::node& n, std::string_view key) {
  const Vec3 v = asVec3(c, n, key);
  if (v == Vec3(0.0)) c.fail(n, keyText(key) + " must not be the zero vector");
  const std::optional<Vec3> unit = unitDirection(v);
  if (!unit) c.fail(n, keyText(key) + " cannot be normalised: its length underflows");
  return *unit;
}

std::vector<Vec2> asPointList(const Context& c, const toml::node& n, std::string_view key) {
  const toml::array& a = asArray(c, n, key, 0, "an array of [x, y] points");
  std::vector<Vec2> pts;
  for (const toml::node& e : a) pts.push_back(asVec2(c, e, key, "an array of [x, y] points"));
  return pts;
}

std::optional<double> optNumber(Table& t, std::string_view key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  return asNumber(t.ctx(), *n, key);
}

double numberOr(Table& t, std::string_view key, double dflt) { return optNumber(t, key).value_or(dflt); }

// `value` must lie in [lo, hi]; the message names the key and the accepted range.
void checkRange(Table& t, std::string_view key, double value, double lo, double hi, const char* unit) {
  if (value >= lo && value <= hi) return;
  std::ostringstream m;
  m << keyText(key) << " must be between " << lo << " and " << hi << unit << ", got " << value;
  throw InputError(t.ctx().at(*t.get(key)), m.str());
}

void checkMin(Table& t, std::string_view key, double value, double lo, bool strict, const char* unit) {
  if (strict ? value > lo : value >= lo) return;
  std::ostringstream m;
  m << keyText(key) << " must be " << (strict ? "greater than " : "at least ") << lo << unit << ", got " << value;
  throw InputError(t.ctx().at(*t.get(key)), m.str());
}

// A referenced file: relative to the case file's folder; it must exist.
fs::path filePath(Table& t, std::string_view key, const char* what) {
  const toml::node& n = t.require(key);
  const std::string text = asString(t.ctx(), n, key);
  if (text.empty()) t.ctx().fail(n, keyText(key) + " must not be empty");
  if (text.find('\0') != std::string::npos) t.ctx().fail(n, keyText(key) + " must not contain a NUL character");
  fs::path p(text);
  if (p.is_relative()) p = t.ctx().dir / p;
  p = p.lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) {
    const std::string where = p == fs::path(text) ? "" : " (looked for " + p.string() + ")";
    t.ctx().fail(n, std::string(what) + " '" + text + "' not found" + where);
  }
  return p;
}

// One [[name]] list: an array of tables (or absent).
const toml::array* tableArray(const Context& c, const toml::table& root, std::string_view key) {
  const toml::node* n = root.get(key);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    c.fail(*n, "'" + std::string(key) + "' must be a list of tables, written [[" + std::string(key) + "]]");
  return a;
}

const toml::table* singleTable(const Context& c, const toml::table& root, std::string_view key) {
  const toml::node* n = root.get(key);
  if (!n) return nullptr;
  if (!n->is_table()) c.fail(*n, "'" + std::string(key) + "' must be a table, written [" + std::string(key) + "]");
  return n->as_table();
}

}  // namespace candela::case_toml
