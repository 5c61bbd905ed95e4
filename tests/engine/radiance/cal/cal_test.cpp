// Radiance's function language: the grammar against hand-worked values, calcomp's rules (lazy
// arguments, 0 for a division by zero or a domain error, right-associative ^ with unary minus
// binding tighter), the library against closed forms, errors at their file and line.
#include "engine/radiance/cal/cal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace candela::cal {
namespace {

double evalVar(Program& p, const std::string& name, const Environment& env = {}) {
  Evaluator e(p);
  e.begin(env);
  return e.value(p.find(name));
}

double evalText(const std::string& text, const std::string& name = "x", const Environment& env = {}) {
  Program p;
  p.addText(text, "t.cal");
  return evalVar(p, name, env);
}

TEST(Cal, OperatorsAndPrecedence) {
  EXPECT_DOUBLE_EQ(evalText("x = 1 + 2 * 3;"), 7.0);
  EXPECT_DOUBLE_EQ(evalText("x = (1 + 2) * 3;"), 9.0);
  EXPECT_DOUBLE_EQ(evalText("x = 10 - 4 - 3;"), 3.0);          // left-associative
  EXPECT_DOUBLE_EQ(evalText("x = 2 ^ 3 ^ 2;"), 512.0);          // right-associative
  EXPECT_DOUBLE_EQ(evalText("x = -2 ^ 2;"), 4.0);               // calcomp: (-2)^2
  EXPECT_DOUBLE_EQ(evalText("x = 2 * -3;"), -6.0);
  EXPECT_DOUBLE_EQ(evalText("x = 12 / 4 / 3;"), 1.0);
  EXPECT_DOUBLE_EQ(evalText("x = 1.5e2 + .5 + 2.E-1;"), 150.7);
  EXPECT_DOUBLE_EQ(evalText("x = 1 / 0;"), 0.0);                // calcomp: division by zero is 0
  EXPECT_DOUBLE_EQ(evalText("x = (-8) ^ .5;"), 0.0);            // illegal power is 0
  EXPECT_DOUBLE_EQ(evalText("x = sqrt(-1) + log(0);"), 0.0);   // domain and range errors are 0
}

TEST(Cal, DefinitionsFunctionsCommentsAndContextNames) {
  const char* text =
      "{ a comment { nested } }\n"
      "a : 3;  b = a * 2;\n"
      "f(u, v) = u * 10 + v;\n"
      "fact(n) = if(n - 1.5, n * fact(n - 1), 1);   { recursion ends through lazy if }\n"
      "x = f(b, a) + fact(5);\n"
      "hid`P. = 4; y = hid`P. + a.b; a.b = 1;\n";
  EXPECT_DOUBLE_EQ(evalText(text), 63.0 + 120.0);
  EXPECT_DOUBLE_EQ(evalText(text, "y"), 5.0);
}

TEST(Cal, ALaterDefinitionReplacesAnEarlierOne) {
  Program p;
  p.addText("x = 1;", "a.cal");
  p.addText("x = 2; PI = 3;", "b.cal");  // the library's too
  EXPECT_DOUBLE_EQ(evalVar(p, "x"), 2.0);
  EXPECT_DOUBLE_EQ(evalVar(p, "PI"), 3.0);
}

TEST(Cal, FunctionsPassedAsArguments) {
  Environment env;
  env.ray[kDx] = 0.6;
  env.ray[kDy] = 0.8;
  env.ray[kNx] = 1.0;
  env.ray[kNz] = 2.0;
  // dot(D, N) and cross(3, D, N) from the library, D and N the ray's vectors as functions.
  EXPECT_DOUBLE_EQ(evalText("x = dot(D, N);", "x", env), 0.6);
  EXPECT_DOUBLE_EQ(evalText("x = cross(3, D, N);", "x", env), 0.6 * 0 - 0.8 * 1.0);
  EXPECT_DOUBLE_EQ(evalText("twice(g, t) = 2 * g(t); sq3(t) = t * t * t; x = twice(sq3, 2);"), 16.0);
  // passed on through a second function's parameter
  EXPECT_DOUBLE_EQ(evalText("ap(h, t) = h(t); on(h, t) = ap(h, t) + 1; cube(t) = t^3; x = on(cube, 2);"), 9.0);
}

TEST(Cal, LibraryAgainstClosedForms) {
  EXPECT_DOUBLE_EQ(evalText("x = select(2, 10, 20, 30);"), 20.0);
  EXPECT_DOUBLE_EQ(evalText("x = select(0, 10, 20, 30);"), 3.0);
  EXPECT_DOUBLE_EQ(evalText("x = min(3, -1, 2) + max(3, -1, 2);"), 2.0);
  EXPECT_DOUBLE_EQ(evalText("x = atan2(1, 1) / DEGREE;"), 45.0);
  EXPECT_DOUBLE_EQ(evalText("x = mod(-7, 3);"), 2.0);
  // A triangle wave of period 2d: 0 at n = 0, d at n = d, 0 at n = 2d.
  EXPECT_DOUBLE_EQ(evalText("x = tri(2.5, 2);"), 1.5);
  EXPECT_DOUBLE_EQ(evalText("x = tri(4, 2) + tri(2, 2);"), 2.0);
  EXPECT_DOUBLE_EQ(evalText("x = bound(0, 7, 1) + clip(-3) + abs(-2) + sgn(-4) + frac(2.25);"), 1 + 0 + 2 - 1 + 0.25);
  EXPECT_DOUBLE_EQ(evalText("x = and(1, -1) + or(-1, 2) + not(-3) + xor(1, 1);"), -1 + 2 + 1 - 1);
  // Cubic curves: the Hermite curve meets its ends and slopes; the Bezier curve at t = 1/2 is
  // (p1 + 3 p2 + 3 p3 + p4)/8; the uniform B-spline's weights sum to 1 at any t.
  EXPECT_DOUBLE_EQ(evalText("x = hermite(2, 5, 0, 0, 0);"), 2.0);
  EXPECT_DOUBLE_EQ(evalText("x = hermite(2, 5, 0, 0, 1);"), 5.0);
  const double h = 1e-6;
  const double slope = (evalText("x = hermite(2, 5, 7, -1, 1e-6);") - 2.0) / h;
  EXPECT_NEAR(slope, 7.0, 1e-4);
  EXPECT_DOUBLE_EQ(evalText("x = bezier(1, 2, 4, 8, .5);"), (1 + 6 + 12 + 8) / 8.0);
  EXPECT_NEAR(evalText("x = bspline(1, 1, 1, 1, .37);"), 1.0, 1e-15);
  // Abramowitz–Stegun's inverse normal: the 97.5 % point is 1.95996 within its 4.5e-4.
  EXPECT_NEAR(evalText("x = unif2norm(.975);"), 1.959964, 4.5e-4);
  EXPECT_NEAR(evalText("x = unif2norm(.025);"), -1.959964, 4.5e-4);
  // calcomp's rand: in [0, 1), a function of its argument only.
  const double r = evalText("x = rand(12.5);");
  EXPECT_GE(r, 0.0);
  EXPECT_LT(r, 1.0);
  EXPECT_EQ(r, evalText("y = 1; x = rand(12.5);"));
  EXPECT_NEAR(evalText("x = erf(1) + erfc(1);"), 1.0, 1e-15);
}

TEST(Cal, RayVariablesAndArguments) {
  Environment env;
  env.ray[kPx] = 2.0;
  env.ray[kPz] = 3.0;
  env.ray[kNz] = 1.0;
  const std::vector<double> args = {0.5, 4.0};
  env.args = args;
  EXPECT_DOUBLE_EQ(evalText("x = A1 * Px + A2 * Pz + AC;", "x", env), 1.0 + 12.0 + 2.0);
  EXPECT_DOUBLE_EQ(evalText("x = arg(0) + arg(2);", "x", env), 6.0);
  // U, V on a horizontal surface (normal +z): U = Px, V = Py.
  env.ray[kPy] = 5.0;
  EXPECT_DOUBLE_EQ(evalText("x = U + 10 * V;", "x", env), 52.0);
}

TEST(Cal, NoiseIsSmoothBoundedAndItsGradientIsItsSlope) {
  Program p;
  p.addText("n = noise3(Px, Py, Pz); gx = noise3x(Px, Py, Pz); f = fnoise3(Px, Py, Pz);", "t.cal");
  Evaluator e(p);
  double mean = 0.0, sq = 0.0;
  const int count = 2000;
  for (int i = 0; i < count; ++i) {
    Environment env;
    env.ray[kPx] = 0.37 * i;
    env.ray[kPy] = 0.11 * i + 0.5;
    env.ray[kPz] = -0.23 * i;
    e.begin(env);
    const double n = e.value(p.find("n"));
    EXPECT_GT(n, -1.0);
    EXPECT_LT(n, 1.0);
    EXPECT_GT(e.value(p.find("f")), -1.0);
    EXPECT_LT(e.value(p.find("f")), 1.0);
    mean += n;
    sq += n * n;
    // The x-gradient against a central difference.
    const double gx = e.value(p.find("gx"));
    Environment a = env, b = env;
    a.ray[kPx] += 1e-6;
    b.ray[kPx] -= 1e-6;
    e.begin(a);
    const double na = e.value(p.find("n"));
    e.begin(b);
    const double nb = e.value(p.find("n"));
    EXPECT_NEAR(gx, (na - nb) / 2e-6, 1e-5);
  }
  mean /= count;
  const double sd = std::sqrt(sq / count - mean * mean);
  EXPECT_GT(sd, 0.05);  // it varies
  EXPECT_LT(std::abs(mean), 4.0 * sd / std::sqrt(count) + 0.05);
}

TEST(Cal, SyntaxErrorsAtTheirLine) {
  auto line = [](const std::string& text) {
    try {
      Program p;
      p.addText(text, "bad.cal");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(line("x = 1;\ny = (2 + 3;\n").find("bad.cal:2: ')' expected"), std::string::npos) << line("x = 1;\ny = (2 + 3;\n");
  EXPECT_NE(line("x = 1;\n\ny 3;").find("bad.cal:3: '=' or ':' expected after 'y'"), std::string::npos);
  EXPECT_NE(line("x = 1 +;").find("bad.cal:1: unexpected ';' in an expression"), std::string::npos);
  EXPECT_NE(line("x = 1;\n{ open\n\n").find("bad.cal:2: comment '{' is never closed"), std::string::npos);
  EXPECT_NE(line("x = 1.e;").find("missing exponent"), std::string::npos);
  EXPECT_NE(line("f(a,) = 1;").find("parameter name expected"), std::string::npos);
  EXPECT_NE(line("x = " + std::string(300, '(') + "1" + std::string(300, ')') + ";").find("nested more than 200"), std::string::npos);
}

TEST(Cal, CheckRefusesWhatAnEvaluationWouldNotFind) {
  Program p;
  p.addText("ok = Dx + sin(PI);\nusesMissing = 1 + missing;\n"
            "g(a, b) = a + b;\nbadCall = g(1);\nvarCall = ok(2);\nfnVar = g + 1;\nlazy = if(1, 2, missing);\n",
            "c.cal");
  const FileLoc at{"scene.rad", 7, 0};
  EXPECT_NO_THROW(p.check("ok", -1, at));
  auto message = [&](const std::string& name, int calls) {
    try {
      p.check(name, calls, at);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("nothing", -1), "scene.rad:7: 'nothing' is not defined in the function files");
  EXPECT_EQ(message("usesMissing", -1), "c.cal:2: 'usesMissing' uses 'missing', which is not defined");
  EXPECT_EQ(message("badCall", -1), "c.cal:4: 'badCall' uses g() with 1 argument; it takes 2");
  EXPECT_EQ(message("varCall", -1), "c.cal:5: 'varCall' uses the variable 'ok' as a function");
  EXPECT_EQ(message("fnVar", -1), "c.cal:6: 'fnVar' uses the function 'g' as a variable");
  // Both branches of an if are checked, as either may be taken.
  EXPECT_EQ(message("lazy", -1), "c.cal:7: 'lazy' uses 'missing', which is not defined");
}

TEST(Cal, RecursionWithoutEndIsAnErrorNotACrash) {
  Program p;
  p.addText("loop(n) = loop(n + 1); x = loop(0); self = self + 1;\n"
            "{ 2^60 calls within the depth bound: stopped by the step bound }\n"
            "fan(n) = if(n, fan(n - 1) + fan(n - 1), 1); wide = fan(60);\n"
            "sel = select(1e300, 1, 2) + select(-1e300, 1) + noise3(1e300, 0, 0);",
            "r.cal");
  Evaluator e(p);
  e.begin({});
  EXPECT_THROW(e.value(p.find("x")), EvalError);
  EXPECT_THROW(e.value(p.find("self")), EvalError);
  EXPECT_THROW(e.value(p.find("wide")), EvalError);
  // Out-of-range selections and a coordinate beyond the lattice's precision give 0, not UB.
  EXPECT_EQ(e.value(p.find("sel")), 0.0);
}

TEST(Cal, VariablesAreComputedOncePerEvaluation) {
  Program p;
  p.addText("v = Px * 2; x = v + v;", "v.cal");
  Evaluator e(p);
  Environment env;
  env.ray[kPx] = 1.0;
  e.begin(env);
  EXPECT_DOUBLE_EQ(e.value(p.find("x")), 4.0);
  env.ray[kPx] = 3.0;
  e.begin(env);  // a new ray: computed again
  EXPECT_DOUBLE_EQ(e.value(p.find("x")), 12.0);
  const double args[] = {3.0};
  EXPECT_DOUBLE_EQ(e.call(p.find("sq"), args), 9.0);
}

}  // namespace
}  // namespace candela::cal
