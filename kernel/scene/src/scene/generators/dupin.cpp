// `dupin NAME (a b c d u v segs) enddupin` (JIPCAD). u and v are the extents of the two angles as
// multiples of pi, 2 being a whole turn, as NOME3's dupin reads them (JIPCAD's reference only calls them
// angles); segs divides each.
#include "nome/scene/generators/dupin.hpp"

#include <cmath>
#include <numbers>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

bool is_whole(double radians) {
  return std::abs(radians - 2 * std::numbers::pi) < 1e-9;
}

}  // namespace

Piece dupin(const DupinParams& p) {
  require(p.a > std::abs(p.c), "dupin: needs a > |c| (the denominator a - c cos u cos v vanishes otherwise)");
  require(p.segs >= 3, "dupin: needs segs >= 3");
  Piece piece;
  SurfaceGrid grid;
  grid.across = grid.along = p.segs;
  grid.is_across_closed = is_whole(p.u_max);
  grid.is_along_closed = is_whole(p.v_max);
  add_surface_grid(piece, grid, [&](int i, int j) {
    const double u = p.u_max * i / p.segs, v = p.v_max * j / p.segs;
    const double cu = std::cos(u), cv = std::cos(v), den = p.a - p.c * cu * cv;
    return Vec3((p.d * (p.c - p.a * cu * cv) + p.b * p.b * cu) / den,
                p.b * std::sin(u) * (p.a - p.d * cv) / den, p.b * std::sin(v) * (p.c * cu - p.d) / den);
  });
  return piece;
}

namespace {

Piece evaluate_dupin(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  DupinParams p;
  p.a = c.positive(a[0], "a");
  p.b = c.number(a[1]);
  p.c = c.number(a[2]);
  if (!(p.a > std::abs(p.c)))
    throw EvaluationError(a[2].location, "|c| must be below a (the cyclide would pass through infinity)");
  p.d = c.number(a[3]);
  p.u_max = number_in(c, a[4], 0, 2, "u") * std::numbers::pi;
  p.v_max = number_in(c, a[5], 0, 2, "v") * std::numbers::pi;
  if (p.u_max == 0 || p.v_max == 0)
    throw EvaluationError((p.u_max == 0 ? a[4] : a[5]).location, "u and v must be above 0");
  p.segs = c.whole(a[6], 3, "segs");
  expect_generator_faces(c, decl, double(p.segs) * p.segs);
  return dupin(p);
}

}  // namespace

StatementKind dupin_statement() {
  return with_generator_syntax({.keyword = "dupin",
                                .end_keyword = "enddupin",
                                .signature = "(a b c d u v segs)",
                                .argument_count = 7,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_dupin,
                                .example = "(1 0.98 0.2 0.5 2 2 6)"});
}

}  // namespace nome::scene
