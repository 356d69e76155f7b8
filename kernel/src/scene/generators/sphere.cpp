// `sphere NAME (radius theta_max phi_min phi_max theta_segs phi_segs) endsphere` (JIPCAD).
#include "nome/scene/generators/sphere.hpp"

#include <cmath>
#include <numbers>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {

Piece sphere(const SphereParams& p) {
  require(p.longitude_segs >= 1 && p.latitude_segs >= 1, "sphere: needs at least one segment each way");
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.longitude_segs;
  grid.along = p.latitude_segs;
  grid.is_across_closed = is_whole_turn(p.longitude_max);
  grid.has_first_pole = p.latitude_min <= -90;
  grid.has_last_pole = p.latitude_max >= 90;
  const double lat0 = p.latitude_min * std::numbers::pi / 180;
  const double lat_span = (p.latitude_max - p.latitude_min) * std::numbers::pi / 180;
  add_surface_grid(piece, grid, [&](int i, int j) {
    const double lon = sample_angle(i, p.longitude_segs, p.longitude_max);
    // The poles are exact: sin(pi/2) is, cos(pi/2) is not quite 0.
    const bool is_pole = (j == 0 && grid.has_first_pole) || (j == grid.along && grid.has_last_pole);
    const double lat = lat0 + lat_span * j / p.latitude_segs;
    const double ring = is_pole ? 0 : p.radius * std::cos(lat);
    return Vec3(ring * std::cos(lon), ring * std::sin(lon), p.radius_z * std::sin(lat));
  });
  return piece;
}

namespace {

Piece evaluate(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = p.radius_z = c.positive(a[0], "radius");
  p.longitude_max = sweep_degrees(c, a[1], "theta_max");
  p.latitude_min = number_in(c, a[2], -90, 90, "phi_min");
  p.latitude_max = number_in(c, a[3], -90, 90, "phi_max");
  if (!(p.latitude_min < p.latitude_max))
    throw EvaluationError(a[3].location, "phi_max must be above phi_min");
  p.longitude_segs = c.whole(a[4], is_whole_turn(p.longitude_max) ? 3 : 1, "theta_segs");
  p.latitude_segs = c.whole(a[5], 2, "phi_segs");
  return sphere(p);
}

}  // namespace

StatementKind sphere_statement() {
  return with_generator_syntax({.keyword = "sphere",
                                .end_keyword = "endsphere",
                                .signature = "(radius theta_max phi_min phi_max theta_segs phi_segs)",
                                .argument_count = 6,
                                .evaluate = evaluate,
                                .example = "(1 360 -90 90 8 4)"});
}

}  // namespace nome::scene
