// `circle NAME (n r) endcircle` (NOME 2.x; the successor's dialect: `(radius segs)`): a closed curve, drawn
// as a rim line, that sweeps take as a path or a cross-section.
#include <cmath>

#include "nome/scene/expression.hpp"
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

// The dialect decides the order: JIPCAD's Circle.cpp reads (radius segs), NOME 2.x (n r). Only a statement
// that cannot be read in its dialect's order (JIPCAD's `(20 1)`: one segment) is read in the other one,
// with a warning that says so.
Piece evaluate_circle(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  const bool is_jipcad = c.ast().dialect.dialect == Dialect::jipcad;
  const Value& first = a[is_jipcad ? 1 : 0];
  const Value& second = a[is_jipcad ? 0 : 1];
  if (is_jipcad && !is_count(c.number(first)) && is_count(c.number(second)) && c.number(first) > 0) {
    c.warning(a[0].location,
              "circle: the successor's dialect reads (radius segs), but " + format_number(c.number(first)) +
                  " is no number of segments (a whole number of at least 3): read as "
                  "NOME 2.x's (n r), " +
                  format_number(c.number(second)) + " segments of radius " + format_number(c.number(first)));
    return circle(c.whole(second, 3, "n"), c.positive(first, "r"));
  }
  if (!is_jipcad && !is_count(c.number(first)) && is_count(c.number(second)))
    return circle(c.whole(second, 3, "n"), c.positive(first, "r"));
  return circle(c.whole(first, 3, is_jipcad ? "segs" : "n"), c.positive(second, is_jipcad ? "radius" : "r"));
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
