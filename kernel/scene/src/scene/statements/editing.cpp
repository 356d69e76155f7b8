// The editing model's statements (report 7.3.3): `delete face NAME endface ... enddelete` and
// `consolidate consolidateface vertex N endvertex ... endconsolidateface ... endconsolidate`.
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_writer.hpp"
#include "scene/statement_parser.hpp"

namespace nome::scene {
namespace {

void parse_delete(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  const BlockContext inner{{"face"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    parser.set_statement_end("endface");
    parser.expect_word("face");
    parser.ast().deleted_faces.push_back(parser.take_name("a face name"));
    parser.expect_word("endface");
  }
}

// The deletions by full hierarchical name.
void save_delete(SceneWriter& writer, Index) {
  const std::vector<std::string>& deleted = writer.edits().deleted;
  if (deleted.empty()) return;
  writer.out() << "delete\n";
  for (const std::string& f : deleted) writer.out() << "    face " << f << " endface\n";
  writer.out() << "enddelete\n";
}

void parse_consolidate(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  const Token opener = parser.take();
  const BlockContext inner{{"consolidateface"}, end};
  while (!parser.block_closed(opener, end, inner)) {
    const Token face = parser.peek();
    parser.expect_word("consolidateface");
    NamedFace f{parser.vertex_blocks("endconsolidateface", face), face.location};
    if (f.vertices.size() < 3)
      parser.diagnostics().error(face.location, "a consolidated face needs at least 3 vertices, found " +
                                                    std::to_string(f.vertices.size()));
    parser.ast().consolidated_faces.push_back(std::move(f));
  }
}

void save_consolidate(SceneWriter& writer, Index) {
  const std::vector<std::vector<std::string>>& faces = writer.edits().consolidated;
  if (faces.empty()) return;
  writer.out() << "consolidate\n";
  for (const std::vector<std::string>& f : faces) {
    writer.out() << "    consolidateface\n";
    for (const std::string& v : f) writer.out() << "        vertex " << v << " endvertex\n";
    writer.out() << "    endconsolidateface\n";
  }
  writer.out() << "endconsolidate\n";
}

// `sharpedges [w] (a b) [w] (c d) ... endsharpedges`: a weight is the sharpness of the one pair after it
// (none: infinitely sharp).
void parse_sharp_edges(StatementParser& parser, Index kind) {
  const std::string_view end = statement_kinds()[kind].end_keyword;
  parser.set_statement_end(end);
  parser.take();
  while (!parser.peek().is_word(end)) {
    SharpEdgeDecl edge;
    if (!parser.peek().is_symbol("(")) {
      const Value weight = parser.literal_value();
      if (weight.literal < 0)
        parser.diagnostics().error(weight.location,
                                   "a sharpness is 0 or more, found " + format_number(weight.literal));
      edge.weight = float(weight.literal);
    }
    const SourceLocation at = parser.peek().location;
    std::vector<Name> pair = parser.name_list("a vertex name or ')'");
    if (pair.size() != 2) {
      parser.diagnostics().error(at, "a sharp edge is two vertices, found " + std::to_string(pair.size()));
      continue;
    }
    edge.edge = {std::move(pair), at};
    parser.ast().sharp_edges.push_back(std::move(edge));
  }
  parser.take();
}

// By full hierarchical names.
void save_sharp_edges(SceneWriter& writer, Index) {
  const std::vector<NamedSharpEdge>& edges = writer.edits().sharp;
  if (edges.empty()) return;
  writer.out() << "sharpedges";
  for (const NamedSharpEdge& e : edges) {
    writer.out() << "\n    ";
    if (e.weight < infinite_sharpness) writer.out() << sharpness_text(e.weight) << " ";
    writer.out() << "(" << e.a << " " << e.b << ")";
  }
  writer.out() << "\nendsharpedges\n";
}

}  // namespace

StatementKind sharp_edges_statement() {
  return {.keyword = "sharpedges",
          .end_keyword = "endsharpedges",
          .parse = parse_sharp_edges,
          .save = save_sharp_edges};
}

StatementKind delete_statement() {
  return {.keyword = "delete", .end_keyword = "enddelete", .parse = parse_delete, .save = save_delete};
}

StatementKind consolidate_statement() {
  return {.keyword = "consolidate",
          .end_keyword = "endconsolidate",
          .parse = parse_consolidate,
          .save = save_consolidate};
}

}  // namespace nome::scene
