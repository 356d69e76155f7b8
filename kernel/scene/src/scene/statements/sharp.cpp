// `sharp [weight] [border] (v1 v2 ...) ... endsharp`: creases and corners, inside a mesh over its vertices,
// or at the top level over any instance's vertices by (a unique suffix of) their hierarchical names.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"
#include "scene/statements/sharp_syntax.hpp"

namespace nome::scene {

void parse_sharp(StatementParser& parser, std::vector<SharpDecl>& out, bool can_name_borders) {
  parser.set_statement_end("endsharp");
  const Token opener = parser.take();
  std::optional<Value> weight;
  // Both dialects carry weights (JIPCAD's files always do): a weight decides nothing about the dialect.
  if (!parser.peek().is_symbol("(") && !(can_name_borders && parser.peek().is_word("border")))
    weight = parser.value();
  const bool is_border = can_name_borders && parser.peek().is_word("border");
  if (is_border) parser.take();
  const size_t first = out.size();
  do {
    SharpDecl s{{}, parser.peek().location, weight, is_border};
    s.vertices = parser.name_list("a vertex name or ')'");
    if (s.vertices.empty())
      parser.diagnostics().error(s.location, is_border ? "sharp border needs a vertex on each border"
                                                       : "sharp needs a vertex (a corner) or a chain of "
                                                         "vertices (edges)");
    out.push_back(std::move(s));
  } while (parser.peek().is_symbol("("));
  if (out.size() == first) parser.fail(opener, "a vertex list");
  parser.expect_word("endsharp");
}

void save_sharps(SceneWriter& writer, const std::vector<SharpDecl>& sharps, const char* indent) {
  for (const SharpDecl& s : sharps)
    writer.out() << indent << "sharp " << (s.weight ? writer.values(&*s.weight, 1) + " " : "")
                 << (s.is_border ? "border " : "") << "(" << writer.names(s.vertices) << ") endsharp\n";
}

namespace {

void parse_top_level_sharp(StatementParser& parser, Index) {
  parse_sharp(parser, parser.ast().sharps, true);
}

void save_top_level_sharps(SceneWriter& writer, Index) {
  save_sharps(writer, writer.ast().sharps, "");
}

}  // namespace

StatementKind sharp_statement() {
  return {.keyword = "sharp",
          .end_keyword = "endsharp",
          .parse = parse_top_level_sharp,
          .save = save_top_level_sharps};
}

}  // namespace nome::scene
