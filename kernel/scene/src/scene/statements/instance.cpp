// `instance NAME TARGET [transforms] [surface S] endinstance` at top level: the scene's roots.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_instance(StatementParser& parser, Index) {
  parser.ast().instances.push_back(parser.instance_statement());
}

void save_instance(SceneWriter& writer, Index) {
  for (const InstanceDecl& i : writer.ast().instances)
    if (i.stage == no_index) writer.instance(i, "");  // a stage block writes its own
  for (const InstanceDecl& i : writer.ast().render_instances) writer.instance(i, "");
}

}  // namespace

StatementKind instance_statement() {
  return {.keyword = "instance",
          .end_keyword = "endinstance",
          .dialect = StatementDialect::slide,
          .parse = parse_instance,
          .save = save_instance};
}

}  // namespace nome::scene
