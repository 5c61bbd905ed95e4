// The function language's program as parsed (engine/radiance/cal/cal.h): nodes over numbered
// symbols, shared by the parser, the library and the evaluator.
#pragma once

#include "engine/radiance/cal/cal.h"

#include <optional>

namespace candela::cal {

enum class Op : uint8_t {
  kNum,      // num
  kVar,      // a: symbol, evaluated as a variable
  kParam,    // a: the enclosing function's parameter index (0-based)
  kNeg,      // a: operand
  kAdd,      // a, b: operands (also kSub, kMul, kDiv, kPow)
  kSub,
  kMul,
  kDiv,
  kPow,
  kCall,       // a: callee symbol; kids: arguments
  kCallParam,  // a: the parameter (a function passed in) called; kids: arguments
};

struct Node {
  Op op = Op::kNum;
  int32_t a = 0, b = 0;
  int32_t firstKid = 0, kidCount = 0;  // into Program::Impl::kids
  double num = 0.0;
};

// The native functions (calcomp's library, Radiance's ray library); kNone: not native.
enum class Native : int8_t {
  kNone = -1, kIf, kSelect, kMin, kMax, kRand, kFloor, kCeil, kSqrt, kSin, kCos, kTan, kAsin,
  kAcos, kAtan, kAtan2, kExp, kLog, kLog10, kErf, kErfc, kNoise3, kNoise3x, kNoise3y, kNoise3z,
  kFnoise3, kArg, kCount
};

struct Definition {
  int32_t body = -1;        // node; -1: not defined
  int32_t params = -1;      // -1: a variable; else the function's parameter count
  bool constant = false;    // written with ':'
  FileLoc loc;
};

struct SymbolInfo {
  std::string name;
  Definition def;
  Native native = Native::kNone;
  int rayVar = -1;  // RayVar, -1: none
};

struct Program::Impl {
  std::vector<Node> nodes;
  std::vector<int32_t> kids;
  std::vector<SymbolInfo> symbols;
  std::unordered_map<std::string, Symbol> byName;

  Symbol intern(std::string_view name);
  int32_t add(const Node& n) {
    nodes.push_back(n);
    return static_cast<int32_t>(nodes.size() - 1);
  }
};

// Parses `text` into `p` (definitions separated by ';').
void parseText(Program::Impl& p, std::string_view text, const std::string& fileName, int firstLine = 1);
// Parses one expression as the body of a new definition of `name`.
void parseExpression(Program::Impl& p, std::string_view text, Symbol name, const FileLoc& loc);
// Native functions and ray variables by name, and the library's definitions in the cal language.
void addLibrary(Program::Impl& p);
// The natives' arity: the fixed count, or -1 for any count from 1.
int nativeArity(Native n);
// Radiance-style noise (engine/radiance/cal/noise.cpp): noise3 in (−1, 1) and its gradient.
double noise3(double x, double y, double z);
void noise3Gradient(double x, double y, double z, double g[3]);
double fractalNoise3(double x, double y, double z);

}  // namespace candela::cal
