#include <catch2/catch.hpp>

#include <string>

#include "nome/scene/save_nome.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {

// The points and the face every row's example may name.
constexpr const char* prelude =
    "point p0 (0 0 0) endpoint\npoint p1 (1 0 0) endpoint\npoint p2 (1 1 0) endpoint\n"
    "point p3 (0 1 0) endpoint\nface pf (p0 p1 p2) endface\n";

// `KEYWORD d EXAMPLE END_KEYWORD`, instantiated: written from the row alone.
std::string example_scene(const StatementKind& kind) {
  return std::string(prelude) + std::string(kind.keyword) + " d " + std::string(kind.example) + " " +
         std::string(kind.end_keyword) + "\ninstance i d endinstance\n";
}

}  // namespace

TEST_CASE("every kind that makes geometry is parsed, evaluated and saved from its row of the table",
          "[scene]") {
  size_t checked = 0;
  for (const StatementKind& kind : statement_kinds()) {
    if (!kind.makes_geometry()) continue;
    INFO(kind.keyword);
    REQUIRE_FALSE(kind.example.empty());
    const Scene s = Scene::from_text(example_scene(kind), "t.nome");
    REQUIRE(s.instances().size() == 1);
    const Piece& piece = s.instances()[0].geometry;
    CHECK(piece.soup.num_vertices() > 0);
    const std::string saved = to_nome_text(s);
    CHECK_THAT(saved, Catch::Contains("\n" + std::string(kind.keyword) + " d"));
    const Scene back = Scene::from_text(saved, "saved.nome");
    REQUIRE(back.instances().size() == 1);
    const Piece& again = back.instances()[0].geometry;
    CHECK(again.soup.positions == piece.soup.positions);
    CHECK(again.soup.vertex_names == piece.soup.vertex_names);
    CHECK(again.soup.face_vertices == piece.soup.face_vertices);
    CHECK(again.soup.face_names == piece.soup.face_names);
    CHECK(again.soup.sharp_edges == piece.soup.sharp_edges);
    CHECK(again.rims.size() == piece.rims.size());
    ++checked;
  }
  CHECK(checked >= 8);  // polyline, face, object, funnel, tunnel, circle, mobiusstrip, mesh
}

TEST_CASE("a generator's argument count and signature are its row's", "[scene]") {
  for (const StatementKind& kind : statement_kinds()) {
    if (kind.argument_count == 0) continue;
    INFO(kind.keyword);
    const std::string text = std::string(kind.keyword) + " d () " + std::string(kind.end_keyword) + "\n";
    CHECK(test::scene_errors(text) ==
          std::vector<std::string>{"t.nome:1:" + std::to_string(kind.keyword.size() + 4) + ": " +
                                   std::string(kind.keyword) + " 'd' takes " +
                                   std::to_string(kind.argument_count) + " arguments " +
                                   std::string(kind.signature) + ", found 0"});
  }
}

TEST_CASE("an unknown statement is refused with every registered keyword", "[scene]") {
  const std::vector<std::string> errors = test::scene_errors("frobnicate x\n");
  REQUIRE(errors.size() == 1);
  CHECK(errors[0] ==
        "t.nome:1:1: expected a statement (" + statement_keyword_list() + "), found 'frobnicate'");
  for (const StatementKind& kind : statement_kinds()) {
    CHECK(find_statement_kind(kind.keyword).has_value());
    CHECK_THAT(errors[0], Catch::Contains(std::string(kind.keyword)));
  }
  CHECK_FALSE(find_statement_kind("frobnicate").has_value());
}
