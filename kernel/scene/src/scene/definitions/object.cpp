// `object NAME (f1 f2 ...) endobject`: a mesh made of top-level faces.
#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_object(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  ObjectDecl o;
  o.name = parser.take_name("an object name");
  o.faces = parser.name_list("a face name or ')'");
  while (parser.skip_display_field() || parser.skip_slide_surface()) {
  }
  parser.expect_word(end);
  parser.ast().objects.push_back(std::move(o));
}

void save_object(SceneWriter& writer, Index) {
  for (const ObjectDecl& o : writer.ast().objects)
    writer.out() << "object " << o.name.text << " (" << writer.names(o.faces) << ") endobject\n";
}

void declare_object(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.objects.size(); ++i) out.push_back({&ast.objects[i].name, i});
}

Piece evaluate_object(DefinitionContext& context, Index decl) {
  const SceneAst& ast = context.ast();
  for (const Name& face : ast.objects[decl].faces) {
    const Index f = context.top_level_face(face.text);
    if (f == no_index) {
      std::vector<std::string> names;
      for (const FaceDecl& d : ast.faces) names.push_back(d.name.text);
      context.error(face.location, "unknown face '" + face.text + "'" + did_you_mean(face.text, names));
      continue;
    }
    context.add_face(ast.faces[f].vertices, ast.faces[f].name.text, ast.faces[f].surface,
                     ast.faces[f].name.location);
  }
  return std::move(context.piece());
}

void vertex_lists_object(const DefinitionScope& scope, Index decl,
                         std::vector<const std::vector<Name>*>& out) {
  for (const Name& face : scope.ast().objects[decl].faces)
    if (const Index f = scope.top_level_face(face.text); f != no_index)
      out.push_back(&scope.ast().faces[f].vertices);
}

}  // namespace

StatementKind object_statement() {
  return {.keyword = "object",
          .end_keyword = "endobject",
          .dialect = StatementDialect::slide,
          .parse = parse_object,
          .save = save_object,
          .declare = declare_object,
          .evaluate = evaluate_object,
          .vertex_lists = vertex_lists_object,
          .example = "(pf)"};
}

}  // namespace nome::scene
