#include "nome/scene/lexer.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace nome::scene {
namespace {

bool is_word_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}
bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

class Lexer {
 public:
  Lexer(std::string_view text, Diagnostics& diagnostics) : text_(text), diagnostics_(diagnostics) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (true) {
      skip_space_and_comments();
      if (at_end()) break;
      const SourceLocation start = here();
      const char c = peek();
      // JIPCAD names may start with a dot (`.bsR.v0`, a vertex of a sibling instance).
      if (is_word_start(c) || (c == '.' && is_word_start(peek(1)))) {
        tokens.push_back({TokenKind::word, take_while(is_word_char), 0, start});
      } else if (is_digit(c) || (c == '.' && is_digit(peek(1)))) {
        lex_number(tokens, start);
      } else if (c == '$') {
        advance();
        std::string name = take_while(is_word_char);
        if (name.empty())
          diagnostics_.error(start, "expected a parameter name after '$'");
        else
          tokens.push_back({TokenKind::parameter, std::move(name), 0, start});
      } else if (std::string_view("(){}+-*/%^,").find(c) != std::string_view::npos) {
        advance();
        tokens.push_back({TokenKind::symbol, std::string(1, c), 0, start});
      } else if (c == '<' || c == '>' || c == '=' || c == '!') {
        advance();
        std::string op(1, c);
        if (peek() == '=') {
          advance();
          op += '=';
        }
        tokens.push_back({TokenKind::symbol, op, 0, start});
      } else if (std::isprint(static_cast<unsigned char>(c))) {
        // Other punctuation is left to the parser, which says what it expected there.
        if (c == '[') ++bracket_depth_;
        if (c == ']' && bracket_depth_ > 0) --bracket_depth_;
        advance();
        tokens.push_back({TokenKind::symbol, std::string(1, c), 0, start});
      } else {
        advance();
        diagnostics_.error(start,
                           "unexpected character code " + std::to_string(int(static_cast<unsigned char>(c))));
      }
    }
    tokens.push_back({TokenKind::end, "", 0, here()});
    return tokens;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  SourceLocation here() const { return {line_, column_}; }
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }
  template <typename Predicate>
  std::string take_while(Predicate keep) {
    const size_t start = pos_;
    while (!at_end() && keep(peek())) advance();
    return std::string(text_.substr(start, pos_ - start));
  }

  void skip_space_and_comments() {
    while (!at_end()) {
      const char c = peek();
      if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else if (c == '#') {
        while (!at_end() && peek() != '\n') advance();
      } else if (c == '(' && peek(1) == '*') {
        const SourceLocation start = here();
        advance();
        advance();
        while (!at_end() && !(peek() == '*' && peek(1) == ')')) advance();
        if (at_end()) {
          diagnostics_.error(start, "unclosed comment: '(*' without '*)'");
          return;
        }
        advance();
        advance();
      } else {
        return;
      }
    }
  }

  void lex_number(std::vector<Token>& tokens, SourceLocation start) {
    const size_t begin = pos_;
    while (is_digit(peek())) advance();
    if (peek() == '.') {
      advance();
      while (is_digit(peek())) advance();
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      advance();
      if (peek() == '+' || peek() == '-') advance();
      while (is_digit(peek())) advance();
    }
    std::string text(text_.substr(begin, pos_ - begin));
    // Inside JIPCAD's bracketed functions `5x` is a product: the number ends where the name starts.
    if (is_word_char(peek()) && bracket_depth_ == 0) {
      text += take_while(is_word_char);
      diagnostics_.error(start, "malformed number '" + text + "'");
      return;
    }
    const double value = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(value)) {
      diagnostics_.error(start, "number out of range '" + text + "'");
      return;
    }
    tokens.push_back({TokenKind::number, std::move(text), value, start});
  }

  std::string_view text_;
  Diagnostics& diagnostics_;
  size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
  int bracket_depth_ = 0;  // inside `[ ... ]`
};

}  // namespace

std::string Token::describe() const {
  // A message names a token, it does not repeat a megabyte of it.
  constexpr size_t shown = 40;
  const std::string brief = text.size() <= shown ? text : text.substr(0, shown) + "...";
  switch (kind) {
    case TokenKind::word:
      return "'" + brief + "'";
    case TokenKind::number:
      return "number " + brief;
    case TokenKind::parameter:
      return "'$" + brief + "'";
    case TokenKind::symbol:
      return "'" + brief + "'";
    case TokenKind::end:
      return "end of file";
  }
  return "?";
}

std::vector<Token> tokenize(std::string_view text, Diagnostics& diagnostics) {
  return Lexer(text, diagnostics).run();
}

}  // namespace nome::scene
