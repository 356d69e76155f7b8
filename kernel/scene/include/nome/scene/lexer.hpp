#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "nome/scene/diagnostic.hpp"

namespace nome::scene {

enum class TokenKind {
  word,  // a name or keyword: letters, digits, `_` and `.` (NOME 2.x dotted paths), not starting with a digit
  number,     // 1, -0.5 is `-` then 1 ... `7.45058e-009`
  parameter,  // `$fp_n` or `$fp.n`; text holds the name without `$`
  symbol,     // ( ) { } + - * / % ^ , < <= > >= == != and any other printable punctuation
  end,        // end of input
};

struct Token {
  TokenKind kind = TokenKind::end;
  std::string text;
  double number = 0;
  SourceLocation location;

  bool is_word(std::string_view w) const { return kind == TokenKind::word && text == w; }
  bool is_symbol(std::string_view s) const { return kind == TokenKind::symbol && text == s; }
  // `'endface'`, `number 3`, `end of file`: how a message names what it found.
  std::string describe() const;
};

// Splits a scene text (.nome, .anom, .slf, .sif) into tokens. Skips `#` line comments and `(* ... *)`
// block comments. Control characters, malformed numbers and unclosed comments are reported and skipped.
// The last token is always `end`.
std::vector<Token> tokenize(std::string_view text, Diagnostics& diagnostics);

}  // namespace nome::scene
