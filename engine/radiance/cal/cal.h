// Radiance's function language (the .cal files of brightfunc, colorfunc, texfunc, mixfunc, the
// sky functions, ...), as its reference manual and calcomp define it: definitions `name = expr;`,
// constants `name : expr;`, functions `f(a, b) = expr;` (an argument may itself be a function:
// `dot(v1, v2)` calls v1(1)), the operators + - * / ^ (^ right-associative, unary minus binding
// tighter than ^, so -2^2 = 4), numbers with exponents, `{ comments }` that nest, names of
// letters, digits, '_', '.' and '`' (context marks, kept as part of the name). Arguments are
// evaluated when used, so `if` evaluates one branch and recursion ends. As calcomp, a division
// by zero, an illegal power or a library function's domain or range error gives 0.
//
// Parsed once into a tree of nodes over numbered symbols: evaluation does no string work. The
// library (Radiance's built-in functions and rayinit.cal's definitions: PI, bound, hermite,
// bezier, noise3, ...) is built in. The ray's variables (Dx, Nx, Px, T, arg(n), A1, ...) come
// from an Environment filled per evaluation.
#pragma once

#include "base/error.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace candela::cal {

// The ray's variables, in this order in Environment::ray (rayinit.cal's list): direction, surface
// normal, intersection point, distance, ray dot product, world scale, local (u, v) of mesh
// triangles, and the perturbed normal and dot product of the *func materials.
enum RayVar : int {
  kDx, kDy, kDz, kNx, kNy, kNz, kPx, kPy, kPz, kT, kTs, kRdot, kS, kTx, kTy, kTz,
  kIx, kIy, kIz, kJx, kJy, kJz, kKx, kKy, kKz, kLu, kLv, kNxP, kNyP, kNzP, kRdotP,
  kCrP, kCgP, kCbP, kRayVarCount
};

// What one evaluation sees: the ray's variables and the primitive's real arguments (arg(1)...,
// arg(0) their count).
struct Environment {
  double ray[kRayVarCount] = {};
  std::span<const double> args;
};

// A name's symbol: its index in the program (stable once made).
using Symbol = int32_t;

class Program {
 public:
  // A program holding the built-in library.
  Program();
  ~Program();
  Program(Program&&) noexcept;
  Program& operator=(Program&&) noexcept;

  // Adds the definitions of a .cal text; a syntax error is an InputError at its file and line. A
  // later definition of a name replaces an earlier one (as calcomp's), the library's included.
  void addText(std::string_view text, const std::string& fileName);
  // Adds one definition written as an expression, e.g. a pattern argument "A1*Dx" (a name
  // "<inline>" is given to it); returns its symbol.
  Symbol addExpression(std::string_view expression, const std::string& name, const FileLoc& loc);

  // The symbol of a name (-1: never mentioned).
  Symbol find(std::string_view name) const;
  // Refuses (InputError at `loc`) a name that is not defined, or whose definition reaches a name
  // that is neither defined nor a ray variable or library function; `calls` arguments when it is
  // called as a function, -1 when used as a variable. Messages call it `label` (default: name).
  void check(std::string_view name, int calls, const FileLoc& loc, std::string_view label = {}) const;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// The text of a function file Radiance's generators name and a Radiance installation keeps in its
// library (surf.cal, rev.cal, tmesh.cal), for when the file is not found where files are looked
// up; nullopt for any other name.
std::optional<std::string_view> libraryFile(std::string_view name);

// Whether `text` is a plain name of the language (a letter or '`', then letters, digits, '_', '.'
// and '`'), as the parser reads names.
bool isName(std::string_view text);

// Evaluates a program's names. Keeps per-evaluation caches: one evaluator per thread.
class Evaluator {
 public:
  explicit Evaluator(const Program& program);
  ~Evaluator();

  // Starts a new evaluation (a new ray or point): variables are computed again.
  void begin(const Environment& env);
  // The value of variable `name`, or of function `name` called with `args`.
  double value(Symbol name);
  double call(Symbol name, std::span<const double> args);

  // Evaluations done (calls of value/call), for the speed measurements.
  uint64_t evaluations() const { return evaluations_; }

 private:
  struct State;
  std::unique_ptr<State> state_;
  uint64_t evaluations_ = 0;
};

// A failure during evaluation that a program's check could not foresee: recursion deeper than
// kMaxDepth calls, or one evaluation of more than kMaxSteps nodes (a recursion that branches
// would otherwise take exponential time: time is bounded by what the input really asks for).
struct EvalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline constexpr int kMaxDepth = 1024;
inline constexpr uint64_t kMaxSteps = 10000000;

}  // namespace candela::cal
