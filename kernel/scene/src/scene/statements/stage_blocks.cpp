// The successor's stage blocks: `subdivision NAME [sd_type T] sd_level N [sd_boundary MODE] instance ...
// endsubdivision` and
// `offset NAME [offset_type T] [height H] [width W] instance ... endoffset`. Their instances are roots of
// the scene; the block sets the pipeline's subdivision levels or offset distance (Scene::stage_settings).
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

struct StageWords {
  std::string_view type, amount, width;
};

StageWords words(StageKind kind) {
  if (kind == StageKind::subdivision) return {"sd_type", "sd_level", ""};
  return {"offset_type", "height", "width"};
}

// SLIDE's settings of a subdivision or offset node that change how it was drawn or tuned SLIDE's own
// algorithms, not the surface Nome makes.
bool is_slide_node_setting(std::string_view word) {
  for (const char* setting : {"type", "drawcontrols", "drawcurrent", "drawvertices", "errormetric", "uknots",
                              "uorder", "vknots", "vorder", "tolerance", "facetsmax"})
    if (word == setting) return true;
  return false;
}

// The settings before the instances: each at most once, in any order.
void stage_settings(StatementParser& parser, StageDecl& stage) {
  const StageWords w = words(stage.kind);
  bool has_amount = false;
  while (true) {
    const Token t = parser.peek();
    if (t.is_word(w.type)) {
      parser.take();
      stage.type = parser.take_name("a type name");
    } else if (t.is_word(w.amount)) {
      parser.take();
      stage.amount = parser.value();
      has_amount = true;
    } else if (stage.kind == StageKind::subdivision && t.is_word("sd_boundary")) {
      parser.take();
      stage.boundary = parser.take_name("a boundary mode (none, edge_only or edge_and_corner)");
    } else if (!w.width.empty() && t.is_word(w.width)) {
      parser.take();
      stage.width = parser.value();
    } else {
      break;
    }
  }
  if (!has_amount) parser.fail(parser.peek(), "'" + std::string(w.amount) + "' and its value");
}

void parse_stage_blocks(StatementParser& parser, StageKind kind, std::string_view end) {
  const Token opener = parser.take();
  StageDecl stage{
      kind, parser.take_name("a block name"), std::nullopt, {}, std::nullopt, std::nullopt, opener.location};
  parser.set_statement_end(end);
  stage_settings(parser, stage);
  const Index index = Index(parser.ast().stages.size());
  parser.ast().stages.push_back(std::move(stage));
  const BlockContext inner{{"instance"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    try {
      if (!parser.peek().is_word("instance"))
        parser.fail(parser.peek(), "'instance' or '" + std::string(end) + "'");
      InstanceDecl instance = parser.instance_statement();
      instance.stage = index;
      parser.ast().instances.push_back(std::move(instance));
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
}

// SLIDE's `subdivision NAME subdivisions N ... instance ... endsubdivision` and `offset NAME height H width W
// ... instance ... endoffset` are nodes that groups instance. Nome's pipeline subdivides and thickens the
// whole scene, so such a node is read as a group of its instances that sets the pipeline's level or
// distance; a second node of the same kind (whose level could differ) is refused. SLIDE's `type` (Nome
// subdivides by Catmull-Clark and offsets both ways), display fields and tuning hacks are set aside.
void parse_slide_stage(StatementParser& parser, StageKind kind, std::string_view end) {
  const Token opener = parser.take();
  StageDecl stage{
      kind, parser.take_name("a node name"), std::nullopt, {}, std::nullopt, std::nullopt, opener.location};
  parser.set_statement_end(end);
  for (const StageDecl& other : parser.ast().stages)
    if (other.kind == kind)
      parser.diagnostics().error(
          opener.location, "not supported yet: a second " + opener.text + " node ('" + other.name.text +
                               "' is at " + location_text(other.location) + "): Nome's pipeline has one " +
                               opener.text + " for the whole scene");
  const std::string_view amount = kind == StageKind::subdivision ? "subdivisions" : "height";
  bool has_amount = false;
  GroupDecl group{stage.name, {}};
  const BlockContext inner{{"instance"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    const Token t = parser.peek();
    try {
      if (t.is_word(amount)) {
        parser.take();
        stage.amount = parser.value();
        has_amount = true;
      } else if (kind == StageKind::offset && t.is_word("width")) {
        parser.take();
        stage.width = parser.value();
      } else if (t.is_word("instance")) {
        group.instances.push_back(parser.instance_statement());
      } else if (parser.skip_display_field() || parser.skip_slide_surface()) {
      } else if (t.kind == TokenKind::word && is_slide_node_setting(t.text)) {
        parser.take();
        parser.skip_display_value();
      } else {
        parser.fail(t, "'" + std::string(amount) + "', a setting, 'instance' or '" + std::string(end) + "'");
      }
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
  if (!has_amount)
    parser.diagnostics().error(opener.location, "'" + opener.text + "' needs '" + std::string(amount) + "'");
  parser.ast().stages.push_back(std::move(stage));
  parser.ast().groups.push_back(std::move(group));
}

void parse_subdivision(StatementParser& parser, Index kind) {
  if (parser.is_slf())
    return parse_slide_stage(parser, StageKind::subdivision, statement_kinds()[kind].end_keyword);
  parse_stage_blocks(parser, StageKind::subdivision, statement_kinds()[kind].end_keyword);
}

void parse_offset(StatementParser& parser, Index kind) {
  if (parser.is_slf())
    return parse_slide_stage(parser, StageKind::offset, statement_kinds()[kind].end_keyword);
  parse_stage_blocks(parser, StageKind::offset, statement_kinds()[kind].end_keyword);
}

// Each block with its settings and the root instances written in it.
void save_stage_blocks(SceneWriter& writer, StageKind kind, std::string_view keyword) {
  const SceneAst& ast = writer.ast();
  const StageWords w = words(kind);
  for (Index s = 0; s < ast.stages.size(); ++s) {
    const StageDecl& stage = ast.stages[s];
    if (stage.kind != kind) continue;
    writer.out() << keyword << " " << stage.name.text << "\n";
    if (stage.type) writer.out() << "    " << w.type << " " << stage.type->text << "\n";
    writer.out() << "    " << w.amount << " " << writer.values(&stage.amount, 1) << "\n";
    if (stage.width) writer.out() << "    " << w.width << " " << writer.values(&*stage.width, 1) << "\n";
    if (stage.boundary) writer.out() << "    sd_boundary " << stage.boundary->text << "\n";
    for (const InstanceDecl& i : ast.instances)
      if (i.stage == s) writer.instance(i, "    ");
    writer.out() << "end" << keyword << "\n";
  }
}

void save_subdivision(SceneWriter& writer, Index) {
  save_stage_blocks(writer, StageKind::subdivision, "subdivision");
}

void save_offset(SceneWriter& writer, Index) {
  save_stage_blocks(writer, StageKind::offset, "offset");
}

}  // namespace

StatementKind subdivision_statement() {
  return {.keyword = "subdivision",
          .end_keyword = "endsubdivision",
          .dialect = StatementDialect::successor_and_slide,
          .parse = parse_subdivision,
          .save = save_subdivision};
}

StatementKind offset_statement() {
  return {.keyword = "offset",
          .end_keyword = "endoffset",
          .dialect = StatementDialect::successor_and_slide,
          .parse = parse_offset,
          .save = save_offset};
}

}  // namespace nome::scene
