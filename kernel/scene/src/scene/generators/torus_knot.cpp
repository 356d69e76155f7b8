// `torusknot NAME (symm turns rad_maj rad_min rad_tube segs_circ segs_sweep) endtorusknot` (JIPCAD).
#include "nome/scene/generators/torus_knot.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

// The knot at parameter t in [0, 2 pi) with the frame of its tube: the normal of the torus there (the
// curve lies on the torus, so it is perpendicular to the tangent) and binormal = tangent x normal.
// Both are periodic in t, so the tube closes without a seam twist.
struct KnotFrame {
  Vec3 point, normal, binormal;
};

KnotFrame knot_frame(const TorusKnotParams& p, double t) {
  const double around = p.turns * t, through = p.symmetry * t;
  const Vec3 radial(std::cos(around), std::sin(around), 0), east(-std::sin(around), std::cos(around), 0);
  const Vec3 up(0, 0, 1);
  const double ring = p.major_radius + p.minor_radius * std::cos(through);
  const Vec3 normal = std::cos(through) * radial + std::sin(through) * up;
  const Vec3 tangent =
      double(p.turns) * ring * east +
      double(p.symmetry) * p.minor_radius * (-std::sin(through) * radial + std::cos(through) * up);
  return {ring * radial + p.minor_radius * std::sin(through) * up, normal,
          glm::normalize(glm::cross(glm::normalize(tangent), normal))};
}

}  // namespace

Piece torus_knot(const TorusKnotParams& p) {
  require(std::gcd(p.symmetry, p.turns) == 1, "torus_knot: symmetry and turns must be coprime");
  require(p.sweep_segs >= 3 && (p.tube_radius == 0 || p.circle_segs >= 3), "torus_knot: too few segments");
  Piece piece;
  auto t_of = [&](int i) { return 2 * std::numbers::pi * i / p.sweep_segs; };
  if (p.tube_radius == 0) {
    RimLine rim{"", {}, true};
    for (int i = 0; i < p.sweep_segs; ++i)
      rim.vertices.push_back(piece.add_vertex(knot_frame(p, t_of(i)).point, "v" + std::to_string(i)));
    piece.rims.push_back(std::move(rim));
    return piece;
  }
  SurfaceGrid grid;
  grid.across = p.sweep_segs;
  grid.along = p.circle_segs;
  grid.is_across_closed = grid.is_along_closed = true;
  add_surface_grid(piece, grid, [&](int i, int j) {
    const KnotFrame f = knot_frame(p, t_of(i));
    // Clockwise around the tangent: d/di x d/dj then points away from the curve.
    const double a = -2 * std::numbers::pi * j / p.circle_segs;
    return f.point + p.tube_radius * (std::cos(a) * f.normal + std::sin(a) * f.binormal);
  });
  return piece;
}

namespace {

int signed_whole(DefinitionContext& c, const Value& v, const char* what) {
  const double x = c.number(v);
  if (std::abs(x - std::round(x)) > 1e-9 || std::abs(x) > 1000)
    throw EvaluationError(v.location, std::string(what) + " must be a whole number in [-1000, 1000], found " +
                                          format_number(x));
  return int(std::lround(x));
}

Piece evaluate_torus_knot(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  TorusKnotParams p;
  p.symmetry = signed_whole(c, a[0], "symm");
  p.turns = signed_whole(c, a[1], "turns");
  if (std::gcd(p.symmetry, p.turns) != 1)
    throw EvaluationError(a[1].location, "symm and turns must have no common factor (found " +
                                             format_number(p.symmetry) + " and " + format_number(p.turns) +
                                             "): the curve would run over itself");
  p.major_radius = c.positive(a[2], "rad_maj");
  p.minor_radius = non_negative(c, a[3], "rad_min");
  p.tube_radius = non_negative(c, a[4], "rad_tube");
  if (p.turns == 0 && p.minor_radius == 0)
    throw EvaluationError(a[3].location,
                          "rad_min must be positive when turns is 0: the curve would be a point");
  p.circle_segs = c.whole(a[5], 3, "segs_circ");
  p.sweep_segs = c.whole(a[6], 3, "segs_sweep");
  expect_generator_faces(c, decl, double(p.circle_segs) * p.sweep_segs);
  return torus_knot(p);
}

}  // namespace

StatementKind torus_knot_statement() {
  return with_generator_syntax({.keyword = "torusknot",
                                .end_keyword = "endtorusknot",
                                .signature = "(symm turns rad_maj rad_min rad_tube segs_circ segs_sweep)",
                                .argument_count = 7,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_torus_knot,
                                .example = "(3 2 2 1 0.2 6 48)"});
}

}  // namespace nome::scene
