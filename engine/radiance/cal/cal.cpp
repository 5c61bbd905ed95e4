#include "engine/radiance/cal/cal_impl.h"

#include <functional>
#include <set>

namespace candela::cal {
namespace {
std::string arguments(int n) { return std::to_string(n) + (n == 1 ? " argument" : " arguments"); }
}  // namespace

Program::Program() : impl_(std::make_unique<Impl>()) { addLibrary(*impl_); }
Program::~Program() = default;
Program::Program(Program&&) noexcept = default;
Program& Program::operator=(Program&&) noexcept = default;

void Program::addText(std::string_view text, const std::string& fileName) { parseText(*impl_, text, fileName); }

Symbol Program::addExpression(std::string_view expression, const std::string& name, const FileLoc& loc) {
  const Symbol s = impl_->intern(name);
  parseExpression(*impl_, expression, s, loc);
  return s;
}

Symbol Program::find(std::string_view name) const {
  const auto it = impl_->byName.find(std::string(name));
  return it == impl_->byName.end() ? -1 : it->second;
}

void Program::check(std::string_view symbolName, int calls, const FileLoc& loc, std::string_view label) const {
  const Impl& p = *impl_;
  const Symbol s = find(symbolName);
  const std::string_view name = label.empty() ? symbolName : label;
  auto refuse = [&](const std::string& why) { throw InputError(loc, why); };
  if (s < 0 || (p.symbols[static_cast<size_t>(s)].def.body < 0 && p.symbols[static_cast<size_t>(s)].rayVar < 0 &&
                p.symbols[static_cast<size_t>(s)].native == Native::kNone))
    refuse("'" + std::string(name) + "' is not defined in the function files");
  // Every name the definition reaches, each checked once: defined, a ray variable or native, and
  // used as it is defined (a variable as a variable, a function with the arguments it takes).
  std::set<std::pair<Symbol, int>> seen;
  std::function<void(Symbol, int, const FileLoc&)> visit = [&](Symbol sym, int args, const FileLoc& where) {
    if (!seen.insert({sym, args}).second) return;
    const SymbolInfo& info = p.symbols[static_cast<size_t>(sym)];
    auto bad = [&](const std::string& why) {
      throw InputError(where, "'" + std::string(name) + "' uses " + why);
    };
    if (info.def.body >= 0) {
      if (args < 0 && info.def.params >= 0) bad("the function '" + info.name + "' as a variable");
      if (args >= 0 && info.def.params < 0) bad("the variable '" + info.name + "' as a function");
      if (args >= 0 && args < info.def.params)
        bad(info.name + "() with " + arguments(args) + "; it takes " + std::to_string(info.def.params));
      std::function<void(int32_t)> walk = [&](int32_t n) {
        const Node& node = p.nodes[static_cast<size_t>(n)];
        switch (node.op) {
          case Op::kVar: visit(node.a, -1, info.def.loc); break;
          case Op::kCall:
            visit(node.a, node.kidCount, info.def.loc);
            [[fallthrough]];
          case Op::kCallParam:
            for (int32_t k = 0; k < node.kidCount; ++k) {
              const int32_t kid = p.kids[static_cast<size_t>(node.firstKid + k)];
              // An argument that names a function is passed as that function.
              const Node& a = p.nodes[static_cast<size_t>(kid)];
              if (a.op == Op::kVar && p.symbols[static_cast<size_t>(a.a)].def.params >= 0) continue;
              walk(kid);
            }
            break;
          case Op::kNeg: walk(node.a); break;
          case Op::kAdd: case Op::kSub: case Op::kMul: case Op::kDiv: case Op::kPow:
            walk(node.a);
            walk(node.b);
            break;
          case Op::kNum: case Op::kParam: break;
        }
      };
      walk(info.def.body);
      return;
    }
    if (info.rayVar >= 0) {
      if (args >= 0) bad("the ray variable '" + info.name + "' as a function");
      return;
    }
    if (info.native != Native::kNone) {
      if (args < 0) bad("the function '" + info.name + "' as a variable");
      const int arity = nativeArity(info.native);
      if ((arity >= 0 && args != arity) || (arity < 0 && args < 1))
        bad(info.name + "() with " + arguments(args));
      return;
    }
    bad("'" + info.name + "', which is not defined");
  };
  visit(s, calls, loc);
}

}  // namespace candela::cal
