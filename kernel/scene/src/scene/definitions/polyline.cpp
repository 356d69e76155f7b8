// `polyline NAME (v1 v2 ...) [isloop | closed] endpolyline`: a rim line over named vertices (SLIDE's
// `polyline NAME pointlist (...) endpolyline` too).
#include "nome/scene/statement_kinds.hpp"
#include "scene/curves.hpp"
#include "scene/definition_context.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_polyline(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  PolylineDecl p;
  p.name = parser.take_name("a polyline name");
  // SLIDE: `polyline NAME pointlist (p1 p2 ...) [drawpoints b] [display fields] endpolyline`; a list that
  // ends where it starts is a loop.
  if (parser.is_slf()) parser.expect_word("pointlist");
  const Token open = parser.peek();
  p.vertices = parser.name_list("a vertex name or ')'");
  if (parser.is_slf()) {
    while (parser.skip_display_field() || parser.skip_slide_surface())
      ;
    if (parser.peek().is_word("drawpoints")) {
      parser.take();
      parser.skip_display_value();
    }
    if (p.vertices.size() > 2 && p.vertices.front().text == p.vertices.back().text) {
      p.vertices.pop_back();
      p.is_loop = true;
    }
  }
  if (p.vertices.size() < 2)
    parser.diagnostics().error(open.location, "polyline '" + p.name.text +
                                                  "' needs at least 2 vertices, found " +
                                                  std::to_string(p.vertices.size()));
  // `isloop` is the 2016 spelling, `closed` the successor's.
  if (parser.peek().is_word("isloop") || parser.peek().is_word("closed")) {
    const Token loop = parser.take();
    parser.note_dialect(loop.text == "closed" ? Dialect::jipcad : Dialect::report2016,
                        "'" + loop.text + "' in a polyline", loop.location);
    p.is_loop = true;
  }
  parser.expect_word(end);
  parser.ast().polylines.push_back(std::move(p));
}

void save_polyline(SceneWriter& writer, Index) {
  const char* loop = writer.ast().dialect.dialect == Dialect::jipcad ? " closed" : " isloop";
  for (const PolylineDecl& p : writer.ast().polylines)
    writer.out() << "polyline " << p.name.text << " (" << writer.names(p.vertices) << ")"
                 << (p.is_loop ? loop : "") << " endpolyline\n";
}

void declare_polyline(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.polylines.size(); ++i) out.push_back({&ast.polylines[i].name, i});
}

Piece evaluate_polyline(DefinitionContext& context, Index decl) {
  const PolylineDecl& line = context.ast().polylines[decl];
  context.add_rim(line.name, line.vertices, line.is_loop);
  return std::move(context.piece());
}

// As a sweep's path or cross-section: its points (control points with their values), closed by
// `isloop` or by ending on its first point.
SampledCurve sample_polyline(DefinitionContext& context, Index decl) {
  const PolylineDecl& line = context.ast().polylines[decl];
  SampledCurve curve;
  for (const Name& n : line.vertices) curve.points.push_back(curve_point(context, n));
  curve.is_closed = line.is_loop;
  if (!curve.is_closed) close_if_repeated(curve);
  return curve;
}

void vertex_lists_polyline(const DefinitionScope& scope, Index decl,
                           std::vector<const std::vector<Name>*>& out) {
  out.push_back(&scope.ast().polylines[decl].vertices);
}

}  // namespace

StatementKind polyline_statement() {
  return {.keyword = "polyline",
          .end_keyword = "endpolyline",
          .dialect = StatementDialect::slide,
          .parse = parse_polyline,
          .save = save_polyline,
          .declare = declare_polyline,
          .evaluate = evaluate_polyline,
          .vertex_lists = vertex_lists_polyline,
          .sample = sample_polyline,
          .example = "(p0 p1 p2) isloop"};
}

}  // namespace nome::scene
