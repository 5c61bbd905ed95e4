// The function language's evaluator: a walk over the parsed nodes with calcomp's rules (lazy
// arguments, each variable computed once per evaluation, 0 for a division by zero, an illegal
// power or a domain or range error).
#include "engine/radiance/cal/cal_impl.h"

#include <algorithm>
#include <cmath>

namespace candela::cal {

namespace {

// One function call: where its arguments come from (nodes evaluated in the caller's activation,
// or values given directly) and those computed so far.
struct Activation {
  const Activation* caller = nullptr;
  const int32_t* argNodes = nullptr;
  const double* argValues = nullptr;
  int count = 0;
  Symbol function = -1;
  mutable double cache[8] = {};
  mutable uint32_t computed = 0;
};

double finiteOrZero(double v) { return std::isfinite(v) ? v : 0.0; }

}  // namespace

struct Evaluator::State {
  const Program::Impl& p;
  Environment env;
  std::vector<double> values;
  std::vector<uint32_t> stamp;
  uint32_t epoch = 1;
  int depth = 0;
  uint64_t steps = 0;  // nodes evaluated by the current value() or call(), at most kMaxSteps

  explicit State(const Program::Impl& program)
      : p(program), values(program.symbols.size(), 0.0), stamp(program.symbols.size(), 0) {}

  [[noreturn]] void fail(const std::string& message) const { throw EvalError(message); }

  const std::string& nameOf(Symbol s) const { return p.symbols[static_cast<size_t>(s)].name; }

  double argument(const Activation& act, int i) {
    if (i >= act.count) fail(nameOf(act.function) + "(): too few arguments");
    if (i < 8 && (act.computed >> i) & 1u) return act.cache[i];
    const double v = act.argValues ? act.argValues[i] : node(act.argNodes[i], act.caller);
    if (i < 8) {
      act.cache[i] = v;
      act.computed |= 1u << i;
    }
    return v;
  }

  double variable(Symbol s) {
    const SymbolInfo& info = p.symbols[static_cast<size_t>(s)];
    if (info.def.body >= 0) {
      if (info.def.params >= 0) fail("'" + info.name + "' is a function, used as a variable");
      if (stamp[static_cast<size_t>(s)] == epoch) return values[static_cast<size_t>(s)];
      if (++depth > kMaxDepth) fail("'" + info.name + "': definitions nested more than 1024 deep (recursion?)");
      const double v = node(info.def.body, nullptr);
      --depth;
      values[static_cast<size_t>(s)] = v;
      stamp[static_cast<size_t>(s)] = epoch;
      return v;
    }
    if (info.rayVar >= 0) return env.ray[info.rayVar];
    fail("'" + info.name + "' is not defined");
  }

  double call(Symbol s, const Activation& act) {
    const SymbolInfo& info = p.symbols[static_cast<size_t>(s)];
    if (++depth > kMaxDepth) fail(info.name + "(): calls nested more than 1024 deep (recursion without end?)");
    double v = 0.0;
    if (info.def.body >= 0) {
      if (info.def.params < 0) fail("'" + info.name + "' is a variable, called as a function");
      v = node(info.def.body, &act);
    } else if (info.native != Native::kNone) {
      v = native(info.native, act);
    } else {
      fail(info.name + "(): undefined function");
    }
    --depth;
    return v;
  }

  // The function passed as parameter i of act (an argument that names one, possibly passed on
  // from the caller's own parameters).
  Symbol functionArgument(const Activation* act, int i) {
    for (;;) {
      if (!act || !act->argNodes || i >= act->count) fail("an argument called as a function is not a function");
      const Node& n = p.nodes[static_cast<size_t>(act->argNodes[i])];
      if (n.op == Op::kVar) return n.a;
      if (n.op != Op::kParam) fail(nameOf(act->function) + "(): argument " + std::to_string(i + 1) + " is not a function");
      i = n.a;
      act = act->caller;
    }
  }

  double node(int32_t index, const Activation* act) {
    if (++steps > kMaxSteps) fail("one evaluation took more than 10^7 steps (a recursion that branches?)");
    const Node& n = p.nodes[static_cast<size_t>(index)];
    switch (n.op) {
      case Op::kNum:
        return n.num;
      case Op::kVar:
        return variable(n.a);
      case Op::kParam:
        if (!act) fail("a parameter outside its function");
        return argument(*act, n.a);
      case Op::kNeg:
        return -node(n.a, act);
      case Op::kAdd:
        return node(n.a, act) + node(n.b, act);
      case Op::kSub:
        return node(n.a, act) - node(n.b, act);
      case Op::kMul:
        return node(n.a, act) * node(n.b, act);
      case Op::kDiv: {
        const double num = node(n.a, act), den = node(n.b, act);
        return den == 0.0 ? 0.0 : num / den;
      }
      case Op::kPow:
        return finiteOrZero(std::pow(node(n.a, act), node(n.b, act)));
      case Op::kCall:
      case Op::kCallParam: {
        const Symbol callee = n.op == Op::kCall ? n.a : functionArgument(act, n.a);
        Activation next;
        next.caller = act;
        next.argNodes = p.kids.data() + n.firstKid;
        next.count = n.kidCount;
        next.function = callee;
        return call(callee, next);
      }
    }
    return 0.0;
  }

  double native(Native f, const Activation& a) {
    auto x = [&](int i) { return argument(a, i); };
    switch (f) {
      case Native::kIf:
        return x(0) > 0.0 ? x(1) : x(2);
      case Native::kSelect: {
        // select(N, a1, a2, ...): aN; select(0, ...) the count of a's.
        const double a1 = x(0);
        if (!(a1 >= -0.5 && a1 + 0.5 < a.count)) return 0.0;  // NaN and out of range alike
        const int n = static_cast<int>(a1 + 0.5);
        return n == 0 ? a.count - 1 : x(n);
      }
      case Native::kMin:
      case Native::kMax: {
        double v = x(0);
        for (int i = 1; i < a.count; ++i) v = f == Native::kMin ? std::min(v, x(i)) : std::max(v, x(i));
        return v;
      }
      case Native::kRand: {
        // calcomp's pseudo-random function of x, in [0, 1).
        double v = x(0);
        v *= 1.0 / (1.0 + v * v) + 2.71828182845904;
        v += 0.785398163397447 - std::floor(v);
        v = 1e5 / v;
        return finiteOrZero(v - std::floor(v));
      }
      case Native::kFloor: return std::floor(x(0));
      case Native::kCeil: return std::ceil(x(0));
      case Native::kSqrt: return finiteOrZero(std::sqrt(x(0)));
      case Native::kSin: return finiteOrZero(std::sin(x(0)));
      case Native::kCos: return finiteOrZero(std::cos(x(0)));
      case Native::kTan: return finiteOrZero(std::tan(x(0)));
      case Native::kAsin: return finiteOrZero(std::asin(x(0)));
      case Native::kAcos: return finiteOrZero(std::acos(x(0)));
      case Native::kAtan: return std::atan(x(0));
      case Native::kAtan2: return finiteOrZero(std::atan2(x(0), x(1)));
      case Native::kExp: return finiteOrZero(std::exp(x(0)));
      case Native::kLog: return finiteOrZero(std::log(x(0)));
      case Native::kLog10: return finiteOrZero(std::log10(x(0)));
      case Native::kErf: return std::erf(x(0));
      case Native::kErfc: return std::erfc(x(0));
      case Native::kNoise3: return noise3(x(0), x(1), x(2));
      case Native::kNoise3x:
      case Native::kNoise3y:
      case Native::kNoise3z: {
        double g[3];
        noise3Gradient(x(0), x(1), x(2), g);
        return g[f == Native::kNoise3x ? 0 : f == Native::kNoise3y ? 1 : 2];
      }
      case Native::kFnoise3: return fractalNoise3(x(0), x(1), x(2));
      case Native::kArg: {
        // arg(0): the count of the primitive's real arguments; arg(n): the n-th.
        const double a1 = x(0);
        if (!(a1 >= -0.5 && a1 + 0.5 < static_cast<double>(env.args.size()) + 1.0))
          fail("arg(" + std::to_string(a1) + "): the primitive has " + std::to_string(env.args.size()) +
               " real arguments");
        const int n = static_cast<int>(a1 + 0.5);
        if (n == 0) return static_cast<double>(env.args.size());
        return env.args[static_cast<size_t>(n - 1)];
      }
      case Native::kNone:
      case Native::kCount:
        break;
    }
    fail("bad native function");
  }
};

Evaluator::Evaluator(const Program& program) : state_(std::make_unique<State>(program.impl())) {}
Evaluator::~Evaluator() = default;

void Evaluator::begin(const Environment& env) {
  state_->env = env;
  if (++state_->epoch == 0) {  // wrapped: forget every cached value
    std::fill(state_->stamp.begin(), state_->stamp.end(), 0u);
    state_->epoch = 1;
  }
}

double Evaluator::value(Symbol name) {
  ++evaluations_;
  state_->depth = 0;
  state_->steps = 0;
  return state_->variable(name);
}

double Evaluator::call(Symbol name, std::span<const double> args) {
  ++evaluations_;
  state_->depth = 0;
  state_->steps = 0;
  Activation act;
  act.argValues = args.data();
  act.count = static_cast<int>(args.size());
  act.function = name;
  return state_->call(name, act);
}

}  // namespace candela::cal
