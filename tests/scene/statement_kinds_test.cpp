#include <catch2/catch.hpp>

#include <string>

#include "nome/scene/parser.hpp"
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

// A generator written outside the kernel, in this file alone: `testwedge NAME (size) endtestwedge`, one
// right triangle with legs of that size along x and y.
Piece evaluate_test_wedge(DefinitionContext& context, Index decl) {
  const double size = generator_numbers(context, decl)[0];
  Piece piece;
  const Index o = piece.add_vertex({0, 0, 0}, "o");
  const Index x = piece.add_vertex({size, 0, 0}, "x");
  const Index y = piece.add_vertex({0, size, 0}, "y");
  piece.add_face(std::vector<Index>{o, x, y}, "f");
  return piece;
}

StatementKind test_wedge_statement() {
  return with_generator_syntax({.keyword = "testwedge",
                                .end_keyword = "endtestwedge",
                                .signature = "(size)",
                                .argument_count = 1,
                                .dialect = StatementDialect::successor,
                                .evaluate = evaluate_test_wedge,
                                .example = "(2)"});
}

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
  // SLIDE's own statements (its Tcl, its render statement) are listed only where .slf files are read.
  for (const StatementKind& kind : statement_kinds()) {
    CHECK(find_statement_kind(kind.keyword).has_value());
    if (is_nome_statement(kind.dialect)) CHECK_THAT(errors[0], Catch::Contains(std::string(kind.keyword)));
    if (is_slide_statement(kind.dialect))
      CHECK_THAT(statement_keyword_list(true), Catch::Contains(std::string(kind.keyword)));
  }
  CHECK_FALSE(find_statement_kind("frobnicate").has_value());
}

TEST_CASE("a generator is one file and one row: the table takes one from outside the kernel", "[scene]") {
  const AddedStatementKind wedge(test_wedge_statement());
  REQUIRE(find_statement_kind("testwedge").has_value());
  const std::string text =
      "bank b\n  set s 2 1 4 1\nendbank\ntestwedge w ({expr $b_s}) endtestwedge\ninstance i w endinstance\n";
  Scene s = Scene::from_text(text, "t.nome");
  // A statement of the successor's dialect alone decides the file's dialect.
  CHECK(s.dialect().dialect == Dialect::jipcad);
  CHECK(s.dialect().cue == "'testwedge' at t.nome:4:1");
  REQUIRE(s.combined_soup().num_faces() == 1);
  CHECK(test::vertex_position(s, "i_x") == Vec3(2, 0, 0));
  CHECK(test::vertex_position(s, "i_y") == Vec3(0, 2, 0));
  // Its argument follows its slider, and it is saved and read back as written.
  s.set_parameter(*s.find_parameter("b_s"), 3);
  CHECK(test::vertex_position(s, "i_y") == Vec3(0, 3, 0));
  CHECK_THAT(to_nome_text(s), Catch::Contains("testwedge w ({expr $b_s}) endtestwedge"));
  CHECK(test::scene_errors("testwedge w () endtestwedge\n") ==
        std::vector<std::string>{"t.nome:1:13: testwedge 'w' takes 1 arguments (size), found 0"});
  CHECK_THAT(test::scene_errors("frobnicate x\n").front(), Catch::Contains(", testwedge), found"));
  // SLIDE's .slf files read their own subset: there it is refused as any statement of the .nome dialects.
  Diagnostics slf("t.slf");
  (void)parse_slf("testwedge w (2) endtestwedge\n", slf);
  REQUIRE(slf.all().size() == 1);
  CHECK(slf.all()[0].to_string() == "t.slf:1:1: not supported yet: testwedge");
}

TEST_CASE("a statement of the successor's dialect alone decides a file's dialect, from its row", "[scene]") {
  size_t successors = 0;
  for (const StatementKind& kind : statement_kinds()) {
    if (!kind.makes_geometry()) continue;
    INFO(kind.keyword);
    const Scene s = Scene::from_text(example_scene(kind), "t.nome");
    const bool is_cue = s.dialect().cue == "'" + std::string(kind.keyword) + "' at t.nome:6:1";
    CHECK(is_cue == (kind.dialect == StatementDialect::successor));
    if (is_cue) ++successors;
  }
  CHECK(successors >= 10);
}
