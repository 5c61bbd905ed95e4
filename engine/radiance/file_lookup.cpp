#include "engine/radiance/file_lookup.h"

#include <cstdlib>
#include <system_error>
#include <vector>

namespace candela {

std::filesystem::path findSceneFile(const std::string& name, const std::filesystem::path& folder, const FileLoc& loc,
                                    const std::string& who, const std::string& role,
                                    const std::filesystem::path& root) {
  const std::filesystem::path rel(name);
  bool up = false;
  for (const auto& part : rel) up |= part == "..";
  if (name.empty() || rel.is_absolute() || up)
    throw InputError(loc, who + ": " + role + " '" + name +
                              "' must be a name relative to the working directory, RAYPATH or the scene's folder "
                              "(no absolute path, no '..')");
  std::vector<std::filesystem::path> places = {std::filesystem::current_path()};
  if (const char* raypath = std::getenv("RAYPATH")) {
    const std::string list(raypath);
    for (size_t start = 0; start <= list.size();) {
      const size_t end = std::min(list.find(':', start), list.size());
      if (end > start) places.emplace_back(list.substr(start, end - start));
      start = end + 1;
    }
  }
  places.push_back(folder.empty() ? std::filesystem::current_path() : folder);
  if (!root.empty()) places.push_back(root);
  for (const std::filesystem::path& place : places) {
    const std::filesystem::path path = place / rel;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  throw InputError(loc, who + ": " + role + " '" + name + "' is not in the working directory, in RAYPATH or in " +
                            (folder.empty() ? std::filesystem::current_path() : folder).string() +
                            (root.empty() ? "" : " or " + root.string()));
}

}  // namespace candela
