#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "nome/io/read_scene.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/scene/source_place.hpp"
#include "support/placed_scene.hpp"

using namespace nome;
using namespace nome::scene;

using nome::test::placed_scene;

TEST_CASE("a diagnostic's or an origin's file:line:col is read back, a file with colons too", "[scene]") {
  CHECK(parse_source_place("a.nome:3:14: expected ')'") == SourcePlace{"a.nome", {3, 14}});
  CHECK(parse_source_place("/tmp/x.nome:12:1") == SourcePlace{"/tmp/x.nome", {12, 1}});
  CHECK(parse_source_place("C:/odd:name.nome:2:5: warning: w") == SourcePlace{"C:/odd:name.nome", {2, 5}});
  const Diagnostic d{Severity::error, "dir/s.nome", {7, 9}, "unknown name 'q'"};
  CHECK(parse_source_place(d.to_string()) == SourcePlace{"dir/s.nome", {7, 9}});
  CHECK_FALSE(parse_source_place("opened /tmp/a.nome (8 vertices, 6 faces)"));
  CHECK_FALSE(parse_source_place("a.nome:3: no column"));
  CHECK_FALSE(parse_source_place(":3:4: no file"));
  CHECK_FALSE(parse_source_place("a.nome:0:4: no line 0"));
  CHECK_FALSE(parse_source_place("a.nome:3:4x"));
}

TEST_CASE("each face and vertex of a scene maps to the statement that made it", "[scene]") {
  const Scene scene = Scene::from_text(placed_scene, "p.nome");
  const PolygonSoup soup = scene.combined_soup();
  const Mesh mesh = glue_faces(soup).mesh;
  REQUIRE(soup.num_faces() == 4 + 2);
  REQUIRE(mesh.num_faces() == soup.num_faces());
  int generator_faces = 0, mesh_faces = 0;
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const auto place = face_statement(soup, f);
    REQUIRE(place);
    CHECK(place->file == "p.nome");
    const std::string& name = soup.face_names[f];
    if (name.rfind("i1_", 0) == 0) {
      CHECK(place->location.line == 2);
      ++generator_faces;
    } else {
      CHECK(place->location.line == (name == "i2_up" ? 7 : 8));
      ++mesh_faces;
    }
  }
  CHECK(generator_faces == 4);
  CHECK(mesh_faces == 2);
  CHECK_FALSE(face_statement(soup, soup.num_faces()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const auto place = vertex_statement(mesh, soup, v);
    REQUIRE(place);
    const bool is_funnel = mesh.vertex_names()[v].rfind("i1_", 0) == 0;
    // A point of both faces is shown with the first face that uses it.
    CHECK(place->location.line == (is_funnel ? 2 : 7));
  }
}

TEST_CASE("a scene text is evaluated as its file would be: located in it, includes beside it", "[scene]") {
  const auto dir =
      std::filesystem::temp_directory_path() / ("nome_scene_text_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir / "parts");
  std::ofstream(dir / "parts" / "shape.nom") << "funnel f (1 0.5 2 5) endfunnel\n";
  const std::filesystem::path file = dir / "main.nome";
  const Scene scene =
      read_scene_text("include [parts/shape.nom] endinclude\ninstance i f endinstance\n", file);
  CHECK(scene.combined_soup().num_faces() == 5);
  CHECK(scene.file() == file.string());
  try {
    read_scene_text("instance i f endinstance\ninstance j nothing endinstance\n", file);
    FAIL("an unknown target is an error");
  } catch (const SceneError& e) {
    REQUIRE_FALSE(e.diagnostics().empty());
    CHECK(e.diagnostics().front().file == file.string());
    CHECK(e.diagnostics().front().location.line == 1);
  }
  std::filesystem::remove_all(dir);
}
