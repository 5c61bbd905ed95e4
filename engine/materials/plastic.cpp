// plastic and metal (Radiance reference manual, "Plastic" and "Metal"): the same arguments; a
// plastic's specular reflection is uncoloured, a metal's takes the colour.
#include "engine/materials/normal.h"
#include "engine/materials/registry.h"

namespace candela {
namespace {

class Plastic : public NormalFamily {
 public:
  MaterialType type() const override { return MaterialType::kPlastic; }
  const char* name() const override { return "plastic"; }
  void read(const MaterialReadContext& ctx, Material& m) const override { readCommon(ctx, m, 5); }
  void derive(MaterialParameters& m) const override { derivePlastic(m); }
  bool matteOpaque(const Material& m) const override { return photopic(m.specularReflectance) <= 0.0; }
};

class Metal : public NormalFamily {
 public:
  MaterialType type() const override { return MaterialType::kMetal; }
  const char* name() const override { return "metal"; }
  void read(const MaterialReadContext& ctx, Material& m) const override { readCommon(ctx, m, 5); }
  void derive(MaterialParameters& m) const override { deriveMetal(m); }
  bool matteOpaque(const Material& m) const override { return photopic(m.specularReflectance) <= 0.0; }
};

}  // namespace

const MaterialFamily& plasticFamily() {
  static const Plastic f;
  return f;
}

const MaterialFamily& metalFamily() {
  static const Metal f;
  return f;
}

}  // namespace candela
