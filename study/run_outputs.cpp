#include "study/run_outputs.h"

#include "base/error.h"

#include <ctime>
#include <stdexcept>

namespace candela {

std::string localTimeNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &tm);
  return buf;
}

void writeRunOutputs(const std::filesystem::path& outDir, const std::function<void()>& write) {
  try {
    std::filesystem::create_directories(outDir);
    write();
  } catch (const std::filesystem::filesystem_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the results: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the results: ") + e.what());
  }
}

}  // namespace candela
