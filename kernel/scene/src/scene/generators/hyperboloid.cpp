// `hyperboloid NAME (a c u_max u_segs v_segs sheet) endhyperboloid` in the 2016 dialect (NOME3's last
// hyperboloid, its increments read as segment counts; sheet 0 one sheet, 1 paraboloid, 2 two sheets), and
// `(segs a b c sheet theta)` in the successor's, as JIPCAD's Hyperboloid.cpp reads them.
#include "nome/scene/generators/hyperboloid.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

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

Piece successor_hyperboloid(const SuccessorHyperboloidParams& p) {
  require(p.segs >= 3 && p.rows >= 1 && p.theta > 0, "successor_hyperboloid: needs segs >= 3 and c >= 1");
  const bool is_closed = std::abs(p.theta - 2) < 1e-9;
  Piece piece;
  SurfaceGrid grid;
  grid.across = is_closed ? p.segs : p.segs - 1;
  grid.is_across_closed = is_closed;
  auto point = [&](int i, int z) {
    const double t = i * p.theta * std::numbers::pi / p.segs;
    const double s = std::sqrt(double(z) * z + (p.is_two_sheets ? -1 : 1));
    return Vec3(p.a * s * std::cos(t), p.b * s * std::sin(t), z);
  };
  if (!p.is_two_sheets) {
    grid.along = 2 * p.rows;
    add_surface_grid(piece, grid, [&](int i, int j) { return point(i, j - p.rows); });
    return piece;
  }
  // Between z = -1 and 1 there is no surface: each sheet runs from its apex at +-1 to +-c.
  if (p.rows < 2) return piece;
  grid.along = p.rows - 1;
  grid.prefix = "top_";
  grid.has_first_pole = true;
  grid.first_pole_name = "apex";
  add_surface_grid(piece, grid, [&](int i, int j) { return point(i, j + 1); });
  grid.prefix = "bottom_";
  grid.has_first_pole = false;
  grid.has_last_pole = true;
  grid.last_pole_name = "apex";
  add_surface_grid(piece, grid, [&](int i, int j) { return point(i, j - p.rows); });
  return piece;
}

namespace {

// NOME3's order, the 2016 dialect's: (a c u_max u_segs v_segs sheet).
bool is_older_order(DefinitionContext& c, const std::vector<Value>& a) {
  auto is_whole = [&](const Value& v, double lo, double hi) {
    const double x = c.number(v);
    return std::abs(x - std::round(x)) < 1e-9 && x >= lo && x <= hi;
  };
  const double u_max = c.number(a[2]);
  return c.number(a[0]) > 0 && c.number(a[1]) > 0 && u_max > 0 && u_max <= 20 && is_whole(a[3], 1, 1e5) &&
         is_whole(a[4], 3, 1e5) && is_whole(a[5], 0, 2);
}

HyperboloidParams older_arguments(DefinitionContext& c, const std::vector<Value>& a) {
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
  return p;
}

Piece older_hyperboloid(DefinitionContext& c, Index decl, const HyperboloidParams& p) {
  expect_generator_faces(c, decl, double(p.u_segs) * p.v_segs * (p.sheet == HyperboloidSheet::two ? 2 : 1));
  return hyperboloid(p);
}

SuccessorHyperboloidParams successor_arguments(DefinitionContext& c, const std::vector<Value>& a) {
  SuccessorHyperboloidParams p;
  p.segs = c.whole(a[0], 3, "segs");
  p.a = c.positive(a[1], "a");
  p.b = c.positive(a[2], "b");
  // JIPCAD takes the whole part of c: the rows are at whole heights.
  p.rows = int(std::floor(number_in(c, a[3], 1, 100000, "c")));
  p.is_two_sheets = c.whole(a[4], 0, "sheet") != 0;
  p.theta = number_in(c, a[5], 0, 2, "theta (a sweep in units of pi)");
  if (p.theta == 0) throw EvaluationError(a[5].location, "theta (a sweep in units of pi) must be above 0");
  if (p.is_two_sheets && p.rows < 2)
    throw EvaluationError(a[3].location, "c must be at least 2 for two sheets (they start at z = +-1)");
  return p;
}

// JIPCAD's own reference documents the hyperboloid in NOME3's older order (its sliders `A C UMax
// UIncrement VIncrement Sheet`), which JIPCAD's Hyperboloid.cpp no longer reads. Arguments that JIPCAD's
// order refuses and NOME3's reads are read in NOME3's, with a warning that says so.
Piece evaluate_successor_hyperboloid(DefinitionContext& c, Index decl, const std::vector<Value>& a) {
  std::optional<SuccessorHyperboloidParams> p;
  try {
    p = successor_arguments(c, a);
  } catch (const EvaluationError& e) {
    if (!is_older_order(c, a)) throw;
    c.warning(a[0].location,
              std::string("hyperboloid: the successor's dialect reads (segs a b c sheet theta), "
                          "but ") +
                  e.what() + ": read as NOME3's older (a c u_max u_segs v_segs sheet)");
    return older_hyperboloid(c, decl, older_arguments(c, a));
  }
  expect_generator_faces(c, decl, double(p->segs) * 2 * p->rows);
  return successor_hyperboloid(*p);
}

Piece evaluate_hyperboloid(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  if (c.ast().dialect.dialect == Dialect::jipcad) return evaluate_successor_hyperboloid(c, decl, a);
  return older_hyperboloid(c, decl, older_arguments(c, a));
}

}  // namespace

StatementKind hyperboloid_statement() {
  return with_generator_syntax({.keyword = "hyperboloid",
                                .end_keyword = "endhyperboloid",
                                .signature = "(segs a b c sheet theta)",
                                .argument_count = 6,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_hyperboloid,
                                .example = "(8 1 1 2 0 2)"});
}

}  // namespace nome::scene
