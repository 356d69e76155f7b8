// `hyperboloid NAME (a c u_max u_segs v_segs sheet) endhyperboloid` (JIPCAD's grammar; its reference does
// not describe it: the arguments are those of NOME3's last hyperboloid, with its increments read as
// segment counts; sheet 0 one sheet, 1 paraboloid, 2 two sheets).
#include "nome/scene/generators/hyperboloid.hpp"

#include <cmath>
#include <numbers>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {

Piece hyperboloid(const HyperboloidParams& p) {
  require(p.u_segs >= 1 && p.v_segs >= 3, "hyperboloid: needs u_segs >= 1 and v_segs >= 3");
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.v_segs;
  grid.along = p.u_segs;
  grid.is_across_closed = true;
  auto around = [&](int i) { return 2 * std::numbers::pi * i / p.v_segs; };
  auto along = [&](int j) { return p.u_max * j / p.u_segs; };
  if (p.sheet == HyperboloidSheet::one) {
    add_surface_grid(piece, grid, [&](int i, int j) {
      const double u = -p.u_max + 2 * along(j), r = p.a * std::cosh(u);
      return Vec3(r * std::cos(around(i)), r * std::sin(around(i)), p.c * std::sinh(u));
    });
    return piece;
  }
  grid.has_first_pole = true;
  grid.first_pole_name = "apex";
  if (p.sheet == HyperboloidSheet::paraboloid) {
    add_surface_grid(piece, grid, [&](int i, int j) {
      const double u = along(j);
      return Vec3(p.a * u * std::cos(around(i)), p.a * u * std::sin(around(i)), p.c * u * u);
    });
    return piece;
  }
  for (const double side : {1.0, -1.0}) {
    grid.prefix = side > 0 ? "top_" : "bottom_";
    // The mirror image turns the faces over: the lower sheet runs around the other way.
    grid.is_reversed = side < 0;
    add_surface_grid(piece, grid, [&](int i, int j) {
      const double u = along(j), r = p.a * std::sinh(u);
      return Vec3(r * std::cos(around(i)), r * std::sin(around(i)), side * p.c * std::cosh(u));
    });
  }
  return piece;
}

namespace {

Piece evaluate_hyperboloid(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  HyperboloidParams p;
  p.a = c.positive(a[0], "a");
  p.c = c.positive(a[1], "c");
  p.u_max = number_in(c, a[2], 0, 20, "u_max");
  if (p.u_max == 0) throw EvaluationError(a[2].location, "u_max must be above 0");
  p.u_segs = c.whole(a[3], 1, "u_segs");
  p.v_segs = c.whole(a[4], 3, "v_segs");
  p.sheet = HyperboloidSheet(c.whole(a[5], 0, "sheet"));
  if (int(p.sheet) > 2)
    throw EvaluationError(a[5].location, "sheet must be 0 (one), 1 (paraboloid) or 2 (two)");
  return hyperboloid(p);
}

}  // namespace

StatementKind hyperboloid_statement() {
  return with_generator_syntax({.keyword = "hyperboloid",
                                .end_keyword = "endhyperboloid",
                                .signature = "(a c u_max u_segs v_segs sheet)",
                                .argument_count = 6,
                                .evaluate = evaluate_hyperboloid,
                                .example = "(1 1 1 4 8 0)"});
}

}  // namespace nome::scene
