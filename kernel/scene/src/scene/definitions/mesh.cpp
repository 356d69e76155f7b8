// `mesh NAME face ... endface ... [sharp [weight] (v1 v2 ...) ... endsharp] endmesh`: faces over named
// vertices. SLIDE's meshes hold `vertex ... endvertex` and `facet ... endfacet`.
#include <algorithm>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"
#include "scene/statements/sharp_syntax.hpp"

namespace nome::scene {
namespace {

// SLIDE's `vertex NAME (x y z) [texture (u v)] endvertex`: a point named within its mesh (MESH_NAME).
PointDecl slide_vertex(StatementParser& parser, const std::string& mesh) {
  parser.take();
  PointDecl p;
  p.name = parser.take_name("a vertex name");
  p.name.text = mesh + "_" + p.name.text;
  parser.value_tuple(p.xyz, 3, "vertex");
  parser.skip_texture_coordinates();
  parser.expect_word("endvertex");
  return p;
}

// SLIDE's `facet NAME (v1 v2 ...) endfacet` over the mesh's own vertices (or points).
FaceDecl slide_facet(StatementParser& parser, const std::string& mesh, const std::vector<std::string>& own) {
  parser.take();
  FaceDecl f;
  f.name = parser.take_name("a facet name");
  f.vertices = parser.name_list("a vertex name or ')'");
  for (Name& v : f.vertices)
    if (std::find(own.begin(), own.end(), v.text) != own.end()) v.text = mesh + "_" + v.text;
  parser.skip_slide_surface();
  parser.expect_word("endfacet");
  return f;
}

void parse_mesh(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  MeshDecl m;
  m.name = parser.take_name("a mesh name");
  const BlockContext inner{{"face", "sharp", "point", "vertex", "facet"}, end};
  std::vector<std::string> own_vertices;  // SLIDE's, named within the mesh
  while (!parser.block_closed(opener, end, inner)) {
    const size_t start = parser.position();
    try {
      if (parser.is_slf() && parser.peek().is_word("vertex")) {
        PointDecl p = slide_vertex(parser, m.name.text);
        own_vertices.push_back(p.name.text.substr(m.name.text.size() + 1));
        parser.ast().points.push_back(std::move(p));
      } else if (parser.is_slf() && parser.peek().is_word("facet")) {
        m.faces.push_back(slide_facet(parser, m.name.text, own_vertices));
      } else if (parser.peek().is_word("face")) {
        m.faces.push_back(parser.face_statement());
      } else if (parser.peek().is_word("sharp")) {
        parse_sharp(parser, m.sharps, false);
      } else if (parser.peek().is_word("point")) {
        // The successor's meshes may define their points inside (kleinbottle.nom): names stay global.
        const Index point = *find_statement_kind("point");
        statement_kinds()[point].parse(parser, point);
      } else {
        parser.fail(parser.peek(), "'face', 'sharp', 'point' or 'endmesh'");
      }
    } catch (const SyntaxError&) {
      parser.resynchronise(inner, start);
    }
  }
  parser.ast().meshes.push_back(std::move(m));
}

void save_mesh(SceneWriter& writer, Index) {
  for (const MeshDecl& m : writer.ast().meshes) {
    writer.out() << "mesh " << m.name.text << "\n";
    for (const FaceDecl& f : m.faces) writer.face(f, "    ");
    save_sharps(writer, m.sharps, "    ");
    writer.out() << "endmesh\n";
  }
}

void declare_mesh(const SceneAst& ast, Index, std::vector<DeclaredName>& out) {
  for (Index i = 0; i < ast.meshes.size(); ++i) out.push_back({&ast.meshes[i].name, i});
}

Piece evaluate_mesh(DefinitionContext& context, Index decl) {
  const MeshDecl& m = context.ast().meshes[decl];
  for (const FaceDecl& f : m.faces) context.add_face(f.vertices, f.name.text, f.surface, f.name.location);
  // A sharp chain v1-v2, v2-v3, ... marks the edges between consecutive vertices, a single vertex is a
  // corner; the weight is OpenSubdiv's sharpness (none: infinitely sharp).
  PolygonSoup& soup = context.piece().soup;
  for (const SharpDecl& s : m.sharps) {
    const float weight = s.weight ? float(context.number(*s.weight)) : infinite_sharpness;
    if (s.vertices.size() == 1) {
      if (const Index v = context.vertex(s.vertices[0]); v != no_index)
        soup.sharp_vertices.emplace_back(v, weight);
      continue;
    }
    for (size_t i = 0; i + 1 < s.vertices.size(); ++i) {
      const Index a = context.vertex(s.vertices[i]), b = context.vertex(s.vertices[i + 1]);
      if (a != no_index && b != no_index) soup.add_sharp_edge(a, b, weight);
    }
  }
  return std::move(context.piece());
}

void vertex_lists_mesh(const DefinitionScope& scope, Index decl, std::vector<const std::vector<Name>*>& out) {
  for (const FaceDecl& f : scope.ast().meshes[decl].faces) out.push_back(&f.vertices);
}

}  // namespace

StatementKind mesh_statement() {
  return {.keyword = "mesh",
          .end_keyword = "endmesh",
          .dialect = StatementDialect::slide,
          .parse = parse_mesh,
          .save = save_mesh,
          .declare = declare_mesh,
          .evaluate = evaluate_mesh,
          .vertex_lists = vertex_lists_mesh,
          .example = "face f (p0 p1 p2) endface face g (p0 p2 p3) endface sharp (p0 p2) endsharp"};
}

}  // namespace nome::scene
