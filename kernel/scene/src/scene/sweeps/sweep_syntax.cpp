#include "scene/sweeps/sweep_syntax.hpp"

#include <algorithm>
#include <unordered_map>

#include "nome/error.hpp"
#include "scene/curves.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

bool is_morph(const SweepDecl& s) {
  return statement_kinds()[s.kind].keyword == "sweepmorph";
}

// `reverse`, `begincap`, `endcap`: of the cross-section block, or of the sweepmorph itself.
bool section_flag(StatementParser& parser, SweepDecl& s) {
  bool* flag = parser.peek().is_word("reverse")    ? &s.is_reversed
               : parser.peek().is_word("begincap") ? &s.has_begin_cap
               : parser.peek().is_word("endcap")   ? &s.has_end_cap
                                                   : nullptr;
  if (!flag) return false;
  parser.take();
  *flag = true;
  return true;
}

void path_block(StatementParser& parser, SweepDecl& s) {
  parser.expect_word("path");
  s.path = parser.take_name("a path curve name");
  while (!parser.peek().is_word("endpath")) {
    const Token t = parser.take();
    if (t.is_word("mintorsion"))
      s.is_minimal_torsion = true;
    else if (t.is_word("cutbegin"))
      s.is_cut_begin = true;
    else if (t.is_word("cutend"))
      s.is_cut_end = true;
    else if (t.is_word("azimuth"))
      s.azimuth = parser.grouped_value();
    else if (t.is_word("twist"))
      s.twist = parser.grouped_value();
    else
      parser.fail(t, "'mintorsion', 'azimuth', 'twist', 'cutbegin', 'cutend' or 'endpath'");
  }
  parser.take();
}

void parse_sweep_syntax(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  SweepDecl s;
  s.kind = kind;
  s.name = parser.take_name("a sweep name");
  if (is_morph(s)) {
    while (section_flag(parser, s)) {
    }
  } else {
    parser.expect_word("crosssection");
    s.cross_section = parser.take_name("a cross-section curve name");
    while (section_flag(parser, s)) {
    }
    parser.expect_word("endcrosssection");
  }
  path_block(parser, s);
  if (parser.peek().is_word("brep")) {
    parser.take();
    const Token t = parser.take();
    if (t.is_word("TRIANGLES") || t.is_word("NOME_TRIAS"))
      s.is_triangles = true;
    else if (!t.is_word("QUADRILATERALS") && !t.is_word("NOME_QUADS"))
      parser.fail(t, "TRIANGLES or QUADRILATERALS");
  }
  parser.expect_word(end);
  parser.ast().sweeps.push_back(std::move(s));
}

void save_sweep_syntax(SceneWriter& writer, Index kind) {
  for (const SweepDecl& s : writer.ast().sweeps) {
    if (s.kind != kind) continue;
    std::ostream& out = writer.out();
    const std::string flags = std::string(s.is_reversed ? " reverse" : "") +
                              (s.has_begin_cap ? " begincap" : "") + (s.has_end_cap ? " endcap" : "");
    out << statement_kinds()[kind].keyword << " " << s.name.text << "\n";
    if (s.cross_section)
      out << "  crosssection " << s.cross_section->text << flags << " endcrosssection\n";
    else if (!flags.empty())
      out << " " << flags << "\n";
    out << "  path " << s.path.text << (s.is_minimal_torsion ? " mintorsion" : "");
    if (s.azimuth) out << " azimuth " << writer.values(&*s.azimuth, 1);
    if (s.twist) out << " twist " << writer.values(&*s.twist, 1);
    out << (s.is_cut_begin ? " cutbegin" : "") << (s.is_cut_end ? " cutend" : "") << " endpath\n";
    if (s.is_triangles) out << "  brep TRIANGLES\n";
    out << statement_kinds()[kind].end_keyword << "\n";
  }
}

void declare_sweep_syntax(const SceneAst& ast, Index kind, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.sweeps.size(); ++i)
    if (ast.sweeps[i].kind == kind) out.push_back({&ast.sweeps[i].name, i});
}

// The vertices the sweep's curves name (a path through other placements' vertices waits for them).
void vertex_lists_sweep_syntax(const DefinitionScope& scope, Index decl,
                               std::vector<const std::vector<Name>*>& out) {
  const SweepDecl& s = scope.ast().sweeps[decl];
  for (const Name* curve : {&s.path, s.cross_section ? &*s.cross_section : nullptr}) {
    if (!curve) continue;
    const auto d = scope.definition(curve->text);
    if (d && statement_kinds()[d->first].sample && statement_kinds()[d->first].vertex_lists)
      statement_kinds()[d->first].vertex_lists(scope, d->second, out);
  }
}

// Reads the statement's curves and runs `make` (sweep or sweep_positions) on them, its refusals and
// warnings located at the statement's name.
template <typename Make>
auto run_sweep(DefinitionContext& context, Index decl, Make make) {
  const SweepDecl& s = context.ast().sweeps[decl];
  const SweepInput in = sweep_input(context, s);
  const std::string statement = std::string(statement_kinds()[s.kind].keyword) + " '" + s.name.text + "'";
  const std::string what = statement + ": ";
  size_t section_points = 0;
  for (const CrossSection& section : in.sections)
    section_points = std::max(section_points, section.points.size());
  context.expect_faces(s.name.location, statement, double(in.path.size()) * double(section_points));
  decltype(make(in)) result;
  try {
    result = make(in);
  } catch (const InvalidInputError& e) {
    throw EvaluationError(s.name.location, what + e.what());
  }
  for (std::string& w : result.warnings) context.warning(s.name.location, what + w);
  return result;
}

Piece evaluate_sweep_syntax(DefinitionContext& context, Index decl) {
  return run_sweep(context, decl,
                   [](const SweepInput& in) { return sweep(in.path, in.sections, in.options); })
      .piece;
}

PiecePositions evaluate_positions_sweep_syntax(DefinitionContext& context, Index decl) {
  SweepPositions result = run_sweep(
      context, decl, [](const SweepInput& in) { return sweep_positions(in.path, in.sections, in.options); });
  return {std::move(result.positions), result.topology_key};
}

}  // namespace

StatementKind with_sweep_syntax(StatementKind kind) {
  kind.parse = parse_sweep_syntax;
  kind.save = save_sweep_syntax;
  kind.declare = declare_sweep_syntax;
  kind.vertex_lists = vertex_lists_sweep_syntax;
  kind.evaluate = evaluate_sweep_syntax;
  kind.evaluate_positions = evaluate_positions_sweep_syntax;
  return kind;
}

}  // namespace nome::scene
