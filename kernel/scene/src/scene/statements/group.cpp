// `group NAME instance ... endgroup`: a definition made of instances, expanded by the scene.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_group(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  GroupDecl g;
  g.name = parser.take_name("a group name");
  // A SLIDE group names its material (`surface S`) among its instances.
  const BlockContext inner{{"instance", "surface"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    try {
      if (parser.skip_display_field() || parser.skip_slide_surface()) continue;
      if (!parser.peek().is_word("instance")) parser.fail(parser.peek(), "'instance' or 'endgroup'");
      g.instances.push_back(parser.instance_statement());
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
  parser.ast().groups.push_back(std::move(g));
}

void save_group(SceneWriter& writer, Index) {
  for (const GroupDecl& g : writer.ast().groups) {
    writer.out() << "group " << g.name.text << "\n";
    for (const InstanceDecl& i : g.instances) writer.instance(i, "    ");
    writer.out() << "endgroup\n";
  }
}

void declare_group(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.groups.size(); ++i) out.push_back({&ast.groups[i].name, i});
}

}  // namespace

StatementKind group_statement() {
  return {.keyword = "group",
          .end_keyword = "endgroup",
          .dialect = StatementDialect::slide,
          .parse = parse_group,
          .save = save_group,
          .declare = declare_group};
}

// SLIDE's `mirror NAME instance ... endmirror`: a group whose faces SLIDE reversed, for the instances under
// it mirror their geometry with a negative scale. Nome reverses the faces of every placement whose
// transform mirrors, so the node is a group here: declared and saved as one.
StatementKind slide_mirror_statement() {
  return {.keyword = "mirror",
          .end_keyword = "endmirror",
          .dialect = StatementDialect::slide_only,
          .parse = parse_group};
}

}  // namespace nome::scene
