// First stage of reading Radiance's scene description language (Radiance reference manual,
// "Scene Description"): text → primitives `modifier type identifier` with their string, integer
// and real arguments, and inline command lines (`!command args`), in file order. Nothing here
// knows what a type means; engine/radiance/reader.cpp builds the scene, engine/radiance/generators.cpp
// expands the commands.
#pragma once

#include "base/error.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

struct RadPrimitive {
  std::string modifier, type, name;
  FileLoc loc;                        // file and line where the primitive starts
  std::vector<std::string> strings;
  std::vector<std::string> integers;  // kept as written (no supported type takes any)
  std::vector<double> reals;
};

// An inline command: the words of a line starting with '!', quotes removed (a quoted word is
// one word), a backslash at the end of a line continuing it on the next.
struct RadCommand {
  std::vector<std::string> words;
  FileLoc loc;
};

// Calls `onPrimitive` and `onCommand` in file order. Throws InputError("file:line: ...") on a
// malformed primitive (bad count, bad number, unclosed quote, unexpected end of file).
void parseRadiance(std::string_view text, const std::string& fileName,
                   const std::function<void(RadPrimitive&&)>& onPrimitive,
                   const std::function<void(RadCommand&&)>& onCommand);

// Splits a command line the way Radiance's words are read: blanks separate words, a word in
// double or single quotes is one word without its quotes. Used for commands and argument files.
std::vector<std::string> splitWords(std::string_view line, const FileLoc& loc);

}  // namespace candela
