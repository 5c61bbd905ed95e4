#include "engine/materials/registry.h"

namespace candela {
namespace {

// void: invisible in Radiance; rays that meet a surface of it see nothing.
class Void : public MaterialFamily {
 public:
  MaterialType type() const override { return MaterialType::kVoid; }
  const char* name() const override { return "void"; }
  HitRole role() const override { return HitRole::kAbsorb; }
  void read(const MaterialReadContext&, Material&) const override {}
};

}  // namespace

const MaterialFamily& voidFamily() {
  static const Void f;
  return f;
}

}  // namespace candela
