// `surface NAME color (r g b) endsurface`: a colour faces and instances refer to.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// SLIDE's surface is a material: `color (r g b)`, `reflectivity (ka kd ks)`, `exponent e`, `metallic m`,
// `bitmap "file.gif" SLF_TEXMAP`, in any order; only the colour is a Nome surface's.
void slide_surface_fields(StatementParser& parser, SurfaceDecl& s, std::string_view end) {
  Value rest[3];
  while (!parser.peek().is_word(end)) {
    const Token field = parser.peek();
    if (field.is_word("color") || field.is_word("reflectivity")) {
      parser.take();
      parser.value_tuple(field.text == "color" ? s.rgb : rest, 3, field.text.c_str());
    } else if (field.is_word("exponent") || field.is_word("metallic")) {
      parser.take();
      parser.value();
    } else if (field.is_word("bitmap")) {
      parser.take();
      parser.quoted_text("a texture file name in quotes");
      if (parser.peek().kind == TokenKind::word && parser.peek().text.starts_with("SLF_")) parser.take();
    } else {
      parser.fail(field, "a surface field (color, reflectivity, exponent, metallic, bitmap) or '" +
                             std::string(end) + "'");
    }
  }
  parser.take();
}

void parse_surface(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  const Token t = parser.take();
  SurfaceDecl s;
  s.name = parser.take_name("a surface name");
  if (parser.is_slf()) {
    slide_surface_fields(parser, s, end);
  } else {
    parser.expect_word("color");
    parser.value_tuple(s.rgb, 3, "color");
    parser.expect_word(end);
  }
  if (parser.is_slf())
    parser.diagnostics().warning(t.location,
                                 "surface '" + s.name.text + "' ignored: colours of .slf files are not read");
  else
    parser.ast().surfaces.push_back(std::move(s));
}

void save_surface(SceneWriter& writer, Index) {
  for (const SurfaceDecl& s : writer.ast().surfaces)
    writer.out() << "surface " << s.name.text << " color (" << writer.values(s.rgb, 3) << ") endsurface\n";
}

}  // namespace

StatementKind surface_statement() {
  return {.keyword = "surface",
          .end_keyword = "endsurface",
          .dialect = StatementDialect::slide,
          .parse = parse_surface,
          .save = save_surface};
}

}  // namespace nome::scene
