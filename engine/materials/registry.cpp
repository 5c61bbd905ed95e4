// The one table of material families: adding a material is its file, its line here and its tests.
#include "engine/materials/registry.h"

#include <array>

namespace candela {
namespace {

// Indexed by MaterialType; the Radiance type names each family reads.
struct Entry {
  const MaterialFamily& (*family)();
  std::array<const char*, 2> radianceTypes;
};

constexpr Entry kFamilies[] = {
    {voidFamily, {nullptr, nullptr}},  // never read: a modifier "void" is no material
    {plasticFamily, {"plastic", nullptr}},
    {metalFamily, {"metal", nullptr}},
    {transFamily, {"trans", nullptr}},
    {mirrorFamily, {"mirror", nullptr}},
    {glassFamily, {"glass", nullptr}},
    {dielectricFamily, {"dielectric", nullptr}},
    {lightFamily, {"light", "spotlight"}},
    {illumFamily, {"illum", nullptr}},
    {glowFamily, {"glow", nullptr}},
    {mixtureFamily, {nullptr, nullptr}},  // read with the patterns (engine/radiance/function_patterns.h)
    {interfaceFamily, {"interface", nullptr}},
    {plastic2Family, {"plastic2", nullptr}},
    {metal2Family, {"metal2", nullptr}},
    {trans2Family, {"trans2", nullptr}},
    {mistFamily, {"mist", nullptr}},
    {brtdFuncFamily, {"BRTDfunc", nullptr}},
    {plasFuncFamily, {"plasfunc", nullptr}},
    {metFuncFamily, {"metfunc", nullptr}},
    {transFuncFamily, {"transfunc", nullptr}},
    {plasDataFamily, {"plasdata", nullptr}},
    {metDataFamily, {"metdata", nullptr}},
    {transDataFamily, {"transdata", nullptr}},
    {ashik2Family, {"ashik2", nullptr}},
    {wgmdFuncFamily, {"WGMDfunc", nullptr}},
    {antimatterFamily, {"antimatter", nullptr}},
    {bsdfFamily, {"BSDF", nullptr}},
    {aBsdfFamily, {"aBSDF", nullptr}},
};
static_assert(std::size(kFamilies) == kMaterialTypeCount, "one family for every MaterialType, in its order");

}  // namespace

const MaterialFamily& familyOf(MaterialType type) { return kFamilies[static_cast<int>(type)].family(); }

const MaterialFamily* familyNamed(std::string_view radianceType) {
  for (const Entry& e : kFamilies)
    for (const char* name : e.radianceTypes)
      if (name && radianceType == name) return &e.family();
  return nullptr;
}

std::string materialTypeNames() {
  std::string out;
  for (const Entry& e : kFamilies)
    for (const char* name : e.radianceTypes)
      if (name) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

const char* materialTypeName(MaterialType t) { return familyOf(t).name(); }

NormalIncidence MaterialFamily::normalIncidence(const Material& m) const {
  return {photopic(m.diffuseReflectance + m.specularReflectance), photopic(m.specularReflectance), std::nullopt};
}

bool MaterialParameters::isEmitter() const { return familyOf(type).emits(); }
bool MaterialParameters::isSampledSource() const { return familyOf(type).sampledSource(); }

void deriveMaterial(MaterialParameters& m) { familyOf(m.type).derive(m); }

void MaterialReadContext::fail(const std::string& message) const { throw InputError(primitive.loc, message); }

std::string MaterialReadContext::what() const { return primitive.type + " '" + primitive.name + "'"; }

void MaterialReadContext::expectReals(size_t n) const {
  if (primitive.reals.size() != n)
    fail(what() + " needs " + std::to_string(n) + " real arguments, got " + std::to_string(primitive.reals.size()));
}

void MaterialReadContext::expectStrings(size_t maxN) const {
  if (primitive.strings.size() > maxN)
    fail(what() + " takes at most " + std::to_string(maxN) + " string arguments, got " +
         std::to_string(primitive.strings.size()));
}

Vec3 MaterialReadContext::vec(size_t i) const {
  return Vec3(primitive.reals[i], primitive.reals[i + 1], primitive.reals[i + 2]);
}

void MaterialReadContext::expectNonNegative(const Rgb& color) const {
  for (int c = 0; c < 3; ++c)
    if (color[c] < 0.0) fail(what() + " has a negative colour component");
}

void MaterialReadContext::expectRadiance(const Rgb& radiance) const {
  expectNonNegative(radiance);
  constexpr double kMaxRadiance = 1e30;
  if (std::max({radiance.x, radiance.y, radiance.z}) > kMaxRadiance)
    fail(what() + " has a radiance above 1e30 W/sr/m2");
}

int MaterialReadContext::alternate() const {
  if (primitive.strings.empty() || primitive.strings[0] == "void") return -1;
  const int found = findMaterial(primitive.strings[0]);
  if (found < 0)
    fail("alternate material '" + primitive.strings[0] + "' of " + primitive.type + " '" + primitive.name +
         "' is not defined before use");
  return found;
}

}  // namespace candela
