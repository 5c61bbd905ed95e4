#include "engine/case_scene.h"

#include "engine/rad_reader.h"

#include <map>

namespace candela {

LuminaireSource placeLuminaire(std::shared_ptr<const PhotometricWeb> web, const LuminairePlacement& p) {
  LuminaireSource l;
  l.web = std::move(web);
  l.name = p.name;
  l.position = p.positionM;
  l.scale = p.multiplier * p.maintenanceFactor;
  orientLuminaire(l, p.aim, p.spinDeg);
  setOpeningFromWeb(l);
  return l;
}

std::unique_ptr<Scene> loadCaseScene(const CaseFile& c) {
  auto scene = std::make_unique<Scene>();
  for (const ScenePath& s : c.scenes) readRadianceFile(s.file, *scene);
  std::map<std::filesystem::path, std::shared_ptr<const PhotometricWeb>> webs;
  for (const LuminairePlacement& p : c.luminaires) {
    auto& web = webs[p.file];
    if (!web) web = std::make_shared<const PhotometricWeb>(readPhotometricFile(p.file));
    scene->luminaires.push_back(placeLuminaire(web, p));
  }
  return scene;
}

}  // namespace candela
