#include "study/case/honeybee_folder.h"

#include "base/error.h"
#include "base/input_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace candela {

namespace fs = std::filesystem;

namespace {

// The files of `dir` ending in `ext`, by name (none when the folder is absent).
std::vector<fs::path> filesEnding(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().extension() == ext) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Line (1-based) of byte `offset` in `text`.
int lineAt(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + std::min(offset, text.size()), '\n'));
}

// A states.json with entries (a group folder Honeybee writes for recipes candela does not run).
void refuseStates(const fs::path& states, const std::string& what) {
  std::error_code ec;
  if (!fs::is_regular_file(states, ec)) return;
  const std::string text = readInputFile(states, "states file");
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_object() && j.empty()) return;
  throw InputError(FileLoc{states.string(), 1, 0}, what + " are not read (only model/aperture_group's states)");
}

}  // namespace

void readHoneybeeFolder(const fs::path& folder, const FileLoc& loc, CaseFile& out) {
  std::error_code ec;
  const fs::path model = fs::is_directory(folder / "model", ec) ? folder / "model" : folder;
  // Honeybee runs Radiance from the folder holding model/, and its files name others from there
  // (./model/bsdf/clear.xml): that folder is looked in for them wherever candela runs.
  fs::path inner = model;
  if (inner.filename().empty()) inner = inner.parent_path();  // "…/model/"
  out.settings.scene.rootFolder = model == folder ? inner.parent_path() : folder;
  if (!fs::is_directory(model / "scene", ec) && !fs::is_directory(model / "aperture", ec))
    throw InputError(loc, "'" + folder.string() + "' is not a Honeybee radiance folder: it has neither "
                          "model/scene nor model/aperture");
  for (const char* ext : {".mat", ".rad"})
    for (const char* sub : {"scene", "aperture"})
      for (const fs::path& p : filesEnding(model / sub, ext)) out.scenes.push_back({p.lexically_normal(), loc});
  refuseStates(model / "scene_dynamic" / "states.json", "dynamic scene groups (model/scene_dynamic)");
  refuseStates(model / "aperture_group" / "interior" / "states.json",
               "interior aperture groups (model/aperture_group/interior)");
  const fs::path groups = model / "aperture_group";
  const fs::path statesFile = groups / "states.json";
  if (!fs::is_regular_file(statesFile, ec)) return;
  const std::string text = readInputFile(statesFile, "states file");
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(FileLoc{statesFile.string(), lineAt(text, e.byte), 0},
                     std::string("not JSON: ") + e.what());
  }
  const FileLoc at{statesFile.string(), 0, 0};
  if (!j.is_object()) throw InputError(at, "states.json must be an object of aperture groups, each a list of states");
  for (auto it = j.begin(); it != j.end(); ++it) {
    WindowGroupSpec g;
    g.name = it.key();
    g.loc = at;
    for (const WindowGroupSpec& o : out.windowGroups)
      if (o.name == g.name) throw InputError(at, "two window groups are named '" + g.name + "'");
    if (!it.value().is_array() || it.value().empty())
      throw InputError(at, "aperture group '" + g.name + "': its value must be a non-empty list of states");
    int index = 0;
    for (const auto& s : it.value()) {
      ++index;
      const std::string where = "aperture group '" + g.name + "', state " + std::to_string(index);
      if (!s.is_object() || !s.contains("identifier") || !s["identifier"].is_string() || !s.contains("default") ||
          !s["default"].is_string())
        throw InputError(at, where + ": needs the strings 'identifier' and 'default'");
      WindowGroupSpec::State st;
      st.name = s["identifier"].get<std::string>();
      st.scene = (groups / s["default"].get<std::string>()).lexically_normal();
      st.loc = at;
      if (st.name.empty()) throw InputError(at, where + ": empty 'identifier'");
      for (const WindowGroupSpec::State& o : g.states)
        if (o.name == st.name) throw InputError(at, where + ": a second state named '" + st.name + "'");
      if (!fs::is_regular_file(st.scene, ec))
        throw InputError(at, where + ": its default file '" + st.scene.string() + "' not found");
      g.states.push_back(std::move(st));
    }
    out.windowGroups.push_back(std::move(g));
  }
}

}  // namespace candela
