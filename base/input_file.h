// Reading input files safely: only regular files are read (never a folder, FIFO, socket or
// device: `/dev/zero` would eat memory, a FIFO would hang the run), every failure to open or read
// is an InputError naming the file, and the size read is bounded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace candela {

// No input file candela reads is larger than this unless the caller says so (bytes).
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t(4) << 30;

// The whole content of `path` as text (normalizeText). `what` names the file in errors ("scene
// file", "case file").
// Throws InputError(path, ...) when it cannot be opened, is not a regular file, is larger than
// `maxBytes` or cannot be read to the end.
std::string readInputFile(const std::filesystem::path& path, const std::string& what,
                          std::uintmax_t maxBytes = kMaxInputFileBytes);

// What the files read while it lives held: every readInputFile call (from any thread) adds the
// file's absolute path and a 64-bit FNV-1a hash of the bytes it returned to every log alive.
// A record of the run, it changes no result: sharded runs compare it (study/run_case.cpp), so
// that parts traced against an edited `!xform` include, `.dat`, OBJ, function file or genprism
// vertex file are not merged. Logs nest; each sees the reads made while it lives.
class InputFileLog {
 public:
  InputFileLog();
  ~InputFileLog();
  InputFileLog(const InputFileLog&) = delete;
  InputFileLog& operator=(const InputFileLog&) = delete;
  // One hash over every file read (path and content, in path order); a file read twice with
  // different content counts both.
  uint64_t fingerprint() const;
  // How many distinct files were read.
  size_t files() const;
  // Adds a read to every live log (readInputFile calls it).
  static void record(const std::filesystem::path& path, const std::string& content);
  struct State;

 private:
  State* state_;
};

// FNV-1a (64 bit) of `n` bytes, continuing from `h`.
uint64_t fnv1a(const void* bytes, size_t n, uint64_t h = 0xcbf29ce484222325ULL);

// Text as every reader expects it: a leading UTF-8 byte-order mark removed, and CRLF and lone CR
// line endings (classic Mac files, some exporters) turned into LF, so line numbers are right
// whatever wrote the file. readInputFile applies it; binary files are not read through it.
std::string normalizeText(std::string text);

// Throws InputError(path, ...) unless `path` names a regular file that can be opened for reading.
void checkInputFile(const std::filesystem::path& path, const std::string& what);

// Where an output file may be written: a new name in an existing folder, or a regular file (a
// link, a folder, a device or a FIFO is refused, so writing never follows or replaces one).
// Throws InputError(path, ...).
void checkOutputFile(const std::filesystem::path& path);

}  // namespace candela
