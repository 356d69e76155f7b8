// `helix NAME (radius rise theta_max segs) endhelix` (JIPCAD's grammar; its reference does not describe it:
// the arguments are those of NOME3's helix).
#include <cmath>
#include <numbers>

#include "nome/scene/generators/curves.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece helix(double radius, double rise, double theta_max, int segs) {
  require(segs >= 1, "helix: needs a segment");
  Piece piece;
  RimLine rim{"", {}, false};
  for (int i = 0; i <= segs; ++i) {
    const double a = theta_max * std::numbers::pi / 180 * i / segs;
    rim.vertices.push_back(
        piece.add_vertex({radius * std::cos(a), radius * std::sin(a), rise * a}, "v" + std::to_string(i)));
  }
  piece.rims.push_back(std::move(rim));
  return piece;
}

namespace {

Piece evaluate_helix(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  const double theta_max = number_in(c, a[2], -360000, 360000, "theta_max");
  if (theta_max == 0) throw EvaluationError(a[2].location, "theta_max must not be 0");
  return helix(c.positive(a[0], "radius"), c.number(a[1]), theta_max, c.whole(a[3], 1, "segs"));
}

}  // namespace

StatementKind helix_statement() {
  return with_generator_syntax({.keyword = "helix",
                                .end_keyword = "endhelix",
                                .signature = "(radius rise theta_max segs)",
                                .argument_count = 4,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_helix,
                                .example = "(1 0.2 720 24)"});
}

}  // namespace nome::scene
