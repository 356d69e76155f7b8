// `gencartesiansurf NAME func [f(x,y)] (x_min x_max y_min y_max x_segs y_segs) endgencartesiansurf`
// (JIPCAD): the height field z = f(x, y) over a rectangle.
#include "scene/generators/function_surfaces.hpp"
#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

Piece evaluate_cartesian_surface(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  constexpr std::array<std::string_view, 2> variables{"x", "y"};
  const std::vector<CompiledExpression> f = read_functions(c, decl, {"func"}, variables);
  const SampleRange x = sample_range(c, a, 0, 4, "x");
  const SampleRange y = sample_range(c, a, 2, 5, "y");
  expect_generator_faces(c, decl, double(x.segs) * y.segs);
  Piece piece;
  SurfaceGrid grid;
  grid.across = x.segs;
  grid.along = y.segs;
  // Faces turn from +x to +y: they face up.
  add_surface_grid(piece, grid, [&](int i, int j) {
    const std::array<double, 2> at{x.at(i), y.at(j)};
    const double z = finite_value(
        c, decl, f[0](at), [&] { return "x = " + format_number(at[0]) + ", y = " + format_number(at[1]); });
    return Vec3(at[0], at[1], z);
  });
  return piece;
}

}  // namespace

StatementKind cartesian_statement() {
  return with_generator_syntax({.keyword = "gencartesiansurf",
                                .end_keyword = "endgencartesiansurf",
                                .signature = "func [f(x,y)] (x_min x_max y_min y_max x_segs y_segs)",
                                .argument_count = 6,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_cartesian_surface,
                                .example = "func [x*y-2x] (-1 1 -1 1 4 3)"});
}

}  // namespace nome::scene
