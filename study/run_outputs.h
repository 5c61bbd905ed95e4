// How a study's results reach the disk, and when they were made. A result folder holds either
// the complete previous result or the complete new one, never a mix (docs/reliability.md).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace candela {

// The local time now, "YYYY-MM-DD HH:MM".
std::string localTimeNow();

// The file that marks a folder as a candela result (so that a later run may replace it whole).
inline constexpr const char* kResultMarker = ".candela-result";

// Throws InputError at `outDir` unless a run may write its result there: a new name in an
// existing or creatable place, an empty folder, or a folder that holds a candela result. Any
// other folder (a user's documents, say) is refused, since the result replaces the folder whole.
void checkResultFolder(const std::filesystem::path& outDir);

// A run's temporary result folder, for a study that writes while it computes (the annual study
// streams its hourly files, docs/annual-outputs.md): the files streamed during the run are
// unnamed temporaries in beside(), the folder that will hold `outDir` (base/atomic_file.h
// AtomicFile), so that a run killed at any point leaves nothing; the temporary result folder is
// made there by the first write(), commit() puts it in place of `outDir` as writeRunOutputs does,
// and the destructor removes it unless committed, so a run that fails leaves `outDir` as it was.
// Files inside are written once, by their one writer, or atomically. Errors as writeRunOutputs:
// InputError at outDir, "cannot write the results: ...".
class RunOutputFolder {
 public:
  // active = false: a process that writes no result (an MPI rank other than 0, a shard): no
  // folder is made, guard(), write() and commit() do nothing.
  explicit RunOutputFolder(const std::filesystem::path& outDir, bool active = true);
  ~RunOutputFolder();
  RunOutputFolder(const RunOutputFolder&) = delete;
  RunOutputFolder& operator=(const RunOutputFolder&) = delete;

  // The folder `outDir` is in (made by the constructor): where files streamed before the result
  // folder exists keep their temporaries, in the same file system as the result.
  const std::filesystem::path& beside() const { return parent_; }
  // Calls work(), turning a failure that is not an InputError into "cannot write the results:
  // ..." (a full disk is the user's to fix, not an internal failure).
  void guard(const std::function<void()>& work) const;
  // Calls write(dir) under guard() with the temporary result folder, made on the first call.
  void write(const std::function<void(const std::filesystem::path&)>& write);
  void commit();

 private:
  // The temporary result folder, made on first use.
  const std::filesystem::path& folder();

  std::filesystem::path outDir_, parent_, tmp_;
  bool active_ = true;
};

// Calls write(dir) with a fresh temporary folder beside `outDir`, then puts that folder in
// place of `outDir` in one step (the previous result, if any, is removed after the swap). A
// file-system or write failure becomes InputError at outDir, "cannot write the results: ...",
// and leaves `outDir` as it was.
void writeRunOutputs(const std::filesystem::path& outDir, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace candela
