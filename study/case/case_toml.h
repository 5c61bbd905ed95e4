// The case file's TOML values as candela reads them (study/case/case_file.cpp and its parts): every
// key consumed once and a leftover one an error at its line, numbers finite and within ±1e7,
// paths relative to the case file's folder, and errors as InputError("case.toml:LINE: ...").
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace candela::case_toml {

// Where we are: the case file (for messages) and its folder (for relative paths).
struct Context {
  std::string file;
  std::filesystem::path dir;
  FileLoc at(const toml::source_region& r) const {
    return FileLoc{file, static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
  }
  FileLoc at(const toml::node& n) const { return at(n.source()); }
  [[noreturn]] void fail(const toml::node& n, const std::string& msg) const { throw InputError(at(n), msg); }
};

// A TOML table whose keys are consumed one by one; finish() rejects whatever is left, so a typo
// ("spacng") is an error at its line, never silently ignored.
class Table {
 public:
  Table(const toml::table& t, const Context& ctx, std::string where) : t_(t), ctx_(ctx), where_(std::move(where)) {}

  const toml::node* get(std::string_view key) {
    used_.insert(std::string(key));
    return t_.get(key);
  }
  const toml::node& require(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) throw InputError(loc(), where_ + " needs the key '" + std::string(key) + "'");
    return *n;
  }
  void finish() const {
    for (auto&& [key, node] : t_) {
      if (!used_.count(std::string(key.str())))
        throw InputError(ctx_.at(key.source()), "unknown key '" + std::string(key.str()) + "' in " + where_);
    }
  }
  FileLoc loc() const { return ctx_.at(t_); }
  const std::string& where() const { return where_; }
  const Context& ctx() const { return ctx_; }

 private:
  const toml::table& t_;
  const Context& ctx_;
  std::string where_;
  std::set<std::string> used_;
};

// "'key'", for messages.
std::string keyText(std::string_view key);

// The value at `n` as the key's type; anything else is an error naming the key and what it got.
double asNumber(const Context& c, const toml::node& n, std::string_view key);
int64_t asInteger(const Context& c, const toml::node& n, std::string_view key);
std::string asString(const Context& c, const toml::node& n, std::string_view key);
bool asBool(const Context& c, const toml::node& n, std::string_view key);
// An array of `size` elements (0: any), else an error saying it must be `what`.
const toml::array& asArray(const Context& c, const toml::node& n, std::string_view key, std::size_t size,
                           const char* what);
// A non-empty array of inline tables, each of the form `shape` ("{ position = [x, y, z], ... }"):
// an error at the key when it is no array or empty, at the element when one is no table.
std::vector<const toml::table*> asTableList(const Context& c, const toml::node& n, std::string_view key,
                                            const char* shape);
Vec3 asVec3(const Context& c, const toml::node& n, std::string_view key);
Vec2 asVec2(const Context& c, const toml::node& n, std::string_view key, const char* what = "an array of 2 numbers");
Vec3 asDirection(const Context& c, const toml::node& n, std::string_view key);  // unit, not zero
std::vector<Vec2> asPointList(const Context& c, const toml::node& n, std::string_view key);

std::optional<double> optNumber(Table& t, std::string_view key);
double numberOr(Table& t, std::string_view key, double dflt);
// `value` must lie in [lo, hi]; the message names the key and the accepted range.
void checkRange(Table& t, std::string_view key, double value, double lo, double hi, const char* unit);
// `value` must be above `lo` (strict) or at least `lo`.
void checkMin(Table& t, std::string_view key, double value, double lo, bool strict, const char* unit);
// A referenced file: relative to the case file's folder; it must exist.
std::filesystem::path filePath(Table& t, std::string_view key, const char* what);
// One [[name]] list: an array of tables (or absent).
const toml::array* tableArray(const Context& c, const toml::table& root, std::string_view key);
// One [name] table (or absent).
const toml::table* singleTable(const Context& c, const toml::table& root, std::string_view key);

}  // namespace candela::case_toml
