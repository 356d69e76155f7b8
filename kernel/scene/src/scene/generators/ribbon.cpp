// `ribbon NAME (RIMLINE width azimuth twist) endribbon`: the rim ribbon of report section 6.3, a band of
// quads `width` across along a rim line (a polyline or any other curve), starting at `azimuth` degrees
// about the line's tangent and turning by `twist` degrees along it. It is the kernel sweep() of a
// two-point cross-section: on a closed rim line half a turn of twist gives a Möbius band.
#include <array>

#include "nome/error.hpp"
#include "nome/scene/sweep.hpp"
#include "scene/curves.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

// The rim line's name is kept as the declaration's one option word, the numbers as its arguments.
void parse_ribbon(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  parser.set_statement_end(row.end_keyword);
  parser.take();
  GeneratorDecl g;
  g.kind = kind;
  g.name = parser.take_name("a ribbon name");
  parser.expect_symbol("(");
  g.options.push_back(parser.take_name("the name of a rim line (polyline, circle, beziercurve, bspline)"));
  for (int i = 0; i < 3; ++i) g.args.push_back(parser.value());
  parser.expect_symbol(")");
  parser.expect_word(row.end_keyword);
  parser.ast().generators.push_back(std::move(g));
}

void save_ribbon(SceneWriter& writer, Index kind) {
  for (const GeneratorDecl& g : writer.ast().generators)
    if (g.kind == kind)
      writer.out() << "ribbon " << g.name.text << " (" << g.options[0].text << " "
                   << writer.values(g.args.data(), int(g.args.size())) << ") endribbon\n";
}

void declare_ribbon(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.generators.size(); ++i)
    if (ast.generators[i].kind == kind) out.push_back({&ast.generators[i].name, i});
}

// A rim line through other placements' vertices waits for them.
void ribbon_vertex_lists(const DefinitionScope& scope, Index decl,
                         std::vector<const std::vector<Name>*>& out) {
  const auto d = scope.definition(scope.ast().generators[decl].options[0].text);
  if (d && statement_kinds()[d->first].sample && statement_kinds()[d->first].vertex_lists)
    statement_kinds()[d->first].vertex_lists(scope, d->second, out);
}

Piece evaluate_ribbon(DefinitionContext& c, Index decl) {
  const GeneratorDecl& g = c.ast().generators[decl];
  const std::string what = "ribbon '" + g.name.text + "': ";
  const Name& rim_name = g.options[0];
  const auto d = c.definition(rim_name.text);
  if (!d || !statement_kinds()[d->first].sample)
    throw EvaluationError(
        rim_name.location,
        what + "'" + rim_name.text + "' is no rim line (a polyline, circle, beziercurve or bspline)");
  const SampledCurve rim = sample_curve(c, rim_name);
  const double width = c.positive(g.args[0], "width");
  SweepOptions options;
  options.azimuth = c.number(g.args[1]);
  options.twist = c.number(g.args[2]);
  options.is_path_closed = rim.is_closed;
  std::vector<PathSample> path;
  for (const CurvePoint& p : rim.points) path.push_back({.position = p.position});
  const std::array<CrossSection, 1> across{CrossSection{{{-width / 2, 0}, {width / 2, 0}}, false}};
  SweepResult result;
  try {
    result = sweep(path, across, options);
  } catch (const InvalidInputError& e) {
    throw EvaluationError(g.name.location, what + e.what());
  }
  for (std::string& w : result.warnings) c.warning(g.name.location, what + w);
  return std::move(result.piece);
}

}  // namespace

StatementKind ribbon_statement() {
  return {
      .keyword = "ribbon",
      .end_keyword = "endribbon",
      .signature = "(RIMLINE width azimuth twist)",
      .parse = parse_ribbon,
      .save = save_ribbon,
      .declare = declare_ribbon,
      .evaluate = evaluate_ribbon,
      .vertex_lists = ribbon_vertex_lists,
      .example = "(pl 0.2 0 0) endribbon\npolyline pl (p0 p1 p2 p3) endpolyline\nribbon z (pl 0.2 30 90)"};
}

}  // namespace nome::scene
