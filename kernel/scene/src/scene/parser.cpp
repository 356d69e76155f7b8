#include "nome/scene/parser.hpp"

#include <algorithm>

#include "scene/slide/slf_text.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {

SceneAst StatementParser::parse_scene() {
  ast_->file = diagnostics_.file();
  parse_statements();
  if (is_slf_) {
    set_aside_slide_cameras_and_lights();
    choose_slf_roots();
  }
  name_backfaces();
  if (options_.dialect) ast_->dialect = {*options_.dialect, "--dialect"};
  return std::move(*ast_);
}

void StatementParser::parse_statements() {
  const BlockContext top{{}, {}};
  while (peek().kind != TokenKind::end) {
    const size_t start = pos_;
    try {
      top_level_statement();
    } catch (const SyntaxError&) {
      resynchronise(top, start);
    }
  }
}

void StatementParser::note_dialect(Dialect dialect, const std::string& cue, SourceLocation at) {
  if (!ast_->dialect.cue.empty() || is_slf_) return;
  ast_->dialect = {dialect, cue + " at " + diagnostics_.file() + ":" + location_text(at)};
}

// Every statement is a row of statement_kinds(): its keyword picks the row that parses it.
void StatementParser::top_level_statement() {
  const Token t = peek();
  statement_end_ = {};
  const std::optional<Index> kind = t.kind == TokenKind::word ? find_statement_kind(t.text) : std::nullopt;
  const StatementDialect dialect = kind ? statement_kinds()[*kind].dialect : StatementDialect::nome;
  if (is_slf_ && !(kind && is_slide_statement(dialect))) {
    if (t.kind != TokenKind::word) fail(t, "a statement (" + statement_keyword_list(true) + ")");
    diagnostics_.error(t.location, "not supported yet: " + t.text);
    skip_unsupported(t.text);
    return;
  }
  if (!kind) fail(t, "a statement (" + statement_keyword_list() + ")");
  if (!is_slf_ && !is_nome_statement(dialect))
    fail(t, "a statement (" + statement_keyword_list() + "): '" + t.text +
                "' runs SLIDE's Tcl, read from .slf files only");
  const StatementKind& row = statement_kinds()[*kind];
  if (row.dialect == StatementDialect::successor || row.dialect == StatementDialect::successor_and_slide)
    note_dialect(Dialect::jipcad, "'" + t.text + "'", t.location);
  row.parse(*this, *kind);
}

// .slf: skips an unsupported statement: to its `endWORD`, or over a `{ ... }` block (tclinit).
void StatementParser::skip_unsupported(const std::string& word) {
  take();
  if (peek().is_symbol("{")) {
    int depth = 0;
    do {
      if (peek().is_symbol("{")) ++depth;
      if (peek().is_symbol("}")) --depth;
      take();
    } while (depth > 0 && peek().kind != TokenKind::end);
    return;
  }
  for (size_t i = pos_; i < tokens_.size(); ++i)
    if (tokens_[i].is_word("end" + word)) {
      pos_ = i + 1;
      return;
    }
}

// SLIDE places cameras and lights with instances inside groups: they draw nothing, so they go with the
// render statements. A `lookat` orients a camera or a light; on geometry it is not read yet.
void StatementParser::set_aside_slide_cameras_and_lights() {
  const auto is_render = [&](const InstanceDecl& i) {
    return std::any_of(ast_->render.begin(), ast_->render.end(),
                       [&](const RenderDecl& r) { return r.name && r.name->text == i.target.text; });
  };
  for (GroupDecl& g : ast_->groups) {
    std::vector<InstanceDecl> kept;
    for (InstanceDecl& i : g.instances) {
      if (is_render(i))
        ast_->render_instances.push_back(std::move(i));
      else if (i.look_at)
        diagnostics_.error(i.look_at->location, "not supported yet: lookat on '" + i.target.text +
                                                    "', which is not a camera or a light");
      else
        kept.push_back(std::move(i));
    }
    g.instances = std::move(kept);
  }
}

// .slf files name no root: SLIDE draws the root of the first render statement; without one, every group no
// instance uses is one (else every object, else every face).
void StatementParser::choose_slf_roots() {
  if (!ast_->instances.empty()) return;
  for (const RenderDecl& r : ast_->render)
    for (const RenderField& f : r.fields)
      if (r.keyword == "render" && f.key.text == "root" && f.word) {
        ast_->instances.push_back({*f.word, *f.word, {}, std::nullopt, f.word->location});
        return;
      }
  std::vector<std::string> used;
  for (const GroupDecl& g : ast_->groups)
    for (const InstanceDecl& i : g.instances) used.push_back(i.target.text);
  auto add_roots = [&](const auto& decls) {
    for (const auto& d : decls)
      if (std::find(used.begin(), used.end(), d.name.text) == used.end())
        ast_->instances.push_back({d.name, d.name, {}, std::nullopt, d.name.location});
    return !ast_->instances.empty();
  };
  if (add_roots(ast_->groups) || add_roots(ast_->objects)) return;
  add_roots(ast_->faces);
}

// JIPCAD's instances name a back colour with `surface B` as well as `backface B` (render__backface.nom),
// and place lights and cameras: both belong to the render defaults, not to the geometry.
void StatementParser::name_backfaces() {
  std::vector<std::string> backfaces;
  for (const RenderDecl& r : ast_->render)
    if (r.keyword == "backface" && r.name) backfaces.push_back(r.name->text);
  const auto is_backface = [&](const std::optional<Name>& s) {
    return s && std::find(backfaces.begin(), backfaces.end(), s->text) != backfaces.end() &&
           std::none_of(ast_->surfaces.begin(), ast_->surfaces.end(),
                        [&](const SurfaceDecl& d) { return d.name.text == s->text; });
  };
  const auto fix = [&](InstanceDecl& i) {
    if (!is_backface(i.surface)) return;
    i.backface = i.surface;
    i.surface.reset();
  };
  for (InstanceDecl& i : ast_->instances) fix(i);
  for (GroupDecl& g : ast_->groups)
    for (InstanceDecl& i : g.instances) fix(i);
  // An instance of a light or camera (render__light_test.nom) places no geometry: it stays with them.
  const auto is_render = [&](const InstanceDecl& i) {
    return std::any_of(ast_->render.begin(), ast_->render.end(),
                       [&](const RenderDecl& r) { return r.name && r.name->text == i.target.text; });
  };
  std::vector<InstanceDecl> roots;
  for (InstanceDecl& i : ast_->instances)
    (is_render(i) ? ast_->render_instances : roots).push_back(std::move(i));
  ast_->instances = std::move(roots);
}

AnomAst StatementParser::parse_anom() {
  AnomAst anom;
  const BlockContext top{{"savedparameter", "savedworkingmesh"}, {}};
  while (peek().kind != TokenKind::end) {
    const size_t start = pos_;
    try {
      anom_statement(anom, top);
    } catch (const SyntaxError&) {
      resynchronise(top, start);
    }
  }
  return anom;
}

void StatementParser::anom_statement(AnomAst& anom, const BlockContext& top) {
  const Token opener = take();
  if (opener.is_word("savedparameter")) {
    statement_end_ = "endsavedparameter";
    while (!block_closed(opener, "endsavedparameter", top)) {
      Name name = take_name("a parameter name");
      const Value v = literal_value();
      anom.saved_parameters.emplace_back(std::move(name), v.literal);
    }
  } else if (opener.is_word("savedworkingmesh")) {
    statement_end_ = "endsavedworkingmesh";
    take_name("the working mesh's name");
    const BlockContext faces{{"face"}, "endsavedworkingmesh"};
    while (!block_closed(opener, "endsavedworkingmesh", faces)) {
      const Token face = peek();
      expect_word("face");
      NamedFace f{vertex_blocks("endface", face), face.location};
      if (f.vertices.size() < 3)
        diagnostics_.error(face.location, "a face of the working mesh needs at least 3 vertices, found " +
                                              std::to_string(f.vertices.size()));
      anom.working_mesh.push_back(std::move(f));
    }
  } else {
    fail(opener, "'savedparameter' or 'savedworkingmesh'");
  }
}

std::string normalize_name(std::string name) {
  name.erase(0, name.find_first_not_of('.'));
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

SceneAst parse_nome(std::string_view text, Diagnostics& diagnostics, const ParseOptions& options) {
  SceneAst ast = StatementParser(text, diagnostics, false, options).parse_scene();
  const size_t header = text.find(jipcad_header);
  if (!options.dialect && header != std::string_view::npos && (header == 0 || text[header - 1] == '\n')) {
    const int line = int(std::count(text.begin(), text.begin() + long(header), '\n')) + 1;
    ast.dialect = {Dialect::jipcad, std::string("the line '") + jipcad_header + "' at " + diagnostics.file() +
                                        ":" + std::to_string(line) + ":1"};
  }
  return ast;
}

SceneAst parse_slf(std::string_view text, Diagnostics& diagnostics) {
  SlfText split = split_slf_text(text, diagnostics);
  StatementParser parser(split.statements, diagnostics, true);
  parser.set_slf_braces(std::move(split.braces));
  return parser.parse_scene();
}

AnomAst parse_anom(std::string_view text, Diagnostics& diagnostics) {
  return StatementParser(text, diagnostics, false).parse_anom();
}

}  // namespace nome::scene
