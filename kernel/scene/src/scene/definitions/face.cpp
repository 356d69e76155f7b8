// `face NAME (v1 v2 ...) [surface S] endface` at top level: one face, instantiable or part of objects.
#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_face(StatementParser& parser, Index) {
  parser.ast().faces.push_back(parser.face_statement());
}

void save_face(SceneWriter& writer, Index) {
  for (const FaceDecl& f : writer.ast().faces) writer.face(f, "");
}

void declare_face(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.faces.size(); ++i) out.push_back({&ast.faces[i].name, i});
}

Piece evaluate_face(DefinitionContext& context, Index decl) {
  const FaceDecl& f = context.ast().faces[decl];
  context.add_face(f.vertices, f.name.text, f.surface, f.name.location);
  return std::move(context.piece());
}

void vertex_lists_face(const DefinitionScope& scope, Index decl, std::vector<const std::vector<Name>*>& out) {
  out.push_back(&scope.ast().faces[decl].vertices);
}

}  // namespace

StatementKind face_statement() {
  return {.keyword = "face",
          .end_keyword = "endface",
          .dialect = StatementDialect::slide,
          .parse = parse_face,
          .save = save_face,
          .declare = declare_face,
          .evaluate = evaluate_face,
          .vertex_lists = vertex_lists_face,
          .example = "(p0 p1 p2)"};
}

}  // namespace nome::scene
