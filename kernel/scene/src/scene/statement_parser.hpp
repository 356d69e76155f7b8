#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nome/scene/ast.hpp"
#include "nome/scene/lexer.hpp"
#include "nome/scene/parser.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/slide/slf_text.hpp"

namespace nome::scene {

// Thrown after a syntax error has been reported: unwinds to the statement loop that resynchronises.
struct SyntaxError {};

// Where the parser is: which tokens start a statement here and which word closes the enclosing block.
struct BlockContext {
  std::vector<std::string_view> starters;
  std::string_view end_word;
};

// The tokens of one text and the AST being built, with what every statement's parser needs: taking
// tokens, reporting `expected X, found Y`, values, expressions, names, blocks and resynchronising.
// The statements themselves are the rows of statement_kinds().
class StatementParser {
 public:
  StatementParser(std::string_view text, Diagnostics& diagnostics, bool is_slf, ParseOptions options = {});
  // An included file's parser: its statements go into `parent`'s AST.
  StatementParser(std::string_view text, Diagnostics& diagnostics, StatementParser& parent,
                  std::vector<std::string> include_chain);

  SceneAst parse_scene();
  // The statements up to the end of the text (an included file's).
  void parse_statements();
  AnomAst parse_anom();

  // --- tokens
  const Token& peek(size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  Token take();
  [[noreturn]] void fail(const Token& found, const std::string& expected);
  void expect_word(std::string_view word);
  void expect_symbol(const char* symbol);
  Name take_name(const char* what);
  // The word that closes the statement being parsed: where resynchronising stops after an error in it.
  void set_statement_end(std::string_view word) { statement_end_ = word; }
  // True (and consumes it) at the block's end word. At the end of the input, or at a statement that cannot
  // stand inside this block, reports the unclosed block at its opener and stops the block.
  bool block_closed(const Token& opener, std::string_view end_word, const BlockContext& inner);
  // Skips to the end of the failed statement or the next statement the context knows. Always moves on.
  void resynchronise(const BlockContext& context, size_t statement_start);
  size_t position() const { return pos_; }

  // --- values and expressions
  Value literal_value();
  Value value();
  // A value, or an expression in parentheses (JIPCAD's `azimuth ($p.a + 180)`).
  Value grouped_value();
  // `( v v v )` with exactly `count` values.
  void value_tuple(Value* out, int count, const char* what);

  // --- shared pieces of statements
  std::vector<Name> name_list(const char* what);
  std::optional<Name> optional_surface();
  FaceDecl face_statement();
  InstanceDecl instance_statement();
  std::vector<Name> vertex_blocks(std::string_view end_word, const Token& opener);
  // .slf: colours are not read; say so once per use.
  void ignore_surface(const Token& at, std::optional<Name>& surface);

  // Records what decides the text's dialect: the first cue wins (the command line's overrides all).
  void note_dialect(Dialect dialect, const std::string& cue, SourceLocation at);
  // The files that include this one, this one last: where an `include` is resolved and cycles are found.
  const std::vector<std::string>& include_chain() const { return options_.include_chain; }

  bool is_slf() const { return is_slf_; }
  // .slf: the braced Tcl texts cut out of the text (split_slf_text), and the one whose `{` is the next token
  // (taking both braces); a syntax error when there is none.
  void set_slf_braces(std::vector<SlfBrace> braces) { slf_braces_ = std::move(braces); }
  ScriptText take_braced_script();
  // .slf: SLIDE's display fields of a node (`solid`, `shading`, `lod` with a flag, a number or a braced
  // value): read and set aside, for they change only how SLIDE drew it. False when none is next.
  bool skip_display_field();
  void skip_display_value();
  // `"text"` (a file name): the words between the quotes, as written.
  std::string quoted_text(const char* what);
  // .slf: a node's `surface NAME` (a material, which .slf colours do not set): read and set aside.
  bool skip_slide_surface();
  // .slf: a point's `texture (u v)`, which Nome does not map: read and set aside.
  void skip_texture_coordinates();
  SceneAst& ast() { return *ast_; }
  Diagnostics& diagnostics() { return diagnostics_; }

 private:
  // A closing word misspelt by a letter or two (hild.nom's `enintance`) is read as meant, with a warning.
  bool near_miss(std::string_view end_word);
  void top_level_statement();
  void instance_transform(const Token& t, InstanceDecl& inst);
  void look_at(InstanceDecl& inst);
  void skip_unsupported(const std::string& word);
  void choose_slf_roots();
  void set_aside_slide_cameras_and_lights();
  void name_backfaces();
  void anom_statement(AnomAst& anom, const BlockContext& top);

  // The expression grammar (expression_parser.cpp).
  ExprId node(ExprOp op, SourceLocation at, ExprId a = no_index, ExprId b = no_index);
  [[noreturn]] void expression_too_deep(SourceLocation at);
  ExprId expression();
  ExprId additive();
  ExprId term();
  ExprId unary();
  ExprId primary();
  ExprId call(const Token& name);
  bool is_operator_next() const;
  bool is_value_separator(size_t at) const;

  Diagnostics& diagnostics_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  bool is_slf_ = false;             // the SLIDE subset of .slf files
  std::string_view statement_end_;  // the word that closes the statement being parsed
  ParseOptions options_;
  SceneAst own_ast_;
  SceneAst* ast_ = &own_ast_;          // an included file's parser writes into the including one's
  std::vector<int> expression_depth_;  // height of each expression node's subtree
  int parse_depth_ = 0;                // expression grammar levels being parsed
  bool is_bare_value_ = false;         // parsing a value written without `{expr ...}`
  std::vector<SlfBrace> slf_braces_;   // in text order
};

bool is_top_level_keyword(const Token& t);

}  // namespace nome::scene
