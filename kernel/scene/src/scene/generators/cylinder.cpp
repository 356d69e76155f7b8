// `cylinder NAME (radius height theta_max theta_segs [botcap] [topcap]) endcylinder` (JIPCAD; the caps
// are words among the arguments, in any order).
#include "nome/scene/generators/cylinder.hpp"

#include <cmath>

#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

// The cap over row `row` of the mantle: its circle's vertices counter-clockwise seen from above (a pie
// through a centre vertex over a wedge), reversed for the bottom so that it faces down.
void add_cap(Piece& piece, const CylinderParams& p, const GridVertices& grid, int row) {
  const bool is_top = row == 1;
  const bool is_whole = is_whole_turn(p.theta_max);
  std::vector<Index> corners;
  if (!is_whole)
    corners.push_back(piece.add_vertex({0, 0, is_top ? p.height : 0}, is_top ? "top" : "bottom"));
  const int last = is_whole ? p.theta_segs - 1 : p.theta_segs;
  for (int i = 0; i <= last; ++i) corners.push_back(grid(is_top ? i : last - i, row));
  piece.add_face(corners, is_top ? "topcap" : "botcap");
}

}  // namespace

Piece cylinder(const CylinderParams& p) {
  require(p.theta_segs >= (is_whole_turn(p.theta_max) ? 3 : 1), "cylinder: too few segments");
  Piece piece;
  SurfaceGrid grid;
  grid.across = p.theta_segs;
  grid.along = 1;
  grid.is_across_closed = is_whole_turn(p.theta_max);
  grid.has_last_pole = p.top_radius == 0;
  grid.last_pole_name = "apex";
  const GridVertices vertices = add_surface_grid(piece, grid, [&](int i, int j) {
    const double theta = sample_angle(i, p.theta_segs, p.theta_max);
    const double r = j == 0 ? p.radius : p.top_radius;
    return Vec3(r * std::cos(theta), r * std::sin(theta), j == 0 ? 0 : p.height);
  });
  if (p.has_bottom_cap) add_cap(piece, p, vertices, 0);
  if (p.has_top_cap) {
    require(p.top_radius > 0, "cylinder: a top cap needs a top circle");
    add_cap(piece, p, vertices, 1);
  }
  return piece;
}

namespace {

Piece evaluate_cylinder(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  CylinderParams p;
  p.radius = p.top_radius = c.positive(a[0], "radius");
  p.height = c.positive(a[1], "height");
  p.theta_max = sweep_degrees(c, a[2], "theta_max");
  p.theta_segs = c.whole(a[3], is_whole_turn(p.theta_max) ? 3 : 1, "theta_segs");
  const std::vector<bool> caps = generator_options(c, decl, {"botcap", "topcap"});
  p.has_bottom_cap = caps[0];
  p.has_top_cap = caps[1];
  return cylinder(p);
}

}  // namespace

StatementKind cylinder_statement() {
  return with_generator_syntax({.keyword = "cylinder",
                                .end_keyword = "endcylinder",
                                .signature = "(radius height theta_max theta_segs [botcap] [topcap])",
                                .argument_count = 4,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_cylinder,
                                .example = "(1 2 360 6 botcap topcap)"});
}

}  // namespace nome::scene
