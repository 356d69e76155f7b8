#include "scene/curves/curve_syntax.hpp"

#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_option(StatementParser& parser, CurveDecl& c) {
  const Token t = parser.peek();
  if (t.is_word("order") || t.is_word("segs")) {
    parser.take();
    (t.text == "order" ? c.order : c.segs) = parser.value();
  } else if (t.is_word("closed")) {
    parser.take();
    c.is_closed = true;
  } else {
    parser.fail(t, "'order', 'segs', 'closed', a point list or '" +
                       std::string(statement_kinds()[c.kind].end_keyword) + "'");
  }
}

void parse_curve_syntax(StatementParser& parser, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  parser.set_statement_end(row.end_keyword);
  parser.take();
  CurveDecl c;
  c.kind = kind;
  c.name = parser.take_name("a curve name");
  while (!parser.peek().is_symbol("(") && !parser.peek().is_word(row.end_keyword)) parse_option(parser, c);
  const Token open = parser.peek();
  c.points = parser.name_list("a point name or ')'");
  if (c.points.size() < 2)
    parser.diagnostics().error(open.location, std::string(row.keyword) + " '" + c.name.text +
                                                  "' needs at least 2 points, found " +
                                                  std::to_string(c.points.size()));
  while (!parser.peek().is_word(row.end_keyword) && parser.peek().kind != TokenKind::end)
    parse_option(parser, c);
  parser.expect_word(row.end_keyword);
  parser.ast().curves.push_back(std::move(c));
}

void save_curve_syntax(SceneWriter& writer, Index kind) {
  const StatementKind& row = statement_kinds()[kind];
  for (const CurveDecl& c : writer.ast().curves) {
    if (c.kind != kind) continue;
    writer.out() << row.keyword << " " << c.name.text;
    if (c.order) writer.out() << " order " << writer.values(&*c.order, 1);
    writer.out() << " (" << writer.names(c.points) << ")";
    if (c.segs) writer.out() << " segs " << writer.values(&*c.segs, 1);
    writer.out() << (c.is_closed ? " closed " : " ") << row.end_keyword << "\n";
  }
}

void declare_curve_syntax(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.curves.size(); ++i)
    if (ast.curves[i].kind == kind) out.push_back({&ast.curves[i].name, i});
}

Piece evaluate_curve_syntax(DefinitionContext& context, Index decl) {
  const SampledCurve curve = statement_kinds()[context.ast().curves[decl].kind].sample(context, decl);
  add_curve_rim(context.piece(), curve, "v");
  return std::move(context.piece());
}

}  // namespace

StatementKind with_curve_syntax(StatementKind kind) {
  kind.parse = parse_curve_syntax;
  kind.save = save_curve_syntax;
  kind.declare = declare_curve_syntax;
  kind.evaluate = evaluate_curve_syntax;
  return kind;
}

int curve_segments(DefinitionContext& context, const CurveDecl& curve) {
  return curve.segs ? context.whole(*curve.segs, 1, "segs") : 8;
}

std::vector<CurvePoint> control_points(DefinitionContext& context, const CurveDecl& curve) {
  std::vector<CurvePoint> points;
  for (const Name& n : curve.points) points.push_back(curve_point(context, n));
  return points;
}

}  // namespace nome::scene
