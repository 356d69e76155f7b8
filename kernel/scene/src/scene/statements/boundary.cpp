// `boundary MODE endboundary`, in either dialect: what subdivision does at the surface's border (none,
// edge_only or edge_and_corner: OpenSubdiv's boundary interpolation). The successor's subdivision block
// says the same with `sd_boundary MODE` (stage_blocks.cpp).
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_boundary(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.take();
  parser.set_statement_end(end);
  parser.ast().boundary_modes.push_back(
      parser.take_name("a boundary mode (none, edge_only or edge_and_corner)"));
  parser.expect_word(end);
}

void save_boundary(SceneWriter& writer, Index) {
  for (const Name& mode : writer.ast().boundary_modes)
    writer.out() << "boundary " << mode.text << " endboundary\n";
}

}  // namespace

StatementKind boundary_statement() {
  return {
      .keyword = "boundary", .end_keyword = "endboundary", .parse = parse_boundary, .save = save_boundary};
}

}  // namespace nome::scene
