// The families the registry lists (engine/materials/registry.cpp), one a file in this folder.
#pragma once

#include "engine/materials/family.h"

namespace candela {

const MaterialFamily& voidFamily();
const MaterialFamily& plasticFamily();
const MaterialFamily& metalFamily();
const MaterialFamily& transFamily();
const MaterialFamily& mirrorFamily();
const MaterialFamily& glassFamily();
const MaterialFamily& dielectricFamily();
const MaterialFamily& lightFamily();
const MaterialFamily& illumFamily();
const MaterialFamily& glowFamily();
const MaterialFamily& mixtureFamily();
const MaterialFamily& interfaceFamily();
const MaterialFamily& plastic2Family();
const MaterialFamily& metal2Family();
const MaterialFamily& trans2Family();
const MaterialFamily& mistFamily();
const MaterialFamily& brtdFuncFamily();
// plasfunc, metfunc, transfunc, plasdata, metdata, transdata (brdf_function.cpp).
const MaterialFamily& plasFuncFamily();
const MaterialFamily& metFuncFamily();
const MaterialFamily& transFuncFamily();
const MaterialFamily& plasDataFamily();
const MaterialFamily& metDataFamily();
const MaterialFamily& transDataFamily();
const MaterialFamily& ashik2Family();
const MaterialFamily& wgmdFuncFamily();
const MaterialFamily& antimatterFamily();
const MaterialFamily& bsdfFamily();
const MaterialFamily& aBsdfFamily();

}  // namespace candela
