#include <catch2/catch.hpp>

#include <filesystem>

#include "nome/io/read_scene.hpp"
#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"
#include "support/scratch_files.hpp"
#include "support/shared_examples.hpp"

using namespace nome;
using nome::scene::Scene;

namespace {

// Same vertices (names, exact positions), same faces, same colours, same rim lines.
void check_same_geometry(const Scene& a, const Scene& b) {
  REQUIRE(a.instances().size() == b.instances().size());
  for (size_t i = 0; i < a.instances().size(); ++i) {
    const scene::Piece& x = a.instances()[i].geometry;
    const scene::Piece& y = b.instances()[i].geometry;
    CHECK(a.instances()[i].name == b.instances()[i].name);
    CHECK(x.soup.positions == y.soup.positions);
    CHECK(x.soup.vertex_names == y.soup.vertex_names);
    CHECK(x.soup.face_offsets == y.soup.face_offsets);
    CHECK(x.soup.face_vertices == y.soup.face_vertices);
    CHECK(x.soup.face_names == y.soup.face_names);
    CHECK(x.soup.face_colors == y.soup.face_colors);
    CHECK(x.soup.sharp_edges == y.soup.sharp_edges);
    CHECK(x.rims.size() == y.rims.size());
  }
}

Scene reread(const Scene& s) {
  return Scene::from_text(scene::to_nome_text(s), "saved.nome");
}

}  // namespace

TEST_CASE("saving every example and reading it back gives the same geometry", "[scene]") {
  const std::vector<std::string> files = test::scene_files();
  for (const std::string& file : files) {
    INFO(file);
    const Scene s = read_scene(file);
    check_same_geometry(s, reread(s));
  }
  CHECK(files.size() >= 12);
}

TEST_CASE("an edited scene saves its slider values, consolidated faces and deletions", "[scene]") {
  Scene s = test::load_scene_file(test::assets_dir() + "funnel_cube.nome");
  s.set_parameter(*s.find_parameter("fp_ro"), 0.5);
  s.set_parameter(*s.find_parameter("fp_z"), -1.1);
  s.set_consolidated_faces(
      {{"fun3_hc3", "fun5_hc3", "fun2_hc5"}, {"fun3_hc3", "fun2_hc5", "fun2_hc6", "fun3_hc2"}});
  s.set_deleted_faces({"fun1_f0", "cf.fun6.f3"});
  CHECK(s.deleted_faces() == std::vector<std::string>{"cf_fun1_f0", "cf_fun6_f3"});
  REQUIRE(s.instances().size() == 2);
  CHECK(s.instances()[0].geometry.soup.num_faces() == 46);
  CHECK(s.instances()[1].name == "consolidatemesh");
  CHECK(s.instances()[1].geometry.soup.num_faces() == 2);

  const std::string dir = test::scratch_path("nome_save_test", "").parent_path();
  scene::write_nome(s, dir + "/edited.nome");
  const Scene back = read_scene(dir + "/edited.nome");
  check_same_geometry(s, back);
  CHECK(back.parameters()[*back.find_parameter("fp_z")].value == -1.1);
  CHECK(back.consolidated_faces().size() == 2);
  const std::string text = scene::to_nome_text(s);
  CHECK_THAT(text, Catch::Contains("    set z -1.1 -1.5 -0.1 0.1\n"));
  CHECK_THAT(text, Catch::Contains("delete\n    face cf_fun1_f0 endface\n"));
  CHECK_THAT(text, Catch::Contains("consolidate\n    consolidateface\n        vertex fun3_hc3 endvertex\n"));
  CHECK_THAT(text, Catch::Contains("translate (0 0 {expr $fp_z}) rotate (1 0 0) (180)"));
}

TEST_CASE("unknown names in the editing data are refused with candidates", "[scene]") {
  Scene s = test::load_scene_file(test::assets_dir() + "funnel_cube.nome");
  CHECK_THROWS_WITH(s.set_deleted_faces({"fun1_f9"}),
                    Catch::Contains("unknown face 'fun1_f9' (did you mean"));
  CHECK_THROWS_WITH(s.set_consolidated_faces({{"hc3", "fun5_hc3", "fun2_hc5"}}),
                    Catch::Contains("ambiguous vertex name 'hc3': 6 candidates: cf_fun1_hc3"));
  CHECK(s.instances().size() == 1);
  CHECK(s.deleted_faces().empty());
}

TEST_CASE(".anom files apply saved slider values and a working mesh to an open scene", "[scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  Scene s = test::load_scene_file(test::originals_dir() + "kleinbottle.nom");
  s.set_parameter(*s.find_parameter("tp3_x"), 1);
  s.apply_anom(test::read_text(test::originals_dir() + "kleinbottle_s1.anom"), "s1.anom");
  CHECK(s.parameters()[*s.find_parameter("tp3_x")].value == -2);
  REQUIRE(s.instances().size() == 2);
  CHECK(s.instances()[1].geometry.soup.num_faces() == 8);
  CHECK(s.consolidated_faces()[0] == std::vector<std::string>{"t1_lc5", "t1_lc4", "t5_lc4", "t5_lc5"});
  CHECK_THROWS_WITH(s.apply_anom("savedparameter tp9_n 8 endsavedparameter\n", "bad.anom"),
                    Catch::Contains("bad.anom:1:16: unknown parameter 'tp9_n' (did you mean tp1_n"));
}
