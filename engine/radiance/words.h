// The words of Radiance's data and font files with their lines, as fgetval reads them
// (src/common/fgetval.c): blanks separate words; '#' starts a comment to the end of the line,
// also in the middle of a word. Numbers are read whole (a word with anything after its number is
// refused), and a failure names the file and the line of the word read last.
#pragma once

#include "base/error.h"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace candela {

class RadWords {
 public:
  // `kind` names the file in the message at its end: "file", "the font file".
  RadWords(std::string_view text, std::string file, std::string kind = "file")
      : text_(text), file_(std::move(file)), kind_(std::move(kind)) {}

  // The next word, or false at the end of the text.
  bool next(std::string_view& word) {
    for (;;) {
      while (pos_ < text_.size() && isSpace(text_[pos_])) {
        if (text_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if (pos_ >= text_.size()) return false;
      if (text_[pos_] != '#') break;
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    }
    const size_t b = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]) && text_[pos_] != '#') ++pos_;
    word = text_.substr(b, pos_ - b);
    wordLine_ = line_;
    return true;
  }

  [[noreturn]] void fail(const std::string& message) const { throw InputError(FileLoc{file_, wordLine_, 0}, message); }

  // The next word; at the end, a failure "unexpected end of <kind>: expected <what>" at the last
  // word's line.
  std::string_view need(const std::string& what) {
    std::string_view w;
    if (!next(w)) fail("unexpected end of " + kind_ + ": expected " + what);
    return w;
  }

  // The next word as a finite number (optional '+').
  double number(const std::string& what) {
    const std::string_view w = need(what);
    const char* b = w.data();
    const char* e = b + w.size();
    if (b != e && *b == '+') ++b;
    double v = 0.0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) fail("'" + quoted(w) + "' is not a number (" + what + ")");
    return v;
  }

  // Word w, or the next word, as an integer (optional sign, digits).
  long integer(std::string_view w, const std::string& what) const {
    const char* b = w.data();
    const char* e = b + w.size();
    if (b != e && *b == '+') ++b;
    long v = 0;
    const auto r = std::from_chars(b, e, v);
    if (b == e || r.ptr != e) fail("'" + quoted(w) + "' is not an integer (" + what + ")");
    if (r.ec != std::errc()) fail("'" + quoted(w) + "' is out of range (" + what + ")");
    return v;
  }
  long integer(const std::string& what) { return integer(need(what), what); }

  // A word as a message quotes it: its first 24 characters.
  static std::string quoted(std::string_view w) {
    return w.size() > 24 ? std::string(w.substr(0, 24)) + "..." : std::string(w);
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

  std::string_view text_;
  std::string file_, kind_;
  size_t pos_ = 0;
  int line_ = 1, wordLine_ = 1;
};

}  // namespace candela
