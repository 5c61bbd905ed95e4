// Fuzz target: Wavefront OBJ text (engine/obj_reader.h, readObjText) with four materials, a
// light and a mirror among them (faces stored as Shapes); the same bytes as an obj2rad mapping
// file (parseObjMapping).
#include "engine/obj_reader.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = candela::fuzz::asText(data, size);
  try {
    candela::Scene scene;
    for (auto [name, type] : {std::pair{"white", candela::MaterialType::kPlastic},
                              std::pair{"red", candela::MaterialType::kTrans},
                              std::pair{"lamp", candela::MaterialType::kLight},
                              std::pair{"mirror", candela::MaterialType::kMirror}}) {
      candela::Material m;
      m.type = type;
      m.name = name;
      m.color = candela::Rgb(0.5);
      scene.addMaterial(m);
    }
    candela::ObjReadOptions opt;
    opt.resolve = [&scene](const std::string& name, const std::string&, const candela::FileLoc& where) {
      if (name == "void") return -1;
      for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return static_cast<int>(i);
      throw candela::InputError(where, "undefined modifier " + name);
    };
    candela::readObjText(text, "fuzz.obj", scene, opt);
    (void)scene.bounds();
  } catch (const candela::InputError&) {
  }
  try {
    (void)candela::parseObjMapping(text, "fuzz.map");
  } catch (const candela::InputError&) {
  }
  return 0;
}
