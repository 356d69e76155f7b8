// The successor's render statements: `camera`, `light`, `window`, `viewport` (named blocks of fields such
// as `type NOME_AMBIENT`, `color (r g b)`, `frustum (...)`, `cameraID c`, `origin (x y)`), the colours
// `frontcolor`, `backcolor`, `backgroundcolor` and the named back colour `backface NAME color (r g b)`.
// They are the picture's defaults (Scene::render_defaults), not geometry: a top-level instance of a camera
// or light is kept with them (SceneAst::render_instances) and places nothing.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// `( v v ... )`: any count (a frustum has six, an origin two).
std::vector<Value> values(StatementParser& parser) {
  parser.expect_symbol("(");
  std::vector<Value> out;
  while (!parser.peek().is_symbol(")")) {
    if (parser.peek().kind == TokenKind::end) parser.fail(parser.peek(), "a number or ')'");
    out.push_back(parser.value());
  }
  parser.take();
  return out;
}

// A field: its key, then a word or values; SLIDE's viewport names its window with a key alone (`viewport vp
// Window endviewport`).
RenderField field(StatementParser& parser, std::string_view end_keyword) {
  RenderField f;
  if (parser.peek().is_symbol("(")) {  // a viewport's `(left top width height)` (the docs' form)
    f.key = {"", parser.peek().location};
  } else {
    f.key = parser.take_name("a setting (type, color, projection, frustum, cameraID, origin, size, ...)");
  }
  if (parser.peek().kind == TokenKind::word) {
    if (!parser.peek().is_word(end_keyword)) f.word = parser.take_name("a name");
  } else if (parser.peek().is_symbol("(")) {
    f.values = values(parser);
    // SLIDE's frustum: `( xmin ymin zmin ) ( xmax ymax zmax )`.
    if (parser.is_slf() && f.key.text == "frustum" && parser.peek().is_symbol("(")) {
      const std::vector<Value> far_corner = values(parser);
      f.values.insert(f.values.end(), far_corner.begin(), far_corner.end());
    }
  } else {
    parser.fail(parser.peek(), "a name or '(' after '" + f.key.text + "'");
  }
  return f;
}

void parse_block(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  const Token opener = parser.take();
  RenderDecl r{std::string(row.keyword), parser.take_name("a name"), {}, opener.location};
  parser.set_statement_end(row.end_keyword);
  const BlockContext inner{{}, row.end_keyword};
  while (!parser.block_closed(opener, row.end_keyword, inner))
    r.fields.push_back(field(parser, row.end_keyword));
  parser.ast().render.push_back(std::move(r));
}

// `frontcolor (r g b) endfrontcolor`, and `backface NAME color (r g b) endbackface`.
void parse_color(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  parser.set_statement_end(row.end_keyword);
  const Token opener = parser.take();
  RenderDecl r{std::string(row.keyword), std::nullopt, {}, opener.location};
  RenderField color{{"color", opener.location}, std::nullopt, {}};
  if (row.keyword == "backface") {
    r.name = parser.take_name("a back colour name");
    parser.expect_word("color");
  }
  color.values = values(parser);
  if (color.values.size() != 3)
    parser.diagnostics().error(opener.location,
                               "a colour takes 3 numbers, found " + std::to_string(color.values.size()));
  if (!parser.peek().is_word(row.alternative_end_keyword) || row.alternative_end_keyword.empty())
    parser.expect_word(row.end_keyword);
  else
    parser.take();
  r.fields.push_back(std::move(color));
  parser.ast().render.push_back(std::move(r));
}

// SLIDE's `render VIEWPORT CAMERA_PATH ROOT [light LIGHT_PATH [FLAG]] ... endrender`: what is drawn (the
// root) and how; kept as the fields "viewport", "camera", "root" and one "light" each.
void parse_render(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  const Token opener = parser.take();
  parser.set_statement_end(row.end_keyword);
  RenderDecl r{std::string(row.keyword), std::nullopt, {}, opener.location};
  for (const char* key : {"viewport", "camera", "root"}) {
    const Name word = parser.take_name(key == std::string("root") ? "the node to draw" : "a name");
    r.fields.push_back({{key, word.location}, word, {}});
  }
  while (!parser.peek().is_word(row.end_keyword)) {
    const Token light = parser.peek();
    parser.expect_word("light");
    const Name path = parser.take_name("a light's path");
    r.fields.push_back({{"light", light.location}, path, {}});
    if (parser.peek().kind == TokenKind::number || parser.peek().is_symbol("{") ||
        (parser.peek().kind == TokenKind::word && parser.peek().text.starts_with("SLF_")))
      parser.skip_display_value();
  }
  parser.take();
  parser.ast().render.push_back(std::move(r));
}

void save_slide_render(SceneWriter& writer, Index) {
  for (const RenderDecl& r : writer.ast().render) {
    if (r.keyword != "render") continue;
    writer.out() << "render";
    for (const RenderField& f : r.fields)
      writer.out() << (f.key.text == "light" ? " light " : " ") << f.word->text;
    writer.out() << " endrender\n";
  }
}

void save_render_statements(SceneWriter& writer, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  for (const RenderDecl& r : writer.ast().render) {
    if (r.keyword != row.keyword) continue;
    const bool is_block = row.parse == parse_block;
    writer.out() << r.keyword << (r.name ? " " + r.name->text : "") << (is_block ? "\n" : "");
    for (const RenderField& f : r.fields) {
      if (is_block)
        writer.out() << "    " << f.key.text;
      else if (r.name)
        writer.out() << " color";
      if (f.word)
        writer.out() << " " << f.word->text;
      else
        writer.out() << (f.key.text.empty() ? "(" : " (")
                     << writer.values(f.values.data(), int(f.values.size())) << ")";
      writer.out() << (is_block ? "\n" : "");
    }
    writer.out() << (is_block ? "" : " ") << row.end_keyword << "\n";
  }
}

StatementKind block(std::string_view keyword, std::string_view end_keyword) {
  return {.keyword = keyword,
          .end_keyword = end_keyword,
          .dialect = StatementDialect::successor_and_slide,
          .parse = parse_block,
          .save = save_render_statements};
}

StatementKind color(std::string_view keyword, std::string_view end_keyword,
                    std::string_view alternative_end_keyword = {}) {
  return {.keyword = keyword,
          .end_keyword = end_keyword,
          .alternative_end_keyword = alternative_end_keyword,
          .dialect = StatementDialect::successor,
          .parse = parse_color,
          .save = save_render_statements};
}

}  // namespace

StatementKind render_statement() {
  return {.keyword = "render",
          .end_keyword = "endrender",
          .dialect = StatementDialect::slide_only,
          .parse = parse_render,
          .save = save_slide_render};
}
StatementKind camera_statement() {
  return block("camera", "endcamera");
}
StatementKind light_statement() {
  return block("light", "endlight");
}
StatementKind window_statement() {
  return block("window", "endwindow");
}
StatementKind viewport_statement() {
  return block("viewport", "endviewport");
}
StatementKind frontcolor_statement() {
  return color("frontcolor", "endfrontcolor");
}
StatementKind backcolor_statement() {
  return color("backcolor", "endbackcolor");
}
StatementKind backgroundcolor_statement() {
  // The docs close it with `endbackground`, the grammar with `endbackgroundcolor`.
  return color("backgroundcolor", "endbackgroundcolor", "endbackground");
}
StatementKind backface_statement() {
  return color("backface", "endbackface");
}

}  // namespace nome::scene
