#include "photometry/photometric_file.h"

#include "base/error.h"
#include "photometry/eulumdat.h"
#include "photometry/ies_lm63.h"

#include <cctype>

namespace candela {

PhotometricWeb readPhotometricFile(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".ies") return readIes(path);
  if (ext == ".ldt") return readEulumdat(path);
  throw InputError(FileLoc{path.string(), 0, 0},
                   "unknown luminaire file type '" + ext + "' (expected .ies or .ldt)");
}

}  // namespace candela
