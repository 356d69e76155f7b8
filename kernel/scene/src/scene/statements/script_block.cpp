// SLIDE's `tclinit { Tcl }`: code run once, in file order, before the scene is evaluated.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_script_block(StatementParser& parser, Index) {
  parser.take();
  parser.ast().script_blocks.push_back(parser.take_braced_script());
}

void save_script_blocks(SceneWriter& writer, Index) {
  for (const ScriptText& block : writer.ast().script_blocks)
    writer.out() << "tclinit {" << block.text << "}\n";
}

}  // namespace

StatementKind script_block_statement() {
  return {.keyword = "tclinit",
          .dialect = StatementDialect::slide_only,
          .parse = parse_script_block,
          .save = save_script_blocks};
}

}  // namespace nome::scene
