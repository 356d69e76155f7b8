// `controlpoint NAME point P [scale (sx sy sz)] [rotate (rx ry rz)] [crosssection C] [reverse]
// endcontrolpoint`: a point that shapes a sweep's cross-section where its path passes.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_control_point(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  ControlPointDecl c;
  c.name = parser.take_name("a control point name");
  parser.expect_word("point");
  c.point = parser.take_name("a point name");
  while (!parser.peek().is_word(end)) {
    const Token t = parser.peek();
    if (t.is_word("scale") || t.is_word("rotate")) {
      parser.take();
      const bool is_scale = t.text == "scale";
      parser.value_tuple(is_scale ? c.scale : c.rotate, 3, t.text.c_str());
      (is_scale ? c.has_scale : c.has_rotate) = true;
    } else if (t.is_word("crosssection")) {
      parser.take();
      c.cross_section = parser.take_name("a cross-section curve name");
    } else if (t.is_word("reverse")) {
      parser.take();
      c.is_reversing = true;
    } else {
      parser.fail(t, "'scale', 'rotate', 'crosssection', 'reverse' or '" + std::string(end) + "'");
    }
  }
  parser.take();
  parser.ast().control_points.push_back(std::move(c));
}

void save_control_point(SceneWriter& writer, Index) {
  for (const ControlPointDecl& c : writer.ast().control_points) {
    std::ostream& out = writer.out();
    out << "controlpoint " << c.name.text << " point " << c.point.text;
    if (c.has_scale) out << " scale (" << writer.values(c.scale, 3) << ")";
    if (c.has_rotate) out << " rotate (" << writer.values(c.rotate, 3) << ")";
    if (c.cross_section) out << " crosssection " << c.cross_section->text;
    out << (c.is_reversing ? " reverse" : "") << " endcontrolpoint\n";
  }
}

}  // namespace

StatementKind control_point_statement() {
  return {.keyword = "controlpoint",
          .end_keyword = "endcontrolpoint",
          .dialect = StatementDialect::successor,
          .parse = parse_control_point,
          .save = save_control_point};
}

}  // namespace nome::scene
