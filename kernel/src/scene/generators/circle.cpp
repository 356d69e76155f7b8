// `circle NAME (n r) endcircle` (NOME 2.x): a closed rim line.
#include "nome/scene/generators/circle.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece circle(int n, double r) {
  require(n >= 3, "circle: n must be at least 3");
  Piece piece;
  ring(piece, n, r, 0, "c");
  RimLine rim{"", {}, true};
  for (Index v = 0; v < Index(n); ++v) rim.vertices.push_back(v);
  piece.rims.push_back(std::move(rim));
  return piece;
}

namespace {

Piece evaluate(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  return circle(c.whole(a[0], 3, "n"), c.positive(a[1], "r"));
}

}  // namespace

StatementKind circle_statement() {
  return with_generator_syntax({.keyword = "circle",
                                .end_keyword = "endcircle",
                                .signature = "(n r)",
                                .argument_count = 2,
                                .evaluate = evaluate,
                                .example = "(6 1.5)"});
}

}  // namespace nome::scene
