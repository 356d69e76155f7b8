// `spiral NAME (rate angle segs) endspiral` (JIPCAD's grammar; its reference does not describe it). NOME3's
// spiral was a thin band of fixed depth whose angle grew oddly with the segment count; ours is the curve,
// so that it can be a rim, a sweep path or a cross-section like every other curve.
#include <cmath>
#include <numbers>

#include "nome/scene/generators/curves.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece spiral(double rate, double angle, int segs) {
  require(segs >= 1, "spiral: needs a segment");
  Piece piece;
  RimLine rim{"", {}, false};
  for (int i = 0; i <= segs; ++i) {
    const double turned = angle * i / segs;
    const double a = turned * std::numbers::pi / 180, r = rate * turned / 360;
    rim.vertices.push_back(piece.add_vertex({r * std::cos(a), r * std::sin(a), 0}, "v" + std::to_string(i)));
  }
  piece.rims.push_back(std::move(rim));
  return piece;
}

namespace {

Piece evaluate_spiral(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  const double angle = number_in(c, a[1], -360000, 360000, "angle");
  if (angle == 0) throw EvaluationError(a[1].location, "angle must not be 0");
  return spiral(c.positive(a[0], "rate"), angle, c.whole(a[2], 1, "segs"));
}

}  // namespace

StatementKind spiral_statement() {
  return with_generator_syntax({.keyword = "spiral",
                                .end_keyword = "endspiral",
                                .signature = "(rate angle segs)",
                                .argument_count = 3,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_spiral,
                                .example = "(1 1080 36)"});
}

}  // namespace nome::scene
