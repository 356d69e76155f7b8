// `ellipsoid NAME (radius_x radius_y long_max latt_min latt_max segs_long segs_latt) endellipsoid`
// (JIPCAD): a sphere with a polar radius of its own.
#include "nome/scene/generators/sphere.hpp"
#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

Piece evaluate(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  SphereParams p;
  p.radius = c.positive(a[0], "radius_x");
  p.radius_z = c.positive(a[1], "radius_y");
  p.longitude_max = sweep_degrees(c, a[2], "long_max");
  p.latitude_min = number_in(c, a[3], -90, 90, "latt_min");
  p.latitude_max = number_in(c, a[4], -90, 90, "latt_max");
  if (!(p.latitude_min < p.latitude_max))
    throw EvaluationError(a[4].location, "latt_max must be above latt_min");
  p.longitude_segs = c.whole(a[5], is_whole_turn(p.longitude_max) ? 3 : 1, "segs_long");
  p.latitude_segs = c.whole(a[6], 2, "segs_latt");
  return sphere(p);
}

}  // namespace

StatementKind ellipsoid_statement() {
  return with_generator_syntax(
      {.keyword = "ellipsoid",
       .end_keyword = "endellipsoid",
       .signature = "(radius_x radius_y long_max latt_min latt_max segs_long segs_latt)",
       .argument_count = 7,
       .evaluate = evaluate,
       .example = "(2 1 360 -90 90 8 4)"});
}

}  // namespace nome::scene
