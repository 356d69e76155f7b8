// `surface NAME color (r g b) endsurface`: a colour faces and instances refer to.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_surface(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  const Token t = parser.take();
  SurfaceDecl s;
  s.name = parser.take_name("a surface name");
  parser.expect_word("color");
  parser.value_tuple(s.rgb, 3, "color");
  parser.expect_word(end);
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
