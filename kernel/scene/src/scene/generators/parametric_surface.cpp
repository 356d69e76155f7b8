// `genparametricsurf NAME funcX [x(u,v)] funcY [y(u,v)] funcZ [z(u,v)] (u_min u_max v_min v_max u_segs
// v_segs) endgenparametricsurf` (JIPCAD): a surface given by its parametrisation over a rectangle.
#include "scene/generators/function_surfaces.hpp"
#include "scene/generators/generator_support.hpp"
#include "scene/generators/surface_grid.hpp"

namespace nome::scene {
namespace {

// The grid stays open: whether two sides of an arbitrary parametrisation meet, and how (a cylinder, a
// Möbius band, a pole), is left to the merge stage, which joins coincident borders by position.
Piece evaluate_parametric_surface(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  constexpr std::array<std::string_view, 2> variables{"u", "v"};
  const std::vector<CompiledExpression> f = read_functions(c, decl, {"funcX", "funcY", "funcZ"}, variables);
  const SampleRange u = sample_range(c, a, 0, 4, "u");
  const SampleRange v = sample_range(c, a, 2, 5, "v");
  expect_generator_faces(c, decl, double(u.segs) * v.segs);
  Piece piece;
  SurfaceGrid grid;
  grid.across = u.segs;
  grid.along = v.segs;
  add_surface_grid(piece, grid, [&](int i, int j) {
    const std::array<double, 2> at{u.at(i), v.at(j)};
    const auto where = [&] { return "u = " + format_number(at[0]) + ", v = " + format_number(at[1]); };
    return Vec3(finite_value(c, decl, f[0](at), where), finite_value(c, decl, f[1](at), where),
                finite_value(c, decl, f[2](at), where));
  });
  return piece;
}

}  // namespace

StatementKind parametric_statement() {
  return with_generator_syntax(
      {.keyword = "genparametricsurf",
       .end_keyword = "endgenparametricsurf",
       .signature = "funcX [x(u,v)] funcY [y(u,v)] funcZ [z(u,v)] (u_min u_max v_min v_max u_segs v_segs)",
       .argument_count = 6,
       .dialect = StatementDialect::successor,
       .evaluate = evaluate_parametric_surface,
       .example = "funcX [u] funcY [v] funcZ [sin(u)*cos(v)] (0 3 0 2 4 3)"});
}

}  // namespace nome::scene
