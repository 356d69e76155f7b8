// `cone NAME (radius height hgt_max theta_max theta_segs [botcap] [topcap]) endcone` (JIPCAD's reference;
// its program never implemented it): the cone of base `radius` and apex at `height`, cut at the fraction
// hgt_max of its height (1: up to the apex).
#include "nome/scene/generators/cylinder.hpp"
#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

Piece evaluate_cone(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  CylinderParams p;
  p.radius = c.positive(a[0], "radius");
  const double full_height = c.positive(a[1], "height");
  const double fraction = number_in(c, a[2], 0, 1, "hgt_max");
  if (fraction == 0) throw EvaluationError(a[2].location, "hgt_max must be above 0");
  p.height = full_height * fraction;
  p.top_radius = p.radius * (1 - fraction);
  p.theta_max = sweep_degrees(c, a[3], "theta_max");
  p.theta_segs = c.whole(a[4], is_whole_turn(p.theta_max) ? 3 : 1, "theta_segs");
  const std::vector<bool> caps = generator_options(c, decl, {"botcap", "topcap"});
  p.has_bottom_cap = caps[0];
  p.has_top_cap = caps[1];
  if (p.has_top_cap && p.top_radius == 0)
    throw EvaluationError(a[2].location, "topcap needs a truncated cone (hgt_max below 1)");
  return cylinder(p);
}

}  // namespace

StatementKind cone_statement() {
  return with_generator_syntax({.keyword = "cone",
                                .end_keyword = "endcone",
                                .signature = "(radius height hgt_max theta_max theta_segs [botcap] [topcap])",
                                .argument_count = 5,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_cone,
                                .example = "(1 2 1 360 6 botcap)"});
}

}  // namespace nome::scene
