// Radiance's generator programs, interpreted: a scene line `!xform ...`, `!genbox ...`, ... is
// expanded by candela into the primitives the program would write (same names, same geometry),
// never run. Any other command is refused; nothing in a scene file ever reaches a shell.
#pragma once

#include "base/warning.h"
#include "engine/radiance/parse.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace candela {

// What a generator may ask of the reader: the folder relative to which the command's file names
// are resolved (the including file's), and the whole expansion of another scene file (its own
// commands expanded, relative to its own folder).
struct RadExpandContext {
  std::filesystem::path folder;
  std::filesystem::path root;  // looked in last (SceneReadOptions::rootFolder)
  std::function<std::vector<RadPrimitive>(const std::filesystem::path& file, const FileLoc& from)> readFile;
  // In a pipeline (`!genbox ... | xform -t ...`), what the previous command wrote: a generator
  // that reads its standard input when given no file (xform) reads this; null when there is none.
  const std::vector<RadPrimitive>* standardInput = nullptr;
  // --max-memory in bytes (0: none): what one command may make is bounded by it too
  // (engine/radiance/gen.h, generatedPrimitivesAllowed).
  uint64_t maxMemoryBytes = 0;
  // Where a command's warnings go (suspicious but valid input, e.g. a sky's values out of range);
  // null: none are kept.
  std::vector<Warning>* warnings = nullptr;
};

// The generators candela expands, in the order the refusal message lists them.
const std::vector<std::string>& radGeneratorNames();

// The primitives the command writes. A pipeline `A | B | ...` runs each command on what the one
// before wrote (RadExpandContext::standardInput); only generators run, never a shell. Throws InputError(cmd.loc, ...) for a command that is not a
// generator ("'!NAME' is not a generator candela can expand; it expands: ...") or bad options.
std::vector<RadPrimitive> expandRadCommand(const RadCommand& cmd, const RadExpandContext& ctx);

}  // namespace candela
