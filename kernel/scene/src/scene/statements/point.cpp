// `point NAME (x y z) endpoint`: a vertex faces, meshes and polylines name.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_point(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  PointDecl p;
  p.name = parser.take_name("a point name");
  parser.value_tuple(p.xyz, 3, "point");
  parser.skip_texture_coordinates();
  parser.expect_word(end);
  parser.ast().points.push_back(std::move(p));
}

void save_point(SceneWriter& writer, Index) {
  for (const PointDecl& p : writer.ast().points)
    writer.out() << "point " << p.name.text << " (" << writer.values(p.xyz, 3) << ") endpoint\n";
}

}  // namespace

StatementKind point_statement() {
  return {.keyword = "point",
          .end_keyword = "endpoint",
          .dialect = StatementDialect::slide,
          .parse = parse_point,
          .save = save_point};
}

}  // namespace nome::scene
