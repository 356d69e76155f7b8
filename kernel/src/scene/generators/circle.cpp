// `circle NAME (n r) endcircle` (NOME 2.x; JIPCAD writes `(radius segs)`): a closed curve, drawn as a
// rim line, that sweeps take as a path or a cross-section.
#include <cmath>

#include "nome/scene/generators/circle.hpp"
#include "scene/curves.hpp"
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

bool is_count(double x) {
  return x >= 3 && std::abs(x - std::round(x)) < 1e-9;
}

// The two orders meet in one statement: the argument that is a whole number of at least 3 is the
// count (JIPCAD's `(0.7 20)`, NOME 2.x's `(20 1)`); when both are, the first is (NOME 2.x's order).
Piece evaluate_circle(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  const bool is_count_first = is_count(c.number(a[0])) || !is_count(c.number(a[1]));
  const Value& count = a[is_count_first ? 0 : 1];
  return circle(c.whole(count, 3, "n"), c.positive(a[is_count_first ? 1 : 0], "r"));
}

SampledCurve sample_circle(DefinitionContext& c, Index decl) {
  const Piece ring = evaluate_circle(c, decl);
  SampledCurve curve{{}, true};
  for (const Vec3& p : ring.soup.positions) curve.points.push_back({p});
  return curve;
}

}  // namespace

StatementKind circle_statement() {
  return with_generator_syntax({.keyword = "circle",
                                .end_keyword = "endcircle",
                                .signature = "(n r)",
                                .argument_count = 2,
                                .evaluate = evaluate_circle,
                                .sample = sample_circle,
                                .example = "(6 1.5)"});
}

}  // namespace nome::scene
