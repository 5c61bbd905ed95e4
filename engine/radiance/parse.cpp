#include "engine/radiance/parse.h"

#include <cctype>
#include <charconv>
#include <cmath>

namespace candela {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

struct Token {
  std::string_view text;
  int line;
};

class Tokenizer {
 public:
  Tokenizer(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  // Next word; an inline command line met at the start of a line is returned through `command`
  // instead (its words, the function returning true with `isCommand` set).
  bool next(Token& tok, RadCommand* command, bool& isCommand) {
    isCommand = false;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
        atLineStart_ = true;
      } else if (isBlank(c)) {
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (c == '!' && atLineStart_ && command) {
        readCommand(*command);
        isCommand = true;
        return true;
      } else if (c == '"' || c == '\'') {
        // A quoted word (Radiance's fgetword, either quote): everything up to the same closing
        // quote, blanks included, without the quotes; an expression such as "if(a, 1, 0)".
        const int line = line_;
        const size_t start = ++pos_;
        while (pos_ < text_.size() && text_[pos_] != c) {
          if (text_[pos_] == '\n') ++line_;
          ++pos_;
        }
        if (pos_ >= text_.size()) throw InputError(FileLoc{file_, line, 0}, "a quoted string is not closed");
        tok = Token{text_.substr(start, pos_ - start), line};
        ++pos_;
        lastTokenLine_ = line_;
        atLineStart_ = false;
        return true;
      } else {
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        tok = Token{text_.substr(start, pos_ - start), line_};
        lastTokenLine_ = line_;
        atLineStart_ = false;
        return true;
      }
    }
    return false;
  }

  int lastTokenLine() const { return lastTokenLine_; }
  const std::string& file() const { return file_; }

 private:
  // The command's text runs to the end of the line; a backslash just before the newline joins
  // the next line (as a shell would read it).
  void readCommand(RadCommand& cmd) {
    const int line = line_;
    ++pos_;  // '!'
    std::string textOf;
    while (pos_ < text_.size() && text_[pos_] != '\n') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') {
        textOf += ' ';
        pos_ += 2;
        ++line_;
        continue;
      }
      textOf += text_[pos_++];
    }
    cmd.loc = FileLoc{file_, line, 0};
    cmd.words = splitWords(textOf, cmd.loc);
    if (cmd.words.empty()) throw InputError(cmd.loc, "an inline command line ('!') names no command");
    lastTokenLine_ = line_;
  }

  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1;
  bool atLineStart_ = true;
  int lastTokenLine_ = 1;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : tok_(text, file) {}

  void run(const std::function<void(RadPrimitive&&)>& onPrimitive,
           const std::function<void(RadCommand&&)>& onCommand) {
    Token first;
    RadCommand cmd;
    bool isCommand = false;
    while (tok_.next(first, &cmd, isCommand)) {
      if (isCommand) {
        onCommand(std::move(cmd));
        cmd = RadCommand{};
        continue;
      }
      RadPrimitive p;
      p.loc = FileLoc{tok_.file(), first.line, 0};
      p.modifier = std::string(first.text);
      p.type = std::string(need("a primitive type after '" + p.modifier + "'").text);
      p.name = std::string(need("an identifier for " + p.type).text);
      if (p.type == "alias") {
        // `modifier alias identifier reference`: no argument counts (Radiance reference manual).
        p.strings.emplace_back(need("the material alias '" + p.name + "' stands for").text);
        onPrimitive(std::move(p));
        continue;
      }
      const int ns = count("string");
      for (int i = 0; i < ns; ++i) p.strings.emplace_back(need("a string argument").text);
      const int ni = count("integer");
      for (int i = 0; i < ni; ++i) p.integers.emplace_back(need("an integer argument").text);
      const int nr = count("real");
      for (int i = 0; i < nr; ++i) p.reals.push_back(number(need("a real argument")));
      onPrimitive(std::move(p));
    }
  }

 private:
  [[noreturn]] void fail(int line, const std::string& msg) { throw InputError(FileLoc{tok_.file(), line, 0}, msg); }

  Token need(const std::string& what) {
    Token t;
    bool isCommand = false;
    if (!tok_.next(t, nullptr, isCommand)) fail(tok_.lastTokenLine(), "unexpected end of file: expected " + what);
    return t;
  }

  double number(const Token& t) {
    double v = 0.0;
    const char* b = t.text.data();
    const char* e = b + t.text.size();
    if (b != e && *b == '+') ++b;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v))
      fail(t.line, "'" + std::string(t.text) + "' is not a number");
    return v;
  }

  int count(const char* kind) {
    const Token t = need(std::string("the number of ") + kind + " arguments");
    int v = 0;
    const auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (r.ec != std::errc() || r.ptr != t.text.data() + t.text.size() || v < 0)
      fail(t.line, "'" + std::string(t.text) + "' is not a valid count of " + kind + " arguments");
    return v;
  }

  Tokenizer tok_;
};

}  // namespace

std::vector<std::string> splitWords(std::string_view line, const FileLoc& loc) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (isBlank(c) || c == '\n') {
      ++i;
    } else if (c == '"' || c == '\'') {
      const size_t close = line.find(c, i + 1);
      if (close == std::string_view::npos) throw InputError(loc, "a quoted string is not closed");
      words.emplace_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
    } else {
      const size_t start = i;
      while (i < line.size() && !isBlank(line[i]) && line[i] != '\n') ++i;
      words.emplace_back(line.substr(start, i - start));
    }
  }
  return words;
}

void parseRadiance(std::string_view text, const std::string& fileName,
                   const std::function<void(RadPrimitive&&)>& onPrimitive,
                   const std::function<void(RadCommand&&)>& onCommand) {
  // What is not a scene at all, said as such: oconv's octree (a header, then binary data) and
  // other binary files (a NUL byte near the start), instead of a message about its first word.
  const std::string_view head = text.substr(0, 4096);
  if (head.rfind("#?RADIANCE", 0) == 0 && head.find("FORMAT=Radiance_octree") != std::string_view::npos)
    throw InputError(FileLoc{fileName, 1}, "a Radiance octree (oconv's output), not a scene file: pass the scene "
                                           "files it was made from (its header's oconv line names them)");
  if (head.find('\0') != std::string_view::npos)
    throw InputError(FileLoc{fileName, 1}, "a binary file, not a Radiance scene (text)");
  Parser(text, fileName).run(onPrimitive, onCommand);
}

}  // namespace candela
