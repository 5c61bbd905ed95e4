// The generators candela expands (engine/rad_generators.cpp registers them): each returns the
// primitives the Radiance program of the same name would write, or throws InputError(cmd.loc, ...).
// One line per generator; docs/engine.md, "Generators and functions", says what each reads.
#pragma once

#include "engine/rad_generators.h"

namespace candela {

std::vector<RadPrimitive> expandXform(const RadCommand& cmd, const RadExpandContext& ctx);    // rad_gen_xform.cpp
std::vector<RadPrimitive> expandGenbox(const RadCommand& cmd, const RadExpandContext& ctx);   // rad_gen_box.cpp
std::vector<RadPrimitive> expandGenprism(const RadCommand& cmd, const RadExpandContext& ctx); // rad_gen_prism.cpp
std::vector<RadPrimitive> expandGensky(const RadCommand& cmd, const RadExpandContext& ctx);   // rad_gen_sky.cpp
std::vector<RadPrimitive> expandGendaylit(const RadCommand& cmd, const RadExpandContext& ctx); // rad_gen_sky.cpp

// Refused above this many primitives from one command (about 300 bytes each once read).
inline constexpr double kMaxGeneratedPrimitives = 1e7;

}  // namespace candela
