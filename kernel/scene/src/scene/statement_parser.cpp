// Token handling, error recovery and the pieces that several statements share (faces, instances, names).
#include "scene/statement_parser.hpp"

#include <algorithm>

namespace nome::scene {

bool is_top_level_keyword(const Token& t) {
  return t.kind == TokenKind::word && find_statement_kind(t.text).has_value();
}

StatementParser::StatementParser(std::string_view text, Diagnostics& diagnostics, bool is_slf,
                                 ParseOptions options)
    : diagnostics_(diagnostics),
      tokens_(tokenize(text, diagnostics)),
      is_slf_(is_slf),
      options_(std::move(options)) {
  if (options_.include_chain.empty()) options_.include_chain.push_back(diagnostics.file());
}

StatementParser::StatementParser(std::string_view text, Diagnostics& diagnostics, StatementParser& parent,
                                 std::vector<std::string> include_chain)
    : diagnostics_(diagnostics),
      tokens_(tokenize(text, diagnostics)),
      is_slf_(parent.is_slf_),
      ast_(parent.ast_) {
  options_.include_chain = std::move(include_chain);
}

Token StatementParser::take() {
  const Token& t = peek();
  if (pos_ + 1 < tokens_.size()) ++pos_;
  return t;
}

void StatementParser::fail(const Token& found, const std::string& expected) {
  diagnostics_.error(found.location, "expected " + expected + ", found " + found.describe());
  throw SyntaxError{};
}

void StatementParser::expect_word(std::string_view word) {
  if (!peek().is_word(word) && !near_miss(word)) fail(peek(), "'" + std::string(word) + "'");
  take();
}

bool StatementParser::near_miss(std::string_view end_word) {
  const Token& t = peek();
  if (t.kind != TokenKind::word || end_word.substr(0, 3) != "end" || is_top_level_keyword(t) ||
      edit_distance(t.text, std::string(end_word)) > 2)
    return false;
  diagnostics_.warning(t.location, "expected '" + std::string(end_word) + "', found '" + t.text +
                                       "': read as '" + std::string(end_word) + "'");
  return true;
}

void StatementParser::expect_symbol(const char* symbol) {
  if (!peek().is_symbol(symbol)) fail(peek(), std::string("'") + symbol + "'");
  take();
}

Name StatementParser::take_name(const char* what) {
  if (peek().kind == TokenKind::parameter) {
    // geom__trefoil.nom names its torus knot `$trefoil` and instantiates it as `trefoil`.
    const Token t = take();
    diagnostics_.warning(t.location, "a definition's name takes no '$': read as '" + t.text + "'");
    return {normalize_name(t.text), t.location};
  }
  if (peek().kind != TokenKind::word) fail(peek(), what);
  const Token t = take();
  return {normalize_name(t.text), t.location};
}

void StatementParser::resynchronise(const BlockContext& context, size_t statement_start) {
  if (pos_ == statement_start) take();
  const auto is_starter = [&](const Token& t) {
    return is_top_level_keyword(t) ||
           std::find(context.starters.begin(), context.starters.end(), t.text) != context.starters.end();
  };
  while (peek().kind != TokenKind::end) {
    const Token& t = peek();
    if (!statement_end_.empty() && t.is_word(statement_end_)) {
      take();
      break;
    }
    // Statements usually start a line: a keyword in mid-line (`surface` in an instance) is no restart.
    const bool starts_line = pos_ == 0 || tokens_[pos_ - 1].location.line != t.location.line;
    if (t.kind == TokenKind::word &&
        ((!context.end_word.empty() && t.text == context.end_word) || (starts_line && is_starter(t))))
      break;
    take();
  }
  statement_end_ = {};
}

bool StatementParser::block_closed(const Token& opener, std::string_view end_word,
                                   const BlockContext& inner) {
  const Token& t = peek();
  if (t.is_word(end_word)) {
    take();
    return true;
  }
  const bool foreign = is_top_level_keyword(t) && std::find(inner.starters.begin(), inner.starters.end(),
                                                            t.text) == inner.starters.end();
  if (t.kind == TokenKind::end || foreign) {
    diagnostics_.error(opener.location, "'" + opener.text + "' is never closed: expected '" +
                                            std::string(end_word) + "', found " + t.describe() + " at " +
                                            location_text(t.location));
    return true;
  }
  return false;
}

Value StatementParser::literal_value() {
  const Token start = peek();
  double sign = 1;
  if (peek().is_symbol("-") || peek().is_symbol("+")) sign = take().text == "-" ? -1 : 1;
  if (peek().kind != TokenKind::number) fail(peek(), "a number");
  return {sign * take().number, no_index, start.location};
}

void StatementParser::value_tuple(Value* out, int count, const char* what) {
  const Token open = peek();
  expect_symbol("(");
  int n = 0;
  while (!peek().is_symbol(")") && peek().kind != TokenKind::end) {
    Value v = value();
    if (n < count) out[n] = v;
    ++n;
  }
  if (n != count) {
    diagnostics_.error(open.location, std::string(what) + " takes " + std::to_string(count) + " number" +
                                          (count == 1 ? "" : "s") + ", found " + std::to_string(n));
  }
  expect_symbol(")");
}

std::vector<Name> StatementParser::name_list(const char* what) {
  expect_symbol("(");
  std::vector<Name> names;
  while (!peek().is_symbol(")")) {
    names.push_back(take_name(what));
    if (peek().is_symbol(",")) take();  // arts_expo__cross.nom separates with commas
  }
  take();
  return names;
}

std::optional<Name> StatementParser::optional_surface() {
  if (!peek().is_word("surface")) return std::nullopt;
  take();
  return take_name("a surface name");
}

FaceDecl StatementParser::face_statement() {
  statement_end_ = "endface";
  expect_word("face");
  FaceDecl f;
  f.name = take_name("a face name");
  const Token open = peek();
  f.vertices = name_list("a vertex name or ')'");
  if (f.vertices.size() < 3)
    diagnostics_.error(open.location, "face '" + f.name.text + "' needs at least 3 vertices, found " +
                                          std::to_string(f.vertices.size()));
  const Token surface = peek();
  f.surface = optional_surface();
  if (is_slf_) ignore_surface(surface, f.surface);
  expect_word("endface");
  return f;
}

InstanceDecl StatementParser::instance_statement() {
  statement_end_ = "endinstance";
  InstanceDecl inst;
  inst.location = peek().location;
  expect_word("instance");
  if (is_slf_) {
    // SLIDE: `instance TARGET [id NAME] ...`; the instance is named by its id, else by its target.
    inst.target = take_name("the name of what to instantiate");
    inst.name = inst.target;
  } else {
    inst.name = take_name("an instance name");
    inst.target = take_name("the name of what to instantiate");
  }
  while (!peek().is_word("endinstance") && !near_miss("endinstance")) instance_transform(peek(), inst);
  take();
  return inst;
}

// One transform, surface or (.slf) id of an instance statement.
void StatementParser::instance_transform(const Token& t, InstanceDecl& inst) {
  TransformDecl tr;
  tr.location = t.location;
  if (t.is_word("translate") || t.is_word("scale")) {
    take();
    tr.kind = t.text == "translate" ? TransformKind::translate : TransformKind::scale;
    value_tuple(tr.args, 3, t.text.c_str());
  } else if (t.is_word("rotate")) {
    take();
    tr.kind = TransformKind::rotate;
    value_tuple(tr.args, 3, "rotate's axis");
    value_tuple(tr.args + 3, 1, "rotate's angle");
  } else if (t.is_word("mirror")) {
    take();
    tr.kind = TransformKind::mirror;
    value_tuple(tr.args, 4, "mirror");
  } else if (t.is_word("surface")) {
    inst.surface = optional_surface();
    if (is_slf_) ignore_surface(t, inst.surface);
    return;
  } else if (!is_slf_ && t.is_word("backface")) {
    take();
    inst.backface = take_name("a backface name");
    return;
  } else if (is_slf_ && t.is_word("id")) {
    take();
    inst.name = take_name("an instance id");
    return;
  } else if (skip_display_field()) {
    return;
  } else if (is_slf_ && t.is_word("lookat")) {
    look_at(inst);
    return;
  } else if (is_slf_ && t.kind == TokenKind::word) {
    diagnostics_.error(t.location, "not supported yet: " + t.text);
    throw SyntaxError{};
  } else {
    fail(t, "a transform (translate, rotate, scale, mirror), 'surface', 'backface' or 'endinstance'");
  }
  inst.transforms.push_back(tr);
}

// SLIDE's `lookat eye (x y z) target (x y z) up (x y z) endlookat`: how a camera or a light looks.
void StatementParser::look_at(InstanceDecl& inst) {
  LookAtDecl look{{}, {}, {}, take().location};
  for (auto [field, values] : {std::pair{"eye", look.eye}, {"target", look.target}, {"up", look.up}}) {
    expect_word(field);
    value_tuple(values, 3, field);
  }
  expect_word("endlookat");
  inst.look_at = look;
}

std::vector<Name> StatementParser::vertex_blocks(std::string_view end_word, const Token& opener) {
  std::vector<Name> names;
  const BlockContext inner{{"vertex"}, end_word};
  while (!block_closed(opener, end_word, inner)) {
    expect_word("vertex");
    names.push_back(take_name("a vertex name"));
    expect_word("endvertex");
  }
  return names;
}

void StatementParser::ignore_surface(const Token& at, std::optional<Name>& surface) {
  if (!surface) return;
  diagnostics_.warning(at.location,
                       "surface '" + surface->text + "' ignored: colours of .slf files are not read");
  surface.reset();
}

bool StatementParser::skip_display_field() {
  const Token t = peek();
  if (!is_slf_ || !(t.is_word("solid") || t.is_word("shading") || t.is_word("lod"))) return false;
  take();
  skip_display_value();
  return true;
}

void StatementParser::skip_display_value() {
  const Token v = peek();
  if (v.is_symbol("{"))
    take_braced_script();
  else if (v.kind == TokenKind::word || v.kind == TokenKind::number)
    take();
  else
    fail(v, "a flag (SLF_...), a number or a braced value");
}

void StatementParser::skip_texture_coordinates() {
  if (!is_slf_ || !peek().is_word("texture")) return;
  take();
  Value uv[2];
  value_tuple(uv, 2, "texture");
}

bool StatementParser::skip_slide_surface() {
  if (!is_slf_ || !peek().is_word("surface")) return false;
  take();
  take_name("a surface name");
  return true;
}

std::string StatementParser::quoted_text(const char* what) {
  const Token open = peek();
  if (!open.is_symbol("\"")) fail(open, what);
  take();
  std::string text;
  while (!peek().is_symbol("\"")) {
    if (peek().kind == TokenKind::end || peek().location.line != open.location.line)
      fail(peek(), "a closing '\"'");
    text += take().text;
  }
  take();
  return text;
}

ScriptText StatementParser::take_braced_script() {
  const Token open = peek();
  if (!open.is_symbol("{")) fail(open, "'{' and Tcl code");
  const auto before = [](const SlfBrace& b, SourceLocation at) {
    return b.at.line != at.line ? b.at.line < at.line : b.at.column < at.column;
  };
  const auto it = std::lower_bound(slf_braces_.begin(), slf_braces_.end(), open.location, before);
  take();
  expect_symbol("}");
  if (it == slf_braces_.end() || !(it->at == open.location)) fail(open, "Tcl code in braces");
  return {it->text, open.location};
}

}  // namespace nome::scene
