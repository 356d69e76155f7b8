// `disk NAME (radius theta_max theta_segs) enddisk` (JIPCAD).
#include "nome/scene/generators/disk.hpp"

#include <cmath>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {

Piece disk(const DiskParams& p) {
  require(p.theta_segs >= (is_whole_turn(p.theta_max) ? 3 : 1), "disk: too few segments");
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.theta_segs;
  grid.along = 1;
  grid.is_across_closed = is_whole_turn(p.theta_max);
  // Row 0 the rim, row 1 the centre: around, then inwards, is counter-clockwise seen from +z.
  grid.has_last_pole = true;
  grid.last_pole_name = "centre";
  add_surface_grid(piece, grid, [&](int i, int j) {
    const double theta = sample_angle(i, p.theta_segs, p.theta_max);
    const double r = j == 0 ? p.radius : 0;
    return Vec3(r * std::cos(theta), r * std::sin(theta), 0);
  });
  return piece;
}

namespace {

Piece evaluate_disk(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  DiskParams p;
  p.radius = c.positive(a[0], "radius");
  p.theta_max = sweep_degrees(c, a[1], "theta_max");
  p.theta_segs = c.whole(a[2], is_whole_turn(p.theta_max) ? 3 : 1, "theta_segs");
  return disk(p);
}

}  // namespace

StatementKind disk_statement() {
  return with_generator_syntax({.keyword = "disk",
                                .end_keyword = "enddisk",
                                .signature = "(radius theta_max theta_segs)",
                                .argument_count = 3,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_disk,
                                .example = "(1 270 6)"});
}

}  // namespace nome::scene
