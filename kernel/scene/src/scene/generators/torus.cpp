// `torus NAME (rad_maj rad_min theta_max phi_min phi_max segs_theta segs_phi) endtorus` (JIPCAD), and the
// older `torus NAME (segs_phi rad_maj rad_min theta_max phi_max segs_theta) endtorus` that
// geom__olympictorus.nom still writes (phi from 0).
#include "nome/scene/generators/torus.hpp"

#include <cmath>
#include <numbers>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {

Piece torus(const TorusParams& p) {
  require(p.theta_segs >= 1 && p.phi_segs >= 1, "torus: needs at least one segment each way");
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.theta_segs;
  grid.along = p.phi_segs;
  grid.is_across_closed = is_whole_turn(p.theta_max);
  grid.is_along_closed = is_whole_turn(p.phi_max - p.phi_min);
  const double phi0 = p.phi_min * std::numbers::pi / 180;
  add_surface_grid(piece, grid, [&](int i, int j) {
    const double theta = sample_angle(i, p.theta_segs, p.theta_max);
    const double phi = phi0 + sample_angle(j, p.phi_segs, p.phi_max - p.phi_min);
    const double ring = p.major_radius + p.minor_radius * std::cos(phi);
    return Vec3(ring * std::cos(theta), ring * std::sin(theta), p.minor_radius * std::sin(phi));
  });
  return piece;
}

namespace {

TorusParams arguments(DefinitionContext& c, const std::vector<Value>& a) {
  TorusParams p;
  if (a.size() == 6) {
    p.phi_segs = c.whole(a[0], 1, "segs_phi");
    p.major_radius = c.positive(a[1], "rad_maj");
    p.minor_radius = c.positive(a[2], "rad_min");
    p.theta_max = sweep_degrees(c, a[3], "theta_max");
    p.phi_max = sweep_degrees(c, a[4], "phi_max");
    p.theta_segs = c.whole(a[5], 1, "segs_theta");
    return p;
  }
  p.major_radius = c.positive(a[0], "rad_maj");
  p.minor_radius = c.positive(a[1], "rad_min");
  p.theta_max = sweep_degrees(c, a[2], "theta_max");
  p.phi_min = number_in(c, a[3], 0, 360, "phi_min");
  p.phi_max = number_in(c, a[4], 0, 360, "phi_max");
  if (!(p.phi_min < p.phi_max)) throw EvaluationError(a[4].location, "phi_max must be above phi_min");
  p.theta_segs = c.whole(a[5], 1, "segs_theta");
  p.phi_segs = c.whole(a[6], 1, "segs_phi");
  return p;
}

Piece evaluate_torus(DefinitionContext& c, Index decl) {
  TorusParams p = arguments(c, generator_arguments(c, decl));
  // A closed ring of fewer than three segments would have two faces on one pair of vertices.
  const Value& where = generator_arguments(c, decl).back();
  if ((is_whole_turn(p.theta_max) && p.theta_segs < 3) ||
      (is_whole_turn(p.phi_max - p.phi_min) && p.phi_segs < 3))
    throw EvaluationError(where.location, "a whole turn needs at least 3 segments");
  expect_generator_faces(c, decl, double(p.theta_segs) * p.phi_segs);
  return torus(p);
}

}  // namespace

StatementKind torus_statement() {
  return with_generator_syntax(
      {.keyword = "torus",
       .end_keyword = "endtorus",
       .signature = "(rad_maj rad_min theta_max phi_min phi_max segs_theta segs_phi)",
       .argument_count = 7,
       .alternative_argument_count = 6,
       .dialect = StatementDialect::successor,
       .evaluate = evaluate_torus,
       .example = "(2 0.5 360 0 360 8 6)"});
}

}  // namespace nome::scene
