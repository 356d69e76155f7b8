#include "scene/slide/slf_text.hpp"

namespace nome::scene {
namespace {

// Without carriage returns: files saved with CR CR LF line ends would otherwise break Tcl's backslash
// continuations (`\` then CR is no continuation).
std::string tcl_text(std::string_view text) {
  std::string out;
  for (char c : text)
    if (c != '\r') out += c;
  return out;
}

class Splitter {
 public:
  Splitter(std::string_view text, Diagnostics& diagnostics) : text_(text), diagnostics_(diagnostics) {
    out_.statements.assign(text);
  }

  SlfText run() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance();
      } else if (c == '(' && next() == '*') {
        block_comment();
      } else if (c == '{') {
        brace();
      } else {
        advance();
      }
    }
    return std::move(out_);
  }

 private:
  // From an opening brace to its match: the contents go to `braces` and are blanked in `statements`.
  void brace() {
    const SourceLocation at{line_, column_};
    advance();
    const size_t start = pos_;
    int depth = 1;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\\' && pos_ + 1 < text_.size()) {
        blank_and_advance();
      } else if (c == '{') {
        ++depth;
      } else if (c == '}' && --depth == 0) {
        out_.braces.push_back({at, tcl_text(text_.substr(start, pos_ - start))});
        advance();
        return;
      }
      blank_and_advance();
    }
    diagnostics_.error(at, "this '{' is never closed: expected '}' before the end of the file");
    out_.braces.push_back({at, tcl_text(text_.substr(start))});
    out_.statements += '}';  // reported once: the statements read on as if it were closed there
  }

  // `(* ... *)`, nested: SLIDE's way to switch off a stretch of statements, braces included. Blanked, as the
  // statements' lexer does not nest them.
  void block_comment() {
    int depth = 0;
    while (pos_ < text_.size()) {
      if (text_[pos_] == '(' && next() == '*') {
        ++depth;
        blank_and_advance();
      } else if (text_[pos_] == '*' && next() == ')') {
        blank_and_advance();
        if (--depth == 0) {
          blank_and_advance();
          return;
        }
      }
      blank_and_advance();
    }
  }

  char next() const { return pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0'; }

  void blank_and_advance() {
    if (text_[pos_] != '\n') out_.statements[pos_] = ' ';
    advance();
  }

  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  std::string_view text_;
  Diagnostics& diagnostics_;
  SlfText out_;
  size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

SlfText split_slf_text(std::string_view text, Diagnostics& diagnostics) {
  return Splitter(text, diagnostics).run();
}

}  // namespace nome::scene
