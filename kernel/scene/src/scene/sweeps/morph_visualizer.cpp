// `morphvisualizer NAME sweep S index (I) endmorphvisualizer`: the cross-section sweep S shapes at its
// I-th path sample (scaled there), as a rim line c0.. in the plane z = 0.
#include <cmath>

#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"
#include "scene/sweeps/sweep_syntax.hpp"

namespace nome::scene {
namespace {

void parse_morph_visualizer(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  MorphVisualizerDecl m;
  m.name = parser.take_name("a name");
  parser.expect_word("sweep");
  m.sweep = parser.take_name("a sweep or sweepmorph name");
  parser.expect_word("index");
  m.index = parser.grouped_value();
  parser.expect_word(end);
  parser.ast().morph_visualizers.push_back(std::move(m));
}

void save_morph_visualizer(SceneWriter& writer, Index) {
  for (const MorphVisualizerDecl& m : writer.ast().morph_visualizers)
    writer.out() << "morphvisualizer " << m.name.text << " sweep " << m.sweep.text << " index "
                 << writer.values(&m.index, 1) << " endmorphvisualizer\n";
}

void declare_morph_visualizer(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.morph_visualizers.size(); ++i) out.push_back({&ast.morph_visualizers[i].name, i});
}

Piece evaluate_morph_visualizer(DefinitionContext& context, Index decl) {
  const MorphVisualizerDecl& m = context.ast().morph_visualizers[decl];
  const auto d = context.definition(m.sweep.text);
  if (!d || statement_kinds()[d->first].declare != statement_kinds()[*find_statement_kind("sweep")].declare)
    throw EvaluationError(m.sweep.location, "'" + m.sweep.text + "' is no sweep or sweepmorph");
  const SweepInput in = sweep_input(context, context.ast().sweeps[d->second]);
  const int index = context.whole(m.index, 0, "index");
  if (std::size_t(index) >= in.path.size())
    throw EvaluationError(m.index.location, "index " + std::to_string(index) +
                                                " is past the sweep's last sample " +
                                                std::to_string(in.path.size() - 1));
  const PathSample& sample = in.path[std::size_t(index)];
  const CrossSection& section = in.sections[sample.section];
  Piece& piece = context.piece();
  RimLine rim{"", {}, section.is_closed};
  for (std::size_t j = 0; j < section.points.size(); ++j) {
    const glm::dvec2 p = section.points[j] * sample.scale;
    rim.vertices.push_back(piece.add_vertex({p.x, p.y, 0.0}, "c" + std::to_string(j)));
  }
  piece.rims.push_back(std::move(rim));
  return std::move(piece);
}

}  // namespace

StatementKind morph_visualizer_statement() {
  return {.keyword = "morphvisualizer",
          .end_keyword = "endmorphvisualizer",
          .dialect = StatementDialect::successor,
          .parse = parse_morph_visualizer,
          .save = save_morph_visualizer,
          .declare = declare_morph_visualizer,
          .evaluate = evaluate_morph_visualizer,
          .example =
              "sweep m index (1) endmorphvisualizer\ncircle c (4 0.2) endcircle\n"
              "controlpoint q point p1 crosssection c endcontrolpoint\npolyline pl (p0 q p2) endpolyline\n"
              "sweepmorph m path pl endpath endsweepmorph\nmorphvisualizer z sweep m index (0)"};
}

}  // namespace nome::scene
