// `sphere NAME (radius theta_max phi_min phi_max theta_segs phi_segs) endsphere` and `ellipsoid` (JIPCAD).
#include "nome/scene/generators/sphere.hpp"

#include <cmath>
#include <numbers>
#include <string>

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

// The arguments after the radii, named as each statement's signature names them: the longitude swept, the
// latitude band and the segments each way.
struct AngleNames {
  const char *longitude_max, *latitude_min, *latitude_max, *longitude_segs, *latitude_segs;
};

Piece evaluate_globe(DefinitionContext& c, const std::vector<Value>& a, size_t first, SphereParams p,
                     const AngleNames& n) {
  p.longitude_max = sweep_degrees(c, a[first], n.longitude_max);
  p.latitude_min = number_in(c, a[first + 1], -90, 90, n.latitude_min);
  p.latitude_max = number_in(c, a[first + 2], -90, 90, n.latitude_max);
  if (!(p.latitude_min < p.latitude_max))
    throw EvaluationError(a[first + 2].location,
                          std::string(n.latitude_max) + " must be above " + n.latitude_min);
  p.longitude_segs = c.whole(a[first + 3], is_whole_turn(p.longitude_max) ? 3 : 1, n.longitude_segs);
  p.latitude_segs = c.whole(a[first + 4], 2, n.latitude_segs);
  return sphere(p);
}

Piece evaluate_sphere(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = p.radius_z = c.positive(a[0], "radius");
  return evaluate_globe(c, a, 1, p, {"theta_max", "phi_min", "phi_max", "theta_segs", "phi_segs"});
}

Piece evaluate_ellipsoid(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = c.positive(a[0], "radius_x");
  p.radius_z = c.positive(a[1], "radius_y");
  return evaluate_globe(c, a, 2, p, {"long_max", "latt_min", "latt_max", "segs_long", "segs_latt"});
}

}  // namespace

StatementKind sphere_statement() {
  return with_generator_syntax({.keyword = "sphere",
                                .end_keyword = "endsphere",
                                .signature = "(radius theta_max phi_min phi_max theta_segs phi_segs)",
                                .argument_count = 6,
                                .evaluate = evaluate_sphere,
                                .example = "(1 360 -90 90 8 4)"});
}

// `ellipsoid NAME (radius_x radius_y long_max latt_min latt_max segs_long segs_latt) endellipsoid`
// (JIPCAD): a sphere with a polar radius of its own.
StatementKind ellipsoid_statement() {
  return with_generator_syntax(
      {.keyword = "ellipsoid",
       .end_keyword = "endellipsoid",
       .signature = "(radius_x radius_y long_max latt_min latt_max segs_long segs_latt)",
       .argument_count = 7,
       .evaluate = evaluate_ellipsoid,
       .example = "(2 1 360 -90 90 8 4)"});
}

}  // namespace nome::scene
