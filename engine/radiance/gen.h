// The generators candela expands (engine/radiance/generators.cpp registers them): each returns the
// primitives the Radiance program of the same name would write, or throws InputError(cmd.loc, ...).
// One line per generator; docs/engine.md, "Generators and functions", says what each reads.
#pragma once

#include "engine/radiance/function_patterns.h"
#include "engine/radiance/generators.h"

namespace candela {

std::vector<RadPrimitive> expandXform(const RadCommand& cmd, const RadExpandContext& ctx);    // gen_xform.cpp
std::vector<RadPrimitive> expandGenbox(const RadCommand& cmd, const RadExpandContext& ctx);   // gen_box.cpp
std::vector<RadPrimitive> expandGenprism(const RadCommand& cmd, const RadExpandContext& ctx); // gen_prism.cpp
std::vector<RadPrimitive> expandGensky(const RadCommand& cmd, const RadExpandContext& ctx);   // gen_sky.cpp
std::vector<RadPrimitive> expandGendaylit(const RadCommand& cmd, const RadExpandContext& ctx); // gen_sky.cpp
std::vector<RadPrimitive> expandGenrev(const RadCommand& cmd, const RadExpandContext& ctx);   // gen_rev.cpp
std::vector<RadPrimitive> expandGensurf(const RadCommand& cmd, const RadExpandContext& ctx);  // gen_surf.cpp
std::vector<RadPrimitive> expandGenworm(const RadCommand& cmd, const RadExpandContext& ctx);  // gen_worm.cpp

// A primitive as a generator writes it (no integer arguments).
// 6 parameters: a primitive's own fields.
RadPrimitive generatedPrimitive(const std::string& modifier, const std::string& type, const std::string& name,
                                const FileLoc& loc, std::vector<std::string> strings, std::vector<double> reals);

// Whether a file a command names may exist: true also when the system cannot look the name up
// (too long, no permission), so that the reader, not a filesystem_error, says what is wrong.
bool mayExist(const std::filesystem::path& p);

// The options genrev, gensurf and genworm share, words[from..]: `-e expr` (definitions added to
// files.program()), `-f file` (a function file, found as every file a scene names) and, where
// `smooth` is given, `-s` (sets it); anything else is refused at the command's line.
void readFunctionOptions(const RadCommand& cmd, const RadExpandContext& ctx, size_t from, FunctionFiles& files,
                         bool* smooth);

// Defines the generator's function `name(params)` (params: "t" or "s, t") as the command's
// argument `expression` in program and checks it (every name it reaches defined, `arity`
// arguments); an InputError at the command's line, "<generator>: <what> '<expression>' is not an
// expression: …", otherwise. Returns its symbol.
// 7 parameters: the program, the command, and the function's name, parameters, arity, text and label.
cal::Symbol defineGeneratorFunction(cal::Program& program, const RadCommand& cmd, const std::string& name,
                                    const std::string& params, int arity, const std::string& expression,
                                    const std::string& what);

// Refused above this many primitives from one command.
inline constexpr double kMaxGeneratedPrimitives = 1e7;
// What a generated primitive takes once read, through the reader, the scene and the accelerator
// (bytes; measured on genbox's rounded boxes and xform arrays of polygons: about 1.2 KB).
inline constexpr double kBytesPerGeneratedPrimitive = 1200.0;
// A polygon smoothed by -s (its texture before it: a pattern and a material of its own) counts as
// this many primitives (measured: gensurf 300 × 300 -s peaks at 521 MB, without -s 154 MB, of
// which about 30 MB the program's own).
inline constexpr double kSmoothedPolygonWeight = 4.0;

// The most primitives one command may make: 10^7, or what --max-memory (ctx.maxMemoryBytes)
// holds at kBytesPerGeneratedPrimitive each when that is fewer.
double generatedPrimitivesAllowed(const RadExpandContext& ctx);
// The words that bound says in messages: "the 10000000 primitives a command may make", or
// "the 1747626 primitives --max-memory 2 GiB holds (about 1.2 KB each once read)".
std::string generatedLimitText(const RadExpandContext& ctx);

}  // namespace candela
