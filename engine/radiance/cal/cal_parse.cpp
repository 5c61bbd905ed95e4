// The function language's parser: calcomp's grammar (engine/radiance/cal/cal.h), one pass over
// the text into nodes, every error an InputError at its file and line.
#include "engine/radiance/cal/cal_impl.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace candela::cal {
namespace {

bool isIdStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '`'; }
bool isIdChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '`';
}

class Parser {
 public:
  Parser(Program::Impl& p, std::string_view text, std::string file, int line)
      : p_(p), text_(text), file_(std::move(file)), line_(line) {
    skip();
  }

  void definitions() {
    while (!atEnd()) {
      definition();
      if (atEnd()) break;
      expect(';', "';' after a definition");
      while (peek() == ';') advance();
    }
  }

  // One expression to the end of the text.
  int32_t wholeExpression() {
    const int32_t e = expression();
    if (!atEnd()) fail("unexpected '" + std::string(1, peek()) + "' after the expression");
    return e;
  }

  FileLoc here() const { return FileLoc{file_, line_, 0}; }
  [[noreturn]] void fail(const std::string& message) const { throw InputError(here(), message); }

 private:
  // name = expr | name : expr | name(params) = expr | name(params) : expr
  void definition() {
    const FileLoc loc = here();
    if (!isIdStart(peek())) fail("a definition must start with a name, not '" + std::string(1, peek()) + "'");
    const std::string name = identifier();
    params_.clear();
    bool function = false;
    if (peek() == '(') {
      function = true;
      advance();
      for (;;) {
        if (!isIdStart(peek())) fail("parameter name expected in the definition of '" + name + "'");
        params_.push_back(identifier());
        if (peek() == ',') {
          advance();
          continue;
        }
        expect(')', "')' after the parameters of '" + name + "'");
        break;
      }
    }
    const char assign = peek();
    if (assign != '=' && assign != ':') fail("'=' or ':' expected after '" + name + "'");
    advance();
    inFunction_ = function;
    const int32_t body = expression();
    inFunction_ = false;
    const Symbol s = p_.intern(name);
    Definition& d = p_.symbols[static_cast<size_t>(s)].def;
    d.body = body;
    d.params = function ? static_cast<int32_t>(params_.size()) : -1;
    d.constant = assign == ':';
    d.loc = loc;
  }

  // E1 -> E1 (+|-) E2 | E2
  int32_t expression() {
    int32_t left = term();
    while (peek() == '+' || peek() == '-') {
      const Op op = peek() == '+' ? Op::kAdd : Op::kSub;
      advance();
      left = binary(op, left, term());
    }
    return left;
  }
  // E2 -> E2 (*|/) E3 | E3
  int32_t term() {
    int32_t left = power();
    while (peek() == '*' || peek() == '/') {
      const Op op = peek() == '*' ? Op::kMul : Op::kDiv;
      advance();
      left = binary(op, left, power());
    }
    return left;
  }
  // E3 -> E4 ^ E3 | E4 (right-associative)
  int32_t power() {
    const int32_t base = unary();
    if (peek() != '^') return base;
    advance();
    return binary(Op::kPow, base, power());
  }
  // E4 -> - E5 | + E5 | E5
  int32_t unary() {
    if (peek() == '-') {
      advance();
      const int32_t e = primary();
      Node& n = p_.nodes[static_cast<size_t>(e)];
      if (n.op == Op::kNum) {
        n.num = -n.num;
        return e;
      }
      Node neg;
      neg.op = Op::kNeg;
      neg.a = e;
      return p_.add(neg);
    }
    if (peek() == '+') advance();
    return primary();
  }
  // E5 -> ( E1 ) | number | name | name ( E1, ... )
  int32_t primary() {
    if (depth_ > 200) fail("expression nested more than 200 levels deep");
    if (peek() == '(') {
      advance();
      ++depth_;
      const int32_t e = expression();
      --depth_;
      expect(')', "')' expected");
      return e;
    }
    if (isIdStart(peek())) return nameOrCall();
    if (std::isdigit(static_cast<unsigned char>(peek())) || peek() == '.') {
      Node n;
      n.op = Op::kNum;
      n.num = number();
      return p_.add(n);
    }
    if (atEnd()) fail("the expression ends too early");
    fail("unexpected '" + std::string(1, peek()) + "' in an expression");
  }

  int32_t nameOrCall() {
    const std::string name = identifier();
    int32_t param = -1;
    if (inFunction_)
      for (size_t i = 0; i < params_.size(); ++i)
        if (params_[i] == name) param = static_cast<int32_t>(i);
    Node n;
    if (peek() != '(') {
      n.op = param >= 0 ? Op::kParam : Op::kVar;
      n.a = param >= 0 ? param : p_.intern(name);
      return p_.add(n);
    }
    advance();
    std::vector<int32_t> args;
    ++depth_;
    for (;;) {
      args.push_back(expression());
      if (peek() == ',') {
        advance();
        continue;
      }
      expect(')', "')' or ',' expected in the arguments of '" + name + "'");
      break;
    }
    --depth_;
    n.op = param >= 0 ? Op::kCallParam : Op::kCall;
    n.a = param >= 0 ? param : p_.intern(name);
    n.firstKid = static_cast<int32_t>(p_.kids.size());
    n.kidCount = static_cast<int32_t>(args.size());
    p_.kids.insert(p_.kids.end(), args.begin(), args.end());
    return p_.add(n);
  }

  int32_t binary(Op op, int32_t a, int32_t b) {
    Node n;
    n.op = op;
    n.a = a;
    n.b = b;
    return p_.add(n);
  }

  std::string identifier() {
    std::string s;
    while (pos_ < text_.size() && isIdChar(text_[pos_])) s += text_[pos_++];
    if (s.size() > 256) fail("name longer than 256 characters");
    skip();
    return s;
  }

  // digits [. digits] [(e|E) [+|-] digits], as calcomp reads a number.
  double number() {
    const size_t start = pos_;
    auto digits = [&] {
      size_t n = 0;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_, ++n;
      return n;
    };
    size_t n = digits();
    if (pos_ < text_.size() && text_[pos_] == '.') {
      ++pos_;
      n += digits();
    }
    if (n == 0) fail("badly formed number");
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      if (digits() == 0) fail("missing exponent in a number");
    }
    const std::string s(text_.substr(start, pos_ - start));
    skip();
    return std::strtod(s.c_str(), nullptr);
  }

  // White space and { comments }, which nest.
  void skip() {
    for (;;) {
      while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if (pos_ >= text_.size() || text_[pos_] != '{') return;
      const int opened = line_;
      int nest = 0;
      do {
        if (pos_ >= text_.size()) throw InputError(FileLoc{file_, opened, 0}, "comment '{' is never closed by '}'");
        if (text_[pos_] == '{') ++nest;
        if (text_[pos_] == '}') --nest;
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
      } while (nest > 0);
    }
  }

  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[pos_]; }
  void advance() {
    ++pos_;
    skip();
  }
  void expect(char c, const std::string& what) {
    if (peek() != c) fail(what + (atEnd() ? ", got the end of the text" : ", got '" + std::string(1, peek()) + "'"));
    advance();
  }

  Program::Impl& p_;
  std::string_view text_;
  std::string file_;
  int line_;
  size_t pos_ = 0;
  int depth_ = 0;
  bool inFunction_ = false;
  std::vector<std::string> params_;
};

}  // namespace

bool isName(std::string_view text) {
  return !text.empty() && isIdStart(text[0]) && std::all_of(text.begin(), text.end(), isIdChar);
}

Symbol Program::Impl::intern(std::string_view name) {
  const auto it = byName.find(std::string(name));
  if (it != byName.end()) return it->second;
  const Symbol s = static_cast<Symbol>(symbols.size());
  symbols.push_back(SymbolInfo{std::string(name), {}, Native::kNone, -1});
  byName.emplace(std::string(name), s);
  return s;
}

void parseText(Program::Impl& p, std::string_view text, const std::string& fileName, int firstLine) {
  Parser(p, text, fileName, firstLine).definitions();
}

void parseExpression(Program::Impl& p, std::string_view text, Symbol name, const FileLoc& loc) {
  Parser parser(p, text, loc.file, loc.line);
  const int32_t body = parser.wholeExpression();
  Definition& d = p.symbols[static_cast<size_t>(name)].def;
  d.body = body;
  d.params = -1;
  d.constant = false;
  d.loc = loc;
}

}  // namespace candela::cal
